// One entry point for every file the page accepts, chosen by extension and, failing that, by
// content. Returns what main.js meshes:
//   { kind: 'rings', rings, fill, label, note }   closed outlines and a fill rule
//   { kind: 'pslg', pslg, label, note }           points, segments, holes (Triangle's rule)
//   { kind: 'font', buffer, label }               a font to set the text in
// The package's own parsers (.poly, .node, the mesher's JSON shapes) come in as `am`; fonts,
// SVG, GeoJSON and TopoJSON are read here and need no WebAssembly.
// The SVG and map readers (and topojson-client behind them) load on first use: the page's
// first mesh needs neither.
const geo = () => import('./geo.js');
const svg = () => import('./svg.js');

const FONT_MAGIC = ['\x00\x01\x00\x00', 'OTTO', 'true', 'wOFF', 'wOF2'];

function extension(name) {
  const m = /\.([a-z0-9]+)$/i.exec(name || '');
  return m ? m[1].toLowerCase() : '';
}

function magic(buffer) {
  return String.fromCharCode(...new Uint8Array(buffer, 0, Math.min(4, buffer.byteLength)));
}

async function fromJson(text, name, label, am) {
  const obj = JSON.parse(text);
  const { isGeoJson, geoJsonToRings } = await geo();
  if (isGeoJson(obj)) {
    const { rings, projected } = geoJsonToRings(obj);
    return { kind: 'rings', rings, fill: 'evenodd', label, units: projected ? 'km' : undefined,
      note: `${obj.type === 'Topology' ? 'TopoJSON' : 'GeoJSON'}: ${rings.length} rings${projected ? ', lon/lat projected (Lambert equal-area, km)' : ''}` };
  }
  // The package reads the mesher's own JSON shapes: a CG:SHOP 2025 instance, a PSLG
  // {"vertices", "segments", "holes"} and {"rings"}.
  if (!am) throw new Error('the mesher is still loading; try again in a moment');
  const pslg = am.parseJson(text, { name });
  const note = pslg.instanceUid ? `CG:SHOP instance ${pslg.instanceUid}` : pslg.fill ? 'rings JSON' : 'PSLG JSON';
  return { kind: 'pslg', pslg, label, note };
}

export async function loadFile(file, { am, tolerance }) {
  const label = (file.name || 'input').replace(/\.[^.]+$/, '') || 'input';
  const ext = extension(file.name);
  const buffer = await file.arrayBuffer();
  if (['ttf', 'otf', 'woff', 'woff2'].includes(ext) || FONT_MAGIC.includes(magic(buffer))) {
    if (ext === 'woff2' || magic(buffer) === 'wOF2') throw new Error(`${file.name}: WOFF2 is not supported; use TTF, OTF or WOFF`);
    return { kind: 'font', buffer, label };
  }
  const text = new TextDecoder().decode(buffer);
  const head = text.trimStart().slice(0, 200);
  const at = (e) => { e.message = `${file.name}: ${e.message}`; return e; };
  try {
    if (ext === 'svg' || head.startsWith('<')) {
      const { rings, fill, mixed } = (await svg()).svgToRings(text, tolerance);
      return { kind: 'rings', rings, fill, label, svg: text,
        note: `SVG: ${rings.length} rings, fill-rule ${fill}${mixed ? ' (elements disagree; nonzero used for all)' : ''}` };
    }
    if (['json', 'geojson', 'topojson'].includes(ext) || head.startsWith('{')) {
      return await fromJson(text, file.name, label, am);
    }
    if (!am) throw new Error('the mesher is still loading; try again in a moment');
    if (ext === 'node') return { kind: 'pslg', pslg: am.parseNode(text, { name: file.name }), label, note: 'point set (.node)' };
    return { kind: 'pslg', pslg: am.parsePoly(text, { name: file.name }), label, note: '.poly' };
  } catch (e) {
    // The package's parse errors already name the file; the page's own do not.
    throw e.message.includes(file.name) ? e : at(e);
  }
}
