// Sizes (Options::maxEdge, size, grading, Region::maxArea; core/src/size_field.h): every
// triangle of a refined mesh is at most as large as asked, in every refining mode, whole and
// by parts, scaled; the angle targets still hold; bad sizes are named. The sizes a triangle is
// held to are computed here from the options, independently of the library.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "acutemesh/acutemesh.h"
#include "acutemesh/io.h"
#include "acutemesh/predicates.h"
#include "fixtures.h"

using namespace acutemesh;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
const Mode kRefining[] = {Mode::Quality, Mode::NonObtuse, Mode::Acute};

const double* at(const Mesh& m, size_t t, int k) { return &m.points[2 * size_t(m.triangles[3 * t + k])]; }

double longestEdge(const Mesh& m, size_t t) {
  double longest = 0;
  for (int k = 0; k < 3; ++k) {
    const double *p = at(m, t, k), *q = at(m, t, (k + 1) % 3);
    longest = std::max(longest, std::hypot(p[0] - q[0], p[1] - q[1]));
  }
  return longest;
}

double area(const Mesh& m, size_t t) { return 0.5 * orient2d(at(m, t, 0), at(m, t, 1), at(m, t, 2)); }

void centroid(const Mesh& m, size_t t, double c[2]) {
  for (int d = 0; d < 2; ++d) c[d] = (at(m, t, 0)[d] + at(m, t, 1)[d] + at(m, t, 2)[d]) / 3;
}

// The largest ratio of a triangle's longest edge to h at its centroid.
double worstRatio(const Mesh& m, const std::function<double(double, double)>& h) {
  double worst = 0;
  for (size_t t = 0; t < m.triangleCount(); ++t) {
    double c[2];
    centroid(m, t, c);
    worst = std::max(worst, longestEdge(m, t) / h(c[0], c[1]));
  }
  return worst;
}

// A refined mesh that met its targets: valid, certified where the mode certifies.
void expectMet(const Pslg& in, const Options& o, const Result& r, const std::string& what) {
  ASSERT_EQ(r.status, Status::Ok) << what << ": " << r.message;
  EXPECT_TRUE(r.stats.targetMet) << what;
  EXPECT_EQ(fixtures::validationErrors(in, o, r.mesh), "") << what;
  if (o.mode != Mode::Quality) {
    EXPECT_TRUE(r.stats.certified) << what;
  }
  EXPECT_GT(r.stats.sizeRatio, 0) << what;
  EXPECT_LE(r.stats.sizeRatio, 1) << what;
}

Pslg plate() { return fixtures::load(fixtures::kData + "/plate.poly").pslg; }  // 200 x 100

// Two squares side by side split by a segment: left [0, 1] x [0, 1], right [1, 2] x [0, 1].
Pslg twoSquares(double leftArea, double rightArea) {
  Pslg in;
  in.points = {0, 0, 1, 0, 2, 0, 2, 1, 1, 1, 0, 1};
  in.segments = {0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 0, 1, 4};
  Region left, right;
  left.x = 0.5, left.y = 0.5, left.attribute = 1, left.maxArea = leftArea;
  right.x = 1.5, right.y = 0.5, right.attribute = 2, right.maxArea = rightArea;
  in.regions = {left, right};
  return in;
}

TEST(Sizes, MaxEdgeInEveryRefiningMode) {
  const Pslg in = plate();
  for (Mode mode : kRefining) {
    Options o;
    o.mode = mode;
    o.maxEdge = 8;
    const Result r = mesh(in, o);
    const std::string what = nameOf(mode);
    expectMet(in, o, r, what);
    const double worst = worstRatio(r.mesh, [](double, double) { return 8.0; });
    EXPECT_LE(worst, 1) << what;
    EXPECT_NEAR(worst, r.stats.sizeRatio, 1e-12) << what;
    // Not refined beyond need: most of the plate's area is in triangles near the bound.
    EXPECT_GT(worst, 0.7) << what;
    Options plain = o;
    plain.maxEdge = 0;
    EXPECT_GT(r.mesh.triangleCount(), mesh(in, plain).mesh.triangleCount()) << what;
  }
}

// Below 90 degrees too: maxAngle 85 met with the sizes, and 'auto' keeps them.
TEST(Sizes, BelowNinetyKeepsTheSizes) {
  const Pslg in = fixtures::load(fixtures::kData + "/A.poly").pslg;
  for (double bound : {85.0, kAutoMaxAngle}) {
    Options o;
    o.mode = Mode::Acute;
    o.maxAngle = bound;
    o.maxEdge = 0.05;
    const Result r = mesh(in, o);
    const std::string what = "maxAngle " + std::to_string(bound);
    expectMet(in, o, r, what);
    EXPECT_LE(worstRatio(r.mesh, [](double, double) { return 0.05; }), 1) << what;
    EXPECT_LT(r.stats.angleBound, 90) << what;
    if (bound > 0) {
      EXPECT_EQ(r.stats.angleBound, 85) << what;
    }
  }
}

// h = 0.8 + 0.05 x: the left end gets much smaller triangles than the right.
TEST(Sizes, FunctionGradesTheMesh) {
  const Pslg in = plate();
  auto h = [](double x, double) { return 0.8 + 0.05 * x; };
  for (Mode mode : kRefining) {
    Options o;
    o.mode = mode;
    o.size.function = h;
    const Result r = mesh(in, o);
    const std::string what = nameOf(mode);
    expectMet(in, o, r, what);
    EXPECT_LE(worstRatio(r.mesh, h), 1) << what;
    double left = 0, right = 0;
    size_t nLeft = 0, nRight = 0;
    for (size_t t = 0; t < r.mesh.triangleCount(); ++t) {
      double c[2];
      centroid(r.mesh, t, c);
      if (c[0] < 20) left += area(r.mesh, t), ++nLeft;
      if (c[0] > 180) right += area(r.mesh, t), ++nRight;
    }
    ASSERT_GT(nLeft, 0u);
    ASSERT_GT(nRight, 0u);
    EXPECT_GT((right / nRight) / (left / nLeft), 10) << what;
  }
}

// A grid, bilinear between its nodes and clamped outside, and the same sizes as a function:
// the grid's field is the one the mesh meets.
TEST(Sizes, GridIsBilinear) {
  const Pslg in = plate();
  Options o;
  o.mode = Mode::Acute;
  SizeField::Grid& g = o.size.grid;
  g.x0 = 0, g.y0 = 0, g.dx = 100, g.dy = 100, g.nx = 3, g.ny = 2;
  g.h = {1, 6, 12, 3, 6, 12};
  auto bilinear = [](double x, double y) {
    const double u = std::clamp(x / 100, 0.0, 2.0), v = std::clamp(y / 100, 0.0, 1.0);
    const double row0 = u <= 1 ? 1 + 5 * u : 6 + 6 * (u - 1);
    const double row1 = u <= 1 ? 3 + 3 * u : 6 + 6 * (u - 1);
    return (1 - v) * row0 + v * row1;
  };
  const Result r = mesh(in, o);
  expectMet(in, o, r, "grid");
  EXPECT_LE(worstRatio(r.mesh, bilinear), 1);
  EXPECT_GT(worstRatio(r.mesh, bilinear), 0.7);
}

// Scattered sizes over a triangle that covers the plate: the size is the plane through them.
TEST(Sizes, ScatteredPointsAreLinear) {
  const Pslg in = plate();
  Options o;
  o.mode = Mode::NonObtuse;
  o.size.points = {-10, -10, 400, -10, -10, 300};
  o.size.sizes = {1, 21.5, 16.5};  // h = 2 + 0.05 x + 0.05 y
  auto plane = [](double x, double y) { return 2 + 0.05 * x + 0.05 * y; };
  const Result r = mesh(in, o);
  expectMet(in, o, r, "points");
  EXPECT_LE(worstRatio(r.mesh, plane), 1 + 1e-6);  // (the plane sampled on the background grid)
  EXPECT_GT(worstRatio(r.mesh, plane), 0.6);
}

// Small triangles near one corner only (a size within 5 of the origin), and a large maxEdge:
// with grading g the sizes grow at most g per unit away from the corner, and the mesh has
// more triangles than without grading but far fewer than the small size everywhere.
TEST(Sizes, GradingLimitsHowFastSizesGrow) {
  const Pslg in = plate();
  Options o;
  o.mode = Mode::Acute;
  o.maxEdge = 30;
  o.size.function = [](double x, double y) { return std::hypot(x, y) < 5 ? 0.5 : kInf; };
  const Result sharp = mesh(in, o);
  expectMet(in, o, sharp, "no grading");
  o.grading = 0.3;
  const Result graded = mesh(in, o);
  expectMet(in, o, graded, "grading");
  // The background grid's cell (plate's 200 / 512) blurs the corner disk by a few cells; its
  // chamfer distance is within 1.4% of the Euclidean one.
  const double cell = 200.0 / 512;
  auto cone = [&](double x, double y) {
    return std::min(30.0, 0.5 + 0.3 * 1.02 * (std::max(0.0, std::hypot(x, y) - 5) + 3 * cell));
  };
  EXPECT_LE(worstRatio(graded.mesh, cone), 1);
  EXPECT_GT(graded.mesh.triangleCount(), 2 * sharp.mesh.triangleCount());
  // A mesh of edges 0.5 everywhere has at least the plate's area over an equilateral
  // triangle's of side 0.5 triangles.
  double plateArea = 0;
  for (size_t t = 0; t < graded.mesh.triangleCount(); ++t) plateArea += area(graded.mesh, t);
  EXPECT_LT(10 * graded.mesh.triangleCount(), plateArea / (std::sqrt(3) / 4 * 0.25));
}

// With maxEdge alone, grading spreads the input's small features (the airfoil's short edges
// at its nose and tail): the smaller the grading, the more triangles, every size still met.
TEST(Sizes, GradingSpreadsSmallFeatures) {
  const Pslg in = fixtures::load(fixtures::kData + "/naca0012.poly").pslg;
  size_t previous = 0;
  for (double grading : {0.0, 0.5, 0.2}) {
    Options o;
    o.mode = Mode::Acute;
    o.maxEdge = 0.5;
    o.grading = grading;
    const Result r = mesh(in, o);
    const std::string what = "grading " + std::to_string(grading);
    expectMet(in, o, r, what);
    EXPECT_TRUE(r.stats.warnings.empty()) << what << ": " << r.stats.warnings[0];
    EXPECT_GT(r.mesh.triangleCount(), previous + previous / 2) << what;
    previous = r.mesh.triangleCount();
  }
}

// Each region's maxArea bounds its own triangles (found by the side of the split at x = 1),
// with options.maxArea over both; an area function too.
TEST(Sizes, RegionAndFunctionAreaBounds) {
  const Pslg in = twoSquares(0.001, 0.02);
  for (Mode mode : kRefining) {
    Options o;
    o.mode = mode;
    const Result r = mesh(in, o);
    const std::string what = nameOf(mode);
    expectMet(in, o, r, what);
    size_t left = 0;
    for (size_t t = 0; t < r.mesh.triangleCount(); ++t) {
      double c[2];
      centroid(r.mesh, t, c);
      const double bound = c[0] < 1 ? 0.001 : 0.02;
      left += c[0] < 1;
      ASSERT_LE(area(r.mesh, t), bound) << what << " triangle " << t;
      ASSERT_EQ(r.mesh.triangleAttributes[t], c[0] < 1 ? 1 : 2) << what << " triangle " << t;
    }
    EXPECT_GT(left, r.mesh.triangleCount() / 2) << what;
    o.maxArea = 0.005;  // the smaller bound holds in each region
    const Result both = mesh(in, o);
    expectMet(in, o, both, what + " with maxArea");
    for (size_t t = 0; t < both.mesh.triangleCount(); ++t) {
      double c[2];
      centroid(both.mesh, t, c);
      ASSERT_LE(area(both.mesh, t), c[0] < 1 ? 0.001 : 0.005) << what << " triangle " << t;
    }
  }
  Options o;
  o.mode = Mode::Acute;
  auto bound = [](double x, double) { return 0.0005 + 0.01 * x; };
  o.size.maxArea = bound;
  const Pslg plain = twoSquares(0, 0);
  const Result r = mesh(plain, o);
  expectMet(plain, o, r, "area function");
  for (size_t t = 0; t < r.mesh.triangleCount(); ++t) {
    double c[2];
    centroid(r.mesh, t, c);
    ASSERT_LE(area(r.mesh, t), bound(c[0], c[1])) << "triangle " << t;
  }
}

// Coordinates 2^300 and 2^-300 times the plate's, the sizes scaled alike: the same mesh, scaled.
TEST(Sizes, ScaledInputsMeshAlike) {
  const Pslg in = plate();
  Options o;
  o.mode = Mode::Acute;
  o.maxEdge = 12;
  o.size.function = [](double x, double) { return 2 + 0.1 * x; };
  const Result base = mesh(in, o);
  expectMet(in, o, base, "plate");
  for (int e : {300, -300}) {
    Pslg scaled = in;
    for (double& v : scaled.points) v = std::ldexp(v, e);
    for (double& v : scaled.holes) v = std::ldexp(v, e);
    Options so = o;
    so.maxEdge = std::ldexp(12.0, e);
    so.size.function = [e](double x, double) { return std::ldexp(2 + 0.1 * std::ldexp(x, -e), e); };
    const Result r = mesh(scaled, so);
    const std::string what = "2^" + std::to_string(e);
    expectMet(scaled, so, r, what);
    EXPECT_EQ(r.mesh.triangles, base.mesh.triangles) << what;
    ASSERT_EQ(r.mesh.points.size(), base.mesh.points.size()) << what;
    for (size_t i = 0; i < r.mesh.points.size(); ++i)
      ASSERT_EQ(r.mesh.points[i], std::ldexp(base.mesh.points[i], e)) << what << " coordinate " << i;
    EXPECT_EQ(r.stats.sizeRatio, base.stats.sizeRatio) << what;
  }
}

// Many islands (meshed part by part): one thread or two give the same mesh, each island's
// region bound and the size field met.
TEST(Sizes, ByPartsOnAnyThreads) {
  Pslg in = fixtures::archipelago(16, 300, [](int, double) { return 1.0; });
  for (Region& g : in.regions) g.maxArea = int(g.attribute) % 2 ? 0.004 : 0;
  Options o;
  o.mode = Mode::Acute;
  o.size.function = [](double x, double) { return 0.1 + 0.04 * x; };
  o.threads = 1;
  const Result one = mesh(in, o);
  expectMet(in, o, one, "one thread");
  const Mesh& m = one.mesh;
  for (size_t t = 0; t < m.triangleCount(); ++t) {
    double c[2];
    centroid(m, t, c);
    ASSERT_LE(longestEdge(m, t), 0.1 + 0.04 * c[0]) << "triangle " << t;
    if (int(m.triangleAttributes[t]) % 2) {
      ASSERT_LE(area(m, t), 0.004) << "triangle " << t;
    }
  }
  o.threads = 2;
  const Result two = mesh(in, o);
  EXPECT_EQ(two.mesh.triangles, m.triangles);
  EXPECT_EQ(two.mesh.points, m.points);
}

// A size far below what the Steiner budget allows: the budget ends the run with the best
// certified mesh, said, never an uncertified one.
TEST(Sizes, BudgetEndsATinySize) {
  const Pslg in = plate();
  Options o;
  o.mode = Mode::Acute;
  o.maxEdge = 0.01;
  o.maxSteiner = 5000;
  const Result r = mesh(in, o);
  ASSERT_EQ(r.status, Status::TargetNotMet) << r.message;
  EXPECT_FALSE(r.stats.targetMet);
  EXPECT_TRUE(r.stats.certified);
  EXPECT_GT(r.stats.sizeRatio, 1);
  EXPECT_EQ(fixtures::validationErrors(in, o, r.mesh), "");
}

TEST(Sizes, BadSizesAreNamed) {
  const Pslg in = plate();
  struct Case {
    const char* says;
    std::function<void(Options&)> set;
  };
  const Case cases[] = {
      {"maxEdge must be a finite number >= 0", [](Options& o) { o.maxEdge = -1; }},
      {"maxEdge must be a finite number >= 0", [](Options& o) { o.maxEdge = kInf; }},
      {"maxEdge must be a finite number >= 0", [](Options& o) { o.maxEdge = std::nan(""); }},
      {"grading must be a finite number >= 0", [](Options& o) { o.grading = -0.1; }},
      {"h must hold nx * ny = 6 values, found 5",
       [](Options& o) { o.size.grid.nx = 3, o.size.grid.ny = 2, o.size.grid.h.assign(5, 1); }},
      {"dx, dy finite and > 0",
       [](Options& o) { o.size.grid.nx = 1, o.size.grid.ny = 1, o.size.grid.dx = 0, o.size.grid.h = {1}; }},
      {"size grid: h[1] must be > 0, found -2",
       [](Options& o) { o.size.grid.nx = 2, o.size.grid.ny = 1, o.size.grid.h = {1, -2}; }},
      {"size points: 4 coordinates for 1 sizes", [](Options& o) { o.size.points = {0, 0, 1, 1}, o.size.sizes = {1}; }},
      {"size point 1: its size must be > 0, found 0",
       [](Options& o) { o.size.points = {0, 0, 1, 1}, o.size.sizes = {1, 0}; }},
      {"size point 0 must have finite coordinates",
       [](Options& o) { o.size.points = {std::nan(""), 0}, o.size.sizes = {1}; }},
      {"the size function returned -1 at (",
       [](Options& o) { o.size.function = [](double, double) { return -1.0; }; }},
      {"the size function returned nan at (",
       [](Options& o) { o.size.function = [](double x, double) { return x > 150 ? std::nan("") : 5.0; }; }},
      {"the maxArea function returned 0 at (",
       [](Options& o) { o.size.maxArea = [](double, double) { return 0.0; }; }},
  };
  for (const Case& c : cases) {
    for (Mode mode : kRefining) {
      Options o;
      o.mode = mode;
      c.set(o);
      const Result r = mesh(in, o);
      EXPECT_EQ(r.status, Status::BadInput) << c.says << " " << nameOf(mode);
      EXPECT_NE(r.message.find(c.says), std::string::npos) << r.message;
      EXPECT_EQ(r.mesh.triangleCount(), 0u) << c.says;
    }
  }
}

TEST(Sizes, NoEffectIsSaid) {
  const Pslg in = plate();
  Options o;
  o.mode = Mode::Cdt;
  o.maxEdge = 5;
  Result r = mesh(in, o);
  ASSERT_EQ(r.status, Status::Ok);
  ASSERT_EQ(r.stats.warnings.size(), 1u);
  EXPECT_NE(r.stats.warnings[0].find("sizes have no effect in mode cdt"), std::string::npos);
  o.mode = Mode::Acute;
  o.maxEdge = 0;
  o.grading = 0.3;
  r = mesh(in, o);
  ASSERT_EQ(r.status, Status::Ok);
  ASSERT_EQ(r.stats.warnings.size(), 1u);
  EXPECT_NE(r.stats.warnings[0].find("grading has no effect without maxEdge or a size"), std::string::npos);
  EXPECT_EQ(r.stats.sizeRatio, 0);
}

TEST(Sizes, SizeFiles) {
  SizeField s;
  ParseResult p = parseSizeField(
      R"({"grid": {"x0": 0, "y0": -1, "dx": 0.5, "dy": 2, "nx": 2, "ny": 2, "h": [1, 2, 3, 4]},
          "points": [[0, 0, 0.25], [3, 4, 1e3]]})",
      "s.json", s);
  ASSERT_TRUE(p.ok) << p.message;
  EXPECT_EQ(s.grid.x0, 0);
  EXPECT_EQ(s.grid.y0, -1);
  EXPECT_EQ(s.grid.dx, 0.5);
  EXPECT_EQ(s.grid.dy, 2);
  EXPECT_EQ(s.grid.nx, 2u);
  EXPECT_EQ(s.grid.ny, 2u);
  EXPECT_EQ(s.grid.h, (std::vector<double>{1, 2, 3, 4}));
  EXPECT_EQ(s.points, (std::vector<double>{0, 0, 3, 4}));
  EXPECT_EQ(s.sizes, (std::vector<double>{0.25, 1e3}));
  const std::pair<const char*, const char*> bad[] = {
      {R"({"grid": {"x0": 0, "y0": 0, "dx": 1, "dy": 1, "nx": 2, "ny": 1, "h": [1, -1]}})",
       "s.json:1: expected sizes > 0 in \"h\", found -1"},
      {"{\"points\": [[0, 0, 1],\n [1, 1]]}", "s.json:2:"},
      {R"({"points": [[0, 0, 0]]})", "expected a size > 0 in [x, y, size], found 0"},
      {R"({"grid": {"x0": 0}})", "s.json:1:"},
      {R"([1, 2])", "s.json:1:"},
      {"", "s.json"},
  };
  for (const auto& [text, says] : bad) {
    SizeField out;
    const ParseResult r = parseSizeField(text, "s.json", out);
    EXPECT_FALSE(r.ok) << text;
    EXPECT_NE(r.message.find(says), std::string::npos) << text << " -> " << r.message;
    EXPECT_TRUE(out.grid.h.empty() && out.points.empty()) << text;
  }
  // A .node: the first attribute is the size, the others and a marker ignored.
  SizeField n;
  p = parseSizeNode("# sizes\n3 2 2 1\n1 0 0 0.5 9 1\n2 2 0 1.5 9 0\n3 0 2 2 9 0\n", "s.node", n);
  ASSERT_TRUE(p.ok) << p.message;
  EXPECT_EQ(n.points, (std::vector<double>{0, 0, 2, 0, 0, 2}));
  EXPECT_EQ(n.sizes, (std::vector<double>{0.5, 1.5, 2}));
  const std::pair<const char*, const char*> badNode[] = {
      {"2 2 0 0\n1 0 0\n2 1 0\n", "s.node:1: expected at least one attribute per vertex (its size)"},
      {"2 2 1 0\n1 0 0 1\n2 1 0 0\n", "s.node: vertex 2: expected a size > 0 (its first attribute), found 0"},
      {"2 2 1 0\n1 0 0 1\n2 1 0\n", "s.node: vertex 2: expected a size > 0 (its first attribute), found 0"},
      {"2 2 1 0\n1 0 0 1\n2 1 0 big\n", "s.node:3: expected attribute 1 (a number), found 'big'"},
      {"3 2 1 0\n1 0 0 1\n", "s.node:1: expected a vertex count the rest of the text can hold"},
  };
  for (const auto& [text, says] : badNode) {
    SizeField out;
    const ParseResult r = parseSizeNode(text, "s.node", out);
    EXPECT_FALSE(r.ok) << text;
    EXPECT_NE(r.message.find(says), std::string::npos) << text << " -> " << r.message;
    EXPECT_TRUE(out.points.empty()) << text;
  }
}

// Every fixture of tests/data (.poly) in every refining mode with a max edge of a sixteenth
// of its box: every edge within it, the angle target met.
// Inside an input corner below the minimum angle, quality refinement leaves its skinny
// triangles (they cannot meet the angle), but not one too big for its size or area bound.
TEST(Sizes, MetInsideSmallInputAngles) {
  const Pslg in = fixtures::load(fixtures::kData + "/angles/wedge-20.poly").pslg;  // 10 long
  for (int area = 0; area < 2; ++area) {
    Options o;
    o.mode = Mode::Quality;
    o.minAngle = 30;
    (area ? o.maxArea : o.maxEdge) = area ? 0.05 : 0.5;
    const std::string what = area ? "maxArea 0.05" : "maxEdge 0.5";
    const Result r = mesh(in, o);
    EXPECT_EQ(r.status, Status::TargetNotMet) << what << ": " << r.message;  // (the 20 degrees)
    EXPECT_EQ(fixtures::validationErrors(in, o, r.mesh), "") << what;
    if (area) {
      EXPECT_LE(fixtures::largestTriangleArea(r.mesh), 0.05) << what;
    } else {
      // (Segment pieces of exactly the size, 10 / 20: a rounding either way.)
      EXPECT_LE(r.stats.sizeRatio, 1) << what;
      EXPECT_LE(worstRatio(r.mesh, [](double, double) { return 0.5; }), 1 + 1e-12) << what;
    }
  }
}

TEST(Sizes, EveryFixtureMeetsMaxEdge) {
  for (const char* name : {"A.poly", "plate.poly", "naca0012.poly", "io/marked-regions.poly", "io/regions.poly", "io/enclave.poly"}) {
    const Pslg in = fixtures::load(fixtures::kData + "/" + name).pslg;
    double lo[2] = {kInf, kInf}, hi[2] = {-kInf, -kInf};
    for (size_t i = 0; i < in.points.size(); ++i)
      lo[i % 2] = std::min(lo[i % 2], in.points[i]), hi[i % 2] = std::max(hi[i % 2], in.points[i]);
    const double h = std::max(hi[0] - lo[0], hi[1] - lo[1]) / 16;
    for (Mode mode : kRefining) {
      Options o;
      o.mode = mode;
      o.maxEdge = h;
      const Result r = mesh(in, o);
      const std::string what = std::string(name) + " " + nameOf(mode);
      expectMet(in, o, r, what);
      EXPECT_LE(worstRatio(r.mesh, [h](double, double) { return h; }), 1) << what;
    }
  }
}

}  // namespace
