// Segment insertion at the store level: each segment becomes a chain of fixed edges, every
// other edge is locally Delaunay (which makes the whole triangulation constrained Delaunay),
// crossings, overlaps and vertices on segments are resolved.
#include <gtest/gtest.h>

#include <dirent.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <random>
#include <string>

#include "acutemesh/io.h"
#include "acutemesh/predicates.h"
#include "build.h"
#include "fixtures.h"
#include "rounding.h"
#include "triangulation.h"

using namespace acutemesh;
using namespace acutemesh::detail;
using fixtures::starPolygon;

namespace {

struct Built {
  Triangulation T;
  std::vector<uint32_t> canonical;
  StepResult result;
  Stats stats;
  NearEnds nearEnds;
};

Built buildCdt(const Pslg& in, bool snapNearEnds = false) {
  Built b;
  b.T.trackSegments = b.T.trackWinding = true;
  Options options;
  Budget budget(options);
  std::vector<uint32_t> inputOf;
  b.result = buildDelaunay(b.T, in.points, b.canonical, inputOf, budget);
  b.nearEnds.snap = snapNearEnds;
  if (b.result.ok()) b.result = insertSegments(b.T, in, b.canonical, b.stats, budget, b.nearEnds);
  return b;
}

// The same, in one pass along the segments (triangulateAlongSegments); `declined` where it
// leaves the input to the two steps.
Built buildAlong(const Pslg& in, bool& declined, bool snapNearEnds = false) {
  Built b;
  b.T.trackSegments = b.T.trackWinding = true;
  Options options;
  Budget budget(options);
  std::vector<uint32_t> inputOf;
  b.nearEnds.snap = snapNearEnds;
  b.result = triangulateAlongSegments(b.T, in, b.canonical, inputOf, b.stats, budget, b.nearEnds,
                                      declined);
  return b;
}

// The fixed edges by their ends' coordinates, sorted.
std::vector<std::array<double, 4>> fixedEdges(const Triangulation& T) {
  std::vector<std::array<double, 4>> edges;
  for (uint32_t e = 0; e < 3 * T.triangleSlots(); ++e) {
    if (T.isFree(e / 3) || !T.fixed[e] || T.tri[e] == kGhost || T.tri[next(e)] == kGhost) continue;
    const double *p = T.point(T.tri[e]), *q = T.point(T.tri[next(e)]);
    if (std::make_pair(p[0], p[1]) < std::make_pair(q[0], q[1]))
      edges.push_back({p[0], p[1], q[0], q[1]});
  }
  std::sort(edges.begin(), edges.end());
  return edges;
}

size_t realTriangles(const Triangulation& T) {
  size_t n = 0;
  for (uint32_t t = 0; t < T.triangleSlots(); ++t) n += !T.isFree(t) && !T.isGhost(t);
  return n;
}

// Every non-fixed edge between two real triangles is locally Delaunay.
size_t nonDelaunayEdges(const Triangulation& T) {
  size_t bad = 0;
  for (uint32_t e = 0; e < 3 * T.triangleSlots(); ++e) {
    if (T.isFree(e / 3) || T.isGhost(e / 3) || T.isGhost(T.opp[e] / 3)) continue;
    bad += T.mustFlip(e);
  }
  return bad;
}

size_t invertedTriangles(const Triangulation& T) {
  size_t bad = 0;
  for (uint32_t t = 0; t < T.triangleSlots(); ++t)
    if (!T.isFree(t) && !T.isGhost(t))
      bad += orient2d(T.point(T.tri[3 * t]), T.point(T.tri[3 * t + 1]),
                      T.point(T.tri[3 * t + 2])) <= 0;
  return bad;
}

// Searches a path of fixed edges from a to b on which every step moves strictly closer to b
// along a->b. Vertices on it must lie exactly on the segment (withinReach: within rounding
// reach of it, what validate() grants a chain) unless they are crossing points added by
// insertion (index >= inputCount), which are rounded.
bool isFixedChain(const Triangulation& T, uint32_t a, uint32_t b, uint32_t inputCount,
                  bool withinReach = false) {
  std::vector<uint32_t> stack{a};
  std::vector<uint8_t> seen(T.vertexCount(), 0);
  while (!stack.empty()) {
    uint32_t at = stack.back();
    stack.pop_back();
    if (at == b) return true;
    if (seen[at]) continue;
    seen[at] = 1;
    uint32_t e0 = T.vertexEdge[at], e = e0;
    do {
      uint32_t w = T.tri[next(e)];
      bool onLine = w == b || w >= inputCount ||
                    (withinReach ? nearLine(T.point(a), T.point(b), T.point(w))
                                 : orient2d(T.point(a), T.point(b), T.point(w)) == 0);
      if (T.fixed[e] && w != kGhost && onLine &&
          (w == b || (dot2d(T.point(w), T.point(at), T.point(b)) < 0 &&
                      dot2d(T.point(at), T.point(w), T.point(b)) > 0)))
        stack.push_back(w);
      e = T.opp[prev(e)];
    } while (e != e0);
  }
  return false;
}

// Twins that do not run between the same two vertices the other way, or whose twin is not
// them; live triangles whose corners' vertexEdge leads elsewhere.
size_t brokenLinks(const Triangulation& T) {
  size_t bad = 0;
  for (uint32_t e = 0; e < 3 * T.triangleSlots(); ++e) {
    if (T.isFree(e / 3)) continue;
    const uint32_t f = T.opp[e];
    bad += f == kNone || T.opp[f] != e || T.tri[f] != T.tri[next(e)] || T.tri[next(f)] != T.tri[e] ||
           T.fixed[e] != T.fixed[f];
  }
  for (uint32_t v = 0; v < T.vertexCount(); ++v)
    bad += T.vertexEdge[v] != kNone && T.tri[T.vertexEdge[v]] != v;
  return bad;
}

void expectValidCdt(const Pslg& in, const Built& b) {
  ASSERT_TRUE(b.result.ok()) << b.result.message;
  EXPECT_EQ(brokenLinks(b.T), 0u);
  EXPECT_EQ(invertedTriangles(b.T), 0u);
  EXPECT_EQ(nonDelaunayEdges(b.T), 0u);
  for (size_t s = 0; s < in.segmentCount(); ++s) {
    uint32_t x = b.canonical[in.segments[2 * s]], y = b.canonical[in.segments[2 * s + 1]];
    if (x != y) {
      EXPECT_TRUE(isFixedChain(b.T, x, y, uint32_t(in.vertexCount()))) << "segment " << s;
    }
  }
}

}  // namespace

TEST(Cdt, PolygonWithDiagonalsAcrossDelaunayEdges) {
  // A zig-zag polygon whose edges are not Delaunay edges of its vertices.
  Pslg in;
  int n = 40;
  for (int i = 0; i < n; ++i) {
    double a = 2 * M_PI * i / n, r = i % 2 ? 1.0 : 0.35;
    in.points.push_back(r * std::cos(a));
    in.points.push_back(r * std::sin(a));
    in.segments.push_back(i);
    in.segments.push_back((i + 1) % n);
  }
  Built b = buildCdt(in);
  expectValidCdt(in, b);
  EXPECT_EQ(b.T.vertexCount(), uint32_t(n));  // no vertex needed
}

TEST(Cdt, RandomCrossingSegments) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  for (int round = 0; round < 5; ++round) {
    Pslg in;
    for (int i = 0; i < 120; ++i) in.points.push_back(u(rng)), in.points.push_back(u(rng));
    for (int s = 0; s < 40; ++s) in.segments.push_back(rng() % 120), in.segments.push_back(rng() % 120);
    Built b = buildCdt(in);
    expectValidCdt(in, b);
    EXPECT_GT(b.T.vertexCount(), 120u);  // 40 random segments always cross somewhere
  }
}

TEST(Cdt, GridOfCrossingLines) {
  Pslg in;
  int k = 15;
  for (int i = 0; i < k; ++i) {
    double c = 0.1 + i * 0.37;
    uint32_t base = uint32_t(in.vertexCount());
    in.points.insert(in.points.end(), {c, -1, c, 7, -1, c, 7, c});
    in.segments.insert(in.segments.end(), {base, base + 1, base + 2, base + 3});
  }
  Built b = buildCdt(in);
  expectValidCdt(in, b);
  EXPECT_EQ(b.T.vertexCount(), uint32_t(4 * k + k * k));
}

TEST(Cdt, NearlyParallelCrossings) {
  Pslg in;
  for (int i = 0; i < 30; ++i) {
    double tilt = 1e-9 * (i + 1);
    uint32_t base = uint32_t(in.vertexCount());
    in.points.insert(in.points.end(), {-1.0, -tilt * (i % 3), 1.0, tilt});
    in.segments.insert(in.segments.end(), {base, base + 1});
  }
  in.points.insert(in.points.end(), {0, 1, 0, -1});
  Built b = buildCdt(in);
  expectValidCdt(in, b);
}

TEST(Cdt, OverlapsVerticesOnSegmentsAndZeroLength) {
  Pslg in;
  in.points = {0, 0, 10, 0, 5, 0, 15, 0, 3, 0, 7, 5, 7, -5, 0, 0};
  in.segments = {0, 1,   // along the x axis
                 2, 3,   // overlaps it from x=5 to 10
                 5, 6,   // crosses both at x=7
                 4, 4,   // zero length
                 7, 1};  // 7 duplicates 0: same as segment 0
  Built b = buildCdt(in);
  expectValidCdt(in, b);
  ASSERT_FALSE(b.stats.warnings.empty());
  EXPECT_NE(b.stats.warnings[0].find("zero length"), std::string::npos);
  // Vertex 4 (x=3) and 2 (x=5) split the axis segment; (7,0) is the only new vertex.
  EXPECT_EQ(b.T.vertexCount(), 9u);
  EXPECT_EQ(b.T.point(8)[0], 7.0);
  EXPECT_EQ(b.T.point(8)[1], 0.0);
}

TEST(Cdt, WindingAddsUpOnOverlappingSegments) {
  Pslg in;
  in.points = {0, 0, 4, 0, 4, 4, 0, 4};
  in.segments = {0, 1, 1, 2, 2, 3, 3, 0, 0, 1};  // edge 0->1 twice
  Built b = buildCdt(in);
  expectValidCdt(in, b);
  uint32_t e = b.T.findEdge(b.canonical[0], b.canonical[1]);
  ASSERT_NE(e, kNone);
  EXPECT_EQ(b.T.wind[e], 2);
  EXPECT_EQ(b.T.wind[b.T.opp[e]], -2);
}

// Found on mirrored CG:SHOP point sets: a segment along the hull through a collinear hull
// vertex, whose outgoing half-edge lies in a ghost triangle, was not recognised.
TEST(Cdt, SegmentAlongHullThroughCollinearVertex) {
  for (bool reversed : {false, true}) {
    Pslg in;
    in.points = {0, 0, 0, 1, 0, 2, 1, 1, 0, 3};
    in.segments = reversed ? std::vector<uint32_t>{4, 0} : std::vector<uint32_t>{0, 4};
    Built b = buildCdt(in);
    expectValidCdt(in, b);
  }
}

// Segments that cross many edges (a star polygon with random radii, as bench/gen.mjs makes):
// the crossed triangles give way to the triangulations of the two sides at once.
TEST(Cdt, StarPolygonSegmentsCrossManyEdges) {
  const int n = 3000;
  const Pslg in = starPolygon(n, 5);
  Built b = buildCdt(in);
  expectValidCdt(in, b);
  EXPECT_EQ(b.T.vertexCount(), uint32_t(n));
}

// One segment across a fence of 2 x 600 points: each side's chain is longer than the cavity
// method takes (Triangulation::kCavityChain), so the crossed edges are flipped away instead.
TEST(Cdt, SegmentAcrossALongFence) {
  Pslg in;
  const int n = 600;
  static_assert(n > Triangulation::kCavityChain, "both paths");
  for (int i = 0; i < n; ++i)
    for (double y : {1.0, -1.0}) in.points.push_back(i + (y > 0 ? 0.5 : 0)), in.points.push_back(y);
  in.points.insert(in.points.end(), {-1, 0.01, n + 1.0, -0.01});
  in.segments = {2 * n, 2 * n + 1};
  Built b = buildCdt(in);
  expectValidCdt(in, b);
}

// Random segments between points of a small integer grid: cocircular and collinear vertices
// everywhere, segments through vertices, overlapping and crossing one another.
TEST(Cdt, RandomSegmentsOnAGrid) {
  const char* env = std::getenv("ACUTEMESH_CDT_ROUNDS");  // (more rounds by hand)
  const int rounds = env ? std::atoi(env) : 30;
  std::mt19937_64 rng(3);
  for (int round = 0; round < rounds; ++round) {
    SCOPED_TRACE("round " + std::to_string(round));
    Pslg in;
    const int side = 4 + int(rng() % 12);
    for (int i = 0; i < side * side; ++i)
      in.points.push_back(double(i % side)), in.points.push_back(double(i / side));
    const int segments = 1 + int(rng() % (3 * side));
    for (int s = 0; s < segments; ++s)
      in.segments.push_back(uint32_t(rng() % (side * side))),
          in.segments.push_back(uint32_t(rng() % (side * side)));
    Built b = buildCdt(in);
    expectValidCdt(in, b);
    if (HasFailure()) return;
  }
}

// A segment end 1.4e-10 off a segment (a digitising spike of Canada's outline, as in
// test_refine's DigitisingSpike tests, its tip moved to the segment's other side): listed
// either way; with snap, the segment runs through it.
TEST(Cdt, SegmentEndNearASegmentSnappedOnlyWhenAsked) {
  Pslg in;
  in.points = {304.044414507, 52.7809173497, 304.047111935, 52.7796528742, 304.045763221,
               52.7802851121, 304.047111935, 52.7802851119, 304.04846065, 52.779, 304.044, 52.779};
  in.segments = {0, 1, 1, 2, 2, 3, 3, 1, 1, 4, 4, 5, 5, 0};
  for (bool snap : {false, true}) {
    SCOPED_TRACE(snap ? "snap" : "as given");
    const Built b = buildCdt(in, snap);
    if (!snap) {
      expectValidCdt(in, b);
    } else {  // (segment 0's chain runs a rounding off its line, through the tip)
      ASSERT_TRUE(b.result.ok()) << b.result.message;
      EXPECT_EQ(brokenLinks(b.T) + invertedTriangles(b.T) + nonDelaunayEdges(b.T), 0u);
    }
    const uint32_t a = b.canonical[0], tip = b.canonical[2], end = b.canonical[1];
    ASSERT_EQ(b.nearEnds.found.size(), 1u);
    EXPECT_EQ(b.nearEnds.found[0].first, tip);
    EXPECT_EQ(b.nearEnds.found[0].second, 0u);
    const uint32_t toTip = b.T.findEdge(a, tip), onward = b.T.findEdge(tip, end);
    EXPECT_EQ(toTip != kNone && b.T.fixed[toTip] && onward != kNone && b.T.fixed[onward], snap);
    EXPECT_EQ(b.T.vertexCount(), in.vertexCount());  // (no crossing)
  }
}

namespace {

// Along the segments or in two steps, the same constrained Delaunay triangulation: the same
// fixed edges, as many triangles (cocircular vertices may tie differently), the same vertices
// found near segments; where `sameRoutes` is false, a valid one whose segments may take other
// routes within rounding reach. Returns whether the one pass took the input.
bool expectSameCdtAlong(const Pslg& in, bool snap = false, bool sameRoutes = true) {
  bool declined = false;
  const Built along = buildAlong(in, declined, snap);
  if (declined) return false;
  const Built twoSteps = buildCdt(in, snap);
  EXPECT_EQ(along.result.ok(), twoSteps.result.ok())
      << along.result.message << " / " << twoSteps.result.message;
  if (!along.result.ok() || !twoSteps.result.ok()) return true;
  EXPECT_EQ(brokenLinks(along.T) + invertedTriangles(along.T) + nonDelaunayEdges(along.T), 0u);
  for (size_t s = 0; s < in.segmentCount(); ++s) {  // (where the two steps' is: fuzz findings')
    const uint32_t *ends = &in.segments[2 * s], count = uint32_t(in.vertexCount());
    const uint32_t a = along.canonical[ends[0]], b = along.canonical[ends[1]];
    if (a != b && isFixedChain(twoSteps.T, twoSteps.canonical[ends[0]], twoSteps.canonical[ends[1]],
                               count, true)) {
      EXPECT_TRUE(isFixedChain(along.T, a, b, count, true)) << "segment " << s;
    }
  }
  EXPECT_EQ(realTriangles(along.T), realTriangles(twoSteps.T));
  if (!sameRoutes) return true;
  for (size_t s = 0; s < in.segmentCount(); ++s) {  // (a fuzz finding's rounded chain fails both)
    const uint32_t *ends = &in.segments[2 * s], count = uint32_t(in.vertexCount());
    const uint32_t a = along.canonical[ends[0]], b = along.canonical[ends[1]];
    const uint32_t c = twoSteps.canonical[ends[0]], d = twoSteps.canonical[ends[1]];
    if (a != b || c != d) {
      EXPECT_EQ(isFixedChain(along.T, a, b, count), isFixedChain(twoSteps.T, c, d, count))
          << "segment " << s;
    }
  }
  EXPECT_TRUE(fixedEdges(along.T) == fixedEdges(twoSteps.T));
  EXPECT_EQ(along.T.vertexCount(), twoSteps.T.vertexCount());  // (crossing points)
  EXPECT_EQ(along.stats.warnings, twoSteps.stats.warnings);
  for (size_t i = 0; i < in.vertexCount(); ++i) {  // (duplicates merged alike)
    EXPECT_EQ(along.T.point(along.canonical[i])[0], twoSteps.T.point(twoSteps.canonical[i])[0]);
    EXPECT_EQ(along.T.point(along.canonical[i])[1], twoSteps.T.point(twoSteps.canonical[i])[1]);
  }
  EXPECT_EQ(along.nearEnds.found.size(), twoSteps.nearEnds.found.size());
  EXPECT_EQ(along.nearEnds.close.size(), twoSteps.nearEnds.close.size());
  return true;
}

}  // namespace

// The one pass along the segments (which mesh() takes for long chained segments, as on the
// 10^5-edge star polygon): star polygons (each segment crosses many Delaunay edges; the hull
// grows past segments on it), random walks on a small grid (crossings, overlaps, vertices on
// segments, cocircular and repeated vertices, returns), and every .poly fixture that meshes
// without scaling, bad and fuzzed ones included.
TEST(Cdt, AlongTheSegmentsTheSameCdtAsInTwoSteps) {
  for (uint64_t seed : {1, 2, 3}) {
    SCOPED_TRACE("star " + std::to_string(seed));
    EXPECT_TRUE(expectSameCdtAlong(starPolygon(2000, seed)));
  }
  // Stars made awkward, one kind each: neighbours swapped (their segments cross), a vertex
  // repeating the one two before (a duplicate), segment midpoints on no segment.
  int awkwardTaken[3] = {0, 0, 0};
  for (uint64_t seed : {4, 5, 6, 7, 8, 9}) {
    SCOPED_TRACE("awkward star " + std::to_string(seed));
    Pslg in = starPolygon(2000, seed);
    std::mt19937_64 rng(seed);
    const int kind = int(seed % 3);
    for (int k = 0; k < 20; ++k) {
      const size_t i = 2 + rng() % 1990;
      switch (kind) {
        case 0:
          std::swap(in.points[2 * i], in.points[2 * i + 2]);
          std::swap(in.points[2 * i + 1], in.points[2 * i + 3]);
          break;
        case 1:
          in.points[2 * i] = in.points[2 * i - 4], in.points[2 * i + 1] = in.points[2 * i - 3];
          break;
        default:
          in.points.push_back(0.5 * (in.points[2 * i] + in.points[2 * i + 2]));
          in.points.push_back(0.5 * (in.points[2 * i + 1] + in.points[2 * i + 3]));
      }
    }
    awkwardTaken[kind] += expectSameCdtAlong(in);
    if (HasFailure()) return;
  }
  // (Crossings inside the hull and repeated vertices go in one pass, as the two steps would;
  // midpoints that land a rounding off their segment's line, and there are some in each,
  // the pass leaves to them.)
  EXPECT_EQ(awkwardTaken[0], 2);
  EXPECT_EQ(awkwardTaken[1], 2);
  EXPECT_EQ(awkwardTaken[2], 0);
  std::mt19937_64 rng(11);
  int taken = 0, walks = 60;
  for (int round = 0; round < walks; ++round) {
    SCOPED_TRACE("walk " + std::to_string(round));
    Pslg in;
    const int side = 3 + int(rng() % 10), steps = 5 + int(rng() % 60);
    for (int i = 0; i <= steps; ++i) {
      in.points.push_back(double(rng() % side));
      in.points.push_back(double(rng() % side));
      if (i > 0) in.segments.insert(in.segments.end(), {uint32_t(i - 1), uint32_t(i)});
    }
    for (int i = 0; i < 5; ++i)  // (vertices on no segment)
      in.points.push_back(double(rng() % side) + 0.5), in.points.push_back(double(rng() % side));
    taken += expectSameCdtAlong(in);
    if (HasFailure()) return;
  }
  EXPECT_GE(taken, 12);  // (the rest cross a segment on the hull so far, or the like)

  int files = 0;
  for (const std::string& dir :
       {std::string(ACUTEMESH_TEST_DATA), std::string(ACUTEMESH_TEST_DATA) + "/bad",
        std::string(ACUTEMESH_SOURCE_DIR) + "/tests/fuzz/findings"}) {
    DIR* d = opendir(dir.c_str());
    ASSERT_NE(d, nullptr) << dir;
    std::vector<std::string> names;
    while (dirent* e = readdir(d)) {
      const std::string name = e->d_name;
      if (name.size() > 5 && name.substr(name.size() - 5) == ".poly") names.push_back(name);
    }
    closedir(d);
    std::sort(names.begin(), names.end());
    for (const std::string& name : names) {
      acutemesh::Input input;
      if (!acutemesh::readInputFile(dir + "/" + name, input).ok) continue;
      const Pslg& in = input.pslg;
      bool indicesOk = in.vertexCount() >= 3 && in.segmentCount() > 0;
      for (uint32_t v : in.segments) indicesOk = indicesOk && v < in.vertexCount();
      CoordinateRange range;
      range.add(in.points);
      int exponent = 0;
      if (!indicesOk || !range.finite || !exactScale(range, exponent) || exponent != 0) continue;
      Options cdt;
      cdt.mode = Mode::Cdt;
      if (mesh(in, cdt).status != Status::Ok) continue;
      SCOPED_TRACE(name);
      // (Vertices 0 and 1 an ulp apart and two segments from them an ulp apart: both ways
      // route one of the two through the other's end, not the same one.)
      const bool sameRoutes = name != "segment-ends-outside-an-ulp-above.poly";
      for (bool snap : {false, true}) expectSameCdtAlong(in, snap, sameRoutes);
      ++files;
      if (HasFailure()) return;
    }
  }
  EXPECT_GT(files, 20);
}

// A segment end within rounding reach of a segment (Canada's spike, as above): inserted after
// the segment, the one pass leaves it to the two steps, which run the segment through it;
// inserted before it (here in the first triangle), the segment's walk finds it as theirs does.
TEST(Cdt, AlongTheSegmentsDeclinesAnEndBesideAnEarlierSegment) {
  Pslg in;
  in.points = {304.044414507, 52.7809173497, 304.047111935, 52.7796528742,
               304.045763221, 52.7802851121, 304.047111935, 52.7802851119,
               304.04846065,  52.779,        304.044,       52.779};
  in.segments = {5, 0, 0, 1, 1, 2, 2, 3, 3, 1, 1, 4, 4, 5};
  bool declined = false;
  buildAlong(in, declined, true);
  EXPECT_TRUE(declined);
  in.segments = {0, 1, 1, 2, 2, 3, 3, 1, 1, 4, 4, 5, 5, 0};
  for (bool snap : {false, true}) {
    SCOPED_TRACE(snap);
    EXPECT_TRUE(expectSameCdtAlong(in, snap));
    const Built b = buildAlong(in, declined, snap);
    ASSERT_EQ(b.nearEnds.found.size(), 1u);
    const uint32_t toTip = b.T.findEdge(b.canonical[0], b.canonical[2]);
    EXPECT_EQ(toTip != kNone && b.T.fixed[toTip], snap);
  }
}

// mesh() takes the one pass for a large star polygon (long chained segments): its CDT is
// the polygon's n - 2 triangles, valid.
TEST(Cdt, MeshTakesTheOnePassForALargeStarPolygon) {
  const int n = int(kAlongSegmentsFrom) + 1000;
  const Pslg in = starPolygon(n, 7);
  ASSERT_TRUE(alongSegmentsPays(in));
  Options options;
  options.mode = Mode::Cdt;
  const Result r = mesh(in, options);
  ASSERT_EQ(r.status, Status::Ok) << r.message;
  EXPECT_EQ(r.mesh.triangleCount(), size_t(n - 2));
  const Validation v = validate(in, r.mesh, options);
  EXPECT_TRUE(v.ok) << (v.errors.empty() ? "" : v.errors[0]);
  // A map's coastline: short segments against the vertex spacing, mostly Delaunay edges.
  Pslg ring;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * M_PI * i / n;
    ring.points.insert(ring.points.end(), {std::cos(a), std::sin(a)});
    ring.segments.insert(ring.segments.end(), {uint32_t(i), uint32_t((i + 1) % n)});
  }
  EXPECT_FALSE(alongSegmentsPays(ring));
}
