// adjacency(): twins, neighbours, edges with markers and boundary loops, checked against the
// triangle list on fixtures meshed in several modes, on a pinch vertex, and on markers given by
// hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <ostream>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "acutemesh/acutemesh.h"
#include "fixtures.h"

using namespace acutemesh;

namespace {

uint32_t nextEdge(uint32_t e) { return e - e % 3 + (e % 3 + 1) % 3; }

// Twice the signed area of a closed polygon of vertex indices.
double loopArea2(const Mesh& m, const uint32_t* loop, size_t n) {
  double sum = 0;
  for (size_t i = 0; i < n; ++i) {
    const uint32_t a = loop[i], b = loop[(i + 1) % n];
    sum += m.points[2 * a] * m.points[2 * b + 1] - m.points[2 * b] * m.points[2 * a + 1];
  }
  return sum;
}

// Triangles joined across shared edges: how many pieces.
size_t edgeComponents(const Adjacency& a, size_t triangles) {
  std::vector<size_t> parent(triangles);
  std::iota(parent.begin(), parent.end(), size_t(0));
  auto find = [&](size_t t) {
    while (parent[t] != t) t = parent[t] = parent[parent[t]];
    return t;
  };
  for (size_t e = 0; e < a.halfedges.size(); ++e)
    if (a.halfedges[e] >= 0) parent[find(e / 3)] = find(size_t(a.halfedges[e]) / 3);
  size_t count = 0;
  for (size_t t = 0; t < triangles; ++t) count += find(t) == t;
  return count;
}

// Everything adjacency() promises, from the triangle list alone. `pinches`: the mesh may have
// vertices where pieces touch (Euler's count is not checked then).
void expectAdjacency(const Mesh& m, const Adjacency& a, bool pinches = false) {
  const std::vector<uint32_t>& tri = m.triangles;
  const size_t t = m.triangleCount();
  ASSERT_EQ(a.halfedges.size(), 3 * t);
  ASSERT_EQ(a.neighbors.size(), 3 * t);

  // Twins: symmetric, reversed; a half-edge without one has no reverse in the mesh at all.
  std::multiset<std::pair<uint32_t, uint32_t>> directed;
  for (uint32_t e = 0; e < 3 * t; ++e) directed.insert({tri[e], tri[nextEdge(e)]});
  size_t boundaryHalfEdges = 0;
  for (uint32_t e = 0; e < 3 * t; ++e) {
    const int32_t h = a.halfedges[e];
    if (h < 0) {
      ++boundaryHalfEdges;
      EXPECT_EQ(directed.count({tri[nextEdge(e)], tri[e]}), 0u) << "half-edge " << e << " untwinned";
      continue;
    }
    ASSERT_LT(size_t(h), 3 * t);
    EXPECT_EQ(a.halfedges[size_t(h)], int32_t(e));
    EXPECT_EQ(tri[size_t(h)], tri[nextEdge(e)]);
    EXPECT_EQ(tri[nextEdge(uint32_t(h))], tri[e]);
  }
  // Neighbour k: the triangle across the edge opposite corner k.
  for (uint32_t e = 0; e < 3 * t; ++e) {
    const int32_t h = a.halfedges[nextEdge(e)];
    EXPECT_EQ(a.neighbors[e], h < 0 ? -1 : h / 3) << "triangle " << e / 3 << " corner " << e % 3;
    if (a.neighbors[e] >= 0) {  // and the neighbour has this triangle among its own
      const int32_t* n = &a.neighbors[3 * size_t(a.neighbors[e])];
      EXPECT_TRUE(n[0] == int32_t(e / 3) || n[1] == int32_t(e / 3) || n[2] == int32_t(e / 3));
    }
  }

  // Edges: each undirected edge of a triangle once, a < b, sorted.
  std::set<std::pair<uint32_t, uint32_t>> undirected, onSegment;
  for (uint32_t e = 0; e < 3 * t; ++e)
    undirected.insert({std::min(tri[e], tri[nextEdge(e)]), std::max(tri[e], tri[nextEdge(e)])});
  for (size_t s = 0; s + 1 < m.segments.size(); s += 2)
    onSegment.insert({std::min(m.segments[s], m.segments[s + 1]),
                      std::max(m.segments[s], m.segments[s + 1])});
  ASSERT_EQ(a.edges.size(), 2 * undirected.size());
  ASSERT_EQ(a.edgeMarkers.size(), undirected.size());
  size_t i = 0;
  for (const auto& [u, w] : undirected) {  // (std::set is sorted the same way)
    EXPECT_EQ(a.edges[2 * i], u);
    EXPECT_EQ(a.edges[2 * i + 1], w);
    const bool boundary = directed.count({u, w}) + directed.count({w, u}) == 1;
    // Boundary edges are marked (Triangle's rule); inner ones on no segment are not. Without
    // markers in the mesh, exactly 1 and 0.
    if (boundary) {
      EXPECT_NE(a.edgeMarkers[i], 0) << u << "-" << w;
    } else if (!onSegment.count({u, w})) {
      EXPECT_EQ(a.edgeMarkers[i], 0) << u << "-" << w;
    }
    if (m.segmentMarkers.empty()) {
      EXPECT_EQ(a.edgeMarkers[i], boundary ? 1 : 0) << u << "-" << w;
    }
    ++i;
  }

  // Loops: closed, every boundary half-edge once, the mesh on their left.
  ASSERT_FALSE(a.hullStarts.empty());
  EXPECT_EQ(a.hullStarts.front(), 0u);
  EXPECT_EQ(a.hullStarts.back(), a.hull.size());
  EXPECT_EQ(a.hull.size(), boundaryHalfEdges);
  std::multiset<std::pair<uint32_t, uint32_t>> boundaryDirected;
  for (uint32_t e = 0; e < 3 * t; ++e)
    if (a.halfedges[e] < 0) boundaryDirected.insert({tri[e], tri[nextEdge(e)]});
  double loopsArea2 = 0;
  const size_t loops = a.hullStarts.size() - 1;
  for (size_t l = 0; l < loops; ++l) {
    const uint32_t first = a.hullStarts[l], end = a.hullStarts[l + 1];
    ASSERT_GE(end - first, 3u) << "loop " << l;
    for (uint32_t k = first; k < end; ++k) {
      const std::pair<uint32_t, uint32_t> step{a.hull[k], a.hull[k + 1 < end ? k + 1 : first]};
      const auto found = boundaryDirected.find(step);
      ASSERT_NE(found, boundaryDirected.end()) << "loop " << l << " step " << step.first << "->"
                                               << step.second << " is no boundary half-edge";
      boundaryDirected.erase(found);
    }
    loopsArea2 += loopArea2(m, &a.hull[first], end - first);
  }
  EXPECT_TRUE(boundaryDirected.empty());
  double meshArea2 = 0, scale = 0;
  for (size_t k = 0; k < t; ++k) {
    const uint32_t v[3] = {tri[3 * k], tri[3 * k + 1], tri[3 * k + 2]};
    const double area2 = loopArea2(m, v, 3);
    EXPECT_GT(area2, 0);
    meshArea2 += area2;
    scale += std::fabs(area2);
  }
  EXPECT_NEAR(loopsArea2, meshArea2, 1e-12 * scale);

  // Euler: each piece a disk with holes, V - E + T = 1 - holes; each piece has 1 + holes loops.
  if (!pinches) {
    std::set<uint32_t> used(tri.begin(), tri.end());
    const long long v = (long long)used.size(), e = (long long)undirected.size();
    const long long c = (long long)edgeComponents(a, t);
    EXPECT_EQ(v - e + (long long)t, 2 * c - (long long)loops);
  }
}

struct Case {
  const char* file;
  Mode mode;
  size_t loops;  // the boundary loops the domain has
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.file << " " << nameOf(c.mode); }

class AdjacencyOfFixtures : public ::testing::TestWithParam<Case> {};

TEST_P(AdjacencyOfFixtures, AgreesWithTheTriangles) {
  const Case c = GetParam();
  const Input in = fixtures::load(fixtures::kData + "/" + c.file);
  Options o;
  o.mode = c.mode;
  o.adjacency = true;
  const Result r = mesh(in.pslg, o);
  ASSERT_NE(r.status, Status::BadInput) << r.message;
  ASSERT_EQ(fixtures::validationErrors(in.pslg, o, r.mesh), "");
  const Adjacency a = adjacency(r.mesh);
  expectAdjacency(r.mesh, a);
  // Options::adjacency fills the same.
  EXPECT_EQ(r.mesh.adjacency.halfedges, a.halfedges);
  EXPECT_EQ(r.mesh.adjacency.edgeMarkers, a.edgeMarkers);
  EXPECT_EQ(r.mesh.adjacency.hull, a.hull);
  EXPECT_EQ(a.hullStarts.size() - 1, c.loops);
}

INSTANTIATE_TEST_SUITE_P(Fixtures, AdjacencyOfFixtures,
                         ::testing::Values(Case{"plate.poly", Mode::Cdt, 5},
                                           Case{"plate.poly", Mode::Acute, 5},
                                           Case{"A.poly", Mode::Cdt, 2},
                                           Case{"A.poly", Mode::Acute, 2},
                                           Case{"A.poly", Mode::Delaunay, 1}),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           std::string name = info.param.file;
                           name = name.substr(0, name.find('.')) + "_" + nameOf(info.param.mode);
                           return name;
                         });

// Two triangles touching at vertex 2 only: two loops, never one through the pinch.
TEST(Adjacency, PinchVertexKeepsTwoLoops) {
  Mesh m;
  m.points = {0, 0, 1, 0, 1, 1, 2, 1, 2, 2};
  m.triangles = {0, 1, 2, 2, 3, 4};
  const Adjacency a = adjacency(m);
  expectAdjacency(m, a, true);
  EXPECT_EQ(a.hullStarts, (std::vector<uint32_t>{0, 3, 6}));
  EXPECT_EQ(a.neighbors, (std::vector<int32_t>{-1, -1, -1, -1, -1, -1}));
  // Four triangles around the pinch, two on each side: each loop stays on its side.
  Mesh fans;
  fans.points = {0, 0, 1, 0, 1, 1, 0, 1, 2, 1, 2, 2, 1, 2};
  fans.triangles = {0, 1, 2, 0, 2, 3, 2, 4, 5, 2, 5, 6};
  const Adjacency b = adjacency(fans);
  expectAdjacency(fans, b, true);
  EXPECT_EQ(b.hullStarts, (std::vector<uint32_t>{0, 4, 8}));
}

// Markers given by hand: an edge takes its segment's, a zero one on the boundary becomes 1,
// an inner segment keeps its own, inner edges on no segment 0.
TEST(Adjacency, MarkersFromTheSegments) {
  Mesh m;
  m.points = {0, 0, 1, 0, 2, 0, 2, 1, 1, 1, 0, 1};
  m.triangles = {0, 1, 4, 0, 4, 5, 1, 2, 3, 1, 3, 4};
  m.segments = {0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 0, 4, 1};
  m.segmentMarkers = {5, 5, 0, -2, 7, 7, 3};
  const Adjacency a = adjacency(m);
  expectAdjacency(m, a);
  EXPECT_EQ(a.edges, (std::vector<uint32_t>{0, 1, 0, 4, 0, 5, 1, 2, 1, 3, 1, 4, 2, 3, 3, 4, 4, 5}));
  EXPECT_EQ(a.edgeMarkers, (std::vector<int32_t>{5, 0, 7, 5, 0, 3, 1, -2, 7}));
  EXPECT_EQ(a.hull, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5}));
}

}  // namespace
