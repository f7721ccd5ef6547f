#include "domain_angles.h"

#include "build.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace acutemesh::detail {
namespace {

// The angle swept counter-clockwise from spoke e to spoke f of one vertex (radians, in
// (0, 2 pi)): a sector of the domain is one turn between two walls, whatever its triangles.
double sweep(const Triangulation& T, uint32_t e, uint32_t f) {
  const double *v = T.point(T.tri[e]), *a = T.point(T.tri[next(e)]), *b = T.point(T.tri[next(f)]);
  const double ux = a[0] - v[0], uy = a[1] - v[1], wx = b[0] - v[0], wy = b[1] - v[1];
  const double angle = std::atan2(ux * wy - uy * wx, ux * wx + uy * wy);
  return angle > 0 ? angle : angle + 2 * M_PI;
}

// Calls visit(v, radians) for every corner of the domain at every vertex v: each turn from a
// wall (a fixed edge, or an edge between the domain and the rest) to the next wall
// counter-clockwise, over triangles of the domain. (Between two walls the triangles are all
// in the domain or all out of it; ghost spokes are never walls.)
template <class Visit>
void forEachCorner(const Triangulation& T, Visit visit) {
  std::vector<uint32_t> walls;  // the wall spokes leaving a vertex, counter-clockwise
  auto in = [&](uint32_t s) { return T.inDomain(s / 3); };
  // Spoke s is a wall between triangle s / 3 and the one before it (clockwise), opp[s] / 3.
  auto wall = [&](uint32_t s) { return T.isFixed(s) || in(s) != in(T.opp[s]); };
  for (uint32_t v = 0; v < T.vertexCount(); ++v) {
    const uint32_t e0 = T.vertexEdge[v];
    if (e0 == kNone) continue;
    walls.clear();
    uint32_t e = e0, steps = 0;
    do {
      if (wall(e)) walls.push_back(e);
      e = T.opp[prev(e)];
    } while (e != e0 && ++steps <= T.triangleSlots());
    if (walls.size() < 2) continue;
    for (size_t k = 0; k < walls.size(); ++k)
      if (in(walls[k])) visit(v, sweep(T, walls[k], walls[(k + 1) % walls.size()]));
  }
}

}  // namespace

double smallestDomainAngle(const Triangulation& T) {
  double smallest = 2 * M_PI;
  forEachCorner(T, [&](uint32_t, double a) { smallest = std::min(smallest, a); });
  return smallest * (180 / M_PI);
}

std::vector<DomainCorner> domainCornersBelow(const Triangulation& T, double degrees) {
  std::vector<DomainCorner> corners;
  forEachCorner(T, [&](uint32_t v, double a) {
    a *= 180 / M_PI;
    if (a > degrees) return;
    if (!corners.empty() && corners.back().vertex == v)
      corners.back().degrees = std::min(corners.back().degrees, a);
    else
      corners.push_back({v, a});
  });
  std::sort(corners.begin(), corners.end(), [](const DomainCorner& a, const DomainCorner& b) {
    return a.degrees != b.degrees ? a.degrees < b.degrees : a.vertex < b.vertex;
  });
  return corners;
}

NamedCorners::NamedCorners(const Triangulation& T, const std::vector<uint32_t>& inputOf,
                           int exponent, const Pslg& input,
                           const std::vector<std::pair<uint32_t, uint32_t>>& slivers)
    : exponent_(exponent) {
  for (const DomainCorner& c : domainCornersBelow(T, kNamedCorner)) {
    const double* p = T.point(c.vertex);
    corners_.push_back({c.vertex < inputOf.size() ? inputOf[c.vertex] : kNone, reported(p[0]),
                        reported(p[1]), c.degrees});
  }
  for (auto [v, s] : slivers) {
    const double* p = T.point(v);
    slivers_.push_back(
        {inputOf[v], s, reported(p[0]), reported(p[1]), reported(offSegment(input, s, p))});
  }
}

std::string NamedCorners::name(const Sliver& s) const {
  char off[32];
  std::snprintf(off, sizeof off, "%.2g", s.off);
  return "input vertex " + std::to_string(s.input) + " (" + shortestText(s.x) + ", " +
         shortestText(s.y) + "), " + off + " off input segment " + std::to_string(s.segment) +
         " (a sliver too thin to refine: move the vertex onto the segment or away from it)";
}

std::string NamedCorners::name(const Named& c) const {
  const std::string at = "(" + shortestText(c.x) + ", " + shortestText(c.y) + ")";
  return (c.input == kNone ? "a segment crossing at " + at
                           : "input vertex " + std::to_string(c.input) + " " + at) +
         ", " + degreesText(c.degrees);
}

std::string NamedCorners::below(double degrees, size_t most) const {
  size_t count = 0;
  std::string text;
  for (const Named& c : corners_) {
    if (c.degrees > degrees) break;
    if (count++ < most) text += (text.empty() ? "" : "; ") + name(c);
  }
  if (count > most) text += " (" + std::to_string(count) + " in all)";
  return text;
}

std::string NamedCorners::nearest(const std::vector<double>& xy) const {
  // Corners numbered first, then slivers (k >= corners_.size()).
  std::vector<size_t> named;
  const size_t count = corners_.size() + slivers_.size();
  for (size_t i = 0; i + 1 < xy.size() && count > 0; i += 2) {
    size_t best = 0;
    double closest = INFINITY;
    for (size_t k = 0; k < count; ++k) {
      const bool corner = k < corners_.size();
      const double x = corner ? corners_[k].x : slivers_[k - corners_.size()].x;
      const double y = corner ? corners_[k].y : slivers_[k - corners_.size()].y;
      const double dx = x - xy[i], dy = y - xy[i + 1];
      if (dx * dx + dy * dy < closest) closest = dx * dx + dy * dy, best = k;
    }
    if (std::find(named.begin(), named.end(), best) == named.end()) named.push_back(best);
  }
  std::string text;
  for (size_t k : named)
    text += (text.empty() ? "" : "; ") +
            (k < corners_.size() ? name(corners_[k]) : name(slivers_[k - corners_.size()]));
  return text;
}

}  // namespace acutemesh::detail
