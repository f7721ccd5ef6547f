#include "geometry.h"

#include "params.h"

namespace acutemesh::detail {

uint32_t firstFixedCrossed(const Triangulation& T, uint32_t t, const double* x, uint32_t& reached) {
  const uint32_t* v = &T.tri[3 * t];
  const double *p0 = T.point(v[0]), *p1 = T.point(v[1]), *p2 = T.point(v[2]);
  double g[2] = {(p0[0] + p1[0] + p2[0]) / 3, (p0[1] + p1[1] + p2[1]) / 3};
  reached = kNone;
  uint32_t entry = kNone;
  for (uint32_t steps = 0; steps < 4 * T.triangleSlots(); ++steps) {
    uint32_t exit = kNone;
    for (uint32_t e = 3 * t; e < 3 * t + 3 && exit == kNone; ++e) {
      if (e == entry) continue;
      const double *a = T.point(T.tri[e]), *b = T.point(T.tri[next(e)]);
      if (orient2d(a, b, x) >= 0) continue;
      double sa = orient2d(g, x, a), sb = orient2d(g, x, b);
      if (sa == 0 || sb == 0) return kNone;
      if ((sa < 0) != (sb < 0)) exit = e;
    }
    if (exit == kNone) {
      reached = t;
      return kNone;
    }
    if (T.isFixed(exit)) return exit;
    entry = T.opp[exit];
    t = entry / 3;
    if (T.isGhost(t)) return kNone;
  }
  return kNone;
}

double smallestEdge2(const Pslg& input) {
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (size_t i = 0; i < input.points.size(); ++i)
    lo[i % 2] = std::min(lo[i % 2], input.points[i]),
           hi[i % 2] = std::max(hi[i % 2], input.points[i]);
  double dx = hi[0] - lo[0], dy = hi[1] - lo[1];
  double diagonal = std::sqrt(dx * dx + dy * dy);
  double largest = std::max({-lo[0], -lo[1], hi[0], hi[1], 0.0});
  double minEdge = std::max(diagonal * std::ldexp(1.0, -kMinEdgeBits),
                            largest * std::ldexp(1.0, -kMinEdgeUlpBits));
  return minEdge * minEdge;
}

}  // namespace acutemesh::detail
