// adjacency(): twins, neighbours, edges and boundary loops of an output mesh, found from its
// triangle list alone (so it serves any mesh, not only one mesh() has just made).
#include <algorithm>

#include "adjacency.h"

namespace acutemesh {

namespace {

// The half-edges leaving each vertex, grouped by vertex (counting sort): those of vertex v are
// order[start[v] .. start[v + 1]).
struct Outgoing {
  std::vector<uint32_t> start, order;
  Outgoing(const std::vector<uint32_t>& tri, size_t vertices) : start(vertices + 1, 0) {
    for (uint32_t v : tri) ++start[v + 1];
    for (size_t v = 0; v < vertices; ++v) start[v + 1] += start[v];
    order.resize(tri.size());
    std::vector<uint32_t> fill(start.begin(), start.end() - 1);
    for (uint32_t e = 0; e < tri.size(); ++e) order[fill[tri[e]]++] = e;
  }
  // A half-edge from a to b, or -1.
  int64_t find(const std::vector<uint32_t>& tri, uint32_t a, uint32_t b) const {
    for (uint32_t i = start[a]; i < start[a + 1]; ++i) {
      const uint32_t e = order[i];
      if (tri[e - e % 3 + (e % 3 + 1) % 3] == b) return e;
    }
    return -1;
  }
};

uint32_t nextEdge(uint32_t e) { return e - e % 3 + (e % 3 + 1) % 3; }

}  // namespace

namespace detail {

HalfEdges halfEdges(const Mesh& mesh) {
  HalfEdges h;
  const std::vector<uint32_t>& tri = mesh.triangles;
  const size_t halfEdges = tri.size() - tri.size() % 3;
  const Outgoing out(tri, mesh.vertexCount());
  h.twin.assign(halfEdges, -1);
  for (uint32_t e = 0; e < halfEdges; ++e) {
    if (h.twin[e] != -1) continue;
    const int64_t twin = out.find(tri, tri[nextEdge(e)], tri[e]);
    if (twin >= 0 && h.twin[size_t(twin)] == -1) {
      h.twin[e] = int32_t(twin);
      h.twin[size_t(twin)] = int32_t(e);
    }
  }
  h.segmentEdge.assign(mesh.segments.size() / 2, -1);
  for (size_t s = 0; s < h.segmentEdge.size(); ++s) {
    const uint32_t u = mesh.segments[2 * s], w = mesh.segments[2 * s + 1];
    if (u >= mesh.vertexCount() || w >= mesh.vertexCount()) continue;
    int64_t e = out.find(tri, u, w);
    if (e < 0) e = out.find(tri, w, u);
    h.segmentEdge[s] = int32_t(e);
  }
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
