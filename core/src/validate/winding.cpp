#include "winding.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>

#include "coord_table.h"

namespace acutemesh::validation {
namespace {

// Winding numbers of points about the input segments (directed a->b): crossings of the +x ray,
// decided by exact orientation with the half-open rule (a segment counts when
// min y <= py < max y), found by a sweep in y over the segments spanning each point's y.
std::vector<int64_t> windingNumbers(const Pslg& in, const std::vector<std::array<double, 2>>& pts) {
  auto P = [&](uint32_t v) { return &in.points[2 * size_t(v)]; };
  std::vector<uint32_t> segs, byY(pts.size());
  for (uint32_t s = 0; s < in.segmentCount(); ++s)
    if (P(in.segments[2 * s])[1] != P(in.segments[2 * s + 1])[1]) segs.push_back(s);
  auto ymin = [&](uint32_t s) {
    return std::min(P(in.segments[2 * s])[1], P(in.segments[2 * s + 1])[1]);
  };
  auto ymax = [&](uint32_t s) {
    return std::max(P(in.segments[2 * s])[1], P(in.segments[2 * s + 1])[1]);
  };
  std::sort(segs.begin(), segs.end(), [&](uint32_t a, uint32_t b) { return ymin(a) < ymin(b); });
  for (uint32_t i = 0; i < pts.size(); ++i) byY[i] = i;
  std::sort(byY.begin(), byY.end(), [&](uint32_t a, uint32_t b) { return pts[a][1] < pts[b][1]; });

  std::vector<int64_t> winding(pts.size(), 0);
  std::vector<uint32_t> active;
  size_t next = 0;
  for (uint32_t i : byY) {
    const double* p = pts[i].data();
    while (next < segs.size() && ymin(segs[next]) <= p[1]) active.push_back(segs[next++]);
    size_t kept = 0;
    for (uint32_t s : active) {
      if (ymax(s) <= p[1]) continue;
      active[kept++] = s;
      const double *a = P(in.segments[2 * s]), *b = P(in.segments[2 * s + 1]);
      double o = orient2d(a, b, p);
      if (a[1] < b[1] && o > 0) ++winding[i];
      if (a[1] > b[1] && o < 0) --winding[i];
    }
    active.resize(kept);
  }
  return winding;
}

// The winding number inside triangle (v, c1, c2) where no double lies strictly inside it (a
// sliver an ulp high): at v + e (c1 - v) + e^2 (c2 - v) for an infinitesimal e > 0, a point
// strictly inside. Every test on it is decided by exact tests on v, c1 and c2 in turn (the
// first that is not zero), so no coordinate of it is ever formed.
int64_t windingNumberInside(const Pslg& in, const double* v, const double* c1, const double* c2) {
  auto P = [&](uint32_t i) { return &in.points[2 * size_t(i)]; };
  auto sign = [](double x) { return (x > 0) - (x < 0); };
  auto aboveY = [&](double y) {  // sign of p.y - y
    if (int s = sign(v[1] - y)) return s;
    if (int s = sign(c1[1] - v[1])) return s;
    return sign(c2[1] - v[1]);
  };
  auto orient = [&](const double* a, const double* b) {  // sign of orient2d(a, b, p)
    if (int s = sign(orient2d(a, b, v))) return s;
    if (int s = sign(orient2d(a, b, c1))) return s;
    return sign(orient2d(a, b, c2));
  };
  int64_t winding = 0;
  for (uint32_t s = 0; s < in.segmentCount(); ++s) {
    const double *a = P(in.segments[2 * s]), *b = P(in.segments[2 * s + 1]);
    if (a[1] < b[1] && aboveY(a[1]) >= 0 && aboveY(b[1]) < 0 && orient(a, b) > 0) ++winding;
    if (a[1] > b[1] && aboveY(b[1]) >= 0 && aboveY(a[1]) < 0 && orient(a, b) < 0) --winding;
  }
  return winding;
}

// Winding numbers are defined (independent of the ray) only when the segments form closed
// cycles: every point is the tail of as many segments as it is the head of. For EvenOdd
// only parity matters, and an even number of segment ends at every point suffices.
bool windingIsDefined(const Check& c) {
  CoordTable table(c.in.points.data(), c.nIn);
  std::vector<int64_t> balance(c.nIn, 0);
  bool parity = c.opt.fill == FillRule::EvenOdd;
  for (uint32_t s = 0; s < c.in.segmentCount(); ++s) {
    uint32_t a = table.insert(c.in.segments[2 * s]), b = table.insert(c.in.segments[2 * s + 1]);
    if (a != b) ++balance[a], balance[b] += parity ? 1 : -1;
  }
  return std::all_of(balance.begin(), balance.end(),
                     [&](int64_t x) { return parity ? x % 2 == 0 : x == 0; });
}

// Labels the connected pieces of the mesh with winding numbers relative to one triangle of
// each, then fixes each piece's offset with a point inside it, and checks every triangle.
class FillRuleCheck {
 public:
  FillRuleCheck(const Check& c, const Topology& topo, const SegmentEdges& edges)
      : c_(c),
        topo_(topo),
        edges_(edges),
        parity_(c.opt.fill == FillRule::EvenOdd),
        comp_(topo.T, kNone),
        rel_(topo.T, 0) {}

  void run() {
    order_.reserve(topo_.T);
    for (uint32_t root = 0; root < topo_.T; ++root)
      if (topo_.good[root] && comp_[root] == kNone) labelComponent(root);
    std::vector<int64_t> seedWinding = windingNumbers(c_.in, seeds_);
    for (size_t i = 0; i < seeds_.size(); ++i) offset_[seeded_[i]] += seedWinding[i];
    const char* rule = parity_ ? "EvenOdd" : "NonZero";
    for (uint32_t t = 0; t < topo_.T; ++t) {
      if (!topo_.good[t]) continue;
      int64_t w = rel_[t] + offset_[comp_[t]];
      if (!keeps(w))
        c_.log.add(topo_.tri(t), " lies where the winding number is ", w, ", which ", rule,
                   " leaves out");
      for (uint32_t h = 3 * t; h < 3 * t + 3; ++h)
        if (topo_.twin[h] == kNone && keeps(w - along(h)))
          c_.log.add("boundary edge ", topo_.org(h), "->", topo_.dst(h), " of ", topo_.tri(t),
                     ": the region beyond it has winding number ", w - along(h), ", which ", rule,
                     " keeps, but it is not meshed");
    }
  }

 private:
  // Under EvenOdd only the parity is defined: going round a vertex the integer count may come
  // back changed by an even number (tests/fuzz/corpus/fuzz_mesh/evenodd-unbalanced-duplicates).
  bool keeps(int64_t w) const { return parity_ ? (w & 1) != 0 : w != 0; }
  bool disagree(int64_t a, int64_t b) const { return parity_ ? ((a - b) & 1) != 0 : a != b; }
  // Input segments along h minus those against it.
  int64_t along(uint32_t h) const {
    uint32_t e = topo_.canon(h);
    return e == h ? edges_.segCount[h] : -edges_.segCount[e];
  }

  // Winding numbers relative to root across the piece of mesh around it (order_[first..]),
  // and the offset that makes them absolute (or the point inside that will fix it).
  void labelComponent(uint32_t root) {
    uint32_t c = uint32_t(offset_.size());
    size_t first = order_.size();
    comp_[root] = c;
    order_.push_back(root);
    for (size_t i = first; i < order_.size(); ++i) {
      uint32_t t = order_[i];
      for (uint32_t h = 3 * t; h < 3 * t + 3; ++h) {
        if (topo_.twin[h] == kNone) continue;
        uint32_t u = topo_.twin[h] / 3;
        int64_t w = rel_[t] - along(h);  // t is left of h, u right of it
        if (comp_[u] == kNone) {
          comp_[u] = c, rel_[u] = w;
          order_.push_back(u);
        } else if (disagree(rel_[u], w) && t < u) {
          c_.log.add("winding numbers disagree across edge ", topo_.org(h), "-", topo_.dst(h),
                     " between ", topo_.tri(t), " and ", topo_.tri(u),
                     ": an input segment crosses the mesh");
        }
      }
    }
    std::array<double, 2> inside;
    uint32_t seed = kNone;
    if (interiorPoint(first, seed, inside)) {
      offset_.push_back(-rel_[seed]);
      seeds_.push_back(inside);
      seeded_.push_back(c);
    } else {
      offset_.push_back(offsetWithoutInteriorPoint(first, seed));
    }
  }

  // No double lies inside this piece: it is all within an ulp of its edges, so of the input
  // segments its chains stand for, and its winding number is defined only up to which side of
  // them the rounding put it. One off from the exact one is taken if that one is consistent
  // (tests/data/bad/parallel-chains-leftover-edge.poly under EvenOdd).
  int64_t offsetWithoutInteriorPoint(size_t first, uint32_t seed) const {
    const uint32_t* v = topo_.corners(seed);
    int64_t offset =
        -rel_[seed] + windingNumberInside(c_.in, topo_.P(v[0]), topo_.P(v[1]), topo_.P(v[2]));
    auto consistent = [&](int64_t o) {
      for (size_t i = first; i < order_.size(); ++i) {
        int64_t w = rel_[order_[i]] + o;
        if (!keeps(w)) return false;
        for (uint32_t h = 3 * order_[i]; h < 3 * order_[i] + 3; ++h)
          if (topo_.twin[h] == kNone && keeps(w - along(h))) return false;
      }
      return true;
    };
    for (int64_t d : {1, -1})
      if (!consistent(offset) && consistent(offset + d)) offset += d;
    return offset;
  }

  std::array<double, 2> centroid(uint32_t t) const {
    const uint32_t* c = topo_.corners(t);
    std::array<double, 2> g;
    for (int k = 0; k < 2; ++k) g[k] = (topo_.P(c[0])[k] + topo_.P(c[1])[k] + topo_.P(c[2])[k]) / 3;
    return g;
  }

  // A point an exact test confirms to lie strictly inside a triangle of the piece
  // order_[first..]: a rounded centroid, which in a needle may round onto or past an edge, or
  // else a double a few ulps from it (tests/data/bad/overlap-twenty-ulps-off.poly under
  // EvenOdd). False if there is none (every triangle an ulp high).
  bool interiorPoint(size_t first, uint32_t& seed, std::array<double, 2>& inside) const {
    auto strictlyIn = [&](const uint32_t* c, const double* g) {
      return orient2d(topo_.P(c[0]), topo_.P(c[1]), g) > 0 &&
             orient2d(topo_.P(c[1]), topo_.P(c[2]), g) > 0 &&
             orient2d(topo_.P(c[2]), topo_.P(c[0]), g) > 0;
    };
    for (int reach = 0; reach <= 4; reach += 4)
      for (size_t i = first; i < order_.size(); ++i) {
        const uint32_t* c = topo_.corners(order_[i]);
        std::array<double, 2> g = centroid(order_[i]);
        for (int dx = -reach; dx <= reach; ++dx)
          for (int dy = -reach; dy <= reach; ++dy) {
            double q[2] = {g[0], g[1]};
            for (int k = 0; k < std::abs(dx); ++k) q[0] = std::nextafter(q[0], dx * INFINITY);
            for (int k = 0; k < std::abs(dy); ++k) q[1] = std::nextafter(q[1], dy * INFINITY);
            if (strictlyIn(c, q)) {
              seed = order_[i];
              inside = {q[0], q[1]};
              return true;
            }
          }
      }
    seed = order_[first];
    return false;
  }

  const Check& c_;
  const Topology& topo_;
  const SegmentEdges& edges_;
  const bool parity_;
  std::vector<uint32_t> comp_;   // per triangle: its piece of mesh, or kNone (not good)
  std::vector<int64_t> rel_;     // per triangle: winding number relative to its piece's root
  std::vector<uint32_t> order_;  // triangles, piece by piece
  std::vector<int64_t> offset_;  // per piece: root's winding number
  std::vector<std::array<double, 2>> seeds_;  // a point inside each piece that has one
  std::vector<uint32_t> seeded_;              // and which piece it is in
};

}  // namespace

void checkFillRule(const Check& c, const Topology& topo, const SegmentEdges& edges) {
  bool rule = c.opt.mode != Mode::Delaunay && c.opt.fill != FillRule::Triangle;
  if (rule && windingIsDefined(c)) FillRuleCheck(c, topo, edges).run();
}

}  // namespace acutemesh::validation
