// Types of `require('acutemesh')` (dist/index.cjs): init is the export itself, and also its
// `default` and `init`; the types are those of the ES module's (index.d.ts).
import type * as acutemesh from './index.js';

interface Init {
  /** Loads acutemesh once (later calls return the same promise; the first call's options apply). */
  (options?: acutemesh.InitOptions): Promise<acutemesh.AcuteMesh>;
  readonly default: Init;
  readonly init: Init;
  /** A separate instance with its own heap (not memoised). */
  createInstance(options?: acutemesh.InitOptions): Promise<acutemesh.AcuteMesh>;
  /** `instanceof` recognises every error acutemesh throws with code BAD_INPUT, OUT_OF_MEMORY, ... */
  readonly AcuteMeshError: typeof acutemesh.AcuteMeshError;
}

declare const init: Init;

declare namespace init {
  export type AcuteMesh = acutemesh.AcuteMesh;
  export type AcuteMeshError = acutemesh.AcuteMeshError;
  export type ErrorCode = acutemesh.ErrorCode;
  export type InitOptions = acutemesh.InitOptions;
  export type Mode = acutemesh.Mode;
  export type FillRule = acutemesh.FillRule;
  export type Status = acutemesh.Status;
  export type Pslg = acutemesh.Pslg;
  export type PslgInput = acutemesh.PslgInput;
  export type ParsedPslg = acutemesh.ParsedPslg;
  export type MeshOptions = acutemesh.MeshOptions;
  export type MeshResult = acutemesh.MeshResult;
  export type MeshStats = acutemesh.MeshStats;
  export type MeshInput = acutemesh.MeshInput;
  export type Validation = acutemesh.Validation;
  export type Progress = acutemesh.Progress;
  export type Vocabulary = acutemesh.Vocabulary;
}

export = init;
