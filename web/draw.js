// Drawing an input by hand: each click on the canvas places a vertex of the open ring; a click
// on its first vertex (or Enter, or "Close ring") closes it. Rings drawn inside another become
// holes under the even-odd rule, so "add a hole" is just "draw a ring inside". Backspace removes
// the last vertex, Escape drops the open ring. Drag still pans and the wheel still zooms.
// From the keyboard: the arrow keys move a cross-hair (Shift: finer), Space places a vertex
// there, Enter closes the ring.
import { cleanRings } from './geometry.js';

const SNAP_PX = 9;
const KEY_STEP_PX = 20;  // cross-hair step of an arrow key; Shift: 2

export class DrawTool {
  constructor(view, onChange) {
    this.view = view;
    this.onChange = onChange;  // (rings) => void, after every closed ring / clear
    this.onVertex = null;      // (count) => void, after a vertex is placed or removed
    this.onDropped = null;     // (why) => void, when a closed ring is dropped
    this.active = false;
    this.rings = [];
    this.open = [];
    this.hover = null;
    this.cursor = null;        // the keyboard's cross-hair, in world coordinates
  }

  start() {
    this.active = true;
    const v = this.view;
    v.canvas.classList.add('drawing');
    v.onClick = (x, y) => this.#click(x, y);
    v.onHover = (x, y) => { this.hover = [x, y]; if (this.open.length) v.requestRender(); };
    v.overlay = (ctx) => this.#drawOverlay(ctx);
    if (!this.rings.length && !v.mesh && !v.preview) v.fit({ x0: 0, y0: 0, x1: 1000, y1: 1000 });
    v.onKey = (e) => this.#key(e);
    v.canvas.focus();
    v.requestRender();
  }

  stop() {
    this.active = false;
    const v = this.view;
    v.canvas.classList.remove('drawing');
    v.onClick = v.onHover = null;
    v.overlay = this.rings.length ? (ctx) => this.#drawOverlay(ctx) : null;
    v.onKey = null;
    this.open = [];
    this.cursor = null;
    v.requestRender();
  }

  // Hides the drawn rings once a mesh of them is shown.
  hide() {
    if (!this.active) this.view.overlay = null;
  }

  closeRing() {
    if (this.open.length >= 3) {
      const [ring] = cleanRings([this.open]);
      if (ring) this.rings.push(ring);
      // A ring without area (one that crosses itself so that its two halves cancel, like a
      // symmetric bow-tie, or one on a line) bounds nothing: it is dropped, and said so.
      else this.onDropped?.('it encloses no area (it crosses itself so that its halves cancel, or lies on a line); draw rings that do not cross themselves');
    }
    this.open = [];
    this.view.requestRender();
    this.onChange(this.rings);
  }

  clear() {
    this.rings = [];
    this.open = [];
    this.view.requestRender();
    this.onChange(this.rings);
  }

  setRings(rings) {
    this.rings = rings;
    this.open = [];
  }

  #click(x, y) {
    if (this.open.length >= 3) {
      const [fx, fy] = this.view.toScreen(...this.open[0]);
      const [cx, cy] = this.view.toScreen(x, y);
      if (Math.hypot(fx - cx, fy - cy) <= SNAP_PX) { this.closeRing(); return; }
    }
    this.open.push([x, y]);
    this.view.requestRender();
    this.onVertex?.(this.open.length);
  }

  // True when the key was the drawing's (the view then does not pan with it).
  #key(e) {
    const v = this.view;
    const moves = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, -1], ArrowDown: [0, 1] };
    if (moves[e.key]) {
      const step = e.shiftKey ? KEY_STEP_PX / 10 : KEY_STEP_PX;
      const [sx, sy] = this.cursor ? v.toScreen(...this.cursor) : [v.w / 2, v.h / 2];
      const [dx, dy] = moves[e.key];
      const nx = Math.min(v.w, Math.max(0, sx + dx * step)), ny = Math.min(v.h, Math.max(0, sy + dy * step));
      this.cursor = v.toWorld(nx, ny);
      this.hover = this.cursor;
      v.requestRender();
    } else if (e.key === ' ') {
      this.#click(...(this.cursor || v.toWorld(v.w / 2, v.h / 2)));
    } else if (e.key === 'Enter') this.closeRing();
    else if (e.key === 'Escape') { this.open = []; v.requestRender(); }
    else if (e.key === 'Backspace') { this.open.pop(); v.requestRender(); this.onVertex?.(this.open.length); }
    else return false;
    return true;
  }

  #drawOverlay(ctx) {
    const v = this.view;
    const path = new Path2D();
    for (const r of this.rings) {
      r.forEach(([x, y], i) => (i ? path.lineTo : path.moveTo).call(path, ...v.toScreen(x, y)));
      path.closePath();
    }
    ctx.fillStyle = 'rgba(31,111,178,.14)';
    ctx.fill(path, 'evenodd');
    ctx.strokeStyle = '#1f6fb2';
    ctx.lineWidth = 1.5;
    ctx.stroke(path);
    if (!this.active) return;
    if (this.cursor) {
      const [cx, cy] = v.toScreen(...this.cursor);
      ctx.strokeStyle = '#1d2430';
      ctx.lineWidth = 1.5;
      ctx.beginPath();
      ctx.moveTo(cx - 10, cy); ctx.lineTo(cx + 10, cy);
      ctx.moveTo(cx, cy - 10); ctx.lineTo(cx, cy + 10);
      ctx.stroke();
    }
    if (this.open.length) {
      const o = new Path2D();
      this.open.forEach(([x, y], i) => (i ? o.lineTo : o.moveTo).call(o, ...v.toScreen(x, y)));
      if (this.hover) o.lineTo(...v.toScreen(...this.hover));
      ctx.strokeStyle = '#d7301f';
      ctx.stroke(o);
      ctx.fillStyle = '#d7301f';
      for (const [x, y] of this.open) {
        const [sx, sy] = v.toScreen(x, y);
        ctx.fillRect(sx - 2.5, sy - 2.5, 5, 5);
      }
      const [fx, fy] = v.toScreen(...this.open[0]);
      ctx.beginPath();
      ctx.arc(fx, fy, SNAP_PX, 0, 2 * Math.PI);
      ctx.strokeStyle = 'rgba(215,48,31,.5)';
      ctx.stroke();
    }
  }
}

// Compact URL form: rings separated by '|', points by ';', coordinates by ','; three
// significant decimals are plenty for a hand drawing.
export function encodeRings(rings) {
  return rings.map((r) => r.map(([x, y]) => `${+x.toFixed(3)},${+y.toFixed(3)}`).join(';')).join('|');
}

export function decodeRings(text) {
  const rings = text.split('|').map((r) => r.split(';').map((p) => p.split(',').map(Number)));
  return cleanRings(rings.filter((r) => r.every((p) => p.length === 2)));
}
