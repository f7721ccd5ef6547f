// Type-checked (never run) by types.test.mjs: require('acutemesh') from CommonJS, whose types
// are dist/index.d.cts (package.json: exports["."].node.require).
import init = require('acutemesh');

export async function use(text: string): Promise<number> {
  const am: init.AcuteMesh = await init();
  const same: init.AcuteMesh = await init.default({ wasmUrl: '/x/acutemesh.wasm' });
  const other = await init.createInstance({ maxMemory: 2 ** 28 });
  const m: init.MeshResult = am.mesh(am.parsePoly(text), { mode: 'acute', maxAngle: 80 });
  try {
    am.mesh({ points: [0, 0] });
  } catch (e) {
    if (e instanceof init.AcuteMeshError) {
      const code: init.ErrorCode = e.code;
      void code;
    }
  }
  const { createMeshWorker } = await import('acutemesh/worker');
  void [same, other, createMeshWorker];
  // @ts-expect-error: not a mode
  am.mesh({ points: [0, 0] }, { mode: 'obtuse' });
  return m.stats.triangles;
}
