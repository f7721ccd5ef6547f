// validate(): hand-built valid meshes pass, and each kind of corruption is reported with a
// message naming the offending item. No test goes through mesh().

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "acutemesh/acutemesh.h"

namespace {

using acutemesh::FillRule;
using acutemesh::Mesh;
using acutemesh::Mode;
using acutemesh::Options;
using acutemesh::Pslg;
using acutemesh::Validation;

std::string listErrors(const Validation& v) {
  std::string s;
  for (const std::string& e : v.errors) s += "  " + e + "\n";
  return s;
}

#define EXPECT_VALID(in, m, opt)                     \
  do {                                               \
    Validation v_ = acutemesh::validate(in, m, opt); \
    EXPECT_TRUE(v_.ok) << listErrors(v_);            \
    EXPECT_TRUE(v_.errors.empty());                  \
  } while (0)

// Expects validation to fail with some message containing `text`.
#define EXPECT_ERROR(in, m, opt, text)                                                           \
  do {                                                                                           \
    Validation v_ = acutemesh::validate(in, m, opt);                                             \
    EXPECT_FALSE(v_.ok);                                                                         \
    bool found_ = false;                                                                         \
    for (const std::string& e_ : v_.errors) found_ |= e_.find(text) != std::string::npos;        \
    EXPECT_TRUE(found_) << "no message contains \"" << (text) << "\"; got:\n" << listErrors(v_); \
  } while (0)

Options withFill(FillRule fill) {
  Options o;
  o.fill = fill;
  return o;
}
Options delaunay() {
  Options o;
  o.mode = Mode::Delaunay;
  return o;
}

// A mesh on the input's vertices plus the given Steiner points, listing the given mesh edges
// as its segments; vertexKind left empty (not checked) unless a test sets it.
Mesh meshOf(const Pslg& in, std::vector<uint32_t> triangles, std::vector<uint32_t> segments,
            std::vector<double> steiner = {}) {
  Mesh m;
  m.points = in.points;
  m.points.insert(m.points.end(), steiner.begin(), steiner.end());
  m.triangles = std::move(triangles);
  m.segments = std::move(segments);
  return m;
}

// The square (0,0) (2,0) (2,2) (0,2) with its four boundary segments, counter-clockwise.
Pslg square() {
  Pslg in;
  in.points = {0, 0, 2, 0, 2, 2, 0, 2};
  in.segments = {0, 1, 1, 2, 2, 3, 3, 0};
  return in;
}
const std::vector<uint32_t> kSquareTris = {0, 1, 2, 0, 2, 3};
const std::vector<uint32_t> kSquareSegs = {0, 1, 1, 2, 2, 3, 3, 0};

// Square (0,0)-(4,4) with the square hole (1,1)-(3,3); inner loop counter-clockwise unless
// `innerClockwise`. Vertices 0-3 outer, 4-7 inner.
Pslg squareWithHole(bool innerClockwise) {
  Pslg in;
  in.points = {0, 0, 4, 0, 4, 4, 0, 4, 1, 1, 3, 1, 3, 3, 1, 3};
  in.segments = {0, 1, 1, 2, 2, 3, 3, 0};
  std::vector<uint32_t> inner = innerClockwise ? std::vector<uint32_t>{4, 7, 7, 6, 6, 5, 5, 4}
                                               : std::vector<uint32_t>{4, 5, 5, 6, 6, 7, 7, 4};
  in.segments.insert(in.segments.end(), inner.begin(), inner.end());
  return in;
}
const std::vector<uint32_t> kRingTris = {0, 1, 5, 0, 5, 4, 1, 2, 6, 1, 6, 5,
                                         2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};
const std::vector<uint32_t> kRingSegs = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4};

// ---- valid meshes ---------------------------------------------------------------------

TEST(Validate, SquareOfTwoTriangles) {
  Pslg in = square();
  Mesh m = meshOf(in, kSquareTris, kSquareSegs);
  m.vertexKind = {0, 0, 0, 0};
  EXPECT_VALID(in, m, Options{});
  EXPECT_VALID(in, m, withFill(FillRule::EvenOdd));
  EXPECT_VALID(in, m, withFill(FillRule::NonZero));
  in.segments = {1, 0, 2, 1, 3, 2, 0, 3};  // clockwise: winding -1, still kept by both rules
  EXPECT_VALID(in, m, withFill(FillRule::EvenOdd));
  EXPECT_VALID(in, m, withFill(FillRule::NonZero));
}

// Under EvenOdd the segments need only meet each vertex an even number of times: here one
// inside the triangle 0-1-2 meets 2-3 twice and 3-0 six times, so integer winding numbers
// change by 4 going round it, and only their parity is defined. The exact mesh (and every
// refinement of it) is valid; validate() once took the changed integer for a segment crossing
// the mesh (fuzz finding).
TEST(Validate, EvenOddNeedsOnlyParity) {
  Pslg in;
  in.points = {-3.5, -3.75, -3.875, -4, -3.75, -3.625, -3.625, -3.75};
  in.segments = {2, 3, 3, 0, 1, 0, 1, 2, 2, 3, 3, 0, 0, 2, 3, 0, 0, 2, 3, 0,
                 2, 1, 1, 2, 3, 0, 2, 0, 0, 2, 3, 0, 2, 0};
  Mesh m = meshOf(in, {1, 3, 2, 2, 3, 0, 0, 3, 1}, {3, 2, 2, 1, 3, 0, 0, 2, 1, 0});
  EXPECT_VALID(in, m, withFill(FillRule::EvenOdd));
  for (Mode mode : {Mode::Cdt, Mode::NonObtuse, Mode::Acute, Mode::Quality})
    for (bool hull : {false, true}) {
      Options o = withFill(FillRule::EvenOdd);
      o.mode = mode;
      o.convexHull = hull;
      acutemesh::Result r = acutemesh::mesh(in, o);
      EXPECT_NE(r.status, acutemesh::Status::BadInput) << r.message;
      EXPECT_VALID(in, r.mesh, o);
    }
}

TEST(Validate, SquareWithHole) {
  Pslg in = squareWithHole(false);
  Mesh m = meshOf(in, kRingTris, kRingSegs);
  EXPECT_VALID(in, m, withFill(FillRule::EvenOdd));
  in.holes = {2, 2};
  EXPECT_VALID(in, m, withFill(FillRule::Triangle));
  Pslg cw = squareWithHole(true);
  EXPECT_VALID(cw, m, withFill(FillRule::NonZero));
  EXPECT_VALID(cw, m, withFill(FillRule::EvenOdd));
}

TEST(Validate, DelaunayOfPointSet) {
  Pslg in;
  in.points = {0, 0, 2, 0, 2, 2, 0, 2, 1, 1};
  Mesh m = meshOf(in, {0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4}, {});
  EXPECT_VALID(in, m, delaunay());
  // A hull vertex in the middle of a hull edge, and an unused duplicate of vertex 4.
  in.points = {0, 0, 2, 0, 2, 2, 0, 2, 1, 1, 1, 0, 1, 1};
  m = meshOf(in, {0, 5, 4, 5, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4}, {});
  EXPECT_VALID(in, m, delaunay());
}

TEST(Validate, SteinerPointSplitsSegment) {
  Pslg in = square();
  Mesh m = meshOf(in, {0, 4, 3, 4, 1, 2, 4, 2, 3}, {0, 4, 4, 1, 1, 2, 2, 3, 3, 0}, {1, 0});
  m.vertexKind = {0, 0, 0, 0, acutemesh::kSegmentVertex};
  EXPECT_VALID(in, m, Options{});
  EXPECT_VALID(in, m, withFill(FillRule::NonZero));
  m.vertexKind[4] = acutemesh::kFreeVertex;
  EXPECT_ERROR(in, m, Options{}, "vertex 4 (1, 0) has kind free, but lies on input segment 0");
}

TEST(Validate, RoundedCrossingPoint) {
  // The diagonal 0->2 crosses the vertical 4->5 at (1, 1/3), which no double represents:
  // Steiner vertex 6 is its rounding, exactly on 4->5 but a hair off 0->2. Listed segment
  // edges may reach such a point.
  Pslg in;
  in.points = {0, 0, 3, 0, 3, 1, 0, 1, 1, 0, 1, 1};
  in.segments = {0, 1, 1, 2, 2, 3, 3, 0, 0, 2, 4, 5};
  const double third = 1.0 / 3;
  std::vector<uint32_t> tris = {0, 4, 6, 0, 6, 5, 0, 5, 3, 4, 1, 2, 4, 2, 6, 6, 2, 5};
  std::vector<uint32_t> segs = {0, 4, 4, 1, 1, 2, 2, 5, 5, 3, 3, 0, 0, 6, 6, 2, 4, 6, 6, 5};
  Mesh m = meshOf(in, tris, segs, {1, third});
  m.vertexKind = {0, 0, 0, 0, 0, 0, acutemesh::kSegmentVertex};
  EXPECT_VALID(in, m, Options{});
  // Unlisted, the rounded edge 0-6 is no part of the chain.
  segs.erase(segs.begin() + 12, segs.begin() + 14);
  EXPECT_ERROR(in, meshOf(in, tris, segs, {1, third}), Options{},
               "input segment 4 (0->2) is not a chain of mesh edges: stops at vertex 0 and enters");
  // Rounding reach is a few hundred ulps, not a tolerance: 1e-9 off is off.
  Mesh far = meshOf(in, tris, m.segments, {1, third + 1e-9});
  EXPECT_ERROR(in, far, Options{},
               "input segment 4 (0->2) is not a chain of mesh edges: stops at vertex 0");
}

TEST(Validate, DuplicateInputVertexMayBeUnused) {
  Pslg in = square();
  in.points.insert(in.points.end(), {2, 0});  // vertex 4 duplicates vertex 1
  in.segments = {0, 4, 4, 2, 2, 3, 3, 0};     // the segments name the duplicate
  Mesh m = meshOf(in, kSquareTris, kSquareSegs);
  m.vertexKind = {0, 0, 0, 0, acutemesh::kUnusedVertex};
  EXPECT_VALID(in, m, Options{});
  EXPECT_VALID(in, m, withFill(FillRule::EvenOdd));
  // The first copy is the one to keep.
  Mesh later = meshOf(in, {0, 4, 2, 0, 2, 3}, {0, 4, 4, 2, 2, 3, 3, 0});
  EXPECT_ERROR(in, later, Options{},
               "input vertex 1 (2, 0) is unused, but its later duplicate 4 is used");
}

TEST(Validate, VertexOutsideDomainMayBeUnused) {
  Pslg in = square();
  in.points.insert(in.points.end(), {5, 5});
  Mesh m = meshOf(in, kSquareTris, kSquareSegs);
  EXPECT_VALID(in, m, Options{});
}

TEST(Validate, SegmentsOutsideTheDomain) {
  // Inside the hole: a dangling segment (unused vertices 8, 9), a segment from the hole's
  // corner into it, and one crossing the hole from corner to corner.
  Pslg in = squareWithHole(false);
  in.points.insert(in.points.end(), {1.5, 2, 2.5, 2});
  in.segments.insert(in.segments.end(), {8, 9, 4, 8, 4, 6});
  in.holes = {2, 2.5};
  Mesh m = meshOf(in, kRingTris, kRingSegs);
  EXPECT_VALID(in, m, Options{});
  // Also valid: from outside, through corner 0, along edge 0-4, across the hole to 6.
  in.points.insert(in.points.end(), {-1, -1});
  in.segments.insert(in.segments.end(), {10, 6});
  std::vector<uint32_t> segs = kRingSegs;
  segs.insert(segs.end(), {0, 4});  // now on an input segment
  m = meshOf(in, kRingTris, segs);
  EXPECT_VALID(in, m, Options{});
  // From outside to the hole's corner 7, crossing the ring's left side between vertices.
  in.points.insert(in.points.end(), {-1, 2});
  in.segments.insert(in.segments.end(), {11, 7});
  m = meshOf(in, kRingTris, segs);
  EXPECT_ERROR(in, m, Options{},
               "input segment 12 (11->7) is not a chain of mesh edges: reaches vertex 7 through "
               "triangle 7 (3,4,7)");
}

TEST(Validate, ConvexHullOption) {
  Pslg in = square();
  in.segments = {0, 1, 1, 2};  // only two sides are segments
  Mesh m = meshOf(in, kSquareTris, {0, 1, 1, 2});
  Options hull;
  hull.convexHull = true;
  EXPECT_VALID(in, m, hull);
  EXPECT_ERROR(in, m, Options{},
               "boundary edge 2->3 of triangle 1 (0,2,3) does not lie on an input segment");
}

TEST(Validate, NoSegmentsMeansTheConvexHull) {
  Pslg in = square();
  in.segments.clear();
  Mesh m = meshOf(in, kSquareTris, {});
  EXPECT_VALID(in, m, Options{});
  m.triangles.resize(3);
  EXPECT_ERROR(in, m, Options{},
               "boundary edge 2->0 of triangle 0 (0,1,2) lies neither on an input segment nor on "
               "the convex hull");
  EXPECT_ERROR(in, m, Options{},
               "vertex 3 (0, 2) is used by no triangle, but the whole convex hull");
}

// Refinement splits a point set's hull edges at rounded points: a Steiner point a rounding
// off the hull edge is accepted on the boundary; one well inside is not.
TEST(Validate, HullSplitPointsWithinRounding) {
  Pslg in = square();
  in.segments.clear();
  double nearEdge = std::nextafter(0.0, 1.0) + 1e-300;  // (1, tiny): a rounding above y = 0
  Mesh m = meshOf(in, {0, 4, 3, 4, 1, 2, 4, 2, 3}, {}, {1, nearEdge});
  m.vertexKind = {0, 0, 0, 0, acutemesh::kFreeVertex};
  EXPECT_VALID(in, m, Options{});
  m.points[9] = 0.25;  // (1, 0.25): the boundary now dents into the square
  EXPECT_ERROR(in, m, Options{}, "lies neither on an input segment nor on the convex hull");
}

TEST(Validate, SteinerVertexKinds) {
  // A free Steiner point in the middle of the square, and one wrongly called a segment point.
  Pslg in = square();
  Mesh m = meshOf(in, {0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4}, kSquareSegs, {1, 1});
  m.vertexKind = {0, 0, 0, 0, acutemesh::kFreeVertex};
  EXPECT_VALID(in, m, Options{});
  m.vertexKind[4] = acutemesh::kSegmentVertex;
  EXPECT_ERROR(in, m, Options{}, "vertex 4 (1, 1) has kind segment, but lies on no input segment");
  m.vertexKind = {0, 0, 1, 0, acutemesh::kFreeVertex};
  EXPECT_ERROR(in, m, Options{}, "vertex 2 (2, 2) has kind unused, expected input");
}

// ---- corruptions ----------------------------------------------------------------------

TEST(Validate, ClockwiseTriangle) {
  Pslg in = square();
  Mesh m = meshOf(in, {0, 2, 1, 0, 2, 3}, kSquareSegs);
  EXPECT_ERROR(in, m, Options{}, "triangle 0 (0,2,1) is not counter-clockwise");
  m.triangles = {0, 1, 1, 0, 2, 3};  // degenerate: a repeated corner
  EXPECT_ERROR(in, m, Options{}, "triangle 0 (0,1,1) is not counter-clockwise");
}

TEST(Validate, DuplicatedTriangle) {
  Pslg in = square();
  Mesh m = meshOf(in, {0, 1, 2, 0, 2, 3, 1, 2, 0}, kSquareSegs);
  EXPECT_ERROR(in, m, Options{},
               "directed edge 0->1 is used twice: by triangle 0 (0,1,2) and triangle 2 (1,2,0)");
}

TEST(Validate, OverlappingTriangle) {
  // An extra counter-clockwise triangle lying inside triangle 0, sharing no vertex with it.
  Pslg in = square();
  Mesh m = meshOf(in, {0, 1, 2, 0, 2, 3, 4, 5, 6}, kSquareSegs, {1, 0.2, 1.8, 0.2, 1.8, 1});
  EXPECT_ERROR(in, m, Options{},
               "boundary edge 4->5 of triangle 2 (4,5,6) does not lie on an input segment");
  EXPECT_ERROR(in, m, delaunay(),
               "boundary edge 4->5 of triangle 2 (4,5,6) is not a convex hull edge");
  // Sharing vertices, an overlapping triangle reuses a directed edge.
  m = meshOf(in, {0, 1, 2, 0, 2, 3, 0, 1, 3}, kSquareSegs);
  EXPECT_ERROR(in, m, Options{}, "directed edge 0->1 is used twice");
}

TEST(Validate, StarWrappingTwice) {
  // Six triangles around vertex 0, each turning 120 degrees: every edge is used once per
  // direction, all are counter-clockwise, yet they cover the plane around 0 twice.
  Pslg in;
  in.points = {0, 0};
  std::vector<double> ring = {1, 0, -0.5, 0.75, -0.5, -0.75, 2, 0, -1, 1.5, -1, -1.5};
  Mesh m = meshOf(in, {0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 5, 0, 5, 6, 0, 6, 1}, {}, ring);
  EXPECT_ERROR(in, m, delaunay(), "vertex 0 (0, 0): its triangles wrap around it 2 times");
}

TEST(Validate, BoundaryFanWrapping) {
  // A fan at boundary vertex 0 turning 400 degrees in four 100-degree steps.
  Pslg in;
  in.points = {0, 0};
  std::vector<double> ring;
  for (int k = 0; k <= 4; ++k) {
    double a = k * 100 * 3.14159265358979 / 180, r = 1 + k;
    ring.insert(ring.end(), {r * std::cos(a), r * std::sin(a)});
  }
  Mesh m = meshOf(in, {0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 5}, {}, ring);
  EXPECT_ERROR(in, m, delaunay(), "of its triangles overlap along boundary edge 0->1");
}

TEST(Validate, MissingInputVertex) {
  Pslg in = square();
  in.points.insert(in.points.end(), {1.5, 0.5});
  Mesh m = meshOf(in, kSquareTris, kSquareSegs);
  EXPECT_ERROR(in, m, Options{},
               "vertex 4 (1.5, 0.5) is used by no triangle but lies in triangle 0 (0,1,2)");
  m.vertexKind = {0, 0, 0, 0, 0};
  EXPECT_ERROR(in, m, Options{}, "vertex 4 (1.5, 0.5) has kind input, expected unused");
  m = meshOf(square(), kSquareTris, kSquareSegs);
  EXPECT_ERROR(in, m, Options{}, "mesh has 4 vertices, fewer than the 5 input vertices");
}

TEST(Validate, SegmentNotInMesh) {
  Pslg in = square();
  in.segments.insert(in.segments.end(), {0, 2});  // the diagonal, but the mesh has 1-3
  Mesh m = meshOf(in, {0, 1, 3, 1, 2, 3}, kSquareSegs);
  EXPECT_ERROR(in, m, Options{},
               "input segment 4 (0->2) is not a chain of mesh edges: stops at vertex 0");
}

// A segment ending in the middle of a boundary edge that has no vertex there: from corner 0,
// exactly on the segment, the edge 0-1 (to (2,0)) runs past the segment's end (1,0).
TEST(Validate, EdgeRunningPastASegmentEnd) {
  Pslg in = square();
  in.points.insert(in.points.end(), {1, 0});
  in.segments.insert(in.segments.end(), {0, 4});
  Mesh m = meshOf(in, kSquareTris, kSquareSegs);
  EXPECT_ERROR(in, m, Options{},
               "input segment 4 (0->4) is not a chain of mesh edges: mesh edge 0-1 runs past 4");
}

TEST(Validate, TriangleInHole) {
  Pslg in = squareWithHole(false);
  std::vector<uint32_t> tris = kRingTris;
  tris.insert(tris.end(), {4, 5, 6, 4, 6, 7});
  Mesh m = meshOf(in, tris, kRingSegs);
  in.holes = {2.5, 1.5};
  EXPECT_ERROR(in, m, Options{}, "hole 0 (2.5, 1.5) lies inside triangle 8 (4,5,6)");
  in.holes = {2, 2};
  EXPECT_ERROR(in, m, Options{},
               "hole 0 (2, 2) lies on edge 6-4 between triangle 8 (4,5,6) and triangle 9 (4,6,7)");
  EXPECT_ERROR(in, m, withFill(FillRule::EvenOdd),
               "triangle 8 (4,5,6) lies where the winding number is 2, which EvenOdd leaves out");
}

TEST(Validate, RegionLeftOutThatTheRuleKeeps) {
  // Inner loop counter-clockwise: winding 2 inside, which NonZero keeps.
  Pslg in = squareWithHole(false);
  Mesh m = meshOf(in, kRingTris, kRingSegs);
  EXPECT_ERROR(in, m, withFill(FillRule::NonZero),
               "boundary edge 5->4 of triangle 1 (0,5,4): the region beyond it has winding number "
               "2, which NonZero keeps");
}

TEST(Validate, MissingTriangle) {
  Pslg in = square();
  Mesh m = meshOf(in, {0, 1, 2}, kSquareSegs);
  EXPECT_ERROR(in, m, Options{},
               "boundary edge 2->0 of triangle 0 (0,1,2) does not lie on an input segment");
  EXPECT_ERROR(in, m, Options{}, "mesh segment 2 (2-3) is not a mesh edge");
  in.segments.clear();
  m.segments.clear();
  EXPECT_ERROR(in, m, delaunay(),
               "boundary edge 2->0 of triangle 0 (0,1,2) is not a convex hull edge");
}

TEST(Validate, MovedVertex) {
  Pslg in = square();
  Mesh m = meshOf(in, kSquareTris, kSquareSegs);
  m.points[4] = 2.0000000000000004;
  EXPECT_ERROR(in, m, Options{},
               "mesh vertex 2 (2.0000000000000004, 2) differs from input vertex 2 (2, 2)");
}

TEST(Validate, IndexOutOfRange) {
  Pslg in = square();
  Mesh m = meshOf(in, {0, 1, 7, 0, 2, 3}, kSquareSegs);
  EXPECT_ERROR(in, m, Options{}, "triangle 0 (0,1,7) has index 7 out of range (4 vertices)");
  in.segments.insert(in.segments.end(), {0, 9});
  EXPECT_ERROR(in, meshOf(in, kSquareTris, kSquareSegs), Options{},
               "input segment 4 (0->9) refers to vertex 9");
}

TEST(Validate, MalformedArrays) {
  Pslg in = square();
  Mesh m = meshOf(in, kSquareTris, kSquareSegs);
  m.triangles.pop_back();
  EXPECT_ERROR(in, m, Options{}, "mesh triangles has length 5, not a multiple of 3");
  m = meshOf(in, kSquareTris, kSquareSegs);
  m.vertexKind = {0, 0};
  EXPECT_ERROR(in, m, Options{}, "vertexKind has 2 entries for 4 vertices");
  m = meshOf(in, kSquareTris, kSquareSegs);
  m.points[0] = std::nan("");
  EXPECT_ERROR(in, m, Options{}, "vertex 0 (nan, 0) is not finite");
}

TEST(Validate, MeshSegmentsList) {
  Pslg in = square();
  Mesh m = meshOf(in, kSquareTris, {0, 1, 1, 2, 2, 3});
  EXPECT_ERROR(in, m, Options{},
               "mesh edge 3-0 lies on an input segment but is missing from mesh segments");
  m.segments = {0, 1, 1, 2, 2, 3, 3, 0, 0, 2};
  EXPECT_ERROR(in, m, Options{}, "mesh segment 4 (0-2) lies on no input segment");
}

// A regular n x n grid of unit squares, two triangles each, bounded by four long segments
// (each a chain of n mesh edges).
void gridMesh(uint32_t n, Pslg& in, Mesh& m) {
  in = Pslg{};
  m = Mesh{};
  auto id = [&](uint32_t i, uint32_t j) { return j * (n + 1) + i; };
  for (uint32_t j = 0; j <= n; ++j)
    for (uint32_t i = 0; i <= n; ++i) in.points.insert(in.points.end(), {double(i), double(j)});
  m.points = in.points;
  in.segments = {id(0, 0), id(n, 0), id(n, 0), id(n, n), id(n, n), id(0, n), id(0, n), id(0, 0)};
  for (uint32_t j = 0; j < n; ++j)
    for (uint32_t i = 0; i < n; ++i) {
      uint32_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      m.triangles.insert(m.triangles.end(), {a, b, c, a, c, d});
    }
  for (uint32_t k = 0; k < n; ++k)
    m.segments.insert(m.segments.end(), {id(k, 0), id(k + 1, 0), id(n, k), id(n, k + 1),
                                         id(k + 1, n), id(k, n), id(0, k + 1), id(0, k)});
}

TEST(Validate, LargeGrid) {
  Pslg in;
  Mesh m;
  const uint32_t n = 500;  // 500,000 triangles
  gridMesh(n, in, m);
  auto start = std::chrono::steady_clock::now();
  EXPECT_VALID(in, m, Options{});
  EXPECT_VALID(in, m, withFill(FillRule::EvenOdd));
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("two validations of %zu triangles: %.3f s\n", m.triangleCount(), seconds);
  // One flipped diagonal deep inside is found among them.
  size_t t = 2 * (250 * n + 250);
  std::swap(m.triangles[3 * t + 1], m.triangles[3 * t + 2]);
  EXPECT_ERROR(in, m, Options{}, "is not counter-clockwise");
}

}  // namespace

// tests/data/bad/max-double-triangle.node, its triangle taken out and a hole point at minus
// infinity (the mean of its corners' y overflows): the points validate() locates then span more
// than the double range, and sizing its search grid by that span asked for an impossible vector
// (std::length_error natively, an abort in WebAssembly). Found by a differential run of the
// validate/ split against the old validate.cpp.
TEST(Validate, NonFiniteHoleBeyondTheDoubleRange) {
  const double big = 1.7976931348623157e308;
  Pslg in;
  in.points = {-big, -big, big, -big, 0, big};
  Options o;
  o.mode = Mode::Delaunay;
  acutemesh::Result r = acutemesh::mesh(in, o);
  ASSERT_EQ(r.mesh.triangleCount(), 1u);
  Mesh m = r.mesh;
  m.triangles.clear();
  in.holes = {0, -INFINITY};
  Validation v = acutemesh::validate(in, m, o);
  EXPECT_FALSE(v.ok);
  EXPECT_FALSE(v.errors.empty());
}
