// The page: inputs -> PSLG -> mesh in a worker -> view, histogram, stats, downloads.
//
// Exactly one input is "current": the one changed last (text or font, a file or sample, or the
// drawing). Changing it shows a preview of the outline and never meshes by itself; the Mesh
// button (or the page's first load) meshes it. Options and the current input, where it fits in
// a link (text, sample, drawing), live in the URL so a view can be shared.
import { loadEngine, meshInWorker, warmUp } from './engine.js';
import { MeshView } from './view.js';
import { analyse, CLASSES } from './angles.js';
import { drawHistogram, SMALL_ANGLE_COLOR } from './histogram.js';
import { AUTO, angleFloor, certifiedBound, measureFloor, smallestDomainCorner } from './max-angle.js';
import { verdict, formatMs, sizeWords } from './verdict.js';
import { meshToSvg } from './svg-export.js';
import { RANGES, checkFields, problem, edgeAt, edgePosition, edgeRange, roundEdge } from './form.js';
import { DrawTool, encodeRings, decodeRings } from './draw.js';
import { parseFont, textToRings, fontName, missingGlyphs } from './loaders/font.js';
import { loadFile } from './loaders/index.js';
import { regionsOf } from './regions.js';

const $ = (id) => document.getElementById(id);
const ui = {
  text: $('text'), font: $('font'), tolerance: $('tolerance'), sample: $('sample'), file: $('file'),
  draw: $('draw'), drawClose: $('draw-close'), drawClear: $('draw-clear'), source: $('source'),
  mode: $('mode'), maxAngle: $('maxAngle'), maxAngleAuto: $('maxAngleAuto'), angleFloor: $('angleFloor'), minAngle: $('minAngle'), maxArea: $('maxArea'),
  maxEdge: $('maxEdge'), maxEdgeSlider: $('maxEdgeSlider'), grading: $('grading'), maxSteiner: $('maxSteiner'), optimize: $('optimize'), run: $('run'), cancel: $('cancel'), progress: $('progress'),
  status: $('status'), stats: $('stats'), histogram: $('histogram'), legend: $('legend'),
  view: $('view'), fit: $('fit'), showEdges: $('show-edges'), showSteiner: $('show-steiner'),
  showRegions: $('show-regions'), regionsToggle: $('regions-toggle'),
  dropHint: $('drop-hint'), downloads: $('downloads'), formError: $('form-error'), linkNote: $('link-note'),
};
// The number fields checked against their ranges (form.js) before a run.
const FIELDS = { maxAngle: ui.maxAngle, minAngle: ui.minAngle, maxArea: ui.maxArea, maxEdge: ui.maxEdge, grading: ui.grading,
  maxSteiner: ui.maxSteiner, optimize: ui.optimize, tolerance: ui.tolerance };

const BUNDLED_FONTS = {
  'pagella-regular': 'fonts/texgyrepagella-regular.otf',
  'pagella-bold': 'fonts/texgyrepagella-bold.otf',
};
// What the option inputs hold when the URL says nothing: the page's mode, and otherwise the
// mesher's defaults (vocabulary.defaults; tests/web checks that they agree). Max edge and
// grading start empty: none (the mesher's 0).
const OPTION_DEFAULTS = { mode: 'acute', maxAngle: '90', minAngle: '0', maxArea: '0', maxEdge: '', grading: '', maxSteiner: '0', optimize: '' };
// The samples: maps are GeoJSON, the others name their file.
const SAMPLE_FILES = { gear: 'samples/gear.svg', plate: 'samples/plate.poly' };
const TEXT_DEFAULTS = { text: 'Acute', font: 'pagella-regular', tol: '5' };

const view = new MeshView(ui.view);
const draw = new DrawTool(view, (rings) => {
  current = { type: 'draw', rings };
  inputChanged();
  takeExtent({ rings });
  showSource(`drawing: ${rings.length} ring${rings.length === 1 ? '' : 's'}`);
  setStatus(droppedRing, droppedRing ? 'warn' : '');
  droppedRing = '';
  saveUrl();
});
let droppedRing = '';  // why the last closed ring was dropped, said until the next ring
draw.onDropped = (why) => { droppedRing = `The ring just closed was dropped: ${why}.`; };
draw.onVertex = (n) => showSource(`drawing: ${n} ${n === 1 ? 'vertex' : 'vertices'} in the open ring; click the first one (or press Enter) to close it`);

const fonts = new Map();      // key -> Promise<opentype Font>
let current = { type: 'text' };  // the input the Mesh button meshes
let lastResult = null;        // { mesh, label, key }
let lastMeshedKey = null;     // to fit the view only when the input itself changed
let running = null;           // AbortController of the run in progress
let runs = 0;
let vocabulary = null;        // the mesher's names and defaults, once it has loaded
let floorInfo = null;         // the current input's { corner, floor, from: 'input' | 'run' }
let inputSeq = 0;             // bumped by every input change and run: late previews are dropped
let extent = null;            // the current input's larger side (the max edge slider's scale)
let extentUnits = 'units';    // what its numbers are in, for the slider's spoken value
warmUp();
const enginePromise = loadEngine();
enginePromise.then(takeVocabulary, (e) => setStatus(`Could not load the mesher: ${e.message}`, 'error'));

// ---- status and source line ---------------------------------------------------------------
function setStatus(text, kind = '') {
  ui.status.textContent = text;
  ui.status.className = `status ${kind}`;
}

function showSource(text) {
  ui.source.textContent = text;
}

// ---- fonts --------------------------------------------------------------------------------
function getFont(key) {
  if (!fonts.has(key)) {
    const url = BUNDLED_FONTS[key];
    if (!url) return Promise.reject(new Error(`unknown font ${key}`));
    fonts.set(key, fetch(url).then((r) => {
      if (!r.ok) throw new Error(`${url}: HTTP ${r.status}`);
      return r.arrayBuffer();
    }).then(parseFont));
  }
  return fonts.get(key);
}

let uploadedFonts = 0;
function addFont(buffer, label) {
  const font = parseFont(buffer);
  const key = `upload-${++uploadedFonts}`;
  fonts.set(key, Promise.resolve(font));
  const opt = new Option(fontName(font, label), key);
  ui.font.add(opt);
  ui.font.value = key;
  return font;
}

// ---- inputs -> meshable input ---------------------------------------------------------------
const tolerance = () => Math.min(100, Math.max(0.1, Number(ui.tolerance.value) || 5));

// Returns { rings, fill } or { pslg }, plus label and key (identity of the input's geometry).
async function buildInput(src) {
  switch (src.type) {
    case 'text': {
      const text = ui.text.value;
      if (!text.trim()) throw new Error('type some text to mesh');
      const font = await getFont(ui.font.value);
      const rings = textToRings(font, text, tolerance());
      const fontLabel = ui.font.selectedOptions[0].text;
      const missing = missingGlyphs(font, text);
      const noGlyph = missing.length ? `${fontLabel} has no glyph for ${missing.map((c) => `"${c}"`).join(', ')}` : '';
      if (!rings.length) throw new Error(noGlyph ? `${noGlyph}: nothing to mesh` : `"${text}" has no outlines in this font`);
      return { rings, fill: 'nonzero', label: slug(text), key: `text:${ui.font.value}:${text}`,
        note: `"${text}" in ${fontLabel}`, warning: noGlyph ? `${noGlyph}: left out.` : '' };
    }
    case 'file': case 'sample': {
      const input = await readFile(src.file);
      if (input.kind === 'font') throw new Error('a font sets the text: type in the Text box');
      return { ...input, key: `${src.type}:${src.file.name}:${src.file.size}:${src.file.lastModified || ''}` };
    }
    case 'draw':
      if (!src.rings.length) throw new Error('draw a closed ring first (click the first vertex to close it)');
      return { rings: src.rings, fill: 'evenodd', label: 'drawing', key: `draw:${encodeRings(src.rings)}`, note: 'drawing' };
    default:
      throw new Error(`unknown input ${src.type}`);
  }
}

function slug(text) {
  return text.trim().replace(/[^\p{L}\p{N}]+/gu, '-').replace(/^-|-$/g, '').slice(0, 40) || 'text';
}

// A new input makes the shown result stale: a run of the old input still going is stopped
// (its mesh must not replace the new preview), and the stats, histogram and downloads go.
function inputChanged() {
  inputSeq++;
  view.stopBuilding();
  stopRun();
  clearResult();
}

async function preview() {
  inputChanged();
  const seq = inputSeq;
  try {
    const input = await buildInput(current);
    if (seq !== inputSeq) return;  // a newer input or a run took over meanwhile
    view.setPreview(input.pslg ? { pslg: input.pslg } : { rings: input.rings, fill: input.fill });
    if (current.type !== 'draw') draw.hide();
    view.fit();
    takeExtent(input);
    showSource(describeInput(input, ' Press Mesh.'));
    const am = await enginePromise.catch(() => null);
    if (am && seq === inputSeq) {
      floorInfo = measureFloor(am, input.pslg || am.fromRings(input.rings, { fill: input.fill }));
      showFloor();
    }
    setStatus('');
  } catch (e) {
    if (seq === inputSeq) inputFailed(e);
  }
}

// The source line: what the input is, its size, and what the page could not take from it.
function describeInput(input, next = '') {
  const n = input.pslg ? input.pslg.points.length / 2 : input.rings.reduce((s, r) => s + r.length, 0);
  return `${input.note || input.label}: ${n} input vertices.${next}${linkNote()}${input.warning ? ` ${input.warning}` : ''}`;
}

// The current input cannot be meshed: nothing of the previous one stays on screen to be
// taken for it, and Mesh says the same again.
function inputFailed(e) {
  view.clear();
  draw.hide();
  floorInfo = null;
  takeExtent(null);
  showFloor();
  const name = current.file ? current.file.name : current.type === 'text' ? `"${ui.text.value}"` : current.type;
  showSource(`${name}: cannot be meshed (the message below says why).${linkNote()}`);
  setStatus(e.message, 'error');
}

// A link to the page holds text, a sample or a drawing, not a file's contents.
function linkNote() {
  return current.type === 'file' ? ' A link to this page cannot carry the file: it opens the default text.' : '';
}

function stopRun() {
  if (!running) return;
  const c = running;
  running = null;
  c.abort();
  ui.cancel.disabled = true;
  ui.progress.hidden = true;
}

function clearResult() {
  if (lastResult?.regions) buildLegend();
  lastResult = null;
  ui.regionsToggle.hidden = true;
  ui.stats.replaceChildren();
  ui.stats.dataset.result = '';
  drawHistogram(ui.histogram, null);
  for (const b of ui.downloads.querySelectorAll('[data-format]')) b.disabled = true;
}

// Past this size a file is refused with a message instead of freezing the tab (the CLI and the
// npm package take any size).
export const MAX_FILE_MB = 32;

// Files are read whole and parsed on the page; past MAX_FILE_MB a file is refused unread.
async function readFile(file) {
  if (file.size > MAX_FILE_MB * 1024 * 1024) {
    throw new Error(`${file.name} is ${(file.size / 1048576).toFixed(1)} MB: files over ${MAX_FILE_MB} MB ` +
                    'are refused here (the acutemesh CLI and npm package take any size)');
  }
  const am = await enginePromise.catch(() => null);
  return loadFile(file, { am, tolerance: tolerance() });
}

async function takeFile(file, type = 'file') {
  if (draw.active) toggleDraw();
  let input;
  try {
    input = await readFile(file);
  } catch (e) {
    // The unreadable file is now the current input: Mesh must not go back to the last one.
    current = { type, file, name: type === 'sample' ? ui.sample.value : undefined };
    if (type === 'file') ui.sample.value = '';
    inputChanged();
    saveUrl();
    inputFailed(e);
    return;
  }
  if (input.kind === 'font') {
    const font = addFont(input.buffer, input.label);
    current = { type: 'text' };
    saveUrl();
    await preview();
    showSource(`font ${fontName(font, input.label)} loaded. ${ui.source.textContent}`);
    return;
  }
  current = { type, file, name: type === 'sample' ? ui.sample.value : undefined };
  if (type === 'file') ui.sample.value = '';
  saveUrl();
  await preview();
}

async function takeSample(name) {
  const file = SAMPLE_FILES[name] || `samples/${name}.geojson`;
  const r = await fetch(file);
  if (!r.ok) throw new Error(`${file}: HTTP ${r.status}`);
  const blob = await r.blob();
  return new File([blob], file.split('/').pop());
}

// ---- options ------------------------------------------------------------------------------
// Only what the user set (a positive number) goes to the mesher; the rest is its own default,
// as for the CLI and the package: quality mode aims at vocabulary.defaults.qualityMinAngle
// only when neither a minimum angle nor a maximum area is given.
function meshOptions() {
  const num = (el) => Number(el.value) || 0;
  const o = { mode: ui.mode.value };
  if (o.mode === 'acute' && autoChosen()) o.maxAngle = AUTO;
  else if (o.mode === 'acute' && num(ui.maxAngle) > 0) o.maxAngle = num(ui.maxAngle);
  if (o.mode !== 'cdt') {
    if (num(ui.minAngle) > 0) o.minAngle = num(ui.minAngle);
    if (num(ui.maxArea) > 0) o.maxArea = num(ui.maxArea);
    // Plain numbers: the worker takes no size function.
    if (num(ui.maxEdge) > 0) o.maxEdge = num(ui.maxEdge);
    if (num(ui.grading) > 0) o.grading = num(ui.grading);
    if (num(ui.maxSteiner) > 0) o.maxSteiner = Math.round(num(ui.maxSteiner));
    if (num(ui.optimize) > 0) o.optimize = num(ui.optimize);
  }
  return o;
}

function autoChosen() {
  return ui.maxAngleAuto.checked;
}

function syncOptionInputs() {
  const m = ui.mode.value;
  ui.maxAngle.disabled = m !== 'acute' || autoChosen();
  ui.maxAngleAuto.disabled = m !== 'acute';
  showFloor();
  for (const el of [ui.minAngle, ui.maxArea, ui.maxEdge, ui.grading, ui.maxSteiner, ui.optimize]) el.disabled = m === 'cdt';
  ui.maxEdgeSlider.disabled = m === 'cdt' || !extent;
  checkFields(FIELDS, ui.formError);
  // An empty input means the mesher's default, which the placeholder shows.
  if (!vocabulary) return;
  const d = vocabulary.defaults;
  const bothUnset = !(Number(ui.minAngle.value) > 0) && !(Number(ui.maxArea.value) > 0);
  ui.maxAngle.placeholder = String(d.maxAngle);
  ui.minAngle.placeholder = String(m === 'quality' && bothUnset ? d.qualityMinAngle : d.minAngle);
  ui.maxArea.placeholder = String(d.maxArea);
  // The mesher's 0 for these means none, which the empty field says in words.
  ui.maxEdge.placeholder = d.maxEdge > 0 ? String(d.maxEdge) : 'none';
  ui.grading.placeholder = d.grading > 0 ? String(d.grading) : 'none';
  ui.maxSteiner.placeholder = String(d.maxSteiner);
  ui.optimize.placeholder = 'none';
}

// ---- the max edge slider ------------------------------------------------------------------
// A new input sets the slider's scale (extent/1000 to extent/4 of its larger side); the field
// keeps its value and the slider moves to it.
function takeExtent(input) {
  let next = null;
  if (input) {
    let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
    const add = (x, y) => { x0 = Math.min(x0, x); x1 = Math.max(x1, x); y0 = Math.min(y0, y); y1 = Math.max(y1, y); };
    if (input.pslg) for (let i = 0; i + 1 < input.pslg.points.length; i += 2) add(input.pslg.points[i], input.pslg.points[i + 1]);
    else for (const ring of input.rings) for (const [x, y] of ring) add(x, y);
    const side = Math.max(x1 - x0, y1 - y0);
    if (side > 0 && Number.isFinite(side)) next = side;
  }
  extent = next;
  extentUnits = input?.units || 'units';
  const s = ui.maxEdgeSlider;
  if (extent) {
    const { lo, hi } = edgeRange(extent);
    s.dataset.min = roundEdge(lo);
    s.dataset.max = roundEdge(hi);
  } else {
    delete s.dataset.min;
    delete s.dataset.max;
  }
  s.disabled = ui.mode.value === 'cdt' || !extent;
  moveEdgeSlider();
}

// The field moved the value: the slider follows (a value it cannot show leaves it be).
function moveEdgeSlider() {
  if (extent) {
    const pos = edgePosition(ui.maxEdge.value, extent);
    if (pos != null) ui.maxEdgeSlider.value = String(pos);
  }
  sayEdge();
}

// The slider's spoken value is the field's: "12.5 km", "0.84 units" or "none".
function sayEdge() {
  const v = ui.maxEdge.value;
  const none = v === '' || Number(v) === 0 || !RANGES.maxEdge.ok(Number(v));
  ui.maxEdgeSlider.setAttribute('aria-valuetext', none ? 'none' : `${v} ${extentUnits}`);
}

// The slider moved: the field takes its (rounded) value, and says so as typing would.
function slideEdge() {
  if (!extent) return;
  ui.maxEdge.value = edgeAt(Number(ui.maxEdgeSlider.value), extent);
  sayEdge();
  checkFields(FIELDS, ui.formError);
}

// The floor beside the dial: no mesh of the current input has every angle below it. A bound
// asked for below it is said at once, before any run.
function showFloor() {
  const el = ui.angleFloor;
  el.dataset.floor = floorInfo ? String(floorInfo.floor) : '';
  el.dataset.from = floorInfo ? floorInfo.from : '';
  const asked = Number(ui.maxAngle.value);
  const below = floorInfo && ui.mode.value === 'acute' && !autoChosen() && asked > 0 && asked < floorInfo.floor;
  el.className = `hint floor${below ? ' warn' : ''}`;
  if (!floorInfo) {
    el.textContent = '';
    return;
  }
  const { corner, floor } = floorInfo;
  const cornerText = corner < 360 ? `smallest corner ${Number(corner.toFixed(2))}°` : 'no corner';
  el.textContent = `floor ${Number(floor.toFixed(2))}° (${cornerText})${below ? `: ${asked}° cannot be met` : ''}`;
}

// The mesher's vocabulary: its descriptions of the modes, its output formats as download
// buttons, its defaults as the placeholders of empty inputs.
function takeVocabulary(am) {
  if (vocabulary) return;
  vocabulary = am.vocabulary;
  for (const option of ui.mode.options) {
    const mode = vocabulary.modes.find((e) => e.name === option.value);
    if (mode) option.title = mode.description;
  }
  const png = ui.downloads.querySelector('[data-format=png]');
  for (const f of vocabulary.outputFormats) {
    if (f.needsInstance) continue;  // a CG:SHOP solution needs its instance
    const b = document.createElement('button');
    b.type = 'button';
    b.dataset.testid = `download-${f.name}`;
    b.dataset.format = f.name;
    b.textContent = f.extension;
    b.title = f.name === 'svg' ? 'SVG: the mesh as the view draws it, triangles coloured as in the legend (largest angle, or region)' : f.description;
    b.disabled = lastResult === null;
    b.addEventListener('click', () => download(f.name));
    ui.downloads.insertBefore(b, png);
  }
  syncOptionInputs();
}

// ---- running --------------------------------------------------------------------------------
async function run() {
  const problems = checkFields(FIELDS, ui.formError);
  if (problems.length) {
    setStatus(`Not meshed: ${problems.join(' ')}`, 'error');
    Object.values(FIELDS).find((el) => el.getAttribute('aria-invalid') === 'true')?.focus();
    return;
  }
  if (running) running.abort();
  inputSeq++;
  const controller = new AbortController();
  running = controller;
  ui.cancel.disabled = false;
  ui.progress.hidden = false;
  ui.progress.value = 0;
  ui.progress.removeAttribute('value');  // indeterminate until the first report
  setStatus('Meshing…');
  const t0 = performance.now();
  try {
    const [am, input] = await Promise.all([enginePromise, buildInput(current)]);
    if (running === controller) takeExtent(input);
    const pslg = input.pslg || am.fromRings(input.rings, { fill: input.fill });
    const options = meshOptions();
    const m = await meshInWorker(pslg, options, {
      signal: controller.signal,
      // Refinement ("refine", "improve") reports one estimated fraction of the whole run that
      // only grows; the other phases report their own ends (1.0 at the end of the Delaunay
      // triangulation, of the segments...), which are not the run's: they, and a fraction not
      // known (-1), leave the bar indeterminate, the vertex count showing work.
      onProgress: (p) => {
        if (running !== controller || !p) return;
        const refining = p.phase === 'refine' || p.phase === 'improve';
        if (refining && p.fraction >= 0) ui.progress.value = Math.min(1, p.fraction);
        else if (!refining) ui.progress.removeAttribute('value');
        setStatus(`Meshing… ${p.phase}${p.vertices ? `, ${p.vertices.toLocaleString('en')} vertices` : ''}`);
      },
    });
    if (running !== controller) return;  // a newer run took over
    show(am, pslg, input, options, m, performance.now() - t0);
  } catch (e) {
    if (running !== controller) return;
    if (controller.signal.aborted || e.name === 'AbortError') setStatus('Cancelled.', 'warn');
    else setStatus(e.message || String(e), 'error');
  } finally {
    if (running === controller) {
      running = null;
      ui.cancel.disabled = true;
      ui.progress.hidden = true;
    }
  }
}

function show(am, pslg, input, options, m, wallMs) {
  const nInput = pslg.points.length / 2;
  const s = m.stats || {};
  // Colours and bars follow the exact verdict: a certified acute mesh's corners at 89.9999
  // degrees may compute as 90 in floating point, and must not be painted as right or obtuse.
  const bound = s.certified ? (options.mode === 'acute' ? 'acute' : options.mode === 'nonobtuse' ? 'nonobtuse' : null) : null;
  const below = certifiedBound(s, options);
  const a = analyse(m.points, m.triangles, bound, below);
  // The floor: the mesher's when it measured one (the refinement modes), else measured here.
  const corner = s.smallestDomainAngle < 360 ? s.smallestDomainAngle : smallestDomainCorner(m.points, m.triangles, m.segments);
  floorInfo = { corner, floor: Number.isFinite(s.angleFloor) && s.smallestDomainAngle < 360 ? s.angleFloor : angleFloor(corner), from: 'run' };
  showFloor();
  // Regions (more than one attribute value): coloured by region unless the box is cleared.
  const regions = regionsOf(m.triangleAttributes);
  lastResult = { am, mesh: m, label: input.label, angles: a.angles, cls: a.cls, nInput, regions };
  ui.regionsToggle.hidden = !regions;
  paintMesh();
  showSource(describeInput(input));
  draw.hide();
  if (input.key !== lastMeshedKey) view.fit();
  lastMeshedKey = input.key;
  // The histogram marks the bound (angles above it are the misses), the floor and the largest
  // angle: the bound asked for, or what auto reached.
  const asked = options.mode === 'acute' ? options.maxAngle ?? vocabulary?.defaults.maxAngle ?? 90 : null;
  const marks = {
    bound: typeof asked === 'number' ? asked : below,
    floor: options.mode === 'acute' ? floorInfo.floor : null,
    max: finite(s.maxAngle),
  };
  lastResult.marks = marks;
  drawHistogram(ui.histogram, a.angles, marks);
  const result = {
    triangles: m.triangles.length / 3,
    vertices: s.vertices ?? m.points.length / 2,
    steiner: s.steiner ?? Math.max(0, m.points.length / 2 - nInput),
    minAngle: finite(s.minAngle),
    maxAngle: finite(s.maxAngle),
    certified: !!s.certified,
    milliseconds: round(Number.isFinite(s.seconds) ? s.seconds * 1000 : wallMs, 1),
    mode: options.mode,
    targetMet: s.targetMet ?? true,
    askedMaxAngle: asked,
    angleBound: below,
    angleFloor: floorInfo.floor,
    smallestDomainAngle: floorInfo.corner,
    inputVertices: nInput,
    wallMilliseconds: round(wallMs, 1),
    status: m.status ?? null,
    // The largest longest-edge / size over the triangles (<= 1: every size met); null when
    // no size was asked for (max edge, max area, a region's area bound).
    sizeRatio: s.sizeRatio > 0 ? s.sizeRatio : null,
    regions: regions ? regions.values.length : 0,
    regionAreas: (pslg.regions || []).some((g) => g.maxArea > 0),
    regionAttributes: regions ? regions.values : [],
    options,  // as the page asked for them
  };
  renderStats(result);
  ui.stats.dataset.result = JSON.stringify(result);
  ui.stats.dataset.runs = String(++runs);
  takeVocabulary(am);
  for (const b of ui.downloads.querySelectorAll('[data-format]')) b.disabled = false;
  const said = verdict(result, m, s.warnings || []);
  setStatus(said.text, said.kind);
  // The first mesh on screen: when the frame that draws it has run.
  if (runs === 1) {
    requestAnimationFrame(() => {
      document.body.dataset.firstMeshMs = performance.now().toFixed(0);
    });
  }
}

function finite(v) {
  return Number.isFinite(v) ? v : null;
}

// Angles are shown truncated, not rounded: 89.99996 must not read as 90.0000.
function truncate(v, digits) {
  const f = 10 ** digits;
  return (Math.trunc(v * f) / f).toFixed(digits);
}

function round(v, digits) {
  return Number.isFinite(v) ? Number(v.toFixed(digits)) : null;
}

function renderStats(r) {
  const rows = [
    ['Vertices', r.vertices.toLocaleString('en')],
    ['Triangles', r.triangles.toLocaleString('en')],
    ['Steiner', r.steiner.toLocaleString('en')],
    ['Input', r.inputVertices.toLocaleString('en')],
    ['Min angle', r.minAngle == null ? '–' : `${truncate(r.minAngle, 2)}°`],
    // Below a certified bound the float angle may round up to it: say "< bound" there.
    ['Max angle', r.maxAngle == null ? '–' : r.angleBound != null && r.maxAngle >= r.angleBound - 5e-5
      ? `< ${r.angleBound}°` : `${truncate(r.maxAngle, 4)}°`],
    // Certification is of acuteness / non-obtuseness: it does not apply to the other modes.
    ['Certified', r.mode === 'acute' || r.mode === 'nonobtuse' ? (r.certified ? 'yes' : 'no') : 'n/a'],
    ['Time', formatMs(r.milliseconds)],
  ];
  if (r.sizeRatio != null) rows.push(['Sizes', sizeWords(r.sizeRatio)]);
  if (r.regions) rows.push(['Regions', String(r.regions)]);
  if (r.mode === 'acute') {
    const target = r.askedMaxAngle === AUTO ? 'auto' : `${r.askedMaxAngle}°`;
    rows.push(['Bound', r.targetMet ? (r.angleBound != null ? `< ${r.angleBound}°` : target) : 'not met']);
  }
  rows.push(['Floor', `${Number(r.angleFloor.toFixed(2))}°`]);
  ui.stats.replaceChildren(...rows.flatMap(([k, v]) => {
    const dt = document.createElement('dt');
    const dd = document.createElement('dd');
    dt.textContent = k;
    dd.textContent = v;
    if (k === 'Certified' && v !== 'n/a') dd.className = r.certified ? 'yes' : 'no';
    if (k === 'Bound') dd.className = r.targetMet ? 'yes' : 'no';
    if (k === 'Sizes') dd.className = r.sizeRatio <= 1 ? 'yes' : 'no';
    return [dt, dd];
  }));
}

// What the view fills the triangles by: the regions (when the mesh has them and the box is
// ticked) or the largest angle's classes. Returns { by, cls, fills: [{ color, label }] }.
function meshFills(r) {
  if (r.regions && ui.showRegions.checked) {
    const { values, cls, colors } = r.regions;
    return { by: 'regions', cls, fills: colors.map((color, k) => ({ color, label: `attribute ${values[k]}` })) };
  }
  return { by: 'angles', cls: r.cls, fills: CLASSES.map((c) => ({ color: c.color, label: c.label })) };
}

// The shown mesh, in the fills chosen, with its legend.
function paintMesh() {
  const r = lastResult;
  const f = meshFills(r);
  view.setMesh(r.mesh, f.cls, r.nInput, f.fills.map((x) => x.color));
  ui.view.dataset.fill = f.by;
  buildLegend(f.by === 'regions' ? r.regions : null);
}

function buildLegend(regions = null) {
  const item = (color, label) => {
    const span = document.createElement('span');
    const i = document.createElement('i');
    i.style.background = color;
    span.append(i, label);
    return span;
  };
  let items;
  if (regions) {
    const n = regions.values.length, K = regions.colors.length;
    items = regions.values.map((v, k) => item(regions.colors[k % K], `attribute ${v}`));
    const line = document.createElement('span');
    line.className = 'regions-line';
    line.dataset.testid = 'regions-line';
    line.textContent = `${n} regions, by the input's regional attribute${n > K ? ` (the colours repeat after ${K})` : ''}`;
    items.unshift(line);
  } else {
    items = CLASSES.map((c) => item(c.color, c.label));
  }
  const seg = document.createElement('span');
  seg.className = 'mark-seg';
  seg.append(document.createElement('i'), 'input segment');
  const st = document.createElement('span');
  st.className = 'mark-steiner';
  st.append(document.createElement('i'), 'Steiner point');
  // The histogram's grey bars: angles below 60 degrees, never a triangle's largest, so they
  // have no triangle colour.
  const small = document.createElement('span');
  small.className = 'mark-small';
  const swatch = document.createElement('i');
  swatch.style.background = SMALL_ANGLE_COLOR;
  small.append(swatch, 'histogram: angles < 60° (never a largest)');
  ui.legend.replaceChildren(...items, seg, st, small);
  ui.legend.title = regions ? 'Triangles are coloured by their region' : 'Triangles are coloured by their largest angle';
  ui.legend.setAttribute('aria-label', regions ? 'Triangle colours by region' : 'Triangle colours by largest angle');
}

// ---- downloads ----------------------------------------------------------------------------

function saveBlob(blob, name) {
  const a = document.createElement('a');
  a.href = URL.createObjectURL(blob);
  a.download = name;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(a.href), 10000);
}

function download(format) {
  if (!lastResult) return;
  const { am, mesh, label } = lastResult;
  if (format === 'png') {
    ui.view.toBlob((blob) => saveBlob(blob, `${label}.png`), 'image/png');
    return;
  }
  const f = am.vocabulary.outputFormats.find((e) => e.name === format);
  // SVG: the picture as the view colours it, not the mesher's one-colour drawing.
  const fills = meshFills(lastResult);
  const text = format === 'svg' ? meshToSvg(mesh, fills.cls, lastResult.nInput, fills.fills) : am.write(mesh, format);
  saveBlob(new Blob([text], { type: f.mediaType }), `${label}${f.extension}`);
}

// ---- URL state ------------------------------------------------------------------------------
function saveUrl() {
  const p = new URLSearchParams();
  for (const [k, d] of Object.entries(OPTION_DEFAULTS)) {
    const v = k === 'maxAngle' && ui.maxAngleAuto.checked ? AUTO : ui[k].value;
    if (v !== d && v !== '' && !(RANGES[k] && v !== AUTO && problem(k, v))) p.set(k, v);
  }
  if (ui.tolerance.value !== TEXT_DEFAULTS.tol && !problem('tolerance', ui.tolerance.value)) p.set('tol', ui.tolerance.value);
  if (current.type === 'text') {
    if (ui.text.value !== TEXT_DEFAULTS.text) p.set('text', ui.text.value);
    if (ui.font.value !== TEXT_DEFAULTS.font && BUNDLED_FONTS[ui.font.value]) p.set('font', ui.font.value);
  } else if (current.type === 'sample') {
    p.set('sample', current.name);
  } else if (current.type === 'draw') {
    p.set('draw', encodeRings(current.rings));
  }
  const q = p.toString();
  history.replaceState(null, '', q ? `?${q}` : location.pathname);
}

// A value in the link that the page does not take falls back to the default, and says so.
function loadUrl() {
  const p = new URLSearchParams(location.search);
  const notes = [];
  const fallBack = (k, v, why, used) => notes.push(`The link's ${k}=${v} ${why}: ${used} is used instead.`);
  for (const [k, d] of Object.entries(OPTION_DEFAULTS)) {
    if (!p.has(k)) continue;
    const v = p.get(k);
    if (k === 'maxAngle' && v === AUTO) {
      // maxAngle=auto ticks the box.
      ui.maxAngleAuto.checked = true;
      ui.maxAngle.value = d;
    } else if (k === 'mode' && ![...ui.mode.options].some((o) => o.value === v)) {
      fallBack(k, v, 'is not a mode here', ui.mode.options[0].textContent);
    } else if (RANGES[k] && problem(k, v)) {
      fallBack(k, v, `is out of range (${RANGES[k].label.toLowerCase()}: ${RANGES[k].words})`, d === '' ? 'none' : `${d}${RANGES[k].unit}`);
    } else {
      ui[k].value = v;
    }
  }
  if (p.has('tol')) {
    const v = p.get('tol');
    if (problem('tolerance', v)) fallBack('tol', v, `is out of range (tolerance: ${RANGES.tolerance.words})`, `${TEXT_DEFAULTS.tol}‰`);
    else ui.tolerance.value = v;
  }
  ui.linkNote.textContent = notes.join(' ');
  ui.linkNote.hidden = !notes.length;
  if (p.has('text')) ui.text.value = p.get('text');
  if (p.has('font') && BUNDLED_FONTS[p.get('font')]) ui.font.value = p.get('font');
  if (p.has('sample') && [...ui.sample.options].some((o) => o.value === p.get('sample'))) {
    return { type: 'sample', name: p.get('sample') };
  }
  if (p.has('draw')) {
    const rings = decodeRings(p.get('draw'));
    if (rings.length) return { type: 'draw', rings };
  }
  return { type: 'text' };
}

// ---- drawing ------------------------------------------------------------------------------
function toggleDraw() {
  if (draw.active) {
    draw.stop();
    ui.draw.setAttribute('aria-pressed', 'false');
  } else {
    if (current.type !== 'draw') draw.setRings([]);
    inputChanged();
    view.clear();
    draw.start();
    ui.draw.setAttribute('aria-pressed', 'true');
    current = { type: 'draw', rings: draw.rings };
    showSource('drawing: click to place vertices, click the first one to close the ring ' +
               '(keyboard: arrows move the cross-hair, Space places a vertex, Enter closes the ring)');
  }
  ui.drawClose.disabled = ui.drawClear.disabled = !draw.active;
}

// ---- wiring -------------------------------------------------------------------------------
function wire() {
  ui.run.addEventListener('click', () => { ui.linkNote.hidden = true; if (draw.active) toggleDraw(); run(); });
  ui.cancel.addEventListener('click', () => { if (running) running.abort(); });
  const textChanged = () => { current = { type: 'text' }; ui.sample.value = ''; saveUrl(); preview(); };
  ui.text.addEventListener('input', textChanged);
  ui.text.addEventListener('keydown', (e) => { if (e.key === 'Enter') run(); });
  ui.font.addEventListener('change', textChanged);
  ui.tolerance.addEventListener('change', () => { saveUrl(); if (current.type !== 'draw') preview(); });
  // (A mesh still being drawn for the old input stops at once, before the new one is read.)
  ui.file.addEventListener('change', () => { view.stopBuilding(); if (ui.file.files[0]) takeFile(ui.file.files[0]); ui.file.value = ''; });
  ui.sample.addEventListener('change', async () => {
    view.stopBuilding();
    if (!ui.sample.value) return;
    try { await takeFile(await takeSample(ui.sample.value), 'sample'); } catch (e) { setStatus(e.message, 'error'); }
  });
  for (const el of [ui.mode, ui.maxAngle, ui.maxAngleAuto, ui.minAngle, ui.maxArea, ui.maxEdge, ui.grading, ui.maxSteiner, ui.optimize]) {
    el.addEventListener('change', () => { syncOptionInputs(); saveUrl(); });
  }
  // The slider writes the field as typing does; the field moves the slider.
  ui.maxEdgeSlider.addEventListener('input', slideEdge);
  ui.maxEdgeSlider.addEventListener('change', () => { slideEdge(); syncOptionInputs(); saveUrl(); });
  ui.maxEdge.addEventListener('input', moveEdgeSlider);
  // Out-of-range values are said while they are typed, not only when Mesh is pressed.
  for (const el of Object.values(FIELDS)) el.addEventListener('input', () => checkFields(FIELDS, ui.formError));
  ui.draw.addEventListener('click', toggleDraw);
  ui.drawClose.addEventListener('click', () => draw.closeRing());
  ui.drawClear.addEventListener('click', () => draw.clear());
  ui.fit.addEventListener('click', () => view.fit());
  ui.showEdges.addEventListener('change', () => { view.showEdges = ui.showEdges.checked; view.requestRender(); });
  ui.showSteiner.addEventListener('change', () => { view.showSteiner = ui.showSteiner.checked; view.requestRender(); });
  ui.showRegions.addEventListener('change', () => { if (lastResult) paintMesh(); });
  ui.downloads.querySelector('[data-format=png]').addEventListener('click', () => download('png'));
  // Drag and drop anywhere on the page.
  let depth = 0;
  window.addEventListener('dragenter', (e) => { e.preventDefault(); depth++; ui.dropHint.hidden = false; });
  window.addEventListener('dragleave', () => { if (--depth <= 0) { depth = 0; ui.dropHint.hidden = true; } });
  window.addEventListener('dragover', (e) => e.preventDefault());
  window.addEventListener('drop', (e) => {
    e.preventDefault();
    depth = 0;
    ui.dropHint.hidden = true;
    const f = e.dataTransfer && e.dataTransfer.files[0];
    if (f) takeFile(f);
  });
  window.addEventListener('resize', () => drawHistogram(ui.histogram, lastResult && lastResult.angles, lastResult && lastResult.marks));
}

async function start() {
  buildLegend();
  drawHistogram(ui.histogram, null);
  wire();
  const src = loadUrl();
  syncOptionInputs();
  if (src.type === 'sample') {
    ui.sample.value = src.name;
    current = { type: 'sample', name: src.name, file: await takeSample(src.name) };
  } else if (src.type === 'draw') {
    draw.setRings(src.rings);
    current = src;
  }
  // The page meshes its default (or the linked input) once on load, so the first thing a
  // visitor sees is the product working.
  await run();
}

start().catch((e) => setStatus(e.message, 'error'));
