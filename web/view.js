// The canvas view: a mesh (triangles coloured by their largest angle or by their region, edges,
// input segments, Steiner points) or an input preview, with pan and zoom by wheel, drag, pinch
// and keys.
//
// Geometry is turned into Path2D objects once per mesh, in world coordinates, grouped in tiles
// of a few thousand triangles (per tile one path per colour class and one of its edges); a
// frame is then a few fill/stroke calls per visible tile under one transform. When a full frame is slow
// (hundreds of thousands of triangles on a software rasteriser), frames during a gesture
// redraw the last full frame as a bitmap, scaled and shifted, and the full frame follows when
// the gesture pauses: panning stays smooth and the picture is sharp again at rest. A large mesh
// (over LARGE_MESH triangles) is turned into paths and drawn a slice of SLICE_MS at a time,
// between frames, into a second canvas that is shown once the frame is whole, so that the page
// keeps answering while it arrives and the picture before it stays meanwhile.
import { CLASSES } from './angles.js';

const SEGMENT_COLOR = '#111';
const STEINER_COLOR = '#c2185b';
const BG = '#ffffff';
const STEINER_SHARE = 0.15; // a Steiner dot's radius: this share of its shortest edge...
const STEINER_MAX_PX = 3;   // ...up to this many CSS pixels
const DOT_MIN_PX = 0.6;     // smaller dots are not drawn
const SLOW_FRAME_MS = 24;   // above this, gestures use the bitmap path
const SETTLE_MS = 140;      // pause after which a gesture counts as over
const LARGE_MESH = 50000;   // triangles from which paths are built and drawn in slices
const SLICE_MS = 40;        // the main thread's time per slice

export class MeshView {
  constructor(canvas) {
    this.canvas = canvas;
    this.ctx = canvas.getContext('2d');
    this.dpr = 1;
    this.w = 1; this.h = 1;
    this.s = 1; this.tx = 0; this.ty = 0;
    this.mesh = null;       // { points, triangles, nInput, tiles, segments, meanEdge }
    this.preview = null;    // { path, fill, segments, points }
    this.showEdges = true;
    this.showSteiner = true;
    this.overlay = null;    // (ctx, view) => void, drawn last in CSS pixels (drawing tool)
    this.onClick = null;    // (x, y, event) => void in world coordinates
    this.onKey = null;      // (keydown event) => true when it took the key (drawing tool)
    this.lastFullMs = 0;
    this.frameCount = 0;
    this.probe = Object.assign(document.createElement('canvas'), { width: 1, height: 1 })
      .getContext('2d', { willReadFrequently: true });
    this.cache = document.createElement('canvas');
    this.back = document.createElement('canvas');  // a frame being drawn in slices
    this.cacheXform = null;
    this.interacting = false;
    this.settleTimer = 0;
    this.pending = 0;
    this.meshSeq = 0;       // bumped by every new content: a slow build of an older one stops
    this.drawJob = null;    // a frame being drawn in slices: { ops, next, busyMs }
    this.bounds = null;
    this.pointers = new Map();
    this.gesture = null;
    this.#listen();
    this.#resize();
  }

  // ---- content ------------------------------------------------------------------------
  // A large mesh's paths are built a slice at a time; the picture before it stays until they
  // are ready (dataset.content is 'building' meanwhile, then 'mesh'; dataset.frame is
  // 'drawing' while a frame is drawn in slices, 'done' once it is whole).
  // cls: per triangle an index into colors (the largest-angle classes by default, or the
  // regions' palette).
  setMesh(m, cls, nInput, colors = CLASSES.map((c) => c.color)) {
    const { points: p, triangles: t } = m;
    const seq = ++this.meshSeq;
    this.preview = null;
    this.bounds = mainBounds(meshParts(p, t));
    this.canvas.dataset.extent = Object.values(boundsOf(p, t)).join(',');
    const build = meshPaths(p, t, cls, m.segments);
    const install = ({ tiles, meanEdge, segments, shortest }) => {
      this.mesh = { points: p, triangles: t, nInput, tiles, meanEdge, segments, shortest, colors };
      this.canvas.dataset.colors = colors.join(',');
      this.cacheXform = null;
      this.canvas.dataset.frame = 'drawing';  // (until its first frame is whole)
      this.canvas.dataset.content = 'mesh';
      this.requestRender();
    };
    if (t.length / 3 <= LARGE_MESH) return install(finish(build));
    this.canvas.dataset.content = 'building';
    const slice = () => {
      if (seq !== this.meshSeq) return;  // newer content took over
      const t0 = performance.now();
      let r;
      do r = build.next(); while (!r.done && performance.now() - t0 < SLICE_MS);
      if (r.done) install(r.value);
      else setTimeout(slice, 0);
    };
    slice();
  }

  // A new input is coming: a mesh still being built for the old one is dropped (the picture
  // on screen stays until the new one replaces it).
  stopBuilding() {
    if (this.canvas.dataset.content !== 'building') return;
    this.meshSeq++;
    this.canvas.dataset.content = this.mesh ? 'mesh' : this.preview ? 'preview' : '';
  }

  // rings + fill rule (a shape), or a PSLG (points and segments, no known inside).
  setPreview({ rings, fill, pslg }) {
    let path = null, segments = null, points = null;
    if (rings) {
      path = new Path2D();
      for (const r of rings) {
        path.moveTo(r[0][0], r[0][1]);
        for (let i = 1; i < r.length; i++) path.lineTo(r[i][0], r[i][1]);
        path.closePath();
      }
      points = Float64Array.from(rings.flat(2));
    } else {
      points = pslg.points;
      segments = segmentPath(points, pslg.segments);
    }
    this.preview = { path, fill: fill === 'nonzero' ? 'nonzero' : 'evenodd', segments, points };
    this.mesh = null;
    this.meshSeq++;
    this.bounds = rings ? mainBounds(rings.map(ringPart)) : boundsOf(points);
    this.canvas.dataset.content = 'preview';
    this.requestRender();
  }

  clear() {
    this.mesh = null;
    this.meshSeq++;
    this.preview = null;
    this.canvas.dataset.content = '';
    this.requestRender();
  }

  // ---- coordinates --------------------------------------------------------------------
  toScreen(x, y) { return [x * this.s + this.tx, -y * this.s + this.ty]; }
  toWorld(sx, sy) { return [(sx - this.tx) / this.s, (this.ty - sy) / this.s]; }

  fit(bounds = this.bounds) {
    if (!bounds || !(bounds.x1 >= bounds.x0)) return;
    const pad = 24;
    const bw = Math.max(bounds.x1 - bounds.x0, 1e-300), bh = Math.max(bounds.y1 - bounds.y0, 1e-300);
    this.s = Math.min((this.w - 2 * pad) / bw, (this.h - 2 * pad) / bh);
    if (!Number.isFinite(this.s) || this.s <= 0) this.s = 1;
    this.tx = this.w / 2 - ((bounds.x0 + bounds.x1) / 2) * this.s;
    this.ty = this.h / 2 + ((bounds.y0 + bounds.y1) / 2) * this.s;
    this.canvas.dataset.fit = [bounds.x0, bounds.y0, bounds.x1, bounds.y1].join(',');
    this.requestRender();
  }

  zoomAt(sx, sy, factor) {
    const [x, y] = this.toWorld(sx, sy);
    this.s *= factor;
    this.tx = sx - x * this.s;
    this.ty = sy + y * this.s;
    this.#gestureFrame();
  }

  panBy(dx, dy) {
    this.tx += dx;
    this.ty += dy;
    this.#gestureFrame();
  }

  // ---- drawing ------------------------------------------------------------------------
  requestRender() {
    if (!this.pending) this.pending = requestAnimationFrame(() => { this.pending = 0; this.render(); });
  }

  render() {
    const fast = this.interacting && this.lastFullMs > SLOW_FRAME_MS && this.cacheXform;
    this.drawJob = null;  // a frame still being drawn in slices starts over
    if (fast) this.#renderCached();
    else if (this.mesh && this.mesh.triangles.length / 3 > LARGE_MESH) return this.#drawInSlices();
    else {
      const t0 = performance.now();
      for (const op of this.#frameOps(this.ctx)) op();
      this.#raster(this.canvas);
      this.#frameDrawn(performance.now() - t0);
      return;
    }
    this.#drawOverlay();
    this.frameCount++;
  }

  // Canvas drawing is recorded and rasterised later, off any measurement; copying one pixel
  // forces the raster now, so a time taken after it is what the drawing really cost. The copy
  // goes to a 1-pixel canvas made for reading: reading the view itself every frame would make
  // the browser warn (and move the view to a slower, readable canvas).
  #raster(canvas) {
    this.probe.drawImage(canvas, 0, 0, 1, 1, 0, 0, 1, 1);
    this.probe.getImageData(0, 0, 1, 1);
  }

  #frameDrawn(ms) {
    this.canvas.dataset.frame = 'done';
    this.lastFullMs = ms;
    this.canvas.dataset.renderMs = ms.toFixed(1);
    if (ms > SLOW_FRAME_MS) this.#storeCache();
    this.#drawOverlay();
    this.frameCount++;
  }

  #drawOverlay() {
    if (!this.overlay) return;
    this.ctx.setTransform(this.dpr, 0, 0, this.dpr, 0, 0);
    this.overlay(this.ctx, this);
  }

  // A large mesh's frame: its drawing steps run on the back canvas until SLICE_MS is spent, the
  // rest in the next animation frames (fills, then edges, then segments and dots, as in one
  // go); the whole frame is then copied to the view. A new frame asked for meanwhile starts over.
  #drawInSlices() {
    const back = this.back;
    const ctx = this.#sizedLikeView(back);
    const job = { ops: this.#frameOps(ctx), next: 0, busyMs: 0 };
    this.drawJob = job;
    this.canvas.dataset.frame = 'drawing';
    const slice = () => {
      if (this.drawJob !== job) return;
      const t0 = performance.now();
      this.#worldTransform(ctx);
      while (job.next < job.ops.length && performance.now() - t0 < SLICE_MS) {
        job.ops[job.next++]();
        this.#raster(back);
      }
      if (job.next === job.ops.length) {
        this.ctx.setTransform(1, 0, 0, 1, 0, 0);
        this.ctx.drawImage(back, 0, 0);
        this.#raster(this.canvas);
      }
      job.busyMs += performance.now() - t0;
      if (job.next < job.ops.length) return void requestAnimationFrame(slice);
      this.drawJob = null;
      this.#frameDrawn(job.busyMs);
    };
    slice();
  }

  // World -> device pixels, y up.
  #worldTransform(ctx) {
    const { dpr, s } = this;
    ctx.setTransform(dpr * s, 0, 0, -dpr * s, dpr * this.tx, dpr * this.ty);
    ctx.lineJoin = 'round';
  }

  // The steps that draw a full frame on ctx (the view's or the back canvas'), in order.
  #frameOps(ctx) {
    const { s } = this;
    const ops = [() => {
      ctx.setTransform(1, 0, 0, 1, 0, 0);
      ctx.fillStyle = BG;
      ctx.fillRect(0, 0, this.canvas.width, this.canvas.height);
      this.#worldTransform(ctx);
    }];
    const px = 1 / s;  // one CSS pixel in world units
    if (this.mesh) {
      const m = this.mesh;
      // Only tiles that meet the window: zoomed in, most of a big mesh costs nothing.
      const [wx0, wy1] = this.toWorld(0, 0), [wx1, wy0] = this.toWorld(this.w, this.h);
      const visible = m.tiles.filter((b) => b.x1 >= wx0 && b.x0 <= wx1 && b.y1 >= wy0 && b.y0 <= wy1);
      m.colors.forEach((color, k) => {
        for (const tile of visible) {
          if (tile.paths[k]) ops.push(() => { ctx.fillStyle = color; ctx.fill(tile.paths[k]); });
        }
      });
      const edgePx = m.meanEdge * s;
      if (this.showEdges && edgePx > 1.5) {
        // Fade edges in as triangles grow on screen, so a dense mesh stays readable. The
        // colour is opaque (a blend toward the ink): translucent strokes of a huge path make
        // the rasteriser composite the whole path as a layer, many times slower.
        const alpha = Math.min(0.55, 0.12 + (edgePx - 1.5) * 0.05);
        for (const tile of visible) {
          ops.push(() => { ctx.strokeStyle = mix(alpha); ctx.lineWidth = 0.7 * px; ctx.stroke(tile.edges); });
        }
      }
      ops.push(() => {
        ctx.strokeStyle = SEGMENT_COLOR;
        ctx.lineWidth = 1.6 * px;
        ctx.stroke(m.segments);
      });
      if (this.showSteiner) ops.push(() => this.#drawSteiner(ctx));
    } else if (this.preview) ops.push(() => this.#drawPreview(ctx, px));
    return ops;
  }

  #drawPreview(ctx, px) {
    const p = this.preview;
    if (p.path) {
      ctx.fillStyle = 'rgba(31,111,178,.12)';
      ctx.fill(p.path, p.fill);
      ctx.strokeStyle = SEGMENT_COLOR;
      ctx.lineWidth = 1.4 * px;
      ctx.stroke(p.path);
    }
    if (p.segments) {
      ctx.strokeStyle = SEGMENT_COLOR;
      ctx.lineWidth = 1.4 * px;
      ctx.stroke(p.segments);
    }
    this.#drawDots(ctx, p.points, 0, SEGMENT_COLOR, 1.6);
  }

  // Steiner points are the vertices past the input's: the mesher keeps input vertex i at i.
  // Each dot is sized by its shortest edge on screen, so it never covers its triangles (dense
  // parts show none until zoomed in) and grows with the zoom up to STEINER_MAX_PX.
  #drawSteiner(ctx) {
    const { points, nInput, shortest } = this.mesh;
    const s = this.s;
    const drawn = this.#drawDots(ctx, points, nInput, STEINER_COLOR,
      (v) => (Number.isFinite(shortest[v]) ? Math.min(STEINER_MAX_PX, STEINER_SHARE * shortest[v] * s) : 0));
    this.canvas.dataset.steiner = drawn.join(',');
  }

  // Dots of radius r(vertex) in CSS pixels (none below DOT_MIN_PX); returns [count, smallest
  // radius, largest radius] of those drawn.
  #drawDots(ctx, points, first, color, r) {
    const { dpr, s, tx, ty, w, h } = this;
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    const path = new Path2D();
    let n = 0, rMin = Infinity, rMax = 0;
    for (let i = 2 * first; i + 1 < points.length; i += 2) {
      const x = points[i] * s + tx, y = -points[i + 1] * s + ty;
      const radius = typeof r === 'number' ? r : r(i / 2);
      if (!(radius >= DOT_MIN_PX) || x < -radius || y < -radius || x > w + radius || y > h + radius) continue;
      path.moveTo(x + radius, y);
      path.arc(x, y, radius, 0, 2 * Math.PI);
      rMin = Math.min(rMin, radius);
      rMax = Math.max(rMax, radius);
      if (++n > 200000) break;
    }
    ctx.fillStyle = color;
    ctx.fill(path);
    return n ? [n, +rMin.toFixed(3), +rMax.toFixed(3)] : [0, 0, 0];
  }

  // The context of canvas c (the cache, the back canvas) once c has the view's size in device
  // pixels.
  #sizedLikeView(c) {
    if (c.width !== this.canvas.width || c.height !== this.canvas.height) {
      c.width = this.canvas.width;
      c.height = this.canvas.height;
    }
    return c.getContext('2d');
  }

  #storeCache() {
    const cctx = this.#sizedLikeView(this.cache);
    cctx.setTransform(1, 0, 0, 1, 0, 0);
    cctx.drawImage(this.canvas, 0, 0);
    this.cacheXform = { s: this.s, tx: this.tx, ty: this.ty };
  }

  #renderCached() {
    const { ctx, dpr } = this;
    const c = this.cacheXform, k = this.s / c.s;
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.fillStyle = BG;
    ctx.fillRect(0, 0, this.canvas.width, this.canvas.height);
    // screen' = k * (screen - t_cache) + t_now, in device pixels.
    ctx.setTransform(k, 0, 0, k, dpr * (this.tx - k * c.tx), dpr * (this.ty - k * c.ty));
    ctx.drawImage(this.cache, 0, 0);
  }

  #gestureFrame() {
    this.interacting = true;
    clearTimeout(this.settleTimer);
    this.settleTimer = setTimeout(() => { this.interacting = false; this.requestRender(); }, SETTLE_MS);
    this.requestRender();
  }

  // ---- size and input events ----------------------------------------------------------
  #resize() {
    const dpr = window.devicePixelRatio || 1;
    const w = this.canvas.clientWidth || 1, h = this.canvas.clientHeight || 1;
    // Keep the world point at the centre where it was.
    const [cx, cy] = this.toWorld(this.w / 2, this.h / 2);
    this.dpr = dpr; this.w = w; this.h = h;
    this.canvas.width = Math.round(w * dpr);
    this.canvas.height = Math.round(h * dpr);
    this.tx = w / 2 - cx * this.s;
    this.ty = h / 2 + cy * this.s;
    this.cacheXform = null;
    this.requestRender();
  }

  #listen() {
    const cv = this.canvas;
    new ResizeObserver(() => this.#resize()).observe(cv);
    // A devicePixelRatio change (browser zoom, moving to another screen) does not resize the
    // element in CSS pixels, so it needs its own listener.
    const watchDpr = () => {
      matchMedia(`(resolution: ${window.devicePixelRatio}dppx)`)
        .addEventListener('change', () => { this.#resize(); watchDpr(); }, { once: true });
    };
    watchDpr();

    cv.addEventListener('wheel', (e) => {
      e.preventDefault();
      const unit = e.deltaMode === 1 ? 16 : e.deltaMode === 2 ? this.h : 1;
      const r = cv.getBoundingClientRect();
      this.zoomAt(e.clientX - r.left, e.clientY - r.top, Math.exp(-e.deltaY * unit * 0.0015));
    }, { passive: false });

    cv.addEventListener('pointerdown', (e) => {
      cv.setPointerCapture(e.pointerId);
      const r = cv.getBoundingClientRect();
      this.pointers.set(e.pointerId, { x: e.clientX - r.left, y: e.clientY - r.top });
      this.#startGesture(e);
    });
    cv.addEventListener('pointermove', (e) => {
      if (!this.pointers.has(e.pointerId)) {
        if (this.onHover) {
          const r = cv.getBoundingClientRect();
          this.onHover(...this.toWorld(e.clientX - r.left, e.clientY - r.top));
        }
        return;
      }
      const r = cv.getBoundingClientRect();
      this.pointers.set(e.pointerId, { x: e.clientX - r.left, y: e.clientY - r.top });
      this.#moveGesture();
      if (this.onHover) this.onHover(...this.toWorld(e.clientX - r.left, e.clientY - r.top));
    });
    const end = (e) => {
      if (!this.pointers.has(e.pointerId)) return;
      const g = this.gesture;
      const p = this.pointers.get(e.pointerId);
      this.pointers.delete(e.pointerId);
      cv.classList.remove('dragging');
      if (g && g.kind === 'pan' && !g.moved && e.type === 'pointerup' && this.onClick) {
        this.onClick(...this.toWorld(p.x, p.y), e);
      }
      this.#startGesture(e);
    };
    cv.addEventListener('pointerup', end);
    cv.addEventListener('pointercancel', end);
    cv.addEventListener('dblclick', (e) => { if (!this.onClick) this.fit(); e.preventDefault(); });
    cv.addEventListener('keydown', (e) => {
      if (this.onKey && this.onKey(e)) { e.preventDefault(); return; }  // the drawing tool's keys
      const step = 40;
      const keys = {
        ArrowLeft: () => this.panBy(step, 0), ArrowRight: () => this.panBy(-step, 0),
        ArrowUp: () => this.panBy(0, step), ArrowDown: () => this.panBy(0, -step),
        '+': () => this.zoomAt(this.w / 2, this.h / 2, 1.25), '=': () => this.zoomAt(this.w / 2, this.h / 2, 1.25),
        '-': () => this.zoomAt(this.w / 2, this.h / 2, 0.8), '0': () => this.fit(),
      };
      if (keys[e.key]) { keys[e.key](); e.preventDefault(); }
    });
  }

  // One pointer pans, two pinch (zoom about their midpoint, which also pans).
  #startGesture() {
    const pts = [...this.pointers.values()];
    if (pts.length === 1) {
      this.gesture = { kind: 'pan', x: pts[0].x, y: pts[0].y, x0: pts[0].x, y0: pts[0].y, moved: false };
    } else if (pts.length >= 2) {
      const [a, b] = pts;
      this.gesture = { kind: 'pinch', d: Math.hypot(a.x - b.x, a.y - b.y) || 1,
        world: this.toWorld((a.x + b.x) / 2, (a.y + b.y) / 2), s: this.s };
    } else {
      this.gesture = null;
    }
  }

  #moveGesture() {
    const g = this.gesture;
    const pts = [...this.pointers.values()];
    if (!g) return;
    if (g.kind === 'pan' && pts.length === 1) {
      const p = pts[0];
      if (!g.moved && Math.hypot(p.x - g.x0, p.y - g.y0) < 4) return;  // still a click
      g.moved = true;
      this.canvas.classList.add('dragging');
      this.panBy(p.x - g.x, p.y - g.y);
      g.x = p.x; g.y = p.y;
    } else if (g.kind === 'pinch' && pts.length >= 2) {
      const [a, b] = pts;
      const mx = (a.x + b.x) / 2, my = (a.y + b.y) / 2;
      this.s = g.s * (Math.hypot(a.x - b.x, a.y - b.y) / g.d);
      this.tx = mx - g.world[0] * this.s;
      this.ty = my + g.world[1] * this.s;
      this.#gestureFrame();
    }
  }
}

function boundsOf(points, triangles) {
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  const visit = (i) => {
    const x = points[2 * i], y = points[2 * i + 1];
    if (x < x0) x0 = x;
    if (x > x1) x1 = x;
    if (y < y0) y0 = y;
    if (y > y1) y1 = y;
  };
  // With triangles, only vertices in use count: an unused input vertex (a duplicate, or one
  // outside the domain) should not shrink the picture.
  if (triangles) for (let i = 0; i < triangles.length; i++) visit(triangles[i]);
  else for (let i = 0; 2 * i + 1 < points.length; i++) visit(i);
  return { x0, y0, x1, y1 };
}

// What "fit" frames: the largest parts of the picture that together hold 99% of its area, and
// the parts near them, so a far islet (South Africa's Prince Edward Islands) does not shrink
// the country to a corner; zooming out still shows it. parts: [{ area, x0, y0, x1, y1 }].
const FIT_AREA_SHARE = 0.99;
const FIT_NEAR = 0.15;  // parts whose centre is within this share of the frame's size count

function mainBounds(parts) {
  const total = parts.reduce((sum, q) => sum + q.area, 0);
  if (!(total > 0)) return parts.reduce(union, { x0: Infinity, y0: Infinity, x1: -Infinity, y1: -Infinity });
  const sorted = [...parts].sort((a, b) => b.area - a.area);
  let b = { x0: Infinity, y0: Infinity, x1: -Infinity, y1: -Infinity }, sum = 0, k = 0;
  while (k < sorted.length && sum < FIT_AREA_SHARE * total) { b = union(b, sorted[k]); sum += sorted[k++].area; }
  const mx = FIT_NEAR * (b.x1 - b.x0), my = FIT_NEAR * (b.y1 - b.y0);
  const near = { x0: b.x0 - mx, y0: b.y0 - my, x1: b.x1 + mx, y1: b.y1 + my };
  for (const q of sorted.slice(k)) {
    const cx = (q.x0 + q.x1) / 2, cy = (q.y0 + q.y1) / 2;
    if (cx >= near.x0 && cx <= near.x1 && cy >= near.y0 && cy <= near.y1) b = union(b, q);
  }
  return b;
}

function union(a, b) {
  return { x0: Math.min(a.x0, b.x0), y0: Math.min(a.y0, b.y0), x1: Math.max(a.x1, b.x1), y1: Math.max(a.y1, b.y1) };
}

function ringPart(ring) {
  let area = 0;
  const b = { x0: Infinity, y0: Infinity, x1: -Infinity, y1: -Infinity };
  ring.forEach(([x, y], i) => {
    const [u, v] = ring[(i + 1) % ring.length];
    area += x * v - u * y;
    b.x0 = Math.min(b.x0, x); b.x1 = Math.max(b.x1, x); b.y0 = Math.min(b.y0, y); b.y1 = Math.max(b.y1, y);
  });
  return { area: Math.abs(area) / 2, ...b };
}

// The mesh's connected parts (triangles joined through shared vertices), with area and bounds.
function meshParts(p, t) {
  const parent = new Int32Array(p.length / 2).map((_, i) => i);
  const root = (i) => { while (parent[i] !== i) i = parent[i] = parent[parent[i]]; return i; };
  for (let i = 0; i < t.length; i += 3) {
    const a = root(t[i]);
    parent[root(t[i + 1])] = a;
    parent[root(t[i + 2])] = a;
  }
  const parts = new Map();
  for (let i = 0; i < t.length; i += 3) {
    const r = root(t[i]);
    let q = parts.get(r);
    if (!q) parts.set(r, q = { area: 0, x0: Infinity, y0: Infinity, x1: -Infinity, y1: -Infinity });
    const [a, b, c] = [2 * t[i], 2 * t[i + 1], 2 * t[i + 2]];
    q.area += Math.abs((p[b] - p[a]) * (p[c + 1] - p[a + 1]) - (p[c] - p[a]) * (p[b + 1] - p[a + 1])) / 2;
    for (const v of [a, b, c]) {
      q.x0 = Math.min(q.x0, p[v]); q.x1 = Math.max(q.x1, p[v]);
      q.y0 = Math.min(q.y0, p[v + 1]); q.y1 = Math.max(q.y1, p[v + 1]);
    }
  }
  return [...parts.values()];
}

// A neutral grey between the triangle colours and the ink, opaque.
function mix(alpha) {
  const v = Math.round(255 * (1 - alpha) * 0.55 + 24 * alpha);
  return `rgb(${v},${v + 2},${v + 6})`;
}

// Triangles bucketed by centroid into a grid of tiles of about TILE_TRIANGLES each; per tile,
// one Path2D per colour class, one of its edges, and its bounds (for culling). Every mesh edge
// is drawn once: half-edge a->b when a < b, and b->a when it has no twin (a boundary edge
// walked the other way); it goes to the tile of the triangle that holds it.
const TILE_TRIANGLES = 4000;
const STEP = 4096;  // triangles (or edges) between the builders' yields

// Everything a mesh is drawn from: its tiles, mean edge length, segments' path and shortest
// edge per vertex. A generator that yields every STEP triangles (setMesh runs it in slices);
// finish() runs it through.
function* meshPaths(p, t, cls, seg) {
  const tiles = yield* buildTiles(p, t, cls);
  let sum = 0, count = 0;
  for (const tile of tiles) { sum += tile.edgeSum; count += tile.edgeCount; }
  const shortest = yield* shortestEdges(p, t);
  return { tiles, meanEdge: count ? sum / count : 0, segments: segmentPath(p, seg), shortest };
}

function finish(generator) {
  for (;;) {
    const r = generator.next();
    if (r.done) return r.value;
  }
}

function* buildTiles(p, t, cls) {
  const T = t.length / 3;
  const b = boundsOf(p, t);
  const g = Math.max(1, Math.round(Math.sqrt(T / TILE_TRIANGLES)));
  const w = (b.x1 - b.x0) / g || 1, h = (b.y1 - b.y0) / g || 1;
  const tiles = Array.from({ length: g * g }, () => ({
    paths: [], edges: new Path2D(), x0: Infinity, y0: Infinity, x1: -Infinity, y1: -Infinity, edgeSum: 0, edgeCount: 0,
  }));
  const n = p.length / 2;
  const forward = new Set();
  for (let i = 0; i < t.length; i += 3) {
    for (let k = 0; k < 3; k++) {
      const a = t[i + k], c = t[i + (k + 1) % 3];
      if (a < c) forward.add(a * n + c);
    }
    if (i % (3 * STEP) === 0) yield;
  }
  for (let i = 0; i < T; i++) {
    if (i % STEP === 0) yield;
    const a = 2 * t[3 * i], bb = 2 * t[3 * i + 1], c = 2 * t[3 * i + 2];
    const cx = (p[a] + p[bb] + p[c]) / 3, cy = (p[a + 1] + p[bb + 1] + p[c + 1]) / 3;
    const col = Math.min(g - 1, Math.floor((cx - b.x0) / w)), row = Math.min(g - 1, Math.floor((cy - b.y0) / h));
    const tile = tiles[row * g + col];
    const path = tile.paths[cls[i]] || (tile.paths[cls[i]] = new Path2D());
    path.moveTo(p[a], p[a + 1]);  // (fill() closes each triangle: closePath took half the time)
    path.lineTo(p[bb], p[bb + 1]);
    path.lineTo(p[c], p[c + 1]);
    for (const v of [a, bb, c]) {
      tile.x0 = Math.min(tile.x0, p[v]); tile.x1 = Math.max(tile.x1, p[v]);
      tile.y0 = Math.min(tile.y0, p[v + 1]); tile.y1 = Math.max(tile.y1, p[v + 1]);
    }
    for (let k = 0; k < 3; k++) {
      const u = t[3 * i + k], v = t[3 * i + (k + 1) % 3];
      if (u > v && forward.has(v * n + u)) continue;  // drawn from its twin
      tile.edges.moveTo(p[2 * u], p[2 * u + 1]);
      tile.edges.lineTo(p[2 * v], p[2 * v + 1]);
      tile.edgeSum += Math.hypot(p[2 * u] - p[2 * v], p[2 * u + 1] - p[2 * v + 1]);
      tile.edgeCount++;
    }
  }
  return tiles.filter((tile) => tile.x1 >= tile.x0);
}

// Per vertex, the length of its shortest edge in the mesh (Infinity for an unused vertex).
function* shortestEdges(p, t) {
  const out = new Float64Array(p.length / 2).fill(Infinity);
  for (let i = 0; i < t.length; i += 3) {
    if (i % (3 * STEP) === 0) yield;
    for (let k = 0; k < 3; k++) {
      const a = t[i + k], b = t[i + (k + 1) % 3];
      const d = Math.hypot(p[2 * a] - p[2 * b], p[2 * a + 1] - p[2 * b + 1]);
      if (d < out[a]) out[a] = d;
      if (d < out[b]) out[b] = d;
    }
  }
  return out;
}

function segmentPath(p, seg) {
  const path = new Path2D();
  if (!seg) return path;
  for (let i = 0; i + 1 < seg.length; i += 2) {
    path.moveTo(p[2 * seg[i]], p[2 * seg[i] + 1]);
    path.lineTo(p[2 * seg[i + 1]], p[2 * seg[i + 1] + 1]);
  }
  return path;
}
