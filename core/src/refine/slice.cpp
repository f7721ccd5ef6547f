#include "slice.h"

#include <algorithm>

#include "params.h"

namespace acutemesh::detail {
namespace {

// Triangle t's shortest edge pq and its circumcircle: where the searches start.
struct ShortestEdge {
  const double *p, *q;
  double center[2], radius2;
};

ShortestEdge shortestEdge(const RefineState& s, uint32_t t) {
  const uint32_t* v = &s.T.tri[3 * t];
  int k0 = 0;
  for (int k = 1; k < 3; ++k)
    if (dist2(s.P(v[(k + 1) % 3]), s.P(v[(k + 2) % 3])) <
        dist2(s.P(v[(k0 + 1) % 3]), s.P(v[(k0 + 2) % 3])))
      k0 = k;
  ShortestEdge e{s.P(v[(k0 + 1) % 3]), s.P(v[(k0 + 2) % 3]), {0, 0}, 0};
  circumcenter(s.P(v[0]), s.P(v[1]), s.P(v[2]), e.center);
  e.radius2 = dist2(e.center, e.p);
  return e;
}

// A walk on the Voronoi diagram near t: breadth first over up to kVoronoiWalk triangles of
// the domain reached from t across edges no segment lies on, through those whose circumcentre
// c passes keep(c); visit(c, r2) for each of those (r2: its circumradius squared, the
// distance from c to its nearest vertices).
template <class Keep, class Visit>
void walkVoronoi(const RefineState& s, uint32_t t, Keep keep, Visit visit) {
  const Triangulation& T = s.T;
  uint32_t ring[kVoronoiWalk];
  size_t head = 0, count = 0;
  ring[count++] = t;
  while (head < count) {
    uint32_t u = ring[head++];
    for (uint32_t e = 3 * u; e < 3 * u + 3; ++e) {
      uint32_t n = T.opp[e] / 3;
      if (T.isFixed(e) || !T.inDomain(n) || count == kVoronoiWalk) continue;
      if (std::find(ring, ring + count, n) != ring + count) continue;
      const uint32_t* w = &T.tri[3 * n];
      double c[2];
      circumcenter(s.P(w[0]), s.P(w[1]), s.P(w[2]), c);
      if (!std::isfinite(c[0]) || !std::isfinite(c[1]) || !keep(c)) continue;
      ring[count++] = n;
      visit(c, dist2(c, s.P(w[0])));
    }
  }
}

}  // namespace

void slicePoints(const RefineState& s, uint32_t t, bool wholeDisk, Candidates& out) {
  const ShortestEdge edge = shortestEdge(s, t);
  const double *p = edge.p, *q = edge.q, *center = edge.center;
  const double radius2 = edge.radius2;
  double ux = q[0] - p[0], uy = q[1] - p[1], len2 = ux * ux + uy * uy;
  auto inSlice = [&](const double* c) {
    double along = (c[0] - p[0]) * ux + (c[1] - p[1]) * uy;
    return (wholeDisk || (along > 0 && along < len2)) && dist2(c, center) < radius2;
  };
  out.assign(1, {center[0], center[1], radius2});
  walkVoronoi(s, t, inSlice, [&](const double* c, double r2) { out.push_back({c[0], c[1], r2}); });
  sortFarthestFirst(out);
}

void qualityPoints(const RefineState& s, uint32_t t, double cosBound, Candidates& out) {
  const ShortestEdge edge = shortestEdge(s, t);
  const double *p = edge.p, *q = edge.q, *center = edge.center;
  const double radius2 = edge.radius2;
  // pq's bisector, pointing to t's side (t is counter-clockwise: left of p->q).
  double ux = q[0] - p[0], uy = q[1] - p[1], len = std::sqrt(ux * ux + uy * uy);
  double mid[2] = {0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1])}, n[2] = {-uy / len, ux / len};
  // tan(bound / 2) from the cosine by IEEE-exact operations (std::tan could round differently
  // in the WebAssembly build's libm).
  double offHeight = 0.5 * len / std::sqrt((1 - cosBound) / (1 + cosBound));
  double centerHeight = (center[0] - mid[0]) * n[0] + (center[1] - mid[1]) * n[1];
  double x[2] = {center[0], center[1]};
  if (centerHeight > offHeight) x[0] = mid[0] + offHeight * n[0], x[1] = mid[1] + offHeight * n[1];
  out.assign(1, {x[0], x[1], dist2(x, p)});  // (for the off-centre: an upper bound)
  auto atLeast = [&](const double* a, const double* b, const double* c) {  // angle bac
    double bx = b[0] - a[0], by = b[1] - a[1], cx = c[0] - a[0], cy = c[1] - a[1];
    return bx * cx + by * cy <= cosBound * std::sqrt((bx * bx + by * by) * (cx * cx + cy * cy));
  };
  auto inRegion = [&](const double* c) {
    return (c[0] - mid[0]) * n[0] + (c[1] - mid[1]) * n[1] > 0 && atLeast(p, q, c) &&
           atLeast(q, c, p) && atLeast(c, p, q);
  };
  auto inDisk = [&](const double* c) { return dist2(c, center) < radius2; };
  walkVoronoi(s, t, inDisk, [&](const double* c, double r2) {
    if (inRegion(c)) out.push_back({c[0], c[1], r2});
  });
  sortFarthestFirst(out);
}

}  // namespace acutemesh::detail
