// mesh() end to end: every fixture, also rotated, mirrored, scaled and translated, gives a mesh
// that validate() accepts, covering exactly the domain's area; bad input gives clear errors.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "acutemesh/acutemesh.h"
#include "acutemesh/io.h"
#include "acutemesh/predicates.h"
#include "fixtures.h"

using namespace acutemesh;

namespace {

using fixtures::cgshopInstances;
using fixtures::kData;
using fixtures::load;

double meshArea(const Mesh& m) {
  double area = 0;
  for (size_t t = 0; t < m.triangleCount(); ++t) {
    const double *a = &m.points[2 * m.triangles[3 * t]], *b = &m.points[2 * m.triangles[3 * t + 1]],
                 *c = &m.points[2 * m.triangles[3 * t + 2]];
    area += 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
  }
  return area;
}

// Area enclosed by the input's closed loops of segments, for inputs made of disjoint simple
// loops (outer boundary and holes): the largest loop minus the others.
double loopsArea(const Pslg& in) {
  size_t n = in.vertexCount();
  std::vector<std::vector<uint32_t>> adjacent(n);
  for (size_t s = 0; s < in.segmentCount(); ++s) {
    adjacent[in.segments[2 * s]].push_back(in.segments[2 * s + 1]);
    adjacent[in.segments[2 * s + 1]].push_back(in.segments[2 * s]);
  }
  std::vector<uint8_t> seen(n, 0);
  std::vector<double> loops;
  for (size_t start = 0; start < n; ++start) {
    if (seen[start] || adjacent[start].size() != 2) continue;
    double twice = 0;
    uint32_t prev = uint32_t(start), at = adjacent[start][0];
    seen[start] = 1;
    while (true) {
      const double *p = &in.points[2 * prev], *q = &in.points[2 * at];
      twice += p[0] * q[1] - p[1] * q[0];
      if (at == start) break;
      seen[at] = 1;
      uint32_t next = adjacent[at][0] == prev ? adjacent[at][1] : adjacent[at][0];
      prev = at, at = next;
    }
    loops.push_back(std::fabs(twice) / 2);
  }
  double largest = 0, total = 0;
  for (double a : loops) largest = std::max(largest, a), total += a;
  return 2 * largest - total;
}

// The same PSLG under an exact (or, for translation, nearly exact) transformation.
Pslg transformed(const Pslg& in, int kind) {
  Pslg out = in;
  auto apply = [&](std::vector<double>& xy) {
    for (size_t i = 0; i + 1 < xy.size(); i += 2) {
      double x = xy[i], y = xy[i + 1];
      switch (kind) {
        case 0: xy[i] = -y, xy[i + 1] = x; break;                       // rotate 90
        case 1: xy[i] = -x, xy[i + 1] = -y; break;                      // rotate 180
        case 2: xy[i] = y, xy[i + 1] = -x; break;                       // rotate 270
        case 3: xy[i] = -x; break;                                      // mirror
        case 4: xy[i] = std::ldexp(x, 20), xy[i + 1] = std::ldexp(y, 20); break;
        case 5: xy[i] = std::ldexp(x, -20), xy[i + 1] = std::ldexp(y, -20); break;
        case 6: xy[i] = x + 1048576.0, xy[i + 1] = y + 1048576.0; break;  // translate 2^20
      }
    }
  };
  apply(out.points);
  apply(out.holes);
  return out;
}
const char* kTransformNames[] = {"rot90", "rot180", "rot270", "mirror", "scale2^20",
                                 "scale2^-20", "translate2^20"};

void expectValid(const Pslg& in, const Options& options, const Result& r, const std::string& what) {
  ASSERT_EQ(r.status, Status::Ok) << what << ": " << r.message;
  EXPECT_EQ(fixtures::validationErrors(in, options, r.mesh), "") << what;
}

// The CDT of a .poly of simple loops, also transformed: valid, covering the loops' area.
void expectPolyAndTransformsMeshed(const std::string& path) {
  Input in = load(path);
  Options options;
  Result base = mesh(in.pslg, options);
  expectValid(in.pslg, options, base, path);
  double expected = loopsArea(in.pslg);
  EXPECT_NEAR(meshArea(base.mesh), expected, 1e-12 * expected) << path;
  EXPECT_EQ(base.stats.steiner, 0u);
  for (int kind = 0; kind < 7; ++kind) {
    Pslg moved = transformed(in.pslg, kind);
    Result r = mesh(moved, options);
    std::string what = path + " " + kTransformNames[kind];
    expectValid(moved, options, r, what);
    if (kind < 6) {
      EXPECT_EQ(r.mesh.triangleCount(), base.mesh.triangleCount()) << what;
    }
  }
}

}  // namespace

TEST(Mesh, PolyFixturesAndTheirTransforms) {
  for (const char* name : {"A.poly", "plate.poly", "naca0012.poly"})
    expectPolyAndTransformsMeshed(kData + "/" + name);
}

TEST(Mesh, SuperiorAndItsTransforms) {
  ACUTEMESH_NEED_REFERENCE_DATA();
  expectPolyAndTransformsMeshed(reference::file("poly/superior.poly"));
}

TEST(Mesh, PolyHoleCountsAndSegments) {
  Input in = load(kData + "/A.poly");
  Result r = mesh(in.pslg);
  // A polygon with h holes and n vertices, all on its boundary, has n + 2h - 2 triangles.
  EXPECT_EQ(r.mesh.triangleCount(), 29u + 2 * 1 - 2);
  EXPECT_EQ(r.mesh.segments.size() / 2, 29u);
  Options hull;
  hull.convexHull = true;
  Result withHull = mesh(in.pslg, hull);
  expectValid(in.pslg, hull, withHull, "A.poly --convex-hull");
  EXPECT_GT(withHull.mesh.triangleCount(), r.mesh.triangleCount());
}

namespace {

// Each instance's CDT, also turned, mirrored and moved: valid, covering the region boundary.
void expectInstancesMeshed(const std::vector<std::string>& files) {
  for (const std::string& path : files) {
    Input in = load(path);
    Options options;
    Result r = mesh(in.pslg, options);
    expectValid(in.pslg, options, r, path);
    // The domain is the region boundary (the parser lists it first, as a closed ring);
    // constraints lie inside it.
    const std::vector<uint32_t>& s = in.pslg.segments;
    double twice = 0;
    for (size_t i = 0; i < s.size() / 2; ++i) {
      const double *p = &in.pslg.points[2 * s[2 * i]], *q = &in.pslg.points[2 * s[2 * i + 1]];
      twice += p[0] * q[1] - p[1] * q[0];
      if (s[2 * i + 1] == s[0]) break;
    }
    EXPECT_NEAR(meshArea(r.mesh), twice / 2, 1e-9 * std::fabs(twice)) << path;
    for (int kind : {0, 3, 6}) {
      Pslg moved = transformed(in.pslg, kind);
      expectValid(moved, options, mesh(moved, options), path + " " + kTransformNames[kind]);
    }
  }
}

}  // namespace

TEST(Mesh, AllCgshopInstances) {
  ACUTEMESH_NEED_REFERENCE_DATA();
  std::vector<std::string> files = cgshopInstances(reference::file("cgshop2025"));
  ASSERT_EQ(files.size(), 150u);
  expectInstancesMeshed(files);
}

TEST(Mesh, SyntheticCgshopInstances) {
  std::vector<std::string> files = cgshopInstances(fixtures::kSyntheticCgshop);
  ASSERT_EQ(files.size(), fixtures::kSyntheticCgshopCount);
  expectInstancesMeshed(files);
}

TEST(Mesh, DelaunayOfRandomPointsAndTransforms) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-3, 3);
  Pslg in;
  for (int i = 0; i < 2000; ++i) in.points.push_back(u(rng)), in.points.push_back(u(rng));
  Options options;
  options.mode = Mode::Delaunay;
  Result base = mesh(in, options);
  expectValid(in, options, base, "random");
  for (int kind = 0; kind < 7; ++kind) {
    Pslg moved = transformed(in, kind);
    Result r = mesh(moved, options);
    expectValid(moved, options, r, kTransformNames[kind]);
    if (kind < 6) {
      EXPECT_EQ(r.mesh.triangleCount(), base.mesh.triangleCount());
    }
  }
  // Empty circumcircles, checked exactly on a sample of triangles.
  for (size_t t = 0; t < base.mesh.triangleCount(); t += 37) {
    const uint32_t* v = &base.mesh.triangles[3 * t];
    for (size_t p = 0; p < in.vertexCount(); ++p)
      ASSERT_LE(incircle(&in.points[2 * v[0]], &in.points[2 * v[1]], &in.points[2 * v[2]],
                         &in.points[2 * p]),
                0);
  }
}

TEST(Mesh, CrossingOverlappingAndTouchingSegments) {
  Pslg in;
  // A square, its two diagonals (crossing in the middle), a segment overlapping the bottom
  // edge, and a vertex lying on the right edge.
  in.points = {0, 0, 4, 0, 4, 4, 0, 4, 1, 0, 6, 0, 4, 1.5};
  in.segments = {0, 1, 1, 2, 2, 3, 3, 0, 0, 2, 1, 3, 4, 1};
  Options options;
  options.convexHull = true;  // segment 4-5 sticks out of the square
  in.segments.push_back(4), in.segments.push_back(5);
  Result r = mesh(in, options);
  expectValid(in, options, r, "crossings");
  EXPECT_EQ(r.stats.steiner, 1u);  // the diagonals' crossing (2, 2)
  ASSERT_EQ(r.mesh.vertexCount(), 8u);
  EXPECT_EQ(r.mesh.points[14], 2.0);
  EXPECT_EQ(r.mesh.points[15], 2.0);
  EXPECT_EQ(r.mesh.vertexKind[7], kSegmentVertex);
}

TEST(Mesh, DuplicateVerticesKeepTheirIndices) {
  Pslg in;
  in.points = {0, 0, 1, 0, 1, 1, 0, 1, 1, 0, 0.5, 0.5};
  in.segments = {0, 1, 4, 2, 2, 3, 3, 0};  // 4 duplicates 1
  Result r = mesh(in);
  expectValid(in, {}, r, "duplicates");
  EXPECT_EQ(r.stats.duplicates, 1u);
  EXPECT_EQ(r.mesh.vertexKind[4], kUnusedVertex);
  EXPECT_EQ(r.mesh.vertexKind[1], kInputVertex);
  EXPECT_EQ(r.mesh.points[8], 1.0);
  EXPECT_EQ(r.mesh.triangleCount(), 4u);
}

TEST(Mesh, FillRulesDecideHolesByNesting) {
  // Outer square counter-clockwise; inner square given clockwise, then counter-clockwise.
  Pslg in;
  in.points = {0, 0, 10, 0, 10, 10, 0, 10, 3, 3, 3, 7, 7, 7, 7, 3};
  in.segments = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4};
  for (FillRule rule : {FillRule::EvenOdd, FillRule::NonZero}) {
    Options options;
    options.fill = rule;
    Result r = mesh(in, options);
    expectValid(in, options, r, "clockwise hole");
    EXPECT_NEAR(meshArea(r.mesh), 100 - 16, 1e-12);
  }
  Pslg same = in;
  same.segments = {0, 1, 1, 2, 2, 3, 3, 0, 4, 7, 7, 6, 6, 5, 5, 4};  // inner counter-clockwise
  Options evenOdd, nonZero;
  evenOdd.fill = FillRule::EvenOdd;
  nonZero.fill = FillRule::NonZero;
  Result a = mesh(same, evenOdd), b = mesh(same, nonZero);
  expectValid(same, evenOdd, a, "evenodd");
  expectValid(same, nonZero, b, "nonzero");
  EXPECT_NEAR(meshArea(a.mesh), 84, 1e-12);
  EXPECT_NEAR(meshArea(b.mesh), 100, 1e-12);  // winding 2 inside: filled
}

TEST(Mesh, TriangleFillWithHolePoint) {
  Pslg in;
  in.points = {0, 0, 10, 0, 10, 10, 0, 10, 3, 3, 3, 7, 7, 7, 7, 3};
  in.segments = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4};
  Result filled = mesh(in);
  expectValid(in, {}, filled, "no hole point");
  EXPECT_NEAR(meshArea(filled.mesh), 100, 1e-12);
  in.holes = {5, 5};
  Result holed = mesh(in);
  expectValid(in, {}, holed, "hole point");
  EXPECT_NEAR(meshArea(holed.mesh), 84, 1e-12);
}

// A constrained Delaunay triangulation reports the domain's corners as refinement would (a
// triangle with a 30-degree corner: floor 75), and says that refinement targets given with it
// do nothing rather than ignore them silently.
TEST(Mesh, CdtReportsTheFloorAndIgnoredTargets) {
  Pslg in;
  const double t = std::tan(30 * M_PI / 180);
  in.points = {0, 0, 10, 0, 10, 10 * t};
  in.segments = {0, 1, 1, 2, 2, 0};
  Options o;
  o.mode = Mode::Cdt;
  Result r = mesh(in, o);
  ASSERT_EQ(r.status, Status::Ok) << r.message;
  EXPECT_NEAR(r.stats.smallestDomainAngle, 30, 1e-9);
  EXPECT_NEAR(r.stats.angleFloor, 75, 1e-9);
  EXPECT_NEAR(r.stats.smallestInputAngle, 30, 1e-9);
  EXPECT_TRUE(r.stats.warnings.empty());
  for (auto set : {+[](Options& x) { x.minAngle = 30; }, +[](Options& x) { x.maxAngle = 80; },
                   +[](Options& x) { x.maxArea = 1; }}) {
    Options with = o;
    set(with);
    r = mesh(in, with);
    ASSERT_EQ(r.stats.warnings.size(), 1u);
    EXPECT_NE(r.stats.warnings[0].find("no effect in mode cdt"), std::string::npos)
        << r.stats.warnings[0];
    EXPECT_EQ(r.mesh.triangles.size(), 3u);
  }
}

TEST(Mesh, BadInputIsAClearError) {
  struct Case {
    Pslg in;
    const char* expect;
  };
  Pslg collinear, tooFew, badIndex, nan, odd, same;
  collinear.points = {0, 0, 1, 1, 2, 2, 3, 3};
  tooFew.points = {0, 0, 1, 0};
  badIndex.points = {0, 0, 1, 0, 0, 1};
  badIndex.segments = {0, 3};
  nan.points = {0, 0, 1, 0, NAN, 1};
  odd.points = {0, 0, 1};
  same.points = {2, 2, 2, 2, 2, 2};
  for (const Case& c : {Case{collinear, "collinear"}, Case{tooFew, "at least 3"},
                        Case{badIndex, "segment 0 refers to vertex 3"},
                        Case{nan, "vertex 2 has a non-finite"}, Case{odd, "odd length"},
                        Case{same, "coincide"}}) {
    Result r = mesh(c.in);
    EXPECT_EQ(r.status, Status::BadInput) << c.expect;
    EXPECT_NE(r.message.find(c.expect), std::string::npos) << r.message;
    EXPECT_EQ(r.mesh.triangleCount(), 0u);
  }
}

// 100 random points and one segment: fill 'triangle' eats the whole hull (nothing is
// enclosed). That is an error naming the rule and the way out, in every constrained mode.
TEST(Mesh, EmptyDomainIsAnErrorThatSaysWhy) {
  std::mt19937_64 rng(24);
  std::uniform_real_distribution<double> u(0, 1);
  Pslg in;
  for (int i = 0; i < 100; ++i) in.points.push_back(u(rng)), in.points.push_back(u(rng));
  in.segments = {0, 1};
  for (Mode mode : {Mode::Cdt, Mode::Quality, Mode::NonObtuse, Mode::Acute}) {
    Options o;
    o.mode = mode;
    const Result r = mesh(in, o);
    EXPECT_EQ(r.status, Status::BadInput) << nameOf(mode);
    EXPECT_NE(r.message.find("the domain is empty"), std::string::npos) << r.message;
    EXPECT_NE(r.message.find("convexHull"), std::string::npos) << r.message;
    EXPECT_EQ(r.mesh.triangleCount(), 0u);
  }
  Options hull;
  hull.convexHull = true;
  EXPECT_EQ(mesh(in, hull).status, Status::Ok);

  // The other fill rules: the segment encloses nothing.
  Options evenOdd;
  evenOdd.fill = FillRule::EvenOdd;
  const Result r = mesh(in, evenOdd);
  EXPECT_EQ(r.status, Status::BadInput);
  EXPECT_NE(r.message.find("no region lies inside an odd number of rings"), std::string::npos)
      << r.message;

  // A hole point in the only region.
  Pslg square;
  square.points = {0, 0, 1, 0, 1, 1, 0, 1};
  square.segments = {0, 1, 1, 2, 2, 3, 3, 0};
  square.holes = {0.5, 0.5};
  const Result holed = mesh(square);
  EXPECT_EQ(holed.status, Status::BadInput);
  EXPECT_NE(holed.message.find("the hole point's region is all of it"), std::string::npos)
      << holed.message;
}

TEST(Mesh, CancelAndTimeLimitStopEarly) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(0, 1);
  Pslg in;
  for (int i = 0; i < 200000; ++i) in.points.push_back(u(rng)), in.points.push_back(u(rng));
  std::atomic<bool> cancel{true};
  Options options;
  options.cancel = &cancel;
  Result r = mesh(in, options);
  EXPECT_EQ(r.status, Status::Cancelled);
  EXPECT_FALSE(r.message.empty());
}

TEST(Mesh, ZeroLengthSegmentWarns) {
  Pslg in;
  in.points = {0, 0, 1, 0, 0, 1};
  in.segments = {0, 1, 1, 2, 2, 0, 1, 1};
  Result r = mesh(in);
  expectValid(in, {}, r, "zero length");
  ASSERT_FALSE(r.stats.warnings.empty());
  EXPECT_NE(r.stats.warnings[0].find("segment 3 has zero length"), std::string::npos);
}

// Random PSLGs on a small lattice: many collinear overlaps, vertices on segments, crossings
// through vertices and through each other, duplicates.
TEST(Mesh, RandomDegenerateLatticePslgs) {
  std::mt19937_64 rng(21);
  for (int round = 0; round < 300; ++round) {
    Pslg in;
    int n = 6 + int(rng() % 30), grid = 3 + int(rng() % 8);
    for (int i = 0; i < n; ++i)
      in.points.push_back(double(rng() % grid)), in.points.push_back(double(rng() % grid));
    in.points.insert(in.points.end(), {-1, -1, double(grid), -1, 0, double(grid)});
    int segments = int(rng() % 25);
    for (int s = 0; s < segments; ++s)
      in.segments.push_back(uint32_t(rng() % n)), in.segments.push_back(uint32_t(rng() % n));
    for (FillRule fill : {FillRule::Triangle, FillRule::EvenOdd, FillRule::NonZero}) {
      Options options;
      options.fill = fill;
      options.convexHull = round % 2;
      const Result r = mesh(in, options);
      // Random segments may enclose nothing: an empty domain is an error, with nothing meshed.
      if (r.status == Status::BadInput && r.message.rfind("the domain is empty", 0) == 0) {
        EXPECT_FALSE(fill == FillRule::Triangle && options.convexHull) << "round " << round;
        EXPECT_EQ(r.mesh.triangleCount(), 0u);
        continue;
      }
      expectValid(in, options, r, "round " + std::to_string(round));
      if (HasFailure()) return;
    }
  }
}

// Found by a hostile-input smoke test: at 1e300 the predicates' products overflowed and at
// 1e-300 they underflowed (three non-collinear points were called collinear). Such inputs
// are now scaled by a power of two, meshed and scaled back, exactly.
TEST(Mesh, CoordinatesFarFromOneAreScaledExactly) {
  Input in = load(kData + "/A.poly");
  Result base = mesh(in.pslg);
  for (int exponent : {1000, -1000, 200, -200}) {
    Pslg far = in.pslg;
    for (double& x : far.points) x = std::ldexp(x, exponent);
    for (double& x : far.holes) x = std::ldexp(x, exponent);
    for (Mode mode : {Mode::Cdt, Mode::Acute}) {
      Options o;
      o.mode = mode;
      Result r = mesh(far, o);
      expectValid(far, o, r, "2^" + std::to_string(exponent));
      if (mode == Mode::Cdt) {
        EXPECT_EQ(r.mesh.triangleCount(), base.mesh.triangleCount());
      }
      else EXPECT_TRUE(r.stats.certified);
    }
  }
  Pslg spread;
  spread.points = {0, 0, 1e300, 0, 0, 1e300, 1e-300, 1e-300};
  Result r = mesh(spread);
  EXPECT_EQ(r.status, Status::BadInput);
  EXPECT_NE(r.message.find("orders of magnitude"), std::string::npos) << r.message;
}
