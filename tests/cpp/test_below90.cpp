// Acute meshes below 90 degrees end to end (refine/below90, refine/descent): on every fixture
// and on turned, mirrored and scaled copies of it, each result is valid (validate()) and its
// certificate is re-checked here corner by corner, exactly and apart from the core's AngleCheck
// (big integers of exact_reference.h behind a floating-point filter; at 90 degrees the exact
// dot-product sign of predicates.h, which test_predicates checks against those big integers).
// Also: a time limit or a cancel mid-descent, a Steiner budget, the same mesh on any threads.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <string>
#include <thread>

#include "acutemesh/acutemesh.h"
#include "acutemesh/predicates.h"
#include "exact_reference.h"
#include "fixtures.h"

using namespace acutemesh;

namespace {

using fixtures::kData;
using fixtures::kSyntheticCgshop;

// --- an exact check of "every angle below B", independent of the core's ----------------------

// A double q >= cos^2 B, so that cos^2 of a corner above q proves the corner below B. 90 - B is
// exact and sin of it within an ulp or two, its square within a few more: 2e-15 above that is
// above cos^2 B for sure. It stays below the core's own q (cos^2 B + 1e-14 relative), so a
// corner the core certifies is not refused here for rounding.
double cos2Above(double degrees) {
  const double s = std::sin((90 - degrees) * M_PI / 180);
  return s * s * (1 + 2e-15);
}

// Whether the angle at a of triangle a, b, c is below `degrees` (q = cos2Above(degrees); at 90,
// whether the dot product is positive, exactly). A corner whose angle, from atan2 of doubles, is
// more than 1e-9 degrees from the bound is decided by it: the rounding of the differences and of
// atan2 moves it by about 1e-13 degrees. Nearer ones are decided with big integers: the dot
// product u.v positive and (u.v)^2 > q |u|^2 |v|^2.
bool cornerBelow(const double* a, const double* b, const double* c, double degrees, double q) {
  const double ux = b[0] - a[0], uy = b[1] - a[1], vx = c[0] - a[0], vy = c[1] - a[1];
  const double angle = std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy) * 180 / M_PI;
  if (angle < degrees - 1e-9) return true;
  if (angle > degrees + 1e-9) return false;
  if (degrees >= 90) return dot2d(a, b, c) > 0;
  using exactref::BigInt;
  const auto v = exactref::toCommonScale({a[0], a[1], b[0], b[1], c[0], c[1]});
  const BigInt bx = v[2] - v[0], by = v[3] - v[1], cx = v[4] - v[0], cy = v[5] - v[1];
  const BigInt dot = bx * cx + by * cy;
  if (dot.sign() <= 0) return false;
  int e = 0;
  const double f = std::frexp(q, &e);  // q = f 2^e, f in [0.5, 1), e <= 0: q = m / 2^(53 - e)
  const BigInt m(int64_t(std::ldexp(f, 53)));
  const BigInt lengths = (bx * bx + by * by) * (cx * cx + cy * cy);
  return ((dot * dot).shl(53 - e) - m * lengths).sign() > 0;
}

// Calls f(a, b, c) for every corner a of every triangle of `m` (b, c: the triangle's others).
template <class F>
void forEachCorner(const Mesh& m, F f) {
  for (size_t t = 0; t < m.triangleCount(); ++t)
    for (int k = 0; k < 3; ++k)
      f(&m.points[2 * size_t(m.triangles[3 * t + k])],
        &m.points[2 * size_t(m.triangles[3 * t + (k + 1) % 3])],
        &m.points[2 * size_t(m.triangles[3 * t + (k + 2) % 3])]);
}

// The corners of `m` that are not below `degrees` (0: every angle below it).
size_t cornersNotBelow(const Mesh& m, double degrees) {
  const double q = cos2Above(degrees);
  size_t n = 0;
  forEachCorner(m, [&](const double* a, const double* b, const double* c) {
    n += !cornerBelow(a, b, c, degrees, q);
  });
  return n;
}

// Obtuse corners (exact dot-product sign below 0).
size_t obtuseCorners(const Mesh& m) {
  size_t n = 0;
  forEachCorner(m, [&](const double* a, const double* b, const double* c) {
    n += dot2d(a, b, c) < 0;
  });
  return n;
}

// The smallest angle of `m` (floating point, degrees).
double smallestAngle(const Mesh& m) {
  double smallest = 180;
  forEachCorner(m, [&](const double* a, const double* b, const double* c) {
    const double ux = b[0] - a[0], uy = b[1] - a[1], vx = c[0] - a[0], vy = c[1] - a[1];
    smallest = std::min(smallest,
                        std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy) * 180 / M_PI);
  });
  return smallest;
}

// --- fixtures and their copies ----------------------------------------------------------------

struct Fixture {
  Input input;
  Options
      base;  // non-zero fill for rings (as test_refine), exact segments for CG:SHOP (as the CLI)
};

Fixture fixture(const std::string& path) {
  Fixture f{fixtures::load(path), {}};
  if (f.input.hasRings) f.base.fill = FillRule::NonZero;
  f.base.exactSegments = path.find(".instance.json") != std::string::npos;
  f.base.threads = 1;
  return f;
}

// Copies that must mesh as well as the original: turned by 30 degrees (coordinates rounded),
// mirrored, and scaled by 2^-20 and 2^30 (exact).
enum Copy { kSame, kTurned30, kMirrored, kTiny, kHuge, kCopies };
const char* const kCopyName[kCopies] = {"", " turned 30", " mirrored", " scaled 2^-20",
                                        " scaled 2^30"};

Pslg copyOf(const Pslg& in, Copy copy) {
  Pslg out = in;
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  for (std::vector<double>* xy : {&out.points, &out.holes})
    for (size_t i = 0; i + 1 < xy->size(); i += 2) {
      const double x = (*xy)[i], y = (*xy)[i + 1];
      switch (copy) {
        case kTurned30:
          (*xy)[i] = c * x - s * y, (*xy)[i + 1] = s * x + c * y;
          break;
        case kMirrored:
          (*xy)[i] = -x;
          break;
        case kTiny:
          (*xy)[i] = std::ldexp(x, -20), (*xy)[i + 1] = std::ldexp(y, -20);
          break;
        case kHuge:
          (*xy)[i] = std::ldexp(x, 30), (*xy)[i + 1] = std::ldexp(y, 30);
          break;
        default:
          break;
      }
    }
  return out;
}

// Result r of an acute run with o.maxAngle kAutoMaxAngle, 90 or a bound below it: the acute
// mesh's certificate. `acute` is the run at 90 of the same input (null for that run): no
// result is worse than it.
void checkAcute(const Pslg& in, const Options& o, const Result& r, const Result* acute,
                const std::string& what) {
  const double bound = o.maxAngle;
  const std::string at = what + " at " + (bound == kAutoMaxAngle ? "auto" : std::to_string(bound));
  EXPECT_NE(r.status, Status::BadInput) << at << ": " << r.message;
  EXPECT_EQ(fixtures::validationErrors(in, o, r.mesh), "") << at;
  EXPECT_TRUE(r.stats.certified) << at;
  EXPECT_GT(r.stats.angleBound, 60) << at;
  EXPECT_LE(r.stats.angleBound, 90) << at;
  EXPECT_EQ(cornersNotBelow(r.mesh, r.stats.angleBound), 0u)
      << at << ": angleBound " << r.stats.angleBound;
  if (acute) {
    EXPECT_LE(r.stats.maxAngle, acute->stats.maxAngle) << at << ": worse than the acute mesh";
  }
  if (bound == kAutoMaxAngle) {
    EXPECT_EQ(r.status, Status::Ok) << at << ": " << r.message;
    EXPECT_TRUE(r.stats.targetMet) << at;
    EXPECT_LT(r.stats.angleBound, 90) << at << ": no lower than the acute mesh's 90";
    EXPECT_EQ(r.stats.angleBound * 10, std::round(r.stats.angleBound * 10)) << at;
  } else if (r.stats.targetMet) {
    EXPECT_EQ(r.status, Status::Ok) << at << ": " << r.message;
    EXPECT_EQ(r.stats.angleBound, bound) << at;
  } else {
    // Missed: said, and true (some corner is not below the bound).
    EXPECT_EQ(r.status, Status::TargetNotMet) << at;
    EXPECT_FALSE(r.message.empty()) << at;
    EXPECT_FALSE(r.stats.missedTriangles.empty()) << at;
    EXPECT_GT(r.stats.angleBound, bound) << at;
    EXPECT_GT(cornersNotBelow(r.mesh, bound), 0u) << at << ": said to miss " << bound;
  }
}

// checkAcute of a run of `in` at `bound`.
Result expectAcute(const Pslg& in, const Options& base, double bound, const Result* acute,
                   const std::string& what) {
  Options o = base;
  o.mode = Mode::Acute;
  o.maxAngle = bound;
  Result r = mesh(in, o);
  checkAcute(in, o, r, acute, what);
  return r;
}

// Non-obtuse and quality (default 20 degrees) certificates of the same copy. A domain corner
// under 20 degrees cannot be met by quality refinement: then the miss is said.
void expectNonObtuseAndQuality(const Pslg& in, const Options& base, const std::string& what) {
  Options o = base;
  o.mode = Mode::NonObtuse;
  Result n = mesh(in, o);
  EXPECT_EQ(n.status, Status::Ok) << what << " nonobtuse: " << n.message;
  EXPECT_TRUE(n.stats.certified) << what << " nonobtuse";
  EXPECT_EQ(fixtures::validationErrors(in, o, n.mesh), "") << what << " nonobtuse";
  // (Exact feet, where they are used, are certified at their rationals, not at these doubles.)
  if (n.mesh.exactPoints.empty()) {
    EXPECT_EQ(obtuseCorners(n.mesh), 0u) << what << " nonobtuse";
  }
  o.mode = Mode::Quality;
  Result q = mesh(in, o);
  EXPECT_EQ(fixtures::validationErrors(in, o, q.mesh), "") << what << " quality";
  if (q.stats.smallestDomainAngle >= kQualityDefaultMinAngle) {
    EXPECT_EQ(q.status, Status::Ok) << what << " quality: " << q.message;
    EXPECT_GE(smallestAngle(q.mesh), kQualityDefaultMinAngle * (1 - 1e-12)) << what << " quality";
  } else {
    EXPECT_EQ(q.status, q.stats.targetMet ? Status::Ok : Status::TargetNotMet)
        << what << " quality";
  }
}

// Every copy of the fixture but those in `skip` (bits 1 << Copy): acute at 90 and at each of
// `bounds`, non-obtuse, quality; acute at kAutoMaxAngle too on the copies in `autoOn`.
void expectEveryCertificate(const std::string& path, std::vector<double> bounds, unsigned autoOn,
                            unsigned skip = 0) {
  const Fixture f = fixture(path);
  for (int copy = kSame; copy < kCopies; ++copy) {
    if (skip & (1u << copy)) continue;
    const Pslg in = copyOf(f.input.pslg, Copy(copy));
    const std::string what = path.substr(path.rfind('/') + 1) + kCopyName[copy];
    const Result acute = expectAcute(in, f.base, 90, nullptr, what);
    ASSERT_EQ(acute.status, Status::Ok) << what << ": " << acute.message;
    EXPECT_EQ(acute.stats.angleBound, 90) << what;
    for (double bound : bounds) expectAcute(in, f.base, bound, &acute, what);
    if (autoOn & (1u << copy)) expectAcute(in, f.base, kAutoMaxAngle, &acute, what);
    expectNonObtuseAndQuality(in, f.base, what);
  }
}

constexpr unsigned kOriginal = 1u << kSame, kEveryCopy = (1u << kCopies) - 1;

}  // namespace

// The check above, on isosceles triangles whose apex is 1e-12 degrees below or above the bound
// (the filter leaves them to the big integers; at 90, to dot2d), turned and scaled: below
// exactly when it is.
TEST(Below90, TheCheckHereIsExact) {
  for (double bound : {72.0, 80.0, 85.0, 89.5, 90.0}) {
    for (double delta : {-1e-12, 1e-12}) {
      const double apex = (bound + delta) * M_PI / 180;
      for (int scale : {-20, 0, 30}) {
        const double r = std::ldexp(1.0, scale);
        Mesh m;
        m.points = {r * 0.25,
                    r * 0.5,
                    r * (0.25 + std::cos(0.3)),
                    r * (0.5 + std::sin(0.3)),
                    r * (0.25 + std::cos(0.3 + apex)),
                    r * (0.5 + std::sin(0.3 + apex))};
        m.triangles = {0, 1, 2};
        // Its apex as built (the rounding of the points moves it by ~1e-14 degrees).
        const size_t want = delta < 0 ? 0 : 1;
        EXPECT_EQ(cornersNotBelow(m, bound), want) << bound << " " << delta << " 2^" << scale;
        if (bound < 90) {
          EXPECT_EQ(cornersNotBelow(m, bound + 2e-12), 0u) << bound << " 2^" << scale;
        }
      }
    }
  }
}

// --- every fixture, its copies, several bounds --------------------------------------------------
// (auto costs 0.3 to 4.5 s a run natively: it runs on the cheaper fixtures' originals here;
// AngleBound.AutoSaysTheBoundReached runs it on A.poly and the plate.)

TEST(Below90, LetterA) { expectEveryCertificate(kData + "/A.poly", {85, 82}, 0); }
TEST(Below90, Plate) { expectEveryCertificate(kData + "/plate.poly", {85, 82}, 0); }
TEST(Below90, Airfoil) { expectEveryCertificate(kData + "/naca0012.poly", {85}, 0); }
TEST(Below90, AcuteText) { expectEveryCertificate(kData + "/acute-text.json", {85}, 0); }
TEST(Below90, CgshopOrtho) {
  expectEveryCertificate(kSyntheticCgshop + "/ortho_10_synthetic.instance.json", {85, 82},
                         kOriginal);
}
// Its smallest corner, 16.8 degrees, sets a floor of 81.6: 82 is just above it.
TEST(Below90, CgshopSimplePolygon) {
  expectEveryCertificate(kSyntheticCgshop + "/simple-polygon_40_synthetic.instance.json", {85, 82},
                         kOriginal);
}
TEST(Below90, CgshopPointSet) {
  expectEveryCertificate(kSyntheticCgshop + "/point-set_60_synthetic.instance.json", {85}, 0);
}

// Auto gets below 85 here (floor 83.6; 84.1 on 2026-12-07). The test was disabled while auto
// ended at the acute mesh's 90 here.
TEST(Below90, CgshopSimplePolygonExterior20Auto) {
  const Fixture f =
      fixture(kSyntheticCgshop + "/simple-polygon-exterior-20_80_synthetic.instance.json");
  const Result acute = expectAcute(f.input.pslg, f.base, 90, nullptr, "exterior-20_80");
  const Result r = expectAcute(f.input.pslg, f.base, kAutoMaxAngle, &acute, "exterior-20_80");
  EXPECT_LT(r.stats.angleBound, 85);
}

// The floor + 3 on the letter A (floor 72): met on every copy. Before the descent split the
// edges of the triangles it stalled at, it stopped at 76 degrees.
TEST(Below90, LetterAAtItsFloorPlusThree) {
  const Fixture f = fixture(kData + "/A.poly");
  for (int copy = kSame; copy < kCopies; ++copy) {
    const Pslg in = copyOf(f.input.pslg, Copy(copy));
    const std::string what = std::string("A.poly") + kCopyName[copy];
    const Result r = expectAcute(in, f.base, 75, nullptr, what);
    EXPECT_TRUE(r.stats.targetMet) << what << ": " << r.message;
    EXPECT_EQ(r.stats.angleFloor, 72) << what;
  }
}

// A.poly turned by 30 degrees: its feet's bottoms are collinear, and turned (rounded) some of
// their vertices lie inside the hull edge along both feet by 1e-19, behind slivers outside the
// domain that no double splitting a foot's bottom falls into. RefineState::start puts such
// vertices on the hull; before, every mode left triangles of up to 148 degrees here (and at
// 10, 20, 60 and 75 degrees).
TEST(Below90, LetterATurned30) {
  expectEveryCertificate(kData + "/A.poly", {85, 82}, 1u << kTurned30,
                         kEveryCopy & ~(1u << kTurned30));
}

// --- anytime: a time limit, a cancel, a Steiner budget ------------------------------------------

namespace {

// A run stopped short at a bound below 90: a valid certified mesh no worse than the acute one
// (`acute`, the run at 90), and said to miss the bound.
void expectStoppedShort(const Pslg& in, const Options& o, const Result& r, const Result& acute,
                        const std::string& what) {
  EXPECT_TRUE(r.status == Status::TargetNotMet || r.status == Status::Cancelled)
      << what << ": status " << int(r.status) << " " << r.message;
  EXPECT_EQ(fixtures::validationErrors(in, o, r.mesh), "") << what;
  EXPECT_FALSE(r.stats.targetMet) << what;
  EXPECT_TRUE(r.stats.certified) << what;
  EXPECT_GT(r.stats.angleBound, o.maxAngle) << what;
  EXPECT_EQ(cornersNotBelow(r.mesh, r.stats.angleBound), 0u)
      << what << ": angleBound " << r.stats.angleBound;
  EXPECT_LE(r.stats.maxAngle, acute.stats.maxAngle) << what << ": worse than the acute mesh";
}

}  // namespace

// A.poly at 74 (the whole run meets it in ~1.5 s natively, after the acute mesh's ~5 ms): time
// limits of a few to a few dozen times the acute mesh's time, in the build at hand, stop it
// before the acute mesh is done with, or in the middle of the descent. A run that meets the
// bound within its limit (the slowest, in a build whose acute mesh is slow) is not cut short:
// it is checked as a met run; the first, at 3 times, always is.
TEST(Below90, TimeLimitMidDescentKeepsTheBestMesh) {
  const Fixture f = fixture(kData + "/A.poly");
  const Pslg& in = f.input.pslg;
  const Result acute = expectAcute(in, f.base, 90, nullptr, "A.poly");
  double lowest = 90;
  for (double times : {3.0, 10.0, 30.0}) {
    Options o = f.base;
    o.mode = Mode::Acute;
    o.maxAngle = 74;
    o.timeLimit = times * std::max(acute.stats.seconds, 1e-3);
    const std::string what = "A.poly at 74, " + std::to_string(o.timeLimit) + " s";
    Result r = mesh(in, o);
    lowest = std::min(lowest, r.stats.maxAngle);
    if (times > 3 && r.stats.targetMet) {
      checkAcute(in, o, r, &acute, what);
      continue;
    }
    expectStoppedShort(in, o, r, acute, what);
    EXPECT_EQ(r.status, Status::TargetNotMet);
  }
  // Some limit fell in the descent, which had lowered the largest angle, and that mesh was kept.
  EXPECT_LT(lowest, acute.stats.maxAngle - 1);
}

#ifndef __EMSCRIPTEN__
// The same, cancelled from another thread ten times the acute mesh's time into the run.
TEST(Below90, CancelFromAnotherThreadMidDescent) {
  const Fixture f = fixture(kData + "/A.poly");
  const Pslg& in = f.input.pslg;
  const Result acute = expectAcute(in, f.base, 90, nullptr, "A.poly");
  Options o = f.base;
  o.mode = Mode::Acute;
  o.maxAngle = 74;
  std::atomic<bool> cancel{false};
  o.cancel = &cancel;
  std::thread canceller([&] {
    std::this_thread::sleep_for(
        std::chrono::duration<double>(10 * std::max(acute.stats.seconds, 1e-3)));
    cancel = true;
  });
  Result r = mesh(in, o);
  canceller.join();
  expectStoppedShort(in, o, r, acute, "A.poly at 74, cancelled");
  EXPECT_EQ(r.status, Status::Cancelled) << r.message;
}
#endif

// A Steiner budget half as much again as the acute mesh's points (its refinement passes through
// more than it keeps: 81 are not enough for its 71): that mesh or a better one, said to miss the
// bound. Half its points: no acute mesh, said too.
TEST(Below90, SteinerBudgetAtALowBound) {
  const Fixture f = fixture(kData + "/A.poly");
  const Pslg& in = f.input.pslg;
  const Result acute = expectAcute(in, f.base, 90, nullptr, "A.poly");
  Options o = f.base;
  o.mode = Mode::Acute;
  o.maxAngle = 75;
  o.maxSteiner = acute.stats.steiner * 3 / 2;
  Result r = mesh(in, o);
  expectStoppedShort(in, o, r, acute, "A.poly at 75, a budget of " + std::to_string(o.maxSteiner));
  EXPECT_EQ(r.status, Status::TargetNotMet);
  EXPECT_LE(r.stats.steiner, o.maxSteiner);

  o.maxSteiner = acute.stats.steiner / 2;
  r = mesh(in, o);
  const std::string what = "A.poly at 75, a budget of " + std::to_string(o.maxSteiner);
  EXPECT_EQ(r.status, Status::TargetNotMet) << what;
  EXPECT_NE(r.message.find("budget"), std::string::npos) << what << ": " << r.message;
  EXPECT_EQ(fixtures::validationErrors(in, o, r.mesh), "") << what;
  EXPECT_LE(r.stats.steiner, o.maxSteiner) << what;
  EXPECT_FALSE(r.stats.targetMet) << what;
  EXPECT_FALSE(r.stats.certified) << what;
  EXPECT_GT(r.stats.nonAcute, 0u) << what;
}

// --- the same mesh on any number of threads ---------------------------------------------------

// A.poly at 80: missed (80.04), so every start of the descent runs.
TEST(Below90, ThreadsMakeTheSameMesh) {
  const Fixture f = fixture(kData + "/A.poly");
  Options o = f.base;
  o.mode = Mode::Acute;
  o.maxAngle = 80;
  o.threads = 1;
  const Result one = mesh(f.input.pslg, o);
  o.threads = 2;
  const Result two = mesh(f.input.pslg, o);
  EXPECT_EQ(two.status, one.status);
  EXPECT_TRUE(two.mesh.points == one.mesh.points);
  EXPECT_TRUE(two.mesh.triangles == one.mesh.triangles);
  EXPECT_EQ(two.stats.angleBound, one.stats.angleBound);
  EXPECT_LT(one.stats.angleBound, 81);  // (the descent ran)
}
