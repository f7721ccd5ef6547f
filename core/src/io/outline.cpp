// The outline of a mesh's domain (outline.h). Holes are counted first by Euler's formula, so
// that a mesh without any (most) costs one sort of its edges. With holes, the constrained
// triangulation of the mesh's vertices and boundary edges (convex hull kept) is split into
// regions by those edges; a region outside the mesh (the side of a boundary edge no mesh
// triangle is on) that does not reach the hull through an edge off the boundary is a hole,
// and the centroid of its largest triangle lies strictly inside it.
#include "outline.h"

#include <algorithm>
#include <cstdint>
#include <numeric>

#include "acutemesh/predicates.h"

namespace acutemesh::io {
namespace {

constexpr uint32_t kNoTriangle = UINT32_MAX;

uint64_t directed(uint32_t a, uint32_t b) { return uint64_t(a) << 32 | b; }
uint64_t undirected(uint32_t a, uint32_t b) { return directed(std::min(a, b), std::max(a, b)); }
bool contains(const std::vector<uint64_t>& sorted, uint64_t k) {
  return std::binary_search(sorted.begin(), sorted.end(), k);
}

struct UnionFind {
  std::vector<uint32_t> parent;
  explicit UnionFind(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  uint32_t find(uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void join(uint32_t a, uint32_t b) { parent[find(a)] = find(b); }
};

// The directed edges of m's triangles (each a->b with the triangle on its left), sorted;
// triangles with a corner out of range or repeated are left out.
std::vector<uint64_t> directedEdges(const Mesh& m) {
  const size_t n = m.vertexCount();
  std::vector<uint64_t> edges;
  edges.reserve(m.triangles.size());
  for (size_t t = 0; t < m.triangleCount(); ++t) {
    const uint32_t* v = &m.triangles[3 * t];
    if (v[0] >= n || v[1] >= n || v[2] >= n || v[0] == v[1] || v[1] == v[2] || v[0] == v[2])
      continue;
    for (int k = 0; k < 3; ++k) edges.push_back(directed(v[k], v[(k + 1) % 3]));
  }
  std::sort(edges.begin(), edges.end());
  return edges;
}

// The bounded regions outside the mesh, by Euler's formula: its components less V - E + T
// (its first Betti number, which for a set in the plane counts them).
long long holeCount(const Mesh& m, const std::vector<uint64_t>& edges, size_t boundaryEdges) {
  UnionFind parts(m.vertexCount());
  std::vector<uint8_t> used(m.vertexCount(), 0);
  for (uint64_t e : edges) {
    const uint32_t a = uint32_t(e >> 32), b = uint32_t(e);
    used[a] = used[b] = 1;
    parts.join(a, b);
  }
  long long vertices = 0, components = 0;
  for (uint32_t v = 0; v < used.size(); ++v) {
    vertices += used[v];
    components += used[v] && parts.find(v) == v;
  }
  const long long triangles = (long long)(edges.size() / 3);
  const long long allEdges = (long long)(edges.size() + boundaryEdges) / 2;
  return components - (vertices - allEdges + triangles);
}

// A point strictly inside each hole (see the top of the file); `boundary` holds a, b per
// boundary edge, `edges` is directedEdges(m).
std::vector<double> holePoints(const Mesh& m, const std::vector<uint64_t>& edges,
                               const std::vector<uint32_t>& boundary) {
  Options options;
  options.mode = Mode::Cdt;
  options.convexHull = true;
  options.threads = 1;
  Pslg outline;
  outline.points = m.points, outline.segments = boundary;
  const Result r = mesh(outline, options);
  if (r.status != Status::Ok) return {};
  const std::vector<uint32_t>& tri = r.mesh.triangles;
  const std::vector<double>& p = r.mesh.points;
  const uint32_t count = uint32_t(r.mesh.triangleCount());
  std::vector<uint64_t> fixed;
  for (size_t i = 0; i + 1 < r.mesh.segments.size(); i += 2)
    fixed.push_back(undirected(r.mesh.segments[i], r.mesh.segments[i + 1]));
  std::sort(fixed.begin(), fixed.end());

  // Regions: triangles joined across edges off the boundary. An edge of one triangle is on the
  // hull; one off the boundary opens the region to the outside.
  std::vector<std::pair<uint64_t, uint32_t>> halves;
  halves.reserve(tri.size());
  for (uint32_t t = 0; t < count; ++t)
    for (int k = 0; k < 3; ++k)
      halves.push_back({undirected(tri[3 * t + k], tri[3 * t + (k + 1) % 3]), t});
  std::sort(halves.begin(), halves.end());
  UnionFind regions(count);
  std::vector<uint8_t> open(count, 0);
  for (size_t i = 0; i < halves.size(); ++i) {
    const bool paired = i + 1 < halves.size() && halves[i + 1].first == halves[i].first;
    if (!contains(fixed, halves[i].first)) {
      if (paired)
        regions.join(halves[i].second, halves[i + 1].second);
      else
        open[halves[i].second] = 1;
    }
    i += paired;
  }
  // Which side of the mesh each region is on: that of a boundary edge on its edge.
  enum : uint8_t { kUnknown, kInMesh, kOutside };
  std::vector<uint8_t> side(count, kUnknown), reaches(count, 0);
  for (uint32_t t = 0; t < count; ++t) {
    const uint32_t root = regions.find(t);
    reaches[root] |= open[t];
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = tri[3 * t + k], b = tri[3 * t + (k + 1) % 3];
      if (side[root] != kUnknown || !contains(fixed, undirected(a, b))) continue;
      if (contains(edges, directed(a, b)))
        side[root] = kInMesh;
      else if (contains(edges, directed(b, a)))
        side[root] = kOutside;
    }
  }
  // Per hole, the largest of its triangles whose centroid is strictly inside it.
  std::vector<uint32_t> best(count, kNoTriangle);
  std::vector<double> area(count, 0), centroid(2 * size_t(count));
  for (uint32_t t = 0; t < count; ++t) {
    const uint32_t root = regions.find(t);
    if (side[root] != kOutside || reaches[root]) continue;
    const double *a = &p[2 * tri[3 * t]], *b = &p[2 * tri[3 * t + 1]], *c = &p[2 * tri[3 * t + 2]];
    const double at = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    if (best[root] != kNoTriangle && at <= area[root]) continue;
    const double x[2] = {(a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3};
    if (orientSign(a, b, x) <= 0 || orientSign(b, c, x) <= 0 || orientSign(c, a, x) <= 0) continue;
    best[root] = t, area[root] = at, centroid[2 * root] = x[0], centroid[2 * root + 1] = x[1];
  }
  std::vector<double> holes;
  for (uint32_t t = 0; t < count; ++t)
    if (best[t] != kNoTriangle) holes.insert(holes.end(), {centroid[2 * t], centroid[2 * t + 1]});
  return holes;
}

}  // namespace

Outline outlineOf(const Mesh& m) {
  Outline out;
  const std::vector<uint64_t> edges = directedEdges(m);
  std::vector<uint64_t> segments;
  for (size_t i = 0; i + 1 < m.segments.size(); i += 2)
    segments.push_back(undirected(m.segments[i], m.segments[i + 1]));
  std::sort(segments.begin(), segments.end());
  std::vector<uint32_t> boundary;
  for (uint64_t e : edges) {
    const uint32_t a = uint32_t(e >> 32), b = uint32_t(e);
    if (contains(edges, directed(b, a))) continue;
    boundary.insert(boundary.end(), {a, b});
    if (!contains(segments, undirected(a, b))) out.boundary.insert(out.boundary.end(), {a, b});
  }
  if (holeCount(m, edges, boundary.size() / 2) > 0) out.holes = holePoints(m, edges, boundary);
  return out;
}

}  // namespace acutemesh::io
