// Maximum angles below 90 degrees: the domain's smallest corner and the floor it sets
// (Stats::smallestDomainAngle, angleFloor), the exact certificate of a bound (AngleCheck,
// Stats::angleBound), maxAngle auto, and a bound below the floor.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "acutemesh/acutemesh.h"
#include "angle_bound.h"
#include "build.h"
#include "exact.h"
#include "fixtures.h"

using namespace acutemesh;

namespace {

using fixtures::kData;

Pslg polygon(std::vector<double> points) {
  Pslg in;
  in.points = std::move(points);
  const uint32_t n = uint32_t(in.vertexCount());
  for (uint32_t i = 0; i < n; ++i) in.segments.insert(in.segments.end(), {i, (i + 1) % n});
  return in;
}

Stats statsOf(const Pslg& in, Mode mode = Mode::NonObtuse) {
  Options o;
  o.mode = mode;
  Result r = mesh(in, o);
  EXPECT_EQ(r.status, Status::Ok) << r.message;
  return r.stats;
}

// Every angle of the mesh below `bound`, by acos in long double (a check apart from AngleCheck).
void expectAnglesBelow(const Mesh& m, double bound, const std::string& what) {
  for (size_t t = 0; t < m.triangleCount(); ++t)
    for (int k = 0; k < 3; ++k) {
      const double* a = &m.points[2 * size_t(m.triangles[3 * t + k])];
      const double* b = &m.points[2 * size_t(m.triangles[3 * t + (k + 1) % 3])];
      const double* c = &m.points[2 * size_t(m.triangles[3 * t + (k + 2) % 3])];
      long double ux = (long double)b[0] - a[0], uy = (long double)b[1] - a[1];
      long double vx = (long double)c[0] - a[0], vy = (long double)c[1] - a[1];
      long double angle = std::acos((ux * vx + uy * vy) / std::sqrt((ux * ux + uy * uy) * (vx * vx + vy * vy)));
      ASSERT_LT(double(angle * 180 / 3.14159265358979323846L), bound) << what << ": triangle " << t;
    }
}

}  // namespace

// --- the domain's corners --------------------------------------------------------------------

// The letter A: its smallest corner inside is 90 degrees (the apex's 45 is outside).
TEST(DomainAngle, LetterA) {
  Stats s = statsOf(fixtures::load(kData + "/A.poly").pslg);
  EXPECT_NEAR(s.smallestDomainAngle, 90, 1e-9);
  EXPECT_EQ(s.angleFloor, 72);
  EXPECT_NEAR(s.smallestInputAngle, 45.375, 0.001);
}

// A square with a narrow notch: the notch's tip is a reflex corner of 353.6 degrees inside,
// 6.4 outside; the smallest corner is a square's 90.
TEST(DomainAngle, ReflexNotchCountsInside) {
  Stats s = statsOf(polygon({0, 0, 10, 0, 10, 10, 5.5, 10, 5, 1, 4.5, 10, 0, 10}));
  EXPECT_NEAR(s.smallestDomainAngle, 90, 1e-9);
  EXPECT_NEAR(s.smallestInputAngle, 2 * std::atan(0.5 / 9) * 180 / M_PI, 1e-9);
  Stats l = statsOf(polygon({0, 0, 2, 0, 2, 1, 1, 1, 1, 2, 0, 2}));
  EXPECT_NEAR(l.smallestDomainAngle, 90, 1e-9);
}

// A point set: its corners are those of its convex hull (here 45, 45, 90).
TEST(DomainAngle, PointSetHullCorners) {
  Pslg in;
  in.points = {0, 0, 4, 0, 0, 4, 1, 1, 0.5, 2};
  Stats s = statsOf(in, Mode::Acute);
  EXPECT_NEAR(s.smallestDomainAngle, 45, 1e-9);
  EXPECT_NEAR(s.angleFloor, 72, 1e-12);
}

// A segment dangling inside a square makes no corner at its free end; one from a side at 45
// degrees cuts that side's straight angle into 45 and 135.
TEST(DomainAngle, DanglingSegments) {
  Pslg in = polygon({0, 0, 4, 0, 4, 4, 0, 4});
  in.points.insert(in.points.end(), {1, 2, 2, 2});
  in.segments.insert(in.segments.end(), {4, 5});
  EXPECT_NEAR(statsOf(in).smallestDomainAngle, 90, 1e-9);
  Pslg side = polygon({0, 0, 4, 0, 4, 4, 0, 4});
  side.points.insert(side.points.end(), {0, 1, 2, 3});
  side.segments.insert(side.segments.end(), {4, 5});
  Stats s = statsOf(side);
  EXPECT_NEAR(s.smallestDomainAngle, 45, 1e-9);
  EXPECT_NEAR(s.angleFloor, 72, 1e-12);
}

// --- the exact certificate -------------------------------------------------------------------

// (b - a).(c - a) squared against q |b - a|^2 |c - a|^2, exactly: at (0,0), (1,0), (3,4) the
// cosine squared is 9/25, and the double nearest 0.36 is below it (floating point finds 0).
TEST(AngleBound, CosineSquaredSignIsExact) {
  const double a[2] = {0, 0}, b[2] = {1, 0}, c[2] = {3, 4};
  EXPECT_EQ(detail::cosineSquaredSign(a, b, c, 0.36), 1);
  EXPECT_EQ(detail::cosineSquaredSign(a, b, c, std::nextafter(0.36, 1.0)), -1);
  const double d[2] = {1, 1};
  EXPECT_EQ(detail::cosineSquaredSign(a, b, d, 0.5), 0);
  const double tiny[2] = {0x1p-1000, 0}, e[2] = {3 * 0x1p-1000, 4 * 0x1p-1000};
  EXPECT_EQ(detail::cosineSquaredSign(a, tiny, e, 0.36), 1);
}

// An isosceles triangle whose apex is 1e-12 degrees below or above the bound, turned, mirrored
// and scaled: certified below the bound exactly when it is.
TEST(AngleBound, ApexWithinATrillionthOfADegree) {
  for (double bound : {60.5, 72.0, 75.0, 80.0, 85.0, 89.0, 89.999}) {
    for (double delta : {-1e-12, 1e-12}) {
      const double apex = (bound + delta) * M_PI / 180;
      for (int variant = 0; variant < 12; ++variant) {
        const double turn = variant * 0.7, scale = std::ldexp(1.0, variant * 13 - 60) * 1.37;
        const double mirror = variant % 2 ? -1 : 1;
        const double ax = 3 * scale, ay = -5 * scale;
        double a[2] = {ax, ay};
        double b[2] = {ax + scale * std::cos(turn), ay + mirror * scale * std::sin(turn)};
        double c[2] = {ax + scale * std::cos(turn + apex), ay + mirror * scale * std::sin(turn + apex)};
        const double* p[3] = {a, b, c};
        const double* q[3] = {b, c, a};  // the apex at another corner
        const detail::AngleCheck check(bound);
        const bool below = delta < 0;
        EXPECT_EQ(check.triangleBelow(p), below) << bound << " " << delta << " variant " << variant;
        EXPECT_EQ(check.triangleBelow(q), below) << bound << " " << delta << " variant " << variant;
        EXPECT_EQ(check.cornerBelow(a, b, c), below);
        EXPECT_TRUE(check.cornerBelow(b, c, a));
      }
    }
  }
}

// At 90 the certificate is the dot product's sign: a right angle is not below 90.
TEST(AngleBound, RightAngleIsNotBelowNinety) {
  const double a[2] = {0, 0}, b[2] = {1, 0}, c[2] = {0, 1e-300};
  EXPECT_FALSE(detail::AngleCheck(90).cornerBelow(a, b, c));
  const double d[2] = {1e-300, 1};
  EXPECT_TRUE(detail::AngleCheck(90).cornerBelow(a, b, d));
  EXPECT_FALSE(detail::AngleCheck(89.999).cornerBelow(a, b, d));
}

// --- options ------------------------------------------------------------------------------------

TEST(AngleBound, MaxAngleValues) {
  Pslg square = polygon({0, 0, 1, 0, 1, 1, 0, 1});
  for (double bad : {59.0, 60.0, 90.5, 180.0, -1.0, double(NAN)}) {
    Options o;
    o.mode = Mode::Acute;
    o.maxAngle = bad;
    Result r = mesh(square, o);
    EXPECT_EQ(r.status, Status::BadInput) << bad;
    EXPECT_NE(r.message.find("maxAngle must be above 60 and at most 90 degrees, or auto"),
              std::string::npos) << r.message;
  }
  for (Mode mode : {Mode::Cdt, Mode::Delaunay, Mode::Quality, Mode::NonObtuse}) {
    Options o;
    o.mode = mode;
    o.maxAngle = kAutoMaxAngle;
    Result r = mesh(square, o);
    EXPECT_EQ(r.status, Status::BadInput);
    EXPECT_EQ(r.message, "maxAngle auto needs mode acute");
  }
}

// Auto: the lowest tenth of a degree the mesh's angles are certified below, said in angleBound.
TEST(AngleBound, AutoSaysTheBoundReached) {
  for (const char* name : {"A.poly", "plate.poly"}) {
    Pslg in = fixtures::load(kData + "/" + name).pslg;
    Options o;
    o.mode = Mode::Acute;
    o.maxAngle = kAutoMaxAngle;
    Result r = mesh(in, o);
    ASSERT_EQ(r.status, Status::Ok) << name << ": " << r.message;
    EXPECT_TRUE(r.stats.certified && r.stats.targetMet) << name;
    EXPECT_GT(r.stats.angleBound, r.stats.maxAngle) << name;
    EXPECT_LE(r.stats.angleBound, std::min(90.0, r.stats.maxAngle + 0.2)) << name;
    EXPECT_EQ(r.stats.angleBound * 10, std::round(r.stats.angleBound * 10)) << name;
    expectAnglesBelow(r.mesh, r.stats.angleBound, name);
  }
}

// A fixed bound met is the bound certified; at the default 90, angleBound is 90.
TEST(AngleBound, FixedBoundIsTheBoundCertified) {
  Pslg square = polygon({0, 0, 1, 0, 1, 1, 0, 1});
  Options o;
  o.mode = Mode::Acute;
  Result r90 = mesh(square, o);
  ASSERT_EQ(r90.status, Status::Ok);
  EXPECT_EQ(r90.stats.angleBound, 90);
  o.maxAngle = 85;
  Result r = mesh(square, o);
  ASSERT_EQ(r.status, Status::Ok) << r.message;
  EXPECT_EQ(r.stats.angleBound, 85);
  EXPECT_TRUE(r.stats.certified);
  expectAnglesBelow(r.mesh, 85, "square at 85");
  o.mode = Mode::NonObtuse;
  EXPECT_EQ(mesh(square, o).stats.angleBound, 0);
}

// A minimum and a maximum angle together: both reach the core, both are reported, and the
// target is met only when both are.
TEST(AngleBound, MinAndMaxTogether) {
  Pslg square = polygon({0, 0, 1, 0, 1, 1, 0, 1});
  Options o;
  o.mode = Mode::Acute;
  o.minAngle = 30;
  o.maxAngle = 80;
  Result r = mesh(square, o);
  EXPECT_GE(r.stats.minAngle, 30 * (1 - 1e-9));
  if (r.status == Status::Ok) {
    EXPECT_TRUE(r.stats.targetMet);
    EXPECT_EQ(r.stats.angleBound, 80);
    expectAnglesBelow(r.mesh, 80, "square, 30 to 80");
  } else {
    EXPECT_FALSE(r.stats.targetMet);
  }
  // A minimum above the domain's corner cannot be met, whatever the maximum: not met.
  Pslg wedge = fixtures::load(kData + "/angles/wedge-20.poly").pslg;
  o.minAngle = 25;
  o.maxAngle = 85;
  Result w = mesh(wedge, o);
  EXPECT_EQ(w.status, Status::TargetNotMet);
  EXPECT_FALSE(w.stats.targetMet);
  EXPECT_NE(w.stats.warnings.front().find("smallest corner (20 degrees) is below the minimum"),
            std::string::npos) << w.stats.warnings.front();
}

// Below the floor: said at once, meshed as auto, not met, and still a certified acute mesh.
TEST(AngleBound, BelowTheFloorAimsForTheLowestBound) {
  Pslg wedge = fixtures::load(kData + "/angles/wedge-20.poly").pslg;
  for (double asked : {75.0, 80.0}) {
    Options o;
    o.mode = Mode::Acute;
    o.maxAngle = asked;
    Result r = mesh(wedge, o);
    EXPECT_NEAR(r.stats.smallestDomainAngle, 20, 1e-9);
    EXPECT_NEAR(r.stats.angleFloor, 80, 1e-9);
    EXPECT_EQ(r.status, Status::TargetNotMet);
    ASSERT_EQ(r.stats.warnings.size(), 1u);
    EXPECT_NE(r.stats.warnings[0].find("sets a floor of 80 degrees: no mesh has every angle below it"),
              std::string::npos) << r.stats.warnings[0];
    EXPECT_NE(r.message.find("a maximum angle of " + detail::degreesText(asked) +
                             " is at or below the floor of 80 degrees"),
              std::string::npos) << r.message;
    EXPECT_NE(r.message.find("every angle below " + detail::degreesText(r.stats.angleBound)),
              std::string::npos) << r.message;
    EXPECT_TRUE(r.stats.certified);
    EXPECT_FALSE(r.stats.targetMet);
    EXPECT_GT(r.stats.angleBound, 80);
    EXPECT_FALSE(r.stats.missedTriangles.empty());
    expectAnglesBelow(r.mesh, r.stats.angleBound, "wedge");
    EXPECT_TRUE(validate(wedge, r.mesh, o).ok);
  }
  // Just above the floor it is a bound like any other (no warning).
  Options o;
  o.mode = Mode::Acute;
  o.maxAngle = 85;
  Result r = mesh(wedge, o);
  EXPECT_TRUE(r.stats.warnings.empty());
}

// --- tiny input corners ----------------------------------------------------------------------

// A digitising step on a map's coast (a 1.31-degree corner 0.0072 long, beside a reflex one,
// in a box 20 wide): the fan there needs edges under 2^-24 of the extent, and the mesh must
// still end acute and certified, turned, scaled and mirrored.
TEST(TinyCorner, DigitisingStepEndsCertified) {
  const Pslg step = fixtures::load(kData + "/angles/step-spike.poly").pslg;
  for (double turn : {0.0, 30.0, -70.0})
    for (double scale : {1.0, 1000.0, 0.001})
      for (double mirror : {1.0, -1.0}) {
        Pslg in = step;
        const double c = std::cos(turn * M_PI / 180), s = std::sin(turn * M_PI / 180);
        for (size_t i = 0; i < in.points.size(); i += 2) {
          const double x = in.points[i], y = mirror * in.points[i + 1];
          in.points[i] = scale * (c * x - s * y);
          in.points[i + 1] = scale * (s * x + c * y);
        }
        const std::string what = "turned " + std::to_string(turn) + ", scaled " +
                                 std::to_string(scale) + ", mirrored " + std::to_string(mirror);
        Options o;
        o.mode = Mode::Acute;
        Result r = mesh(in, o);
        EXPECT_NEAR(r.stats.smallestDomainAngle, 1.3107, 1e-3) << what;
        EXPECT_EQ(r.status, Status::Ok) << what << ": " << r.message;
        EXPECT_TRUE(r.stats.certified) << what;
        EXPECT_EQ(r.stats.nonAcute, 0u) << what;
        EXPECT_TRUE(validate(in, r.mesh, o).ok) << what;
      }
}

// A spike whose tip is 5e-11 degrees (a ring out and back along nearly the same line, as in
// Norway's and Chile's borders): 90 is above its floor (just), so there is no floor warning;
// no double mesh reaches it, and the message says where the triangles missed and names the
// input vertex at the tip with its coordinates.
TEST(TinyCorner, UnreachableCornerIsNamed) {
  Pslg spike = polygon({0, 0, 10, 0, 10, 10, 5.0000000000044, 10, 5, 15, 5, 10, 0, 10});
  Options o;
  o.mode = Mode::Acute;
  o.maxSteiner = 2000;
  Result r = mesh(spike, o);
  EXPECT_LT(r.stats.smallestDomainAngle, 1e-10);
  EXPECT_LT(r.stats.angleFloor, 90);
  EXPECT_TRUE(r.stats.warnings.empty()) << r.stats.warnings.front();
  EXPECT_EQ(r.status, Status::TargetNotMet);
  EXPECT_FALSE(r.stats.missedTriangles.empty());
  EXPECT_NE(r.message.find("missed triangles at (5, "), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("the input corners nearest them: input vertex 4 (5, 15), 5.04"),
            std::string::npos) << r.message;
  EXPECT_TRUE(validate(spike, r.mesh, o).ok);
}

// Below the floor, the warning and the message name the corners that set it: the smallest
// few, and how many in all.
TEST(TinyCorner, CornersUnderTheFloorAreNamed) {
  // A four-pointed star: tips of 12.68 degrees at vertices 0, 2, 4, 6 (floor 83.66).
  Pslg star = polygon({10, 0, 1, 1, 0, 10, -1, 1, -10, 0, -1, -1, 0, -10, 1, -1});
  Options o;
  o.mode = Mode::Acute;
  o.maxAngle = 80;
  Result r = mesh(star, o);
  EXPECT_EQ(r.status, Status::TargetNotMet);
  ASSERT_EQ(r.stats.warnings.size(), 1u);
  const std::string& w = r.stats.warnings[0];
  EXPECT_NE(w.find("the corners of 20 degrees or less: input vertex "), std::string::npos) << w;
  EXPECT_NE(w.find(", 12.6804 degrees (4 in all))"), std::string::npos) << w;
  EXPECT_NE(r.message.find("set by the domain's smallest corner (input vertex "), std::string::npos)
      << r.message;
  EXPECT_NE(r.message.find("(4 in all)"), std::string::npos) << r.message;
  // One corner under the floor is named alone.
  Pslg wedge = fixtures::load(kData + "/angles/wedge-20.poly").pslg;
  r = mesh(wedge, o);
  EXPECT_NE(r.message.find("corner (input vertex 0 (0, 0), 20 degrees)"), std::string::npos)
      << r.message;
}

// An angle a hair under 90 is not printed as 90.
TEST(TinyCorner, DegreesUnderNinetyAreNotPrintedAsNinety) {
  EXPECT_EQ(detail::degreesText(90 - 2.3e-11), "89.999999999977 degrees");
  EXPECT_EQ(detail::degreesText(90), "90 degrees");
  EXPECT_EQ(detail::degreesText(80), "80 degrees");
  EXPECT_EQ(detail::degreesText(16.49264), "16.4926 degrees");
}
