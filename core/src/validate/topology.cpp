#include "topology.h"

namespace acutemesh::validation {
namespace {

// Twins, and each directed edge at most once. Half-edges are grouped by the smaller end of
// their edge, so a twin pair lands side by side once each (small) group is sorted: a count,
// a scatter and a scan, with no search.
void findTwins(Topology& t, ErrorLog& log) {
  const uint32_t n = t.n, T = t.T;
  std::vector<uint32_t> off(n + 1, 0);
  for (uint32_t h = 0; h < 3 * T; ++h)
    if (t.good[h / 3]) ++off[std::min(t.org(h), t.dst(h)) + 1];
  for (uint32_t v = 0; v < n; ++v) off[v + 1] += off[v];
  // Entry: larger end << 32 | half-edge << 1 | whether the half-edge runs from the larger end.
  std::vector<uint64_t> edges(off[n]);
  std::vector<uint32_t> fill(off.begin(), off.end() - 1);
  for (uint32_t h = 0; h < 3 * T; ++h) {
    if (!t.good[h / 3]) continue;
    uint32_t u = t.org(h), v = t.dst(h);
    edges[fill[std::min(u, v)]++] = uint64_t(std::max(u, v)) << 32 | uint64_t(h) << 1 | (u > v);
  }
  t.twin.assign(3 * size_t(T), kNone);
  auto half = [](uint64_t e) { return uint32_t(e) >> 1; };
  for (uint32_t v = 0; v < n; ++v) {
    auto first = edges.begin() + off[v], last = edges.begin() + off[v + 1];
    std::sort(first, last);
    for (auto run = first, end = first; run != last; run = end) {
      while (end != last && *end >> 32 == *run >> 32) ++end;
      if (end - run == 2 && (run[0] & 1) != (run[1] & 1)) {
        t.twin[half(run[0])] = half(run[1]);
        t.twin[half(run[1])] = half(run[0]);
        continue;
      }
      for (auto e = run; e != end; ++e) t.boundary.push_back(half(*e));
      for (auto e = run + 1; e != end; ++e) {
        auto same = std::find_if(run, e, [&](uint64_t x) { return (x & 1) == (*e & 1); });
        if (same == e) continue;
        log.add("directed edge ", t.org(half(*e)), "->", t.dst(half(*e)), " is used twice: by ",
                t.tri(half(*same) / 3), " and ", t.tri(half(*e) / 3));
        break;
      }
    }
  }
}

}  // namespace

// Also counts, per vertex, the triangles (v, p, q) whose wedge [p - v, q - v) holds the +x
// direction: with the triangle strictly CCW, that is exactly p.y <= v.y < q.y.
Topology buildTopology(const Mesh& m, ErrorLog& log) {
  Topology t(m);
  t.good.assign(t.T, 0);
  t.cover.assign(t.n, 0);
  t.anyOut.assign(t.n, kNone);
  for (uint32_t tr = 0; tr < t.T; ++tr) {
    const uint32_t* c = t.corners(tr);
    const double *a = t.P(c[0]), *b = t.P(c[1]), *d = t.P(c[2]);
    if (!(orient2d(a, b, d) > 0)) {
      log.add(t.tri(tr), " is not counter-clockwise");
      continue;
    }
    t.good[tr] = 1;
    double y[3] = {a[1], b[1], d[1]};
    for (int k = 0; k < 3; ++k) {
      t.cover[c[k]] += y[(k + 1) % 3] <= y[k] && y[(k + 2) % 3] > y[k];
      t.anyOut[c[k]] = 3 * tr + k;
    }
  }
  findTwins(t, log);
  // Open fans start at the boundary half-edges, grouped here by origin.
  t.boundaryVertex.assign(t.n, 0);
  t.fanOff.assign(t.n + 1, 0);
  for (uint32_t h : t.boundary) {
    t.boundaryVertex[t.org(h)] = t.boundaryVertex[t.dst(h)] = 1;
    ++t.fanOff[t.org(h) + 1];
  }
  for (uint32_t v = 0; v < t.n; ++v) t.fanOff[v + 1] += t.fanOff[v];
  t.fanStart.resize(t.boundary.size());
  std::vector<uint32_t> fill(t.fanOff.begin(), t.fanOff.end() - 1);
  for (uint32_t h : t.boundary) t.fanStart[fill[t.org(h)]++] = h;
  return t;
}

void checkStars(const Topology& t, ErrorLog& log) {
  for (uint32_t v = 0; v < t.n; ++v) {
    if (t.anyOut[v] == kNone) continue;
    if (t.cover[v] > 1)
      log.add("vertex ", v, ' ', Xy{t.P(v)}, ": its triangles wrap around it ", t.cover[v],
              " times (folded or overlapping triangles)");
    else if (t.cover[v] == 0 && !t.boundaryVertex[v])
      log.add("vertex ", v, ' ', Xy{t.P(v)},
              " has no boundary edge, but its triangles do not close around it");
  }
  // Each fan at a boundary vertex starts at an outgoing boundary edge; the fan must not
  // wrap past its own start, nor may another fan cover that direction.
  for (uint32_t h : t.boundary) {
    uint32_t v = t.org(h), covering = 0;
    t.forEachOut(v, [&](uint32_t g) {
      covering += orient2d(t.P(v), t.P(t.dst(g)), t.P(t.dst(h))) >= 0 &&
                  orient2d(t.P(v), t.P(t.dst(h)), t.P(t.org(Topology::prevHe(g)))) > 0;
    });
    if (covering > 1)
      log.add("vertex ", v, ' ', Xy{t.P(v)}, ": ", covering,
              " of its triangles overlap along boundary edge ", v, "->", t.dst(h));
  }
}

}  // namespace acutemesh::validation
