#include "domain_angles.h"

#include <cmath>

namespace acutemesh::detail {
namespace {

// The angle at T.tri[e] of triangle e / 3 (radians).
double cornerAngle(const Triangulation& T, uint32_t e) {
  const double *a = T.point(T.tri[e]), *b = T.point(T.tri[next(e)]), *c = T.point(T.tri[prev(e)]);
  const double ux = b[0] - a[0], uy = b[1] - a[1], vx = c[0] - a[0], vy = c[1] - a[1];
  return std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy);
}

}  // namespace

double smallestDomainAngle(const Triangulation& T) {
  double smallest = 2 * M_PI;
  std::vector<uint32_t> spokes;  // the half-edges leaving a vertex, counter-clockwise
  for (uint32_t v = 0; v < T.vertexCount(); ++v) {
    const uint32_t e0 = T.vertexEdge[v];
    if (e0 == kNone) continue;
    spokes.clear();
    uint32_t e = e0;
    do {
      spokes.push_back(e);
      e = T.opp[prev(e)];
    } while (e != e0 && spokes.size() <= T.triangleSlots());
    auto in = [&](uint32_t s) { return T.inDomain(s / 3); };
    // Spoke s is a wall between triangle s / 3 and the one before it (clockwise), opp[s] / 3.
    auto wall = [&](uint32_t s) { return T.isFixed(s) || in(s) != in(T.opp[s]); };
    const size_t n = spokes.size();
    size_t first = n;
    for (size_t i = 0; i < n && first == n; ++i)
      if (wall(spokes[i])) first = i;
    if (first == n) continue;
    double sector = 0;
    size_t walls = 0;
    for (size_t k = 0; k < n; ++k) {
      const uint32_t s = spokes[(first + k) % n];
      if (k > 0 && wall(s)) {
        if (sector > 0) smallest = std::min(smallest, sector);
        sector = 0;
        ++walls;
      }
      if (in(s)) sector += cornerAngle(T, s);
    }
    if (walls > 0 && sector > 0) smallest = std::min(smallest, sector);
  }
  return smallest * (180 / M_PI);
}

}  // namespace acutemesh::detail
