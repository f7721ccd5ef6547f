// The option fields' ranges, checked on the page in its own words before anything is sent, and
// the same checks for values that come in a link. An empty field means the mesher's default.

export const RANGES = {
  maxAngle: { label: 'Max angle', unit: '°', ok: (v) => v > 60 && v <= 90,
    words: 'above 60° and at most 90°', why: 'a triangle always has an angle of 60° or more' },
  minAngle: { label: 'Min angle', unit: '°', ok: (v) => v >= 0 && v < 60,
    words: 'from 0° to below 60°', why: '0: none; above 40° it is seldom reached' },
  maxArea: { label: 'Max area', unit: '', ok: (v) => v >= 0, words: '0 (no bound) or more' },
  maxEdge: { label: 'Max edge', unit: '', ok: (v) => v >= 0, words: '0 (none) or more' },
  grading: { label: 'Grading', unit: '', ok: (v) => v >= 0, words: '0 (none) or more', why: '0.2 to 0.5 is usual' },
  maxSteiner: { label: 'Steiner budget', unit: '', ok: (v) => v >= 0 && Number.isInteger(v),
    words: 'a whole number, 0 (automatic) or more' },
  optimize: { label: 'Spend more time', unit: ' s', ok: (v) => v >= 0 && v <= 600,
    words: 'from 0 (none) to 600 seconds', why: 'looking for a mesh with fewer points after refinement' },
  tolerance: { label: 'Tolerance', unit: '‰', ok: (v) => v >= 0.1 && v <= 100, words: 'from 0.1 to 100' },
};

// The message for one value (a string as typed or linked), or '' when it is fine.
export function problem(key, text, badInput = false) {
  const r = RANGES[key];
  const why = r.why ? ` (${r.why})` : '';
  if (badInput) return `${r.label}: not a number; it must be ${r.words}${why}.`;
  if (text === '' || text == null) return '';
  const v = Number(text);
  if (!Number.isFinite(v) || !r.ok(v)) return `${r.label} ${text}${Number.isFinite(v) ? r.unit : ''} is out of range: it must be ${r.words}${why}.`;
  return '';
}

// Marks each field of `inputs` ({ key: <input> }) valid or not and writes the messages into
// `out`; returns the messages ([] when all are fine). Disabled fields are not sent, so not
// checked.
export function checkFields(inputs, out) {
  const messages = [];
  for (const [key, el] of Object.entries(inputs)) {
    const message = el.disabled ? '' : problem(key, el.value, el.validity && el.validity.badInput);
    el.setAttribute('aria-invalid', message ? 'true' : 'false');
    if (message) {
      el.setAttribute('aria-describedby', out.id);
      messages.push(message);
    } else {
      el.removeAttribute('aria-describedby');
    }
  }
  out.textContent = messages.join(' ');
  out.hidden = !messages.length;
  return messages;
}

// The max edge slider: positions 0..EDGE_STEPS on a logarithmic scale from extent/1000 to
// extent/4 (the input's larger side), then one more, EDGE_STEPS + 1, meaning none.
export const EDGE_STEPS = 100;
export const EDGE_NONE = EDGE_STEPS + 1;
export const edgeRange = (extent) => ({ lo: extent / 1000, hi: extent / 4 });

// 3 significant digits, written without an exponent where a person would (1230, 0.0123).
export function roundEdge(v) {
  return String(Number(v.toPrecision(3)));
}

// The field's value ('' for none) at slider position `pos`.
export function edgeAt(pos, extent) {
  if (pos >= EDGE_NONE) return '';
  const { lo, hi } = edgeRange(extent);
  return roundEdge(lo * (hi / lo) ** (pos / EDGE_STEPS));
}

// The slider position of the field's value: none for empty or 0, clamped to the scale's ends;
// null for a value that is not a max edge (left where it is).
export function edgePosition(text, extent) {
  if (text === '' || text == null) return EDGE_NONE;
  const v = Number(text);
  if (!Number.isFinite(v) || v < 0) return null;
  if (v === 0) return EDGE_NONE;
  const { lo, hi } = edgeRange(extent);
  const pos = Math.round(EDGE_STEPS * Math.log(v / lo) / Math.log(hi / lo));
  return Math.min(EDGE_STEPS, Math.max(0, pos));
}
