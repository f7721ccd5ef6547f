#include "domain.h"

#include <algorithm>
#include <cmath>

#include "../rounding.h"

namespace acutemesh::validation {
namespace {

using detail::nearLine;
using detail::nearSegment;

// Vertices on the boundary of the convex hull of the distinct points, counter-clockwise,
// including those in the middle of a hull edge. Among equal points the used one is taken.
std::vector<uint32_t> convexHull(const std::vector<double>& xy, const std::vector<uint8_t>& used) {
  struct Point {
    double xy[2];
    bool unused;
    uint32_t v;
    bool operator<(const Point& o) const {
      if (xy[0] != o.xy[0]) return xy[0] < o.xy[0];
      if (xy[1] != o.xy[1]) return xy[1] < o.xy[1];
      return unused != o.unused ? o.unused : v < o.v;  // the used copy of a point first
    }
  };
  size_t n = xy.size() / 2;
  if (n == 0) return {};
  // Akl-Toussaint: drop the points strictly left of every edge of a closed polygon of input
  // points (the extremes in 8 directions, counter-clockwise). Such a point has positive
  // winding number, so it lies strictly inside the hull, whatever the rounding of the scores
  // that picked the polygon.
  auto at = [&](uint32_t v) { return &xy[2 * size_t(v)]; };
  const double dir[8][2] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};
  uint32_t ext[8] = {};
  for (uint32_t v = 1; v < n; ++v)
    for (int k = 0; k < 8; ++k)
      if (dir[k][0] * at(v)[0] + dir[k][1] * at(v)[1] >
          dir[k][0] * at(ext[k])[0] + dir[k][1] * at(ext[k])[1])
        ext[k] = v;
  std::vector<uint32_t> poly;
  for (uint32_t v : ext)
    if (poly.empty() || (v != poly.back() && v != poly.front())) poly.push_back(v);
  std::vector<Point> pts;
  for (uint32_t v = 0; v < n; ++v) {
    bool inside = poly.size() >= 3;
    for (size_t k = 0; k < poly.size() && inside; ++k)
      inside = orient2d(at(poly[k]), at(poly[(k + 1) % poly.size()]), at(v)) > 0;
    if (!inside) pts.push_back({{at(v)[0], at(v)[1]}, !used[v], v});
  }
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end(),
                        [](const Point& a, const Point& b) {
                          return a.xy[0] == b.xy[0] && a.xy[1] == b.xy[1];
                        }),
            pts.end());
  std::vector<uint32_t> hull;
  if (pts.size() < 3) {
    for (const Point& p : pts) hull.push_back(p.v);
    return hull;
  }
  // Monotone chain that pops only on a right turn, so collinear boundary points stay.
  std::vector<const Point*> chainPts;
  auto chain = [&](auto first, auto last) {
    size_t base = chainPts.size();
    for (auto it = first; it != last; ++it) {
      while (chainPts.size() >= base + 2 &&
             orient2d(chainPts[chainPts.size() - 2]->xy, chainPts.back()->xy, it->xy) < 0)
        chainPts.pop_back();
      chainPts.push_back(&*it);
    }
    chainPts.pop_back();
  };
  chain(pts.begin(), pts.end());
  chain(pts.rbegin(), pts.rend());
  for (const Point* p : chainPts) hull.push_back(p->v);
  return hull;
}

// A hole point (Triangle fill) found in or on triangle t, with orientations o against its
// edges: inside is an error, and so is on an unconstrained edge between two triangles.
void checkHole(const Topology& topo, const SegmentEdges& edges, ErrorLog& log, uint32_t t,
               const Query& q, const double o[3]) {
  int zeros = (o[0] == 0) + (o[1] == 0) + (o[2] == 0);
  // A hole point on a segment may end up a rounding inside a triangle beside the chain of
  // split points that stands for the segment (tests/data/bad/hole-on-a-split-segment.poly):
  // then which side it eats is a rounding's choice.
  bool besideChain = false;
  for (uint32_t h = 3 * t; h < 3 * t + 3 && zeros == 0; ++h)
    besideChain |=
        edges.marked[topo.canon(h)] && nearSegment(topo.P(topo.org(h)), topo.P(topo.dst(h)), q.xy);
  if (zeros == 0 && !besideChain) {
    log.add("hole ", q.id, ' ', Xy{q.xy}, " lies inside ", topo.tri(t));
  } else if (zeros == 1) {
    uint32_t h = 3 * t + (o[0] == 0 ? 0 : o[1] == 0 ? 1 : 2);
    if (topo.twin[h] != kNone && !edges.marked[topo.canon(h)] && t < topo.twin[h] / 3)
      log.add("hole ", q.id, ' ', Xy{q.xy}, " lies on edge ", topo.org(h), "-", topo.dst(h),
              " between ", topo.tri(t), " and ", topo.tri(topo.twin[h] / 3),
              ", inside the meshed domain");
  }
}

}  // namespace

void checkBoundaryEdges(const Check& c, const Topology& topo, const VertexMap& vertices,
                        const SegmentEdges& edges) {
  const uint32_t nIn = c.nIn;
  auto P = [&](uint32_t v) { return topo.P(v); };
  bool hullOk = c.hullDomain();
  bool segmentOk = c.segmentsKept();
  std::vector<uint32_t> hull, hullNext;
  if (hullOk) {
    // The hull of the input vertices only: refinement splits hull edges at rounded points,
    // and one rounded outward would push an input vertex of a nearly straight hull stretch
    // off the hull (tests/data/bad/one-ulp-apart.node, nonobtuse).
    std::vector<uint8_t> usedInput(vertices.used.begin(), vertices.used.begin() + nIn);
    std::vector<double> inputPoints(topo.m.points.begin(), topo.m.points.begin() + 2 * size_t(nIn));
    hull = convexHull(inputPoints, usedInput);
    hullNext.assign(topo.n, kNone);
    for (size_t i = 0; i < hull.size(); ++i) hullNext[hull[i]] = hull[(i + 1) % hull.size()];
  }
  // A boundary edge with a Steiner end lies along an input hull edge A->B: each end is A, B
  // or a Steiner point within rounding reach of the line, inside the edge's extent.
  auto alongHullEdge = [&](uint32_t u, uint32_t v) {
    for (size_t i = 0; i < hull.size(); ++i) {
      uint32_t a = hull[i], b = hull[(i + 1) % hull.size()];
      auto fits = [&](uint32_t x) {
        return x == a || x == b ||
               (x >= nIn && nearLine(P(a), P(b), P(x)) && dot2d(P(x), P(a), P(b)) < 0);
      };
      if (fits(u) && fits(v)) return true;
    }
    return false;
  };
  for (uint32_t h : topo.boundary) {
    uint32_t u = topo.org(h), v = topo.dst(h);
    if (segmentOk && edges.marked[h]) continue;
    if (hullOk && hullNext[u] == v) continue;
    if (hullOk && (u >= nIn || v >= nIn) && alongHullEdge(u, v)) continue;
    c.log.add("boundary edge ", u, "->", v, " of ", topo.tri(h / 3),
              !hullOk     ? " does not lie on an input segment"
              : segmentOk ? " lies neither on an input segment nor on the convex hull"
                          : " is not a convex hull edge");
  }
}

QueryGrid pointsToLocate(const Check& c, const Topology& topo, const VertexMap& vertices) {
  std::vector<Query> q;
  for (uint32_t v = 0; v < topo.n; ++v)
    if (!vertices.used[v] && vertices.twinOfUnused[v] == kNone)
      q.push_back({Query::Unused, v, {topo.P(v)[0], topo.P(v)[1]}});
  if (c.opt.mode != Mode::Delaunay && c.opt.fill == FillRule::Triangle)
    for (uint32_t i = 0; i < c.in.holes.size() / 2; ++i) {
      const double* h = &c.in.holes[2 * size_t(i)];
      if (std::isfinite(h[0]) && std::isfinite(h[1]))
        q.push_back({Query::Hole, i, {h[0], h[1]}});
      else
        c.log.add("hole ", i, ' ', Xy{h}, " is not finite");
    }
  return QueryGrid(std::move(q));
}

// Boundary vertices are not located: a domain's long thin triangles would make that
// O(T sqrt(n)), and overlaps show up as folded stars, reused directed edges, coincident
// vertices or stray boundary edges.
void locatePoints(const Check& c, const Topology& topo, const SegmentEdges& edges,
                  const QueryGrid& points) {
  if (points.queries().empty()) return;
  for (uint32_t t = 0; t < topo.T; ++t) {
    if (!topo.good[t]) continue;
    const uint32_t* v = topo.corners(t);
    const double* pts[3] = {topo.P(v[0]), topo.P(v[1]), topo.P(v[2])};
    points.forEachNear(pts, 3, [&](const Query& q) {
      double o[3];
      for (int k = 0; k < 3; ++k)
        if ((o[k] = orient2d(pts[k], pts[(k + 1) % 3], q.xy)) < 0) return;
      switch (q.kind) {
        case Query::Unused:
          c.log.add("vertex ", q.id, ' ', Xy{q.xy}, " is used by no triangle but lies in ",
                    topo.tri(t));
          break;
        case Query::Boundary:
          break;
        case Query::Hole:
          checkHole(topo, edges, c.log, t, q, o);
          break;
      }
    });
  }
}

}  // namespace acutemesh::validation
