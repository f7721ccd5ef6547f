// adjacency(): twins, neighbours, edges and boundary loops of an output mesh, found from its
// triangle list alone (so it serves any mesh, not only one mesh() has just made).
#include <algorithm>

#include "adjacency.h"

namespace acutemesh {

namespace {

uint32_t nextEdge(uint32_t e) { return e - e % 3 + (e % 3 + 1) % 3; }

}  // namespace

namespace detail {

namespace {

// The half-edges of each edge meet in the bucket of the edge's smaller end: a counting sort by
// that end, each entry holding the other end, so the twins are matched from the buckets alone
// (reading the triangles in order once; following each half-edge to its neighbour's corners
// instead costs a cache miss per half-edge on a large mesh).
std::vector<int32_t> findTwins(const Mesh& mesh) {
  const std::vector<uint32_t>& tri = mesh.triangles;
  const size_t halfEdges = tri.size() - tri.size() % 3, n = mesh.vertexCount();
  struct Entry {
    uint32_t other;  // the larger end; kMatched once paired
    uint32_t edge;   // the half-edge, kDown set when it runs from the larger end
  };
  constexpr uint32_t kMatched = 0xFFFFFFFFu, kDown = 0x80000000u;
  auto ends = [&](uint32_t e, uint32_t& lo, uint32_t& hi) {
    lo = tri[e], hi = tri[nextEdge(e)];
    if (lo > hi) std::swap(lo, hi);
    return lo < n && hi < n;
  };
  // start[v] .. start[v + 1]: the bucket of vertex v (filled from its end down).
  std::vector<uint32_t> start(n + 1, 0);
  uint32_t lo, hi;
  for (uint32_t e = 0; e < halfEdges; ++e)
    if (ends(e, lo, hi)) ++start[lo];
  for (size_t v = 1; v <= n; ++v) start[v] += start[v - 1];
  std::vector<Entry> bucket(n ? start[n - 1] : 0);
  if (n) start[n] = start[n - 1];
  for (uint32_t e = 0; e < halfEdges; ++e)
    if (ends(e, lo, hi)) bucket[--start[lo]] = {hi, tri[e] == lo ? e : e | kDown};
  std::vector<int32_t> twin(halfEdges, -1);
  for (size_t v = 0; v < n; ++v)
    for (uint32_t i = start[v]; i < start[v + 1]; ++i) {
      Entry& s = bucket[i];
      if (s.other == kMatched) continue;
      for (uint32_t j = i + 1; j < start[v + 1]; ++j) {
        Entry& t = bucket[j];
        if (t.other != s.other || ((s.edge ^ t.edge) & kDown) == 0) continue;
        twin[s.edge & ~kDown] = int32_t(t.edge & ~kDown);
        twin[t.edge & ~kDown] = int32_t(s.edge & ~kDown);
        s.other = t.other = kMatched;
        break;
      }
    }
  return twin;
}

// Per segment edge (u, w) a half-edge on it: around u's star by the twins (one half-edge
// leaving each vertex noted first), both ways where the star is open at the boundary.
std::vector<int32_t> findSegmentEdges(const Mesh& mesh, const std::vector<int32_t>& twin) {
  const std::vector<uint32_t>& tri = mesh.triangles;
  const size_t n = mesh.vertexCount();
  std::vector<int32_t> found(mesh.segments.size() / 2, -1);
  if (found.empty()) return found;
  std::vector<int32_t> leaving(n, -1);
  for (uint32_t e = 0; e < twin.size(); ++e)
    if (tri[e] < n) leaving[tri[e]] = int32_t(e);
  const auto prev = [](uint32_t e) { return nextEdge(nextEdge(e)); };
  for (size_t s = 0; s < found.size(); ++s) {
    const uint32_t u = mesh.segments[2 * s], w = mesh.segments[2 * s + 1];
    if (u >= n || w >= n || leaving[u] < 0) continue;
    // e leaves u: it is on the edge u-w, or its triangle's edge into u is.
    auto on = [&](uint32_t e) {
      if (tri[nextEdge(e)] == w) return int32_t(e);
      if (tri[prev(e)] == w) return int32_t(prev(e));
      return int32_t(-1);
    };
    const uint32_t first = uint32_t(leaving[u]);
    int32_t hit = on(first);
    // (Twins that are not a mesh's could circle without coming back: steps are capped.)
    size_t steps = 0;
    for (int32_t e = twin[prev(first)]; hit < 0 && e >= 0 && uint32_t(e) != first &&
                                        ++steps < twin.size();
         e = twin[prev(uint32_t(e))])
      hit = on(uint32_t(e));
    for (int32_t t = twin[first]; hit < 0 && t >= 0 && nextEdge(uint32_t(t)) != first &&
                                  ++steps < twin.size();
         t = twin[nextEdge(uint32_t(t))])
      hit = on(nextEdge(uint32_t(t)));
    found[s] = hit;
  }
  return found;
}

}  // namespace

HalfEdges halfEdges(const Mesh& mesh, std::vector<int32_t> twin) {
  HalfEdges h;
  h.twin = twin.size() == mesh.triangles.size() - mesh.triangles.size() % 3 ? std::move(twin)
                                                                            : findTwins(mesh);
  h.segmentEdge = findSegmentEdges(mesh, h.twin);
  return h;
}

Adjacency adjacency(const Mesh& mesh, HalfEdges&& h) {
  Adjacency a;
  const std::vector<uint32_t>& tri = mesh.triangles;
  const size_t halfEdges = tri.size() - tri.size() % 3;
  a.halfedges = std::move(h.twin);

  a.neighbors.resize(halfEdges);
  for (uint32_t e = 0; e < halfEdges; ++e) {
    const int32_t twin = a.halfedges[nextEdge(e)];  // the edge opposite corner e % 3
    a.neighbors[e] = twin < 0 ? -1 : twin / 3;
  }

  // Each undirected edge once, from its smaller end; its marker from the segment on it.
  std::vector<int32_t> markerOf(halfEdges, 0);
  const bool marked = mesh.segmentMarkers.size() * 2 == mesh.segments.size();
  for (size_t s = 0; s < h.segmentEdge.size(); ++s) {
    const int32_t e = h.segmentEdge[s];
    if (e < 0) continue;
    const int32_t m = marked ? mesh.segmentMarkers[s] : 0;
    markerOf[size_t(e)] = m;
    if (a.halfedges[size_t(e)] >= 0) markerOf[size_t(a.halfedges[size_t(e)])] = m;
  }
  std::vector<std::pair<uint64_t, int32_t>> edges;
  edges.reserve(halfEdges / 2 + 1);
  for (uint32_t e = 0; e < halfEdges; ++e) {
    const int32_t twin = a.halfedges[e];
    if (twin >= 0 && uint32_t(twin) < e) continue;
    const uint32_t u = std::min(tri[e], tri[nextEdge(e)]), w = std::max(tri[e], tri[nextEdge(e)]);
    const int32_t m = markerOf[e] == 0 && twin < 0 ? 1 : markerOf[e];
    edges.push_back({uint64_t(u) << 32 | w, m});
  }
  std::sort(edges.begin(), edges.end());
  a.edges.reserve(2 * edges.size());
  a.edgeMarkers.reserve(edges.size());
  for (const auto& [key, m] : edges) {
    a.edges.push_back(uint32_t(key >> 32));
    a.edges.push_back(uint32_t(key));
    a.edgeMarkers.push_back(m);
  }

  // Boundary loops: from a boundary half-edge u->v, the next one leaves v in the fan of
  // triangles around v that e's triangle belongs to (so a vertex where two loops touch
  // keeps them apart).
  std::vector<uint8_t> done(halfEdges, 0);
  for (uint32_t first = 0; first < halfEdges; ++first) {
    if (a.halfedges[first] >= 0 || done[first]) continue;
    a.hullStarts.push_back(uint32_t(a.hull.size()));
    uint32_t e = first;
    while (!done[e]) {
      done[e] = 1;
      a.hull.push_back(tri[e]);
      uint32_t f = nextEdge(e);
      for (size_t turns = 0; a.halfedges[f] >= 0 && turns < halfEdges; ++turns)
        f = nextEdge(uint32_t(a.halfedges[f]));
      if (a.halfedges[f] >= 0) break;  // (a fan that closes: not a valid mesh)
      e = f;
    }
  }
  a.hullStarts.push_back(uint32_t(a.hull.size()));
  return a;
}

}  // namespace detail

Adjacency adjacency(const Mesh& mesh) { return detail::adjacency(mesh, detail::halfEdges(mesh)); }

}  // namespace acutemesh
