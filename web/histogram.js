// The angle histogram (the seed's Figure 5): how many of the mesh's angles fall in each
// 2-degree bin. The axis runs to 90 degrees, or to 180 when some angle is obtuse, so an acute
// mesh's distribution fills the plot and a failure is visible at once.
import { CLASSES } from './angles.js';

const BIN = 2;

export function binAngles(angles) {
  const bins = new Uint32Array(180 / BIN);
  let max = 0;
  for (let i = 0; i < angles.length; i++) {
    const a = angles[i];
    // The last bin below 90 is closed: a right angle (non-obtuse meshes) counts with 88-90.
    bins[a === 90 ? 90 / BIN - 1 : Math.min(bins.length - 1, Math.floor(a / BIN))]++;
    if (a > max) max = a;
  }
  return { bins, max };
}

function colorFor(angle) {
  for (const c of CLASSES) if (!c.right && angle < c.hi) return c.color;
  return CLASSES[CLASSES.length - 1].color;
}

export function drawHistogram(canvas, angles) {
  const dpr = window.devicePixelRatio || 1;
  const w = canvas.clientWidth, h = canvas.clientHeight;
  canvas.width = Math.round(w * dpr);
  canvas.height = Math.round(h * dpr);
  const ctx = canvas.getContext('2d');
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  ctx.clearRect(0, 0, w, h);
  const padL = 6, padR = 6, padT = 8, padB = 18;
  const pw = w - padL - padR, ph = h - padT - padB;
  ctx.font = '10px system-ui, sans-serif';
  ctx.fillStyle = '#5d6675';
  if (!angles || !angles.length) {
    ctx.fillText('angles of the mesh appear here', padL, padT + ph / 2);
    canvas.dataset.bins = '';
    return;
  }
  const { bins, max } = binAngles(angles);
  const top = max > 90 ? 180 : 90;
  const n = top / BIN;
  let peak = 1;
  for (let i = 0; i < n; i++) peak = Math.max(peak, bins[i]);
  const bw = pw / n;
  for (let i = 0; i < n; i++) {
    if (!bins[i]) continue;
    const bh = Math.max(1, (bins[i] / peak) * ph);
    // Colour each bar as a triangle with that largest angle would be coloured.
    ctx.fillStyle = i * BIN >= 60 ? colorFor(i * BIN + BIN / 2) : '#8a94a6';
    ctx.fillRect(padL + i * bw + 0.5, padT + ph - bh, Math.max(1, bw - 1), bh);
  }
  ctx.strokeStyle = '#9aa3b2';
  ctx.lineWidth = 1;
  ctx.beginPath();
  ctx.moveTo(padL, padT + ph + 0.5);
  ctx.lineTo(padL + pw, padT + ph + 0.5);
  ctx.stroke();
  ctx.fillStyle = '#5d6675';
  ctx.textBaseline = 'top';
  for (let a = 0; a <= top; a += top === 90 ? 15 : 30) {
    const x = padL + (a / top) * pw;
    ctx.fillRect(x, padT + ph, 1, 3);
    ctx.textAlign = a === 0 ? 'left' : a === top ? 'right' : 'center';
    ctx.fillText(`${a}°`, x, padT + ph + 4);
  }
  // The 90-degree line: everything left of it is acute.
  const x90 = padL + (90 / top) * pw;
  ctx.fillStyle = 'rgba(215,48,31,.8)';
  ctx.fillRect(Math.round(x90) - 1, padT, 1.5, ph);
  canvas.dataset.bins = Array.from(bins.subarray(0, n)).join(',');
  canvas.dataset.binWidth = String(BIN);
}
