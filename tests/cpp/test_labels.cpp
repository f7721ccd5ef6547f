// Output labels (core/src/labels.h): boundary markers and region attributes by Triangle's rules,
// in every mode, whole and by parts, read from .poly and JSON. Every expectation is found
// independently of the library, from the geometry with exact orient2d: which side of the
// splitting segment a triangle lies on, which input segments a vertex lies on, whether it lies
// on the outline.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "acutemesh/acutemesh.h"
#include "acutemesh/io.h"
#include "acutemesh/predicates.h"
#include "acutemesh/vocabulary.h"
#include "fixtures.h"

using namespace acutemesh;

namespace {

// A 4 x 3 rectangle split by the segment (1, 0)-(3, 3) into a left and a right region. Each
// segment has its own marker but the top (0: the boundary makes it 1), and vertex 0 its own
// (5). Regions: the right (2), the left (1), one outside (9, ignored with a warning) and the
// left again (7: the later wins).
constexpr int32_t kSegmentMarkers[] = {11, 12, 13, 14, 0, 16, 20};
constexpr double kLeft = 7, kRight = 2;
Pslg splitRectangle() {
  Pslg in;
  in.points = {0, 0, 1, 0, 4, 0, 4, 3, 3, 3, 0, 3};
  in.segments = {0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 0, 1, 4};
  in.vertexMarkers = {5, 0, 0, 0, 0, 0};
  in.segmentMarkers.assign(std::begin(kSegmentMarkers), std::end(kSegmentMarkers));
  auto region = [](double x, double y, double attribute) {
    Region r;
    r.x = x, r.y = y, r.attribute = attribute;
    return r;
  };
  in.regions = {region(3.5, 1, kRight), region(0.5, 1.5, 1), region(10, 10, 9),
                region(0.2, 2.5, kLeft)};
  return in;
}

const double* at(const Mesh& m, uint32_t v) { return &m.points[2 * size_t(v)]; }

// How far off the line of a-b point p may be: exactly on it, or within the rounding of a
// point constructed on it (a few ulps of the coordinates' magnitude, times the length).
bool onLine(const double* a, const double* b, const double* p, bool exact) {
  const double o = orient2d(a, b, p);
  if (exact) return o == 0;
  const double scale = std::max({std::fabs(a[0]), std::fabs(a[1]), std::fabs(b[0]), std::fabs(b[1]), 1.0});
  return std::fabs(o) <= 1e-12 * scale * scale;
}
// On the segment a-b: on its line and within its box.
bool onSegment(const double* a, const double* b, const double* p, bool exact) {
  for (int d = 0; d < 2; ++d)
    if (p[d] < std::min(a[d], b[d]) || p[d] > std::max(a[d], b[d])) return false;
  return onLine(a, b, p, exact);
}

// The side of segment 1-4 a triangle is on: the sign of the orientation of its corner
// farthest from the line (its other corners lie on the line or the same side).
int side(const Pslg& in, const Mesh& m, size_t t) {
  const double *a = &in.points[2], *b = &in.points[8];
  double best = 0;
  for (int k = 0; k < 3; ++k) {
    const double o = orient2d(a, b, at(m, m.triangles[3 * t + k]));
    if (std::fabs(o) > std::fabs(best)) best = o;
  }
  return (best > 0) - (best < 0);
}

// Every label of a mesh of `in` (the split rectangle, or any PSLG without regions when
// `regions` is false) checked against the geometry.
void expectLabels(const Pslg& in, const Options& o, const Result& r, bool regions,
                  const std::string& what) {
  const Mesh& m = r.mesh;
  const bool exact = o.exactSegments;
  ASSERT_EQ(m.vertexMarkers.size(), m.vertexCount()) << what;
  ASSERT_EQ(m.segmentMarkers.size() * 2, m.segments.size()) << what;
  ASSERT_EQ(m.segmentInput.size() * 2, m.segments.size()) << what;
  // Segments: each on its input segment, with its marker (the top's 0 made 1).
  for (size_t s = 0; s < m.segmentInput.size(); ++s) {
    const uint32_t i = m.segmentInput[s];
    ASSERT_LT(i, in.segmentCount()) << what;
    const double *a = &in.points[2 * size_t(in.segments[2 * i])],
                 *b = &in.points[2 * size_t(in.segments[2 * i + 1])];
    for (int k = 0; k < 2; ++k)
      EXPECT_TRUE(onSegment(a, b, at(m, m.segments[2 * s + k]), exact))
          << what << ": segment edge " << s << " off input segment " << i;
    const int32_t marker = in.segmentMarkers.empty() ? 0 : in.segmentMarkers[i];
    const bool inner = i == 6;  // (the splitting segment; the others bound the domain)
    EXPECT_EQ(m.segmentMarkers[s], marker == 0 && !inner ? 1 : marker) << what << " edge " << s;
  }
  // Vertices: their own marker, else the lowest-numbered marked segment they lie on, else 1
  // on the outline.
  for (uint32_t v = 0; v < m.vertexCount(); ++v) {
    if (m.vertexKind[v] == kUnusedVertex) continue;
    int32_t expected = v < in.vertexCount() && !in.vertexMarkers.empty() ? in.vertexMarkers[v] : 0;
    if (o.mode != Mode::Delaunay)
      for (size_t i = 0; i < in.segmentCount() && expected == 0; ++i) {
        const int32_t marker = in.segmentMarkers.empty() ? 0 : in.segmentMarkers[i];
        if (marker && onSegment(&in.points[2 * size_t(in.segments[2 * i])],
                                &in.points[2 * size_t(in.segments[2 * i + 1])], at(m, v), exact))
          expected = marker;
      }
    const double* p = at(m, v);
    if (expected == 0 && (p[0] == 0 || p[0] == 4 || p[1] == 0 || p[1] == 3)) expected = 1;
    EXPECT_EQ(m.vertexMarkers[v], expected)
        << what << ": vertex " << v << " (" << p[0] << ", " << p[1] << ") kind "
        << int(m.vertexKind[v]);
  }
  if (!regions) return;
  // Triangles: the region of their side (Delaunay: the last region reaches everything).
  ASSERT_EQ(m.triangleAttributes.size(), m.triangleCount()) << what;
  for (size_t t = 0; t < m.triangleCount(); ++t) {
    const double expected = o.mode == Mode::Delaunay ? kLeft : side(in, m, t) > 0 ? kLeft : kRight;
    ASSERT_EQ(m.triangleAttributes[t], expected) << what << ": triangle " << t;
  }
  // The region outside is named.
  bool warned = false;
  for (const std::string& w : r.stats.warnings) warned |= w.find("region 2 at (10, 10)") != std::string::npos;
  EXPECT_TRUE(warned) << what;
}



}  // namespace

TEST(Labels, SplitRectangleInEveryMode) {
  const Pslg in = splitRectangle();
  for (const auto& named : kModes)
    for (bool exact : {false, true}) {
      const Mode mode = named.value;
      Options o;
      o.mode = mode;
      o.exactSegments = exact;
      if (mode != Mode::Delaunay && mode != Mode::Cdt) o.maxArea = 0.05;  // (Steiner points on the segments)
      const Result r = mesh(in, o);
      const std::string what = std::string(nameOf(mode)) + (exact ? " exact" : "");
      ASSERT_EQ(r.status, Status::Ok) << what << ": " << r.message;
      EXPECT_EQ(fixtures::validationErrors(in, o, r.mesh), "") << what;
      if (mode != Mode::Delaunay && mode != Mode::Cdt) {
        // (The test means something only with Steiner points on the segments.)
        EXPECT_TRUE(std::count(r.mesh.vertexKind.begin(), r.mesh.vertexKind.end(),
                               uint8_t(kSegmentVertex)) > 0)
            << what;
      }
      expectLabels(in, o, r, true, what);
      // The twins the store gave (Options::adjacency) are the ones found from the triangles.
      Options asked = o;
      asked.adjacency = true;
      const Result withAdjacency = mesh(in, asked);
      EXPECT_EQ(withAdjacency.mesh.adjacency.halfedges, adjacency(r.mesh).halfedges) << what;
      EXPECT_TRUE(r.mesh.adjacency.halfedges.empty()) << what << ": adjacency not asked for";
      if (HasFailure()) return;
    }
}

TEST(Labels, WithoutMarkersTheBoundaryIsOne) {
  Pslg in = splitRectangle();
  in.vertexMarkers.clear();
  in.segmentMarkers.clear();
  in.regions.clear();
  Options o;
  o.mode = Mode::Acute;
  const Result r = mesh(in, o);
  ASSERT_EQ(r.status, Status::Ok) << r.message;
  EXPECT_TRUE(r.mesh.triangleAttributes.empty());
  expectLabels(in, o, r, false, "no markers");
}

TEST(Labels, AdjacencyEdgesCarryTheSegmentMarkers) {
  const Pslg in = splitRectangle();
  Options o;
  o.mode = Mode::Quality;
  o.maxArea = 0.1;
  o.adjacency = true;
  const Result r = mesh(in, o);
  ASSERT_EQ(r.status, Status::Ok) << r.message;
  const Adjacency& a = r.mesh.adjacency;
  ASSERT_EQ(a.halfedges.size(), r.mesh.triangles.size());
  // The same as adjacency() finds alone.
  const Adjacency alone = adjacency(r.mesh);
  EXPECT_EQ(a.halfedges, alone.halfedges);
  EXPECT_EQ(a.edges, alone.edges);
  EXPECT_EQ(a.edgeMarkers, alone.edgeMarkers);
  EXPECT_EQ(a.hull, alone.hull);
  size_t marked = 0;
  for (size_t s = 0; s < r.mesh.segmentMarkers.size(); ++s) {
    uint32_t u = r.mesh.segments[2 * s], w = r.mesh.segments[2 * s + 1];
    if (u > w) std::swap(u, w);
    for (size_t e = 0; e < a.edgeMarkers.size(); ++e)
      if (a.edges[2 * e] == u && a.edges[2 * e + 1] == w) {
        EXPECT_EQ(a.edgeMarkers[e], r.mesh.segmentMarkers[s]) << "edge " << u << "-" << w;
        ++marked;
      }
  }
  EXPECT_EQ(marked, r.mesh.segmentMarkers.size());
}

// Scaled far out of the predicates' range, the regions scale with the points: the same labels.
TEST(Labels, ScaledInputGetsTheSameLabels) {
  const Pslg in = splitRectangle();
  Options o;
  o.mode = Mode::Acute;
  const Result plain = mesh(in, o);
  ASSERT_EQ(plain.status, Status::Ok) << plain.message;
  for (int exponent : {300, -300}) {
    Pslg big = in;
    for (double& x : big.points) x = std::ldexp(x, exponent);
    for (Region& g : big.regions) g.x = std::ldexp(g.x, exponent), g.y = std::ldexp(g.y, exponent);
    const Result r = mesh(big, o);
    ASSERT_EQ(r.status, Status::Ok) << exponent << ": " << r.message;
    EXPECT_EQ(r.mesh.triangleAttributes, plain.mesh.triangleAttributes) << exponent;
    EXPECT_EQ(r.mesh.vertexMarkers, plain.mesh.vertexMarkers) << exponent;
    EXPECT_EQ(r.mesh.segmentMarkers, plain.mesh.segmentMarkers) << exponent;
    EXPECT_EQ(r.mesh.segmentInput, plain.mesh.segmentInput) << exponent;
  }
}

// Many islands (>= kPartsFrom domain triangles: meshed part by part), each ring with its
// marker and a region: every island's triangles get its attribute, its boundary edges its
// marker, and one thread or two make the same labels.
TEST(Labels, ArchipelagoByPartsOnAnyThreads) {
  constexpr int kIslands = 16, kCorners = 300;
  Pslg in = fixtures::archipelago(kIslands, kCorners,
                                  [](int i, double a) { return 1 + 0.1 * std::sin(5 * a + i); });
  for (int i = 0; i < kIslands; ++i) in.segmentMarkers.insert(in.segmentMarkers.end(), kCorners, 100 + i);
  in.vertexMarkers.assign(in.vertexCount(), 0);
  in.vertexMarkers[0] = -3;  // (its own marker stays)
  Options cdt;
  const Result plain = mesh(in, cdt);
  ASSERT_EQ(plain.status, Status::Ok) << plain.message;
  ASSERT_GE(plain.mesh.triangleCount(), 4096u) << "too small to go by parts";
  Options o;
  o.mode = Mode::Acute;
  o.threads = 1;
  const Result one = mesh(in, o);
  ASSERT_EQ(one.status, Status::Ok) << one.message;
  EXPECT_EQ(fixtures::validationErrors(in, o, one.mesh), "");
  const Mesh& m = one.mesh;
  ASSERT_EQ(m.triangleAttributes.size(), m.triangleCount());
  for (size_t t = 0; t < m.triangleCount(); ++t) {
    double c[2] = {0, 0};
    for (int k = 0; k < 3; ++k)
      for (int d = 0; d < 2; ++d) c[d] += at(m, m.triangles[3 * t + k])[d] / 3;
    const int island = int(std::lround(c[0] / 3)) + 4 * int(std::lround(c[1] / 3));
    ASSERT_EQ(m.triangleAttributes[t], island) << "triangle " << t;
  }
  ASSERT_EQ(m.segmentInput.size() * 2, m.segments.size());
  for (size_t s = 0; s < m.segmentInput.size(); ++s) {
    const uint32_t i = m.segmentInput[s];
    ASSERT_LT(i, in.segmentCount());
    EXPECT_EQ(m.segmentMarkers[s], 100 + int(i / kCorners)) << "edge " << s;
    for (int k = 0; k < 2; ++k)
      EXPECT_TRUE(onSegment(&in.points[2 * size_t(in.segments[2 * i])],
                            &in.points[2 * size_t(in.segments[2 * i + 1])],
                            at(m, m.segments[2 * s + k]), false))
          << "edge " << s << " off input segment " << i;
  }
  EXPECT_EQ(m.vertexMarkers[0], -3);
  for (uint32_t v = 1; v < m.vertexCount(); ++v) {
    if (m.vertexKind[v] == kFreeVertex) {
      EXPECT_EQ(m.vertexMarkers[v], 0) << v;
      continue;
    }
    const double* p = at(m, v);
    const int island = int(std::lround(p[0] / 3)) + 4 * int(std::lround(p[1] / 3));
    EXPECT_EQ(m.vertexMarkers[v], 100 + island) << "vertex " << v;
    if (::testing::Test::HasFailure()) return;
  }
  // The twins the parts' stores gave are the ones found from the triangles.
  o.adjacency = true;
  const Result withAdjacency = mesh(in, o);
  EXPECT_EQ(withAdjacency.mesh.adjacency.halfedges, adjacency(m).halfedges);
  EXPECT_EQ(withAdjacency.mesh.adjacency.edgeMarkers, adjacency(m).edgeMarkers);
  o.adjacency = false;
  o.threads = 2;
  const Result two = mesh(in, o);
  EXPECT_EQ(two.mesh.triangles, m.triangles);
  EXPECT_EQ(two.mesh.triangleAttributes, m.triangleAttributes);
  EXPECT_EQ(two.mesh.vertexMarkers, m.vertexMarkers);
  EXPECT_EQ(two.mesh.segmentMarkers, m.segmentMarkers);
  EXPECT_EQ(two.mesh.segmentInput, m.segmentInput);
}

TEST(Labels, PolyWithRegionalAttributes) {
  const Input in = fixtures::load(fixtures::kData + "/io/regions.poly");
  const Pslg expected = splitRectangle();
  EXPECT_EQ(in.pslg.points, expected.points);
  EXPECT_EQ(in.pslg.segments, expected.segments);
  EXPECT_EQ(in.pslg.vertexMarkers, expected.vertexMarkers);
  EXPECT_EQ(in.pslg.segmentMarkers, expected.segmentMarkers);
  ASSERT_EQ(in.pslg.regions.size(), 4u);
  EXPECT_EQ(in.pslg.regions[0].maxArea, 0.5);
  EXPECT_EQ(in.pslg.regions[1].maxArea, 0);  // (negative: none, as in Triangle)
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(in.pslg.regions[i].x, expected.regions[i].x) << i;
    EXPECT_EQ(in.pslg.regions[i].y, expected.regions[i].y) << i;
    EXPECT_EQ(in.pslg.regions[i].attribute, expected.regions[i].attribute) << i;
  }
  Options o;
  o.mode = Mode::NonObtuse;
  const Result r = mesh(in.pslg, o);
  ASSERT_EQ(r.status, Status::Ok) << r.message;
  expectLabels(in.pslg, o, r, true, "regions.poly");
}

TEST(Labels, JsonKeys) {
  Input in;
  ParseResult p = parseJson(R"({"vertices": [[0,0],[1,0],[4,0],[4,3],[3,3],[0,3]],
    "segments": [[0,1],[1,2],[2,3],[3,4],[4,5],[5,0],[1,4]],
    "vertexMarkers": [5, 0, 0, 0, 0, 0],
    "segmentMarkers": [11, 12, 13, 14, 0, 16, 20],
    "regions": [[3.5, 1, 2, 0.25], [0.5, 1.5, 1], [10, 10, 9], [0.2, 2.5, 7]]})",
                            "split.json", in);
  ASSERT_TRUE(p.ok) << p.message;
  EXPECT_TRUE(in.warnings.empty());
  const Pslg expected = splitRectangle();
  EXPECT_EQ(in.pslg.vertexMarkers, expected.vertexMarkers);
  EXPECT_EQ(in.pslg.segmentMarkers, expected.segmentMarkers);
  ASSERT_EQ(in.pslg.regions.size(), 4u);
  EXPECT_EQ(in.pslg.regions[0].maxArea, 0.25);
  Options o;
  o.mode = Mode::Acute;
  const Result r = mesh(in.pslg, o);
  ASSERT_EQ(r.status, Status::Ok) << r.message;
  expectLabels(in.pslg, o, r, true, "split.json");

  // Rings: a marker per ring for its segments, regions as for a PSLG.
  p = parseJson(R"({"rings": [[[0,0],[4,0],[4,4],[0,4]], [[1,1],[2,1],[2,2]]],
    "ringMarkers": [3, -4], "regions": [[3, 3, 1.5]]})", "rings.json", in);
  ASSERT_TRUE(p.ok) << p.message;
  EXPECT_EQ(in.pslg.segmentMarkers, (std::vector<int32_t>{3, 3, 3, 3, -4, -4, -4}));
  ASSERT_EQ(in.pslg.regions.size(), 1u);
  EXPECT_EQ(in.pslg.regions[0].attribute, 1.5);
  EXPECT_TRUE(in.pslg.vertexMarkers.empty());
}

TEST(Labels, BadMarkersAndRegionsNameTheItem) {
  struct Bad {
    void (*spoil)(Pslg&);
    const char* message;
  };
  const Bad bad[] = {
      {[](Pslg& in) { in.vertexMarkers.pop_back(); },
       "vertexMarkers has 5 markers; expected one per vertex (6) or none"},
      {[](Pslg& in) { in.segmentMarkers.push_back(1); },
       "segmentMarkers has 8 markers; expected one per segment (7) or none"},
      {[](Pslg& in) { in.regions[1].y = NAN; }, "region 1 has a non-finite coordinate"},
      {[](Pslg& in) { in.regions[3].x = INFINITY; }, "region 3 has a non-finite coordinate"},
      {[](Pslg& in) { in.regions[2].attribute = -INFINITY; }, "region 2 has a non-finite attribute"},
      {[](Pslg& in) { in.regions[0].maxArea = -1; }, "region 0 has maxArea -1; expected a finite number >= 0"},
      {[](Pslg& in) { in.regions[0].maxArea = NAN; }, "region 0 has maxArea nan; expected a finite number >= 0"},
  };
  for (const Bad& b : bad) {
    Pslg in = splitRectangle();
    b.spoil(in);
    for (const auto& named : kModes) {
      const Mode mode = named.value;
      Options o;
      o.mode = mode;
      const Result r = mesh(in, o);
      EXPECT_EQ(r.status, Status::BadInput) << b.message;
      EXPECT_EQ(r.message, b.message) << nameOf(mode);
    }
  }
}
