#include <algorithm>
#include "triangulation.h"
#include "rounding.h"

#include "acutemesh/predicates.h"

namespace acutemesh::detail {

uint32_t Triangulation::addVertex(double x, double y) {
  pts.push_back(x);
  pts.push_back(y);
  vertexEdge.push_back(kNone);
  return vertexCount() - 1;
}

void Triangulation::undoTo(const Journal::Mark& m) {
  Journal& j = *journal;
  for (size_t i = j.slots.size(); i-- > m.slots;) {
    const Journal::Slot& r = j.slots[i];
    for (int k = 0; k < 3; ++k) {
      const size_t e = 3 * size_t(r.t) + size_t(k);
      tri[e] = r.tri[k], opp[e] = r.opp[k], fixed[e] = r.fixed[k];
      if (trackWinding) wind[e] = r.wind[k];
      if (trackSegments) segment[e] = r.segment[k];
    }
    if (!inside.empty()) inside[r.t] = r.inside;
  }
  // (A vertex added and dropped since, RefineState::dropLastVertex, is gone already.)
  for (size_t i = j.edges.size(); i-- > m.edges;)
    if (j.edges[i].first < vertexEdge.size()) vertexEdge[j.edges[i].first] = j.edges[i].second;
  for (size_t i = j.points.size(); i-- > m.points;) {
    const Journal::Point& p = j.points[i];
    if (p.v < vertexCount()) pts[2 * size_t(p.v)] = p.xy[0], pts[2 * size_t(p.v) + 1] = p.xy[1];
  }
  j.slots.resize(m.slots), j.edges.resize(m.edges), j.points.resize(m.points);
  pts.resize(2 * size_t(m.vertices));
  vertexEdge.resize(m.vertices);
  slots_ = m.slotCount;
  freeSlots_ = m.freeSlots;
  rng_ = m.rng;
}

void Triangulation::reserveTriangles(size_t count) {
  if (3 * count <= tri.size()) return;
  tri.resize(3 * count, kNone);
  opp.resize(3 * count, kNone);
  fixed.resize(3 * count, 0);
  if (trackWinding) wind.resize(3 * count, 0);
  if (trackSegments) segment.resize(3 * count, kNone);
}

void Triangulation::reserveCapacity(size_t vertices, size_t triangles) {
  pts.reserve(2 * vertices);
  vertexEdge.reserve(vertices);
  for (std::vector<uint32_t>* v : {&tri, &opp}) v->reserve(3 * triangles);
  fixed.reserve(3 * triangles);
  if (trackWinding) wind.reserve(3 * triangles);
  if (trackSegments) segment.reserve(3 * triangles);
  if (!inside.empty()) inside.reserve(triangles);
}

void Triangulation::permuteSlots(const std::vector<uint32_t>& order) {
  std::vector<uint32_t> to(slots_, kNone);
  for (size_t i = 0; i < order.size(); ++i) to[order[i]] = uint32_t(i);
  auto edgeTo = [&](uint32_t e) { return e == kNone ? kNone : 3 * to[e / 3] + e % 3; };
  auto permute = [&](auto& a, size_t per, auto map) {
    if (a.empty()) return;
    std::remove_reference_t<decltype(a)> b(per * order.size());
    for (size_t i = 0; i < order.size(); ++i)
      for (size_t k = 0; k < per; ++k) b[per * i + k] = map(a[per * size_t(order[i]) + k]);
    a.swap(b);
  };
  auto same = [](auto x) { return x; };
  permute(tri, 3, same);
  permute(opp, 3, edgeTo);
  permute(fixed, 3, same);
  permute(wind, 3, same);
  permute(segment, 3, same);
  permute(inside, 1, same);
  for (uint32_t& e : vertexEdge) e = edgeTo(e);
  slots_ = uint32_t(order.size());
  freeSlots_.clear();
}

void Triangulation::trimToSlots() {
  auto trim = [&](auto& a, size_t n) {
    if (a.size() <= n) return;
    a.resize(n);
    a.shrink_to_fit();
  };
  const size_t halfEdges = 3 * size_t(slots_);
  trim(tri, halfEdges), trim(opp, halfEdges), trim(fixed, halfEdges);
  trim(wind, halfEdges), trim(segment, halfEdges), trim(inside, slots_);
}

Triangulation::Compact Triangulation::compact() const {
  Compact c;
  const size_t halfEdges = 3 * size_t(slots_);
  c.pts = pts, c.vertexEdge = vertexEdge, c.freeSlots = freeSlots_;
  c.tri.assign(tri.begin(), tri.begin() + ptrdiff_t(halfEdges));
  if (!inside.empty()) c.inside.assign(inside.begin(), inside.begin() + ptrdiff_t(slots_));
  if (trackWinding) c.wind.assign(wind.begin(), wind.begin() + ptrdiff_t(halfEdges));
  for (size_t e = 0; e < halfEdges; ++e) {
    const uint32_t seg = trackSegments ? segment[e] : kNone;
    if (fixed[e] || seg != kNone) c.marked.push_back({uint32_t(e), seg, fixed[e]});
  }
  c.slots = slots_, c.rng = rng_;
  c.trackSegments = trackSegments, c.trackWinding = trackWinding;
  return c;
}

void Triangulation::restore(Compact&& c) {
  pts = std::move(c.pts), vertexEdge = std::move(c.vertexEdge), tri = std::move(c.tri);
  inside = std::move(c.inside), wind = std::move(c.wind), freeSlots_ = std::move(c.freeSlots);
  slots_ = c.slots, rng_ = c.rng;
  trackSegments = c.trackSegments, trackWinding = c.trackWinding;
  const size_t halfEdges = tri.size();
  fixed.assign(halfEdges, 0);
  segment.assign(trackSegments ? halfEdges : 0, kNone);
  for (const Compact::Marked& m : c.marked) {
    fixed[m.e] = m.fixed;
    if (trackSegments) segment[m.e] = m.segment;
  }
  // The twins: each half-edge a->b's is the one b->a, found among the half-edges leaving b
  // (bucketed by the vertex they leave, the ghost vertex last).
  const uint32_t n = vertexCount();
  auto bucketOf = [&](uint32_t v) { return v == kGhost ? n : v; };
  std::vector<uint32_t> first(size_t(n) + 2, 0), leaving;
  for (size_t e = 0; e < halfEdges; ++e)
    if (tri[e] != kNone) ++first[bucketOf(tri[e]) + 1];
  for (size_t v = 1; v < first.size(); ++v) first[v] += first[v - 1];
  leaving.resize(first.back());
  std::vector<uint32_t> fill(first.begin(), first.end() - 1);
  for (size_t e = 0; e < halfEdges; ++e)
    if (tri[e] != kNone) leaving[fill[bucketOf(tri[e])]++] = uint32_t(e);
  opp.assign(halfEdges, kNone);
  for (size_t e = 0; e < halfEdges; ++e) {
    if (tri[e] == kNone) continue;
    const uint32_t a = tri[e], b = tri[next(uint32_t(e))], from = bucketOf(b);
    for (uint32_t i = first[from]; i < first[from + 1]; ++i)
      if (tri[next(leaving[i])] == a) {
        opp[e] = leaving[i];
        break;
      }
  }
}

uint32_t Triangulation::newTriangle() {
  if (!freeSlots_.empty()) {
    uint32_t t = freeSlots_.back();
    freeSlots_.pop_back();
    return t;
  }
  // (An eighth more at a time, within reserveCapacity's room while there is some: the arrays
  // are filled as they grow, and filled memory is resident.)
  if (3 * size_t(slots_ + 1) > tri.size()) {
    const size_t more = size_t(slots_) + std::max<size_t>(slots_ / 8, 1024),
                 room = tri.capacity() / 3;
    reserveTriangles(room > size_t(slots_) ? std::min(more, room) : more);
  }
  if (!inside.empty() && inside.size() < tri.size() / 3) inside.resize(tri.size() / 3, 0);
  return slots_++;
}

void Triangulation::freeTriangle(uint32_t t) {
  noteSlot(t);
  if (!inside.empty()) inside[t] = 0;
  for (int k = 0; k < 3; ++k) {
    tri[3 * t + k] = kNone;
    setAttr(3 * t + k, kPlain, false);
    opp[3 * t + k] = kNone;
  }
  freeSlots_.push_back(t);
}

void Triangulation::setCorners(uint32_t t, uint32_t a, uint32_t b, uint32_t c) {
  if (touched) touched->push_back(t);
  noteSlot(t);
  noteEdge(a), noteEdge(b), noteEdge(c);
  uint32_t e = 3 * t;
  tri[e] = a;
  tri[e + 1] = b;
  tri[e + 2] = c;
  if (a != kGhost) vertexEdge[a] = e;
  if (b != kGhost) vertexEdge[b] = e + 1;
  if (c != kGhost) vertexEdge[c] = e + 2;
}

void Triangulation::init(uint32_t a, uint32_t b, uint32_t c) {
  if (orient2d(point(a), point(b), point(c)) < 0) std::swap(b, c);
  uint32_t t = newTriangle(), g0 = newTriangle(), g1 = newTriangle(), g2 = newTriangle();
  setCorners(t, a, b, c);
  setCorners(g0, b, a, kGhost);
  setCorners(g1, c, b, kGhost);
  setCorners(g2, a, c, kGhost);
  link(3 * t, 3 * g0);
  link(3 * t + 1, 3 * g1);
  link(3 * t + 2, 3 * g2);
  link(3 * g0 + 1, 3 * g2 + 2);
  link(3 * g0 + 2, 3 * g1 + 1);
  link(3 * g1 + 2, 3 * g2 + 1);
}

// Where a point lies in the closed triangle t, given the edges whose line it is on.
Location Triangulation::closedIn(uint32_t t, uint32_t zeros, const uint32_t zeroEdge[2]) const {
  if (zeros == 0) return {Where::InTriangle, t, kNone, kNone};
  if (zeros == 1) return {Where::OnEdge, t, zeroEdge[0], kNone};
  uint32_t v = next(zeroEdge[0]) == zeroEdge[1] ? tri[zeroEdge[1]] : tri[zeroEdge[0]];
  return {Where::OnVertex, t, kNone, v};
}

Location Triangulation::locate(const double* p, uint32_t hint) const {
  uint32_t slots = triangleSlots();
  uint32_t t = hint < slots && !isFree(hint) ? hint : kNone;
  if (t == kNone) {
    for (uint32_t s = 0; s < slots && t == kNone; ++s)
      if (!isFree(s)) t = s;
    if (t == kNone) return {};
  }
  if (isGhost(t)) {
    // Step onto the real triangle across the ghost's hull edge.
    for (uint32_t k = 0; k < 3; ++k) {
      uint32_t e = 3 * t + k;
      if (tri[e] != kGhost && tri[next(e)] != kGhost) {
        t = opp[e] / 3;
        break;
      }
    }
  }
  // A visibility walk always terminates in a Delaunay triangulation; in a constrained one it
  // terminates with probability 1 because the exit edge is tried from a random start. The
  // step cap only guards against bugs elsewhere: it falls back to a scan.
  uint64_t maxSteps = 4ull * slots + 64;
  uint32_t entered = kNone;  // the half-edge we came in through: p is known to be inside it
  for (uint64_t step = 0; step < maxSteps; ++step) {
    if (isGhost(t)) return {Where::InTriangle, t, kNone, kNone};
    rng_ ^= rng_ << 13;
    rng_ ^= rng_ >> 17;
    rng_ ^= rng_ << 5;
    uint32_t start = rng_ % 3;
    uint32_t zeros = 0, zeroEdge[2] = {kNone, kNone};
    bool moved = false;
    for (uint32_t i = 0; i < 3; ++i) {
      uint32_t e = 3 * t + (start + i) % 3;
      if (e == entered) continue;
      double o = orient2d(point(tri[e]), point(tri[next(e)]), p);
      if (o < 0) {
        entered = opp[e];
        t = entered / 3;
        moved = true;
        break;
      }
      if (o == 0) zeroEdge[zeros++ & 1] = e;
    }
    if (moved) continue;
    return closedIn(t, zeros, zeroEdge);
  }
  for (uint32_t s = 0; s < slots; ++s) {
    if (isFree(s) || isGhost(s)) continue;
    uint32_t zeros = 0, zeroEdge[2] = {kNone, kNone};
    bool inside = true;
    for (uint32_t k = 0; k < 3 && inside; ++k) {
      uint32_t e = 3 * s + k;
      double o = orient2d(point(tri[e]), point(tri[next(e)]), p);
      if (o < 0) inside = false;
      if (o == 0) zeroEdge[zeros++ & 1] = e;
    }
    if (!inside) continue;
    return closedIn(s, zeros, zeroEdge);
  }
  // Outside the hull: any ghost whose hull edge the point sees strictly will do.
  for (uint32_t s = 0; s < slots; ++s) {
    if (isFree(s) || !isGhost(s)) continue;
    for (uint32_t k = 0; k < 3; ++k) {
      uint32_t e = 3 * s + k;
      if (tri[e] != kGhost && tri[next(e)] != kGhost &&
          orient2d(point(tri[e]), point(tri[next(e)]), p) > 0)
        return {Where::InTriangle, s, kNone, kNone};
    }
  }
  return {};
}

uint32_t Triangulation::splitTriangle(uint32_t t, uint32_t v) {
  uint32_t e = 3 * t;
  uint32_t a = tri[e], b = tri[e + 1], c = tri[e + 2];
  EdgeAttr ab = attr(e), bc = attr(e + 1), ca = attr(e + 2);
  uint32_t t1 = newTriangle(), t2 = newTriangle();
  noteSlot(t1), noteSlot(t2);
  if (!inside.empty()) inside[t1] = inside[t2] = inside[t];
  setCorners(t, a, b, v);
  setCorners(t1, b, c, v);
  setCorners(t2, c, a, v);
  // Slot 0 of each new triangle is an old edge; slots 1 and 2 are spokes to v.
  setAttr(3 * t, ab);
  setAttr(3 * t1, bc);
  setAttr(3 * t2, ca);
  for (uint32_t s : {t, t1, t2}) {
    setAttr(3 * s + 1, kPlain, false);
    setAttr(3 * s + 2, kPlain, false);
  }
  link(3 * t + 1, 3 * t1 + 2);
  link(3 * t + 2, 3 * t2 + 1);
  link(3 * t1 + 1, 3 * t2 + 2);
  scratch_.push_back(3 * t);
  scratch_.push_back(3 * t1);
  scratch_.push_back(3 * t2);
  return v;
}

uint32_t Triangulation::splitEdge(uint32_t e, uint32_t v) {
  uint32_t f = opp[e];
  uint32_t t0 = e / 3, t1 = f / 3;
  uint32_t e1 = next(e), e2 = prev(e), f1 = next(f), f2 = prev(f);
  uint32_t a = tri[e], b = tri[e1], c = tri[e2], d = tri[f2];
  EdgeAttr ab = attr(e), ba = attr(f), bc = attr(e1), ca = attr(e2), ad = attr(f1), db = attr(f2);
  uint32_t t2 = newTriangle(), t3 = newTriangle();
  for (uint32_t s : {t0, t1, t2, t3}) noteSlot(s);
  if (!inside.empty()) {
    // t0 and t1 now hold the two halves on c's side, t2 and t3 those on d's side.
    uint8_t cSide = inside[t0], dSide = inside[t1];
    inside[t0] = inside[t1] = cSide;
    inside[t2] = inside[t3] = dSide;
  }
  setCorners(t0, c, a, v);
  setCorners(t1, b, c, v);
  setCorners(t2, a, d, v);
  setCorners(t3, d, b, v);
  // Slot 0: the outer edges, keeping twins and flags. The halves of the split edge (a-v,
  // v-b) inherit its flags; the other spokes are plain.
  setAttr(3 * t0, ca);
  setAttr(3 * t1, bc);
  setAttr(3 * t2, ad);
  setAttr(3 * t3, db);
  setAttr(3 * t0 + 1, ab, false);  // a->v
  setAttr(3 * t1 + 2, ab, false);  // v->b
  setAttr(3 * t2 + 2, ba, false);  // v->a
  setAttr(3 * t3 + 1, ba, false);  // b->v
  setAttr(3 * t0 + 2, kPlain, false);
  setAttr(3 * t1 + 1, kPlain, false);
  setAttr(3 * t2 + 1, kPlain, false);
  setAttr(3 * t3 + 2, kPlain, false);
  link(3 * t0 + 1, 3 * t2 + 2);  // a->v | v->a
  link(3 * t0 + 2, 3 * t1 + 1);  // v->c | c->v
  link(3 * t1 + 2, 3 * t3 + 1);  // v->b | b->v
  link(3 * t2 + 1, 3 * t3 + 2);  // d->v | v->d
  for (uint32_t s : {t0, t1, t2, t3}) scratch_.push_back(3 * s);
  return v;
}

bool Triangulation::inCircumcircle(uint32_t t, uint32_t p) const {
  if (p == kGhost) return false;
  uint32_t a = tri[3 * t], b = tri[3 * t + 1], c = tri[3 * t + 2];
  // A ghost's "circumcircle" is the open half-plane outside its hull edge.
  if (a == kGhost) return orient2d(point(b), point(c), point(p)) > 0;
  if (b == kGhost) return orient2d(point(c), point(a), point(p)) > 0;
  if (c == kGhost) return orient2d(point(a), point(b), point(p)) > 0;
  return incircle(point(a), point(b), point(c), point(p)) > 0;
}

bool Triangulation::mustFlip(uint32_t e) const {
  if (fixed[e]) return false;
  if (hullFollowsSegments && (tri[e] == kGhost || tri[next(e)] == kGhost)) {
    // A spoke to infinity between two hull edges. Where a hull edge is a segment, a rounded
    // split point on it may bend the hull inward by an ulp; flipping the spoke would wrap a
    // sliver triangle around that bend, so the hull is left as the segments make it.
    auto hullEdgeFixed = [&](uint32_t t) {
      for (uint32_t f = 3 * t; f < 3 * t + 3; ++f)
        if (tri[f] != kGhost && tri[next(f)] != kGhost) return fixed[f] != 0;
      return false;
    };
    if (hullEdgeFixed(e / 3) || hullEdgeFixed(opp[e] / 3)) return false;
  }
  return inCircumcircle(e / 3, tri[prev(opp[e])]);
}

void Triangulation::flip(uint32_t e) {
  uint32_t f = opp[e];
  uint32_t t0 = e / 3, t1 = f / 3;
  uint32_t e1 = next(e), e2 = prev(e), f1 = next(f), f2 = prev(f);
  uint32_t a = tri[e], b = tri[e1], c = tri[e2], d = tri[f2];
  EdgeAttr bc = attr(e1), ca = attr(e2), ad = attr(f1), db = attr(f2);
  // Quadrilateral a, d, b, c (counter-clockwise) gets the diagonal c-d.
  setCorners(t0, c, a, d);
  setCorners(t1, d, b, c);
  setAttr(3 * t0, ca);
  setAttr(3 * t0 + 1, ad);
  setAttr(3 * t1, db);
  setAttr(3 * t1 + 1, bc);
  linkPlain(3 * t0 + 2, 3 * t1 + 2);
}

void Triangulation::legalizeFrom(uint32_t v, std::vector<uint32_t>& stack) {
  (void)v;
  // Every half-edge on the stack lies opposite the new vertex in its triangle; after a flip
  // the two edges opposite it in the new triangles are the only ones that can be illegal.
  while (!stack.empty()) {
    uint32_t e = stack.back();
    stack.pop_back();
    if (!mustFlip(e)) continue;
    uint32_t t0 = e / 3, t1 = opp[e] / 3;
    flip(e);
    stack.push_back(3 * t0 + 1);
    stack.push_back(3 * t1);
  }
}

void Triangulation::legalize(std::vector<uint32_t>& stack) {
  while (!stack.empty()) {
    uint32_t e = stack.back();
    stack.pop_back();
    if (isFree(e / 3) || !mustFlip(e)) continue;
    uint32_t t0 = e / 3, t1 = opp[e] / 3;
    flip(e);
    stack.push_back(3 * t0);
    stack.push_back(3 * t0 + 1);
    stack.push_back(3 * t1);
    stack.push_back(3 * t1 + 1);
  }
}

bool Triangulation::splitFixedEdge(uint32_t e, uint32_t v) {
  uint32_t f = opp[e];
  uint32_t a = tri[e], b = tri[next(e)], c = tri[prev(e)], d = tri[prev(f)];
  const double* p = point(v);
  // The four new triangles (c,a,v), (b,c,v), (a,d,v), (d,b,v) must all be counter-clockwise
  // (ghost corners excepted: the hull may bend by a rounding at v).
  auto ccw = [&](uint32_t x, uint32_t y) {
    return x == kGhost || y == kGhost || orient2d(point(x), point(y), p) > 0;
  };
  if (!ccw(c, a) || !ccw(b, c) || !ccw(a, d) || !ccw(d, b)) return false;
  // Nor may v come within rounding reach of another fixed edge of the two triangles: in a
  // sliver between two segments thinner than that, v would lie on both, and no check could
  // tell the two segments' chains apart afterwards (fuzz finding sliver-thinner-than-rounding).
  auto nearFixed = [&](uint32_t h) {
    return isFixed(h) && tri[h] != kGhost && tri[next(h)] != kGhost &&
           nearSegment(point(tri[h]), point(tri[next(h)]), p);
  };
  if (nearFixed(next(e)) || nearFixed(prev(e)) || nearFixed(next(f)) || nearFixed(prev(f)))
    return false;
  scratch_.clear();
  splitEdge(e, v);
  legalizeFrom(v, scratch_);
  return true;
}

uint32_t Triangulation::insertAt(uint32_t v, const Location& loc) {
  scratch_.clear();
  switch (loc.where) {
    case Where::OnVertex:
      return loc.vertex;
    case Where::InTriangle:
      splitTriangle(loc.tri, v);
      break;
    case Where::OnEdge:
      splitEdge(loc.edge, v);
      break;
    case Where::Failed:
      return kNone;
  }
  legalizeFrom(v, scratch_);
  return v;
}

uint32_t Triangulation::insert(uint32_t v, uint32_t hint) {
  return insertAt(v, locate(point(v), hint));
}

uint32_t Triangulation::insertEdgeThroughCavity(uint32_t u, uint32_t w,
                                                const std::vector<uint32_t>& crossed) {
  // Side 0 runs left of u->w, side 1 right of it; both chains from u to w. A side's old edges
  // are the cavity triangles' half-edges along it: on the left from the later vertex to the
  // earlier, on the right from the earlier to the later.
  std::vector<uint32_t>& left = chains_[0];
  std::vector<uint32_t>& right = chains_[1];
  left.assign(1, u), right.assign(1, u);
  sides_[0].clear(), sides_[1].clear(), cavity_.clear();
  auto add = [&](int side, uint32_t v, uint32_t e) {
    std::vector<uint32_t>& chain = chains_[side];
    if (chain.back() == v) return true;  // a fan around v: still the same vertex
    // (A linear search: filling the side is quadratic in its length anyway.)
    if (chain.size() > kCavityChain || std::find(chain.begin(), chain.end(), v) != chain.end())
      return false;
    chain.push_back(v);
    sides_[side].push_back(attr(e));
    return true;
  };
  uint32_t h = crossed[0];  // in (u, r, l): h = r->l, next(h) = l->u, prev(h) = u->r
  cavity_.push_back(h / 3);
  if (!add(1, tri[h], prev(h)) || !add(0, tri[next(h)], next(h))) return kNone;
  for (size_t i = 0; i < crossed.size(); ++i) {
    const uint32_t g = opp[crossed[i]];  // l->r, in (l, r, y)
    const uint32_t y = tri[prev(g)];
    cavity_.push_back(g / 3);
    const bool last = i + 1 == crossed.size();
    const bool yLeft = !last && crossed[i + 1] == next(g);
    if ((last || !yLeft) && !add(1, y, next(g))) return kNone;  // r->y on the right
    if ((last || yLeft) && !add(0, y, prev(g))) return kNone;   // y->l on the left
  }
  if (left.back() != w || right.back() != w) return kNone;
  for (uint32_t t : cavity_) freeTriangle(t);
  // Left: the base u->w, the chain left of it. Right: the base w->u, the chain reversed.
  std::reverse(right.begin(), right.end());
  std::reverse(sides_[1].begin(), sides_[1].end());
  const uint32_t e = fillPseudoPolygon(left.data(), sides_[0].data(), 0, left.size() - 1);
  const uint32_t f = fillPseudoPolygon(right.data(), sides_[1].data(), 0, right.size() - 1);
  linkPlain(e, f);
  return e;
}

uint32_t Triangulation::fillPseudoPolygon(const uint32_t* chain, const EdgeAttr* sides, size_t lo,
                                          size_t hi) {
  // The apex: the chain vertex whose circle through the base's ends holds no other.
  size_t k = lo + 1;
  for (size_t i = lo + 2; i < hi; ++i)
    if (incircle(point(chain[lo]), point(chain[hi]), point(chain[k]), point(chain[i])) > 0) k = i;
  const uint32_t t = newTriangle();
  setCorners(t, chain[lo], chain[hi], chain[k]);
  const uint32_t e = 3 * t;  // chain[lo]->chain[hi]; then chain[hi]->apex, apex->chain[lo]
  auto side = [&](uint32_t edge, size_t from, size_t to) {
    if (to == from + 1) return setAttr(edge, sides[from]);
    linkPlain(edge, fillPseudoPolygon(chain, sides, from, to));
  };
  side(e + 1, k, hi);
  side(e + 2, lo, k);
  return e;
}

uint32_t Triangulation::findEdge(uint32_t a, uint32_t b) const {
  uint32_t e0 = vertexEdge[a];
  if (e0 == kNone) return kNone;
  uint32_t e = e0;
  do {
    if (tri[next(e)] == b) return e;
    e = opp[prev(e)];
  } while (e != e0);
  return kNone;
}

void Triangulation::fixEdge(uint32_t e, int dir, uint32_t seg) {
  noteSlot(e / 3), noteSlot(opp[e] / 3);
  fixed[e] = fixed[opp[e]] = 1;
  if (trackWinding) {
    wind[e] += dir;
    wind[opp[e]] -= dir;
  }
  if (trackSegments && seg != kNone) segment[e] = segment[opp[e]] = seg;
}

void Triangulation::unfixEdge(uint32_t e) {
  setAttr(e, kPlain, false);
  setAttr(opp[e], kPlain, false);
}

void Triangulation::flipAwaySpoke(uint32_t v, uint32_t w, std::vector<uint32_t>& stack,
                                  bool queueDiagonal) {
  uint32_t spoke = findEdge(v, w);
  uint32_t t1 = opp[spoke] / 3;
  flip(spoke);
  // The ear triangle (now t1 = x, w, y; 3 * t1 + 2 is y-x, the diagonal) leaves v's star; its
  // edges may need flips later.
  stack.push_back(3 * t1);
  stack.push_back(3 * t1 + 1);
  if (queueDiagonal) stack.push_back(3 * t1 + 2);
}

bool Triangulation::removeVertex(uint32_t v) {
  uint32_t e0 = vertexEdge[v];
  if (e0 == kNone) return false;
  std::vector<uint32_t>& ring = ring_;  // link vertices in counter-clockwise order around v
  ring.clear();
  uint32_t e = e0;
  do {
    if (isGhost(e / 3) || fixed[e]) return false;
    ring.push_back(tri[next(e)]);
    e = opp[prev(e)];
  } while (e != e0);

  std::vector<uint32_t>& stack = scratch_;
  stack.clear();
  while (ring.size() > 3) {
    // Flip away the spoke v-w of an ear x, w, y of the link (x before w, y after it). Prefer an
    // ear whose circumcircle holds no other link vertex: it is a triangle of the final
    // Delaunay triangulation, so later flips have little to repair.
    size_t n = ring.size(), best = n;
    bool bestDelaunay = false;
    for (size_t i = 0; i < n && !bestDelaunay; ++i) {
      uint32_t x = ring[(i + n - 1) % n], w = ring[i], y = ring[(i + 1) % n];
      if (orient2d(point(y), point(v), point(x)) <= 0 ||
          orient2d(point(x), point(w), point(y)) <= 0)
        continue;
      bool delaunay = n <= 32;
      for (size_t j = 0; j < n && delaunay; ++j) {
        uint32_t q = ring[j];
        if (q != x && q != w && q != y &&
            incircle(point(x), point(w), point(y), point(q)) > 0)
          delaunay = false;
      }
      if (best == n || delaunay) best = i, bestDelaunay = delaunay;
    }
    if (best == n) return false;  // only on degenerate (collinear) links; mesh stays valid
    flipAwaySpoke(v, ring[best], stack, false);
    ring.erase(ring.begin() + long(best));
  }
  // Degree 3: v sits inside triangle ring[0..2]; merge its three triangles into that one.
  uint32_t ea = findEdge(v, ring[0]);
  uint32_t eb = opp[prev(ea)], ec = opp[prev(eb)];
  uint32_t t = ea / 3;
  EdgeAttr outer[3] = {attr(next(ea)), attr(next(eb)), attr(next(ec))};
  freeTriangle(eb / 3);
  freeTriangle(ec / 3);
  setCorners(t, ring[0], ring[1], ring[2]);
  for (uint32_t i = 0; i < 3; ++i) {
    setAttr(3 * t + i, outer[i]);
    stack.push_back(3 * t + i);
  }
  noteEdge(v);
  vertexEdge[v] = kNone;
  legalize(stack);
  return true;
}

bool Triangulation::removeFromSegment(uint32_t v, uint32_t ends[2]) {
  uint32_t e0 = vertexEdge[v];
  if (e0 == kNone) return false;
  std::vector<uint32_t>& ring = ring_;  // link vertices in counter-clockwise order around v
  ring.clear();
  size_t fixedAt[2], fixedCount = 0;
  uint32_t e = e0;
  do {
    if (isGhost(e / 3)) return false;
    if (fixed[e] && fixedCount++ < 2) fixedAt[fixedCount - 1] = ring.size();
    ring.push_back(tri[next(e)]);
    e = opp[prev(e)];
  } while (e != e0);
  if (fixedCount != 2) return false;
  // Rotate the ring to start at a: a, left side..., b, right side...
  std::rotate(ring.begin(), ring.begin() + long(fixedAt[0]), ring.end());
  const uint32_t a = ring[0], b = ring[fixedAt[1] - fixedAt[0]];
  ends[0] = a, ends[1] = b;
  std::vector<uint32_t>& stack = scratch_;
  stack.clear();
  // Flip away the spokes to the link vertices strictly between a and b on each side, ears
  // first as in removeVertex, until one link vertex is left per side. Spokes v-a and v-b,
  // the segment's pieces, are never flipped.
  while (true) {
    size_t n = ring.size(), ib = std::find(ring.begin(), ring.end(), b) - ring.begin();
    if (ib == 2 && n == 4) break;
    size_t best = n;
    for (size_t i = 1; i < n && best == n; ++i) {
      if (i == ib) continue;
      bool lone = i < ib ? ib == 2 : n - ib == 2;  // the only vertex left on its side
      if (lone) continue;
      uint32_t x = ring[i - 1], w = ring[i], y = ring[(i + 1) % n];
      if (orient2d(point(y), point(v), point(x)) > 0 && orient2d(point(x), point(w), point(y)) > 0)
        best = i;
    }
    if (best == n || ib < 2 || n - ib < 2) {
      legalize(stack);
      return false;  // v stays (its star flipped, still a valid triangulation)
    }
    flipAwaySpoke(v, ring[best], stack, true);  // v may stay (below): its link edges too
    ring.erase(ring.begin() + long(best));
  }
  const uint32_t left = ring[1], right = ring[3];
  if (orient2d(point(a), point(left), point(b)) <= 0 || orient2d(point(b), point(right), point(a)) <= 0) {
    legalize(stack);
    return false;
  }
  // The four triangles (v,a,left), (v,left,b), (v,b,right), (v,right,a) become (a,left,b)
  // and (b,right,a); the new edge a-b takes the attributes of the piece b->v.
  uint32_t ea = findEdge(v, a), el = findEdge(v, left), eb = findEdge(v, b), er = findEdge(v, right);
  EdgeAttr aLeft = attr(next(ea)), leftB = attr(next(el)), bRight = attr(next(eb)), rightA = attr(next(er));
  EdgeAttr piece = attr(prev(el));  // b->v, in triangle (v, left, b)
  uint8_t insideLeft = inside.empty() ? 0 : inside[el / 3];
  uint8_t insideRight = inside.empty() ? 0 : inside[er / 3];
  uint32_t t1 = ea / 3, t2 = eb / 3;
  freeTriangle(el / 3);
  freeTriangle(er / 3);
  setCorners(t1, a, left, b);
  setCorners(t2, b, right, a);
  setAttr(3 * t1, aLeft);
  setAttr(3 * t1 + 1, leftB);
  setAttr(3 * t2, bRight);
  setAttr(3 * t2 + 1, rightA);
  link(3 * t1 + 2, 3 * t2 + 2);  // (notes t1 and t2)
  fixed[3 * t1 + 2] = fixed[3 * t2 + 2] = 1;
  if (trackWinding) wind[3 * t1 + 2] = piece.wind, wind[3 * t2 + 2] = -piece.wind;
  if (trackSegments) segment[3 * t1 + 2] = segment[3 * t2 + 2] = piece.segment;
  if (!inside.empty()) inside[t1] = insideLeft, inside[t2] = insideRight;
  noteEdge(v);
  vertexEdge[v] = kNone;
  for (uint32_t f : {3 * t1, 3 * t1 + 1, 3 * t2, 3 * t2 + 1}) stack.push_back(f);
  legalize(stack);
  return true;
}

}  // namespace acutemesh::detail
