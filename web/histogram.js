// The angle histogram (the seed's Figure 5): how many of the mesh's angles fall in each
// 2-degree bin. The axis runs to 90 degrees, or to 180 when some angle is obtuse, so an acute
// mesh's distribution fills the plot and a failure is visible at once. Acute mode marks where
// the largest angles sit against the dial: the bound (a red line; the angles at or above it are
// the part of each bar drawn in red), the input's floor (dashed) and the largest angle (a
// triangle over the plot).
import { CLASSES } from './angles.js';

const BIN = 2;
const MISS = '#d7301f';
const INK = '#5d6675';
// Bars below 60 degrees: no triangle's largest angle is there, so no triangle colour applies.
export const SMALL_ANGLE_COLOR = '#8a94a6';

// Counts per bin, and per bin the angles at or above `bound` (none when no bound is given).
export function binAngles(angles, bound = Infinity) {
  const bins = new Uint32Array(180 / BIN);
  const over = new Uint32Array(180 / BIN);
  let max = 0;
  for (let i = 0; i < angles.length; i++) {
    const a = angles[i];
    // The last bin below 90 is closed: a right angle (non-obtuse meshes) counts with 88-90.
    const k = a === 90 ? 90 / BIN - 1 : Math.min(bins.length - 1, Math.floor(a / BIN));
    bins[k]++;
    if (a >= bound) over[k]++;
    if (a > max) max = a;
  }
  return { bins, over, max };
}

function colorFor(angle) {
  for (const c of CLASSES) if (!c.right && angle < c.hi) return c.color;
  return CLASSES[CLASSES.length - 1].color;
}

// marks: { bound, floor, max } in degrees, each optional (null: not drawn).
export function drawHistogram(canvas, angles, marks = {}) {
  const dpr = window.devicePixelRatio || 1;
  const w = canvas.clientWidth, h = canvas.clientHeight;
  canvas.width = Math.round(w * dpr);
  canvas.height = Math.round(h * dpr);
  const ctx = canvas.getContext('2d');
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  ctx.clearRect(0, 0, w, h);
  const { bound = null, floor = null, max: maxMark = null } = marks || {};
  // Two rows above the bars for the bound's and the floor's labels.
  const padL = 6, padR = 6, padT = bound != null || floor != null ? 30 : 8, padB = 18;
  const pw = w - padL - padR, ph = h - padT - padB;
  ctx.font = '10px system-ui, sans-serif';
  ctx.fillStyle = INK;
  for (const k of ['bins', 'over', 'bound', 'floor', 'max']) canvas.dataset[k] = '';
  if (!angles || !angles.length) {
    ctx.fillText('angles of the mesh appear here', padL, padT + ph / 2);
    return;
  }
  const { bins, over, max } = binAngles(angles, bound ?? Infinity);
  const top = max > 90 ? 180 : 90;
  const n = top / BIN;
  const xOf = (a) => padL + (a / top) * pw;
  let peak = 1;
  for (let i = 0; i < n; i++) peak = Math.max(peak, bins[i]);
  // Beyond the bound, up to 90: the angles there miss the target.
  if (bound != null && bound < 90) {
    ctx.fillStyle = 'rgba(215,48,31,.07)';
    ctx.fillRect(xOf(bound), padT, xOf(90) - xOf(bound), ph);
  }
  const bw = pw / n;
  for (let i = 0; i < n; i++) {
    if (!bins[i]) continue;
    const bh = Math.max(1, (bins[i] / peak) * ph);
    const oh = over[i] ? Math.max(1, (over[i] / bins[i]) * bh) : 0;
    const x = padL + i * bw + 0.5, bwide = Math.max(1, bw - 1);
    // Colour each bar as a triangle with that largest angle would be coloured; its part at or
    // above the bound on top, in the bound's red.
    ctx.fillStyle = i * BIN >= 60 ? colorFor(i * BIN + BIN / 2) : SMALL_ANGLE_COLOR;
    ctx.fillRect(x, padT + ph - bh, bwide, bh - oh);
    if (oh) {
      ctx.fillStyle = MISS;
      ctx.fillRect(x, padT + ph - bh, bwide, oh);
    }
  }
  ctx.strokeStyle = '#9aa3b2';
  ctx.lineWidth = 1;
  ctx.beginPath();
  ctx.moveTo(padL, padT + ph + 0.5);
  ctx.lineTo(padL + pw, padT + ph + 0.5);
  ctx.stroke();
  ctx.fillStyle = INK;
  ctx.textBaseline = 'top';
  for (let a = 0; a <= top; a += top === 90 ? 15 : 30) {
    const x = xOf(a);
    ctx.fillRect(x, padT + ph, 1, 3);
    ctx.textAlign = a === 0 ? 'left' : a === top ? 'right' : 'center';
    ctx.fillText(`${a}°`, x, padT + ph + 4);
  }
  // The 90-degree line: everything left of it is acute.
  ctx.fillStyle = 'rgba(215,48,31,.8)';
  ctx.fillRect(Math.round(xOf(90)) - 1, padT, 1.5, ph);
  if (floor != null) {
    const x = Math.round(xOf(floor)) + 0.5;
    ctx.strokeStyle = INK;
    ctx.setLineDash([3, 3]);
    ctx.beginPath();
    ctx.moveTo(x, 13);
    ctx.lineTo(x, padT + ph);
    ctx.stroke();
    ctx.setLineDash([]);
    label(ctx, `floor ${fmt(floor)}°`, x, 14, w, INK);
  }
  if (bound != null) {
    const x = Math.round(xOf(bound)) - 0.5;
    ctx.fillStyle = MISS;
    ctx.fillRect(x - 0.5, 1, 2, padT + ph - 1);
    label(ctx, `bound ${fmt(bound)}°`, x, 1, w, MISS);
  }
  if (maxMark != null && bound != null) {
    // A small triangle pointing down at the largest angle, just above the bars.
    const x = xOf(Math.min(top, maxMark));
    ctx.fillStyle = '#1d2430';
    ctx.beginPath();
    ctx.moveTo(x - 4, padT - 6);
    ctx.lineTo(x + 4, padT - 6);
    ctx.lineTo(x, padT);
    ctx.fill();
  }
  canvas.dataset.bins = Array.from(bins.subarray(0, n)).join(',');
  canvas.dataset.over = String(over.reduce((s, v) => s + v, 0));
  canvas.dataset.binWidth = String(BIN);
  canvas.dataset.bound = bound == null ? '' : String(bound);
  canvas.dataset.floor = floor == null ? '' : String(floor);
  canvas.dataset.max = maxMark == null ? '' : String(maxMark);
}

const fmt = (v) => String(Number(v.toFixed(2)));

// A label beside the line at x: to its left, unless it would leave the canvas there.
function label(ctx, text, x, y, w, color) {
  const width = ctx.measureText(text).width;
  ctx.textBaseline = 'top';
  ctx.textAlign = x - 4 - width >= 0 ? 'right' : 'left';
  const tx = ctx.textAlign === 'right' ? x - 4 : Math.min(x + 4, w - width);
  ctx.fillStyle = 'rgba(255,255,255,.85)';
  ctx.fillRect(ctx.textAlign === 'right' ? tx - width - 1 : tx - 1, y - 1, width + 2, 12);
  ctx.fillStyle = color;
  ctx.fillText(text, tx, y);
}
