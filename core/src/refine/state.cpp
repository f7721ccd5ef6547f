#include "state.h"

#include <algorithm>
#include <cmath>

#include "params.h"

#include "../curve_order.h"
#include "../rounding.h"

namespace acutemesh::detail {

RefineState RefineState::start(Triangulation T, size_t inputVertices) {
  RefineState s;
  s.T = std::move(T);
  s.role.assign(s.T.vertexCount(), kOnSegment);
  std::fill(s.role.begin(), s.role.begin() + inputVertices, kInput);
  s.fanCenter.assign(s.T.vertexCount(), kNone);
  s.footOf.assign(s.T.vertexCount(), kNone);
  s.fanRadius.assign(inputVertices, 0);
  Triangulation& t = s.T;
  // A vertex within rounding reach of a hull edge, with only triangles outside the domain
  // between them (a turned copy of collinear input), joins the hull: the slivers there leave
  // no double to split a segment along it, and flips outside only pass them around.
  std::vector<uint32_t> hull;
  auto pushHullEdge = [&](uint32_t g) {  // the hull edge of ghost triangle g
    for (uint32_t k = 0; k < 3; ++k)
      if (t.tri[3 * g + k] != kGhost && t.tri[3 * g + (k + 1) % 3] != kGhost)
        hull.push_back(3 * g + k);
  };
  for (uint32_t g = 0; g < t.triangleSlots(); ++g)
    if (!t.isFree(g) && t.isGhost(g)) pushHullEdge(g);
  while (!hull.empty()) {
    const uint32_t e = hull.back();
    hull.pop_back();
    const uint32_t h = t.opp[e];  // the same edge in the triangle inside the hull
    if (t.isGhost(h / 3) || t.inside[h / 3] || t.isFixed(h)) continue;
    if (!nearSegment(t.point(t.tri[h]), t.point(t.tri[next(h)]), t.point(t.tri[prev(h)])))
      continue;
    const uint32_t inner = h / 3, ghost = e / 3;
    t.flip(h);
    pushHullEdge(inner);
    pushHullEdge(ghost);
  }
  for (uint32_t e = 0; e < 3 * t.triangleSlots(); ++e)
    if (!t.isFree(e / 3) && t.inside[e / 3] && !t.isFixed(e) && !t.inside[t.opp[e] / 3])
      t.fixEdge(e, 0);
  return s;
}

void RefineState::reserve(size_t vertices) {
  T.reserveCapacity(vertices, 2 * vertices + 16);
  role.reserve(vertices);
  fanCenter.reserve(vertices);
  footOf.reserve(vertices);
}

void RefineState::releaseChords() {
  for (uint32_t e = 0; e < 3 * T.triangleSlots(); ++e)
    if (!T.isFree(e / 3) && T.isFixed(e) && !T.isGhost(e / 3) && isChord(e)) T.unfixEdge(e);
}

bool RefineState::slideOf(uint32_t v, uint32_t ends[2], uint32_t& segment) const {
  const bool onSegment = role[v] == kOnSegment || role[v] == kOnHull;
  ends[0] = ends[1] = segment = kNone;
  if (!(role[v] == kFree || onSegment) || T.vertexEdge[v] == kNone) return false;
  int fixedSpokes = 0;
  uint32_t e0 = T.vertexEdge[v], e = e0;
  do {
    if (T.isGhost(e / 3) && !onSegment) return false;
    if (T.isFixed(e) && T.tri[next(e)] != kGhost) {
      if (!onSegment || fixedSpokes == 2) return false;
      ends[fixedSpokes++] = T.tri[next(e)];
      segment = T.segment[e];
    }
    e = T.opp[prev(e)];
  } while (e != e0);
  return !onSegment || fixedSpokes == 2;
}

void RefineState::visitOrder(uint32_t from, uint32_t to, std::vector<uint32_t>& order) const {
  order.clear();
  for (uint32_t v = from; v < to; ++v)
    if (T.vertexEdge[v] != kNone) order.push_back(v);
  if (order.size() < kSpatialOrderFrom) return;
  sortAlongCurve(order, [&](uint32_t v, double* p) { p[0] = P(v)[0], p[1] = P(v)[1]; });
}

void RefineState::compactTriangles(size_t inputVertices) {
  if (T.journal || liveSteiner(inputVertices) < kSpatialOrderFrom) return;
  std::vector<uint32_t> order;
  for (uint32_t t = 0; t < T.triangleSlots(); ++t)
    if (!T.isFree(t)) order.push_back(t);
  sortAlongCurve(order, [&](uint32_t t, double* p) {
    int n = 0;
    p[0] = p[1] = 0;
    for (int k = 0; k < 3; ++k)
      if (const uint32_t v = T.tri[3 * t + k]; v != kGhost) p[0] += P(v)[0], p[1] += P(v)[1], ++n;
    p[0] /= n, p[1] /= n;
  });
  T.permuteSlots(order);
}

size_t RefineState::liveSteiner(size_t inputVertices) const {
  size_t n = 0;
  for (uint32_t v = uint32_t(inputVertices); v < T.vertexCount(); ++v)
    n += T.vertexEdge[v] != kNone;
  return n;
}

void RefineState::markFree(std::vector<uint8_t>& out) const {
  out.resize(role.size());
  for (size_t v = 0; v < role.size(); ++v)
    out[v] = role[v] == kFree || role[v] == kOnHull || role[v] == kArc;
}

}  // namespace acutemesh::detail
