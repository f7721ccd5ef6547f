// Exact predicates (orient2d, incircle, dot2d and cornerDots) checked against a slow big-integer
// reference (exact_reference.h) on random, near-degenerate and exactly degenerate inputs.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>

#include "acutemesh/predicates.h"
#include "exact_reference.h"
#include "portable_math.h"

namespace {

using acutemesh::sign;
using Pt = std::array<double, 2>;

constexpr double kInf = std::numeric_limits<double>::infinity();

// x moved by k ulps (k < 0: towards -inf).
double ulpStep(double x, int k) {
  for (; k > 0; --k) x = std::nextafter(x, kInf);
  for (; k < 0; ++k) x = std::nextafter(x, -kInf);
  return x;
}

std::string fmt(const Pt& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%a, %a)", p[0], p[1]);
  return buf;
}

// Compares predicate signs with the exact reference, counting cases and keeping the first
// few mismatches for the failure message.
struct Checker {
  long cases = 0;
  long mismatches = 0;
  long zeros = 0;  // cases whose exact answer is 0
  std::string report;

  void fail(const std::string& what) {
    if (++mismatches <= 8) report += what + "\n";
  }

  // Returns the predicate's sign.
  int orient(const Pt& a, const Pt& b, const Pt& c, bool mustBeZero = false) {
    const int got = sign(acutemesh::orient2d(a.data(), b.data(), c.data()));
    const int want = exactref::orient2dSign(a.data(), b.data(), c.data());
    ++cases;
    zeros += want == 0;
    if (got != want || (mustBeZero && want != 0) ||
        acutemesh::orientSign(a.data(), b.data(), c.data()) != got) {
      fail("orient2d" + fmt(a) + fmt(b) + fmt(c) + " got " + std::to_string(got) +
           " want " + std::to_string(want) + (mustBeZero ? " (must be 0)" : ""));
    }
    return got;
  }

  int incircle(const Pt& a, const Pt& b, const Pt& c, const Pt& d, bool mustBeZero = false) {
    const int got = sign(acutemesh::incircle(a.data(), b.data(), c.data(), d.data()));
    const int want = exactref::incircleSign(a.data(), b.data(), c.data(), d.data());
    ++cases;
    zeros += want == 0;
    if (got != want || (mustBeZero && want != 0) ||
        acutemesh::incircleSign(a.data(), b.data(), c.data(), d.data()) != got) {
      fail("incircle" + fmt(a) + fmt(b) + fmt(c) + fmt(d) + " got " + std::to_string(got) +
           " want " + std::to_string(want) + (mustBeZero ? " (must be 0)" : ""));
    }
    return got;
  }

  int dot(const Pt& a, const Pt& b, const Pt& c, bool mustBeZero = false) {
    const int got = sign(acutemesh::dot2d(a.data(), b.data(), c.data()));
    const int want = exactref::dot2dSign(a.data(), b.data(), c.data());
    ++cases;
    zeros += want == 0;
    if (got != want || (mustBeZero && want != 0) ||
        acutemesh::dotSign(a.data(), b.data(), c.data()) != got) {
      fail("dot2d" + fmt(a) + fmt(b) + fmt(c) + " got " + std::to_string(got) + " want " +
           std::to_string(want) + (mustBeZero ? " (must be 0)" : ""));
    }
    // cornerDots gives the same sign with the corner in each of its three places.
    double d[3][3];
    acutemesh::cornerDots(a.data(), b.data(), c.data(), d[0]);
    acutemesh::cornerDots(c.data(), a.data(), b.data(), d[1]);
    acutemesh::cornerDots(b.data(), c.data(), a.data(), d[2]);
    for (int k = 0; k < 3; ++k)
      if (sign(d[k][k]) != want)
        fail("cornerDots" + fmt(a) + fmt(b) + fmt(c) + " corner " + std::to_string(k) + " got " +
             std::to_string(sign(d[k][k])) + " want " + std::to_string(want));
    return got;
  }
};

#define EXPECT_CLEAN(chk, minCases)                                                      \
  do {                                                                                   \
    EXPECT_EQ((chk).mismatches, 0) << (chk).report;                                      \
    EXPECT_GE((chk).cases, (minCases));                                                  \
    std::printf("    [%ld cases, %ld exactly degenerate]\n", (chk).cases, (chk).zeros); \
  } while (0)

struct Rng {
  std::mt19937_64 gen;
  explicit Rng(uint64_t seed) : gen(seed) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(gen); }
  long integer(long lo, long hi) { return std::uniform_int_distribution<long>(lo, hi)(gen); }
  Pt point(double lo = -1.0, double hi = 1.0) { return {uniform(lo, hi), uniform(lo, hi)}; }
  bool coin() { return integer(0, 1) == 1; }
};

Pt scaled(const Pt& p, double s, double tx = 0.0, double ty = 0.0) {
  return {p[0] * s + tx, p[1] * s + ty};
}

// Parity (+1 even, -1 odd) of a permutation of 0..n-1.
int parity(const int* perm, int n) {
  int inversions = 0;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) inversions += perm[i] > perm[j];
  return inversions % 2 == 0 ? 1 : -1;
}

// Power-of-two similarity transforms under which integer lattice configurations stay
// exactly representable (coordinates below 2^22 in magnitude): scale s, then translate t.
struct ExactTransform {
  double s, t;
};
const ExactTransform kExactTransforms[] = {
    {1.0, 0.0},          {0x1p-40, 0.0},     {0x1p40, 0.0},       {1.0, 0x1p30},
    {0x1p40, 0x1p30},    {0x1p-40, 0x1p-12}, {-0x1p-20, -0x1p10}, {0x1p100, -0x1p130},
    {0x1p-100, 0x1p-90},
};

// ---------------------------------------------------------------------------------------

TEST(Predicates, KnownValues) {
  const Pt o{0, 0}, ex{1, 0}, ey{0, 1}, mx{-1, 0}, my{0, -1};
  EXPECT_GT(acutemesh::orient2d(o.data(), ex.data(), ey.data()), 0.0);
  EXPECT_LT(acutemesh::orient2d(o.data(), ey.data(), ex.data()), 0.0);
  EXPECT_EQ(acutemesh::orient2d(o.data(), ex.data(), mx.data()), 0.0);
  EXPECT_EQ(acutemesh::orient2d(o.data(), ex.data(), ey.data()), 1.0);  // twice the area

  // Unit circle through ex, ey, mx (counter-clockwise).
  const Pt inside{0.25, -0.5}, outside{2, 0};
  EXPECT_GT(acutemesh::incircle(ex.data(), ey.data(), mx.data(), o.data()), 0.0);
  EXPECT_GT(acutemesh::incircle(ex.data(), ey.data(), mx.data(), inside.data()), 0.0);
  EXPECT_LT(acutemesh::incircle(ex.data(), ey.data(), mx.data(), outside.data()), 0.0);
  EXPECT_EQ(acutemesh::incircle(ex.data(), ey.data(), mx.data(), my.data()), 0.0);
  EXPECT_EQ(acutemesh::incircleSign(ex.data(), ey.data(), mx.data(), o.data()), 1);
  EXPECT_EQ(acutemesh::incircleSign(ey.data(), ex.data(), mx.data(), o.data()), -1);

  const Pt acute{1, 1}, obtuse{-1, 1};
  EXPECT_GT(acutemesh::dot2d(o.data(), ex.data(), acute.data()), 0.0);
  EXPECT_EQ(acutemesh::dot2d(o.data(), ex.data(), ey.data()), 0.0);
  EXPECT_LT(acutemesh::dot2d(o.data(), ex.data(), obtuse.data()), 0.0);
  EXPECT_EQ(acutemesh::dotSign(o.data(), ex.data(), obtuse.data()), -1);
  EXPECT_EQ(acutemesh::dotSign(o.data(), o.data(), obtuse.data()), 0);
  EXPECT_EQ(acutemesh::orientSign(o.data(), ex.data(), acute.data()), 1);
}

// ---------------------------------------------------------------------------------------
// orient2d

TEST(Orient2d, RandomMatchesReference) {
  Checker chk;
  Rng rng(1);
  for (int i = 0; i < 10000; ++i) chk.orient(rng.point(), rng.point(), rng.point());
  // Random magnitudes.
  for (int i = 0; i < 10000; ++i) {
    const double s = std::ldexp(1.0, int(rng.integer(-60, 60)));
    chk.orient(scaled(rng.point(), s), scaled(rng.point(), s), scaled(rng.point(), s));
  }
  // Tiny triangles far from the origin: the coordinate differences are inexact.
  for (int i = 0; i < 10000; ++i) {
    const Pt base = rng.point(-1e6, 1e6);
    const double h = std::ldexp(1.0, int(rng.integer(-40, -10)));
    chk.orient(scaled(rng.point(), h, base[0], base[1]), scaled(rng.point(), h, base[0], base[1]),
               scaled(rng.point(), h, base[0], base[1]));
  }
  EXPECT_CLEAN(chk, 30000);
}

TEST(Orient2d, NearCollinearMatchesReference) {
  Checker chk;
  Rng rng(2);
  for (int i = 0; i < 25000; ++i) {
    const double s = std::ldexp(1.0, int(rng.integer(-30, 30)));
    const double tx = rng.coin() ? rng.uniform(-1e3, 1e3) * s : 0.0;
    const Pt a = scaled(rng.point(), s, tx), b = scaled(rng.point(), s, tx);
    const double t = rng.uniform(-1.0, 2.0);
    Pt c{a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])};  // rounded: near the line
    c[0] = ulpStep(c[0], int(rng.integer(-2, 2)));
    c[1] = ulpStep(c[1], int(rng.integer(-2, 2)));
    switch (rng.integer(0, 2)) {
      case 0: chk.orient(a, b, c); break;
      case 1: chk.orient(c, a, b); break;
      default: chk.orient(b, c, a); break;
    }
  }
  for (int i = 0; i < 5000; ++i) {
    // Multiples of a lattice vector at very different scales (exactly collinear through the
    // origin, inexact differences), then one coordinate moved by an ulp: the determinant is
    // tiny compared with its terms, so only the exact stage can decide.
    const long vx = rng.integer(-1024, 1024), vy = rng.integer(1, 1024);
    Pt p[3];
    for (Pt& q : p) {
      const double m = std::ldexp(double(rng.integer(-1023, 1023)), int(rng.integer(-70, 70)));
      q = {m * double(vx), m * double(vy)};
    }
    const int k = int(rng.integer(0, 2)), axis = int(rng.integer(0, 1));
    p[k][axis] = ulpStep(p[k][axis], rng.coin() ? 1 : -1);
    chk.orient(p[0], p[1], p[2]);
  }
  // The classic grid of consecutive doubles around (0.5, 0.5) against the line through
  // (12, 12) and (24, 24), where naive evaluation gives a chaotic sign pattern.
  const Pt q{12, 12}, r{24, 24};
  for (int i = 0; i < 160; ++i) {
    for (int j = 0; j < 160; ++j) {
      const Pt p{0.5 + i * 0x1p-53, 0.5 + j * 0x1p-53};
      const int got = chk.orient(p, q, r);
      EXPECT_EQ(got, (j > i) - (j < i)) << i << "," << j;  // above the line y = x: ccw
    }
  }
  EXPECT_CLEAN(chk, 55000);
}

TEST(Orient2d, ExactlyCollinearIsZero) {
  Checker chk;
  Rng rng(3);
  for (int i = 0; i < 2500; ++i) {
    // p + k v on an integer lattice, |coordinates| < 2^21.
    const long px = rng.integer(-(1 << 20), 1 << 20), py = rng.integer(-(1 << 20), 1 << 20);
    const long vx = rng.integer(-1024, 1024), vy = rng.integer(-1024, 1024);
    const long k1 = rng.integer(-1023, 1023), k2 = rng.integer(-1023, 1023);
    const Pt a{double(px), double(py)};
    const Pt b{double(px + k1 * vx), double(py + k1 * vy)};
    const Pt c{double(px + k2 * vx), double(py + k2 * vy)};
    for (const ExactTransform& tr : kExactTransforms) {
      const Pt ta = scaled(a, tr.s, tr.t, -tr.t), tb = scaled(b, tr.s, tr.t, -tr.t),
               tc = scaled(c, tr.s, tr.t, -tr.t);
      chk.orient(ta, tb, tc, true);
      chk.orient(tb, ta, tc, true);
      chk.orient(tc, tb, ta, true);
    }
    // Not exactly representable after this transform: just compare with the reference.
    chk.orient(scaled(a, 0x1p-40, 0x1p30), scaled(b, 0x1p-40, 0x1p30), scaled(c, 0x1p-40, 0x1p30));
  }
  for (int i = 0; i < 3000; ++i) {
    // Axis-parallel lines, repeated points, and consecutive doubles on a line.
    const Pt a = rng.point(-1e3, 1e3), b = rng.point(-1e3, 1e3);
    const double y = rng.uniform(-1e9, 1e9);
    chk.orient({a[0], y}, {b[0], y}, {rng.uniform(-1e9, 1e9), y}, true);
    chk.orient({y, a[1]}, {y, b[1]}, {y, rng.uniform(-1, 1)}, true);
    chk.orient(a, b, a, true);
    chk.orient(a, a, b, true);
    chk.orient({a[0], a[1]}, {ulpStep(a[0], 1), a[1]}, {ulpStep(a[0], 2), a[1]}, true);
    chk.orient({a[0], a[1]}, {a[0], ulpStep(a[1], -1)}, {a[0], ulpStep(a[1], 3)}, true);
  }
  for (int i = 0; i < 4000; ++i) {
    // Multiples of one lattice vector at wildly different power-of-two scales: exactly
    // collinear (through the origin) although the coordinate differences are inexact.
    const long vx = rng.integer(-1024, 1024), vy = rng.integer(1, 1024);
    Pt p[3];
    for (Pt& q : p) {
      const double m = std::ldexp(double(rng.integer(-1023, 1023)), int(rng.integer(-70, 70)));
      q = {m * double(vx), m * double(vy)};
    }
    chk.orient(p[0], p[1], p[2], true);
  }
  EXPECT_CLEAN(chk, 40000);
  EXPECT_GE(chk.zeros, 40000);
}

TEST(Orient2d, UlpNeighbourhoods) {
  // All ordered triples of distinct points from a 3x3 grid of consecutive doubles.
  Checker chk;
  Rng rng(4);
  for (int base = 0; base < 120; ++base) {
    double x = rng.uniform(-10, 10), y = rng.uniform(-10, 10);
    if (base % 4 == 0) x = std::ldexp(1.0, int(rng.integer(-5, 5)));  // ulp changes at 2^k
    if (base % 8 == 0) y = -std::ldexp(1.0, int(rng.integer(-5, 5)));
    Pt grid[9];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) grid[3 * i + j] = {ulpStep(x, i - 1), ulpStep(y, j - 1)};
    for (int i = 0; i < 9; ++i)
      for (int j = 0; j < 9; ++j)
        for (int k = 0; k < 9; ++k)
          if (i != j && j != k && i != k) chk.orient(grid[i], grid[j], grid[k]);
  }
  EXPECT_CLEAN(chk, 60000);
}

TEST(Orient2d, Symmetries) {
  Checker chk;
  Rng rng(5);
  long failures = 0;
  for (int i = 0; i < 6000; ++i) {
    const Pt a = rng.point(), b = rng.point();
    Pt c = rng.point();
    if (i % 2 == 0) {  // near-collinear
      const double t = rng.uniform(-1, 2);
      c = {ulpStep(a[0] + t * (b[0] - a[0]), int(rng.integer(-1, 1))),
           ulpStep(a[1] + t * (b[1] - a[1]), int(rng.integer(-1, 1)))};
    }
    const int s = chk.orient(a, b, c);
    failures += chk.orient(b, c, a) != s;
    failures += chk.orient(c, a, b) != s;
    failures += chk.orient(b, a, c) != -s;
    failures += chk.orient(a, c, b) != -s;
    failures += chk.orient(c, b, a) != -s;
  }
  EXPECT_EQ(failures, 0);
  EXPECT_CLEAN(chk, 30000);
}

// ---------------------------------------------------------------------------------------
// incircle

TEST(Incircle, RandomMatchesReference) {
  Checker chk;
  Rng rng(11);
  for (int i = 0; i < 10000; ++i) chk.incircle(rng.point(), rng.point(), rng.point(), rng.point());
  for (int i = 0; i < 10000; ++i) {
    const double s = std::ldexp(1.0, int(rng.integer(-60, 60)));
    chk.incircle(scaled(rng.point(), s), scaled(rng.point(), s), scaled(rng.point(), s),
                 scaled(rng.point(), s));
  }
  for (int i = 0; i < 10000; ++i) {
    const Pt base = rng.point(-1e6, 1e6);
    const double h = std::ldexp(1.0, int(rng.integer(-30, -10)));
    chk.incircle(scaled(rng.point(), h, base[0], base[1]), scaled(rng.point(), h, base[0], base[1]),
                 scaled(rng.point(), h, base[0], base[1]), scaled(rng.point(), h, base[0], base[1]));
  }
  EXPECT_CLEAN(chk, 30000);
}

TEST(Incircle, NearCocircularMatchesReference) {
  Checker chk;
  Rng rng(12);
  const double twoPi = 6.283185307179586;
  for (int i = 0; i < 25000; ++i) {
    const double s = std::ldexp(1.0, int(rng.integer(-20, 20)));
    const Pt center = scaled(rng.point(), rng.coin() ? s : 1e3 * s);
    const double r = rng.uniform(0.01, 1.0) * s;
    Pt p[4];
    for (Pt& q : p) {
      const double th = rng.uniform(0, twoPi);
      q = {center[0] + r * std::cos(th), center[1] + r * std::sin(th)};  // rounded: near circle
    }
    const int k = int(rng.integer(0, 3));
    p[k][0] = ulpStep(p[k][0], int(rng.integer(-2, 2)));
    p[k][1] = ulpStep(p[k][1], int(rng.integer(-2, 2)));
    chk.incircle(p[0], p[1], p[2], p[3]);
  }
  // Grid of consecutive doubles around the corner (0.5, 0.5) of the rectangle whose other
  // corners are a, b, c: the four corners are exactly cocircular.
  const Pt a{12, 0.5}, b{12, 24}, c{0.5, 24};
  for (int i = -60; i < 60; ++i) {
    for (int j = -60; j < 60; ++j) {
      const Pt d{0.5 + i * 0x1p-53, 0.5 + j * 0x1p-53};
      const int got = chk.incircle(a, b, c, d);
      if (i == 0 && j == 0) {
        EXPECT_EQ(got, 0);
      } else if (i >= 0 && j >= 0) {
        EXPECT_EQ(got, 1);  // moved into the rectangle
      } else if (i <= 0 && j <= 0) {
        EXPECT_EQ(got, -1);
      }
    }
  }
  EXPECT_CLEAN(chk, 35000);
}

TEST(Incircle, ExactlyCocircularIsZero) {
  Checker chk;
  Rng rng(13);
  for (int i = 0; i < 1200; ++i) {
    // The eight points (+-p, +-q), (+-q, +-p) lie on one circle about the origin.
    const long p = rng.integer(1, 1 << 12), q = rng.integer(0, 1 << 12);
    const long cx = rng.integer(-(1 << 20), 1 << 20), cy = rng.integer(-(1 << 20), 1 << 20);
    const long pts[8][2] = {{p, q}, {-p, q}, {p, -q}, {-p, -q}, {q, p}, {-q, p}, {q, -p}, {-q, -p}};
    int idx[8] = {0, 1, 2, 3, 4, 5, 6, 7};
    std::shuffle(idx, idx + 8, rng.gen);
    Pt four[4];
    for (int k = 0; k < 4; ++k) four[k] = {double(cx + pts[idx[k]][0]), double(cy + pts[idx[k]][1])};
    for (const ExactTransform& tr : kExactTransforms) {
      Pt t[4];
      for (int k = 0; k < 4; ++k) t[k] = scaled(four[k], tr.s, tr.t, tr.t);
      chk.incircle(t[0], t[1], t[2], t[3], true);
      chk.incircle(t[3], t[0], t[2], t[1], true);
    }
  }
  for (int i = 0; i < 1200; ++i) {
    // Pythagorean circle of radius 5m: (+-5m, 0), (0, +-5m), (+-3m, +-4m), (+-4m, +-3m).
    const long m = rng.integer(1, 1 << 16);
    const long pts[12][2] = {{5 * m, 0}, {-5 * m, 0}, {0, 5 * m}, {0, -5 * m},
                             {3 * m, 4 * m}, {-3 * m, 4 * m}, {3 * m, -4 * m}, {-3 * m, -4 * m},
                             {4 * m, 3 * m}, {-4 * m, 3 * m}, {4 * m, -3 * m}, {-4 * m, -3 * m}};
    int idx[12];
    for (int k = 0; k < 12; ++k) idx[k] = k;
    std::shuffle(idx, idx + 12, rng.gen);
    const ExactTransform& tr = kExactTransforms[rng.integer(0, 8)];
    Pt t[4];
    for (int k = 0; k < 4; ++k)
      t[k] = scaled({double(pts[idx[k]][0]), double(pts[idx[k]][1])}, tr.s, tr.t, -tr.t);
    chk.incircle(t[0], t[1], t[2], t[3], true);
  }
  for (int i = 0; i < 4000; ++i) {
    // The corners of any axis-parallel rectangle are cocircular, whatever the doubles: the
    // coordinate differences are inexact, which drives the evaluation to the exact stage.
    const double s = std::ldexp(1.0, int(rng.integer(-30, 30)));
    const double x1 = rng.uniform(-1e3, 1e3) * s, y1 = rng.uniform(-1e3, 1e3) * s;
    double x2 = rng.uniform(-1e3, 1e3) * s, y2 = rng.uniform(-1e3, 1e3) * s;
    if (i % 3 == 0) {  // very thin rectangles: sides of a few ulps
      x2 = ulpStep(x1, int(rng.integer(1, 3)));
      y2 = rng.coin() ? ulpStep(y1, -int(rng.integer(1, 3))) : y2;
    }
    Pt corners[4] = {{x1, y1}, {x2, y1}, {x2, y2}, {x1, y2}};
    std::shuffle(corners, corners + 4, rng.gen);
    chk.incircle(corners[0], corners[1], corners[2], corners[3], true);
  }
  for (int i = 0; i < 3000; ++i) {
    // Repeated points, and four collinear points.
    const Pt a = rng.point(), b = rng.point(), c = rng.point();
    chk.incircle(a, b, c, a, true);
    chk.incircle(a, b, b, c, true);
    const double y = rng.uniform(-1, 1);
    chk.incircle({a[0], y}, {b[0], y}, {c[0], y}, {rng.uniform(-1, 1), y}, true);
  }
  EXPECT_CLEAN(chk, 30000);
  EXPECT_GE(chk.zeros, 30000);
}

TEST(Incircle, PermutationSigns) {
  // The determinant is alternating in its four points: an odd permutation flips the sign.
  Checker chk;
  Rng rng(14);
  long failures = 0;
  const double twoPi = 6.283185307179586;
  for (int i = 0; i < 1500; ++i) {
    Pt p[4];
    if (i % 3 == 0) {
      for (Pt& q : p) q = rng.point();
    } else if (i % 3 == 1) {
      const double r = rng.uniform(0.1, 2);
      for (Pt& q : p) {
        const double th = rng.uniform(0, twoPi);
        q = {3 + r * std::cos(th), -1 + r * std::sin(th)};
      }
      p[3][0] = ulpStep(p[3][0], int(rng.integer(-1, 1)));
    } else {
      const double x1 = rng.uniform(-5, 5), y1 = rng.uniform(-5, 5);
      const double x2 = rng.uniform(-5, 5), y2 = ulpStep(y1, int(rng.integer(-1, 1)));
      p[0] = {x1, y1};
      p[1] = {x2, y1};
      p[2] = {x2, y2};
      p[3] = {x1, ulpStep(y2, int(rng.integer(-1, 1)))};
    }
    int perm[4] = {0, 1, 2, 3};
    const int base = chk.incircle(p[0], p[1], p[2], p[3]);
    while (std::next_permutation(perm, perm + 4)) {
      const int s = sign(acutemesh::incircle(p[perm[0]].data(), p[perm[1]].data(),
                                             p[perm[2]].data(), p[perm[3]].data()));
      failures += s != parity(perm, 4) * base;
    }
  }
  EXPECT_EQ(failures, 0);
  EXPECT_CLEAN(chk, 1500);
}

// ---------------------------------------------------------------------------------------
// dot2d

TEST(Dot2d, RandomMatchesReference) {
  Checker chk;
  Rng rng(21);
  for (int i = 0; i < 10000; ++i) chk.dot(rng.point(), rng.point(), rng.point());
  for (int i = 0; i < 10000; ++i) {
    const double s = std::ldexp(1.0, int(rng.integer(-60, 60)));
    chk.dot(scaled(rng.point(), s), scaled(rng.point(), s), scaled(rng.point(), s));
  }
  for (int i = 0; i < 10000; ++i) {
    const Pt base = rng.point(-1e6, 1e6);
    const double h = std::ldexp(1.0, int(rng.integer(-40, -10)));
    chk.dot(scaled(rng.point(), h, base[0], base[1]), scaled(rng.point(), h, base[0], base[1]),
            scaled(rng.point(), h, base[0], base[1]));
  }
  EXPECT_CLEAN(chk, 30000);
}

TEST(Dot2d, NearRightAngleMatchesReference) {
  Checker chk;
  Rng rng(22);
  for (int i = 0; i < 25000; ++i) {
    const double s = std::ldexp(1.0, int(rng.integer(-30, 30)));
    const Pt a = scaled(rng.point(), s, rng.coin() ? 1e3 * s : 0.0);
    const Pt v = scaled(rng.point(), s);
    const double k = rng.uniform(-2, 2);
    const Pt b{a[0] + v[0], a[1] + v[1]};
    Pt c{a[0] - k * v[1], a[1] + k * v[0]};  // rounded: nearly perpendicular
    c[0] = ulpStep(c[0], int(rng.integer(-2, 2)));
    c[1] = ulpStep(c[1], int(rng.integer(-2, 2)));
    const int got = chk.dot(a, b, c);
    if (chk.dot(a, c, b) != got) chk.fail("dot2d not symmetric in b, c");
  }
  EXPECT_CLEAN(chk, 50000);
}

TEST(Dot2d, ExactRightAngleIsZero) {
  Checker chk;
  Rng rng(23);
  for (int i = 0; i < 2500; ++i) {
    const long px = rng.integer(-(1 << 20), 1 << 20), py = rng.integer(-(1 << 20), 1 << 20);
    const long vx = rng.integer(-1024, 1024), vy = rng.integer(-1024, 1024);
    const long k1 = rng.integer(-1023, 1023), k2 = rng.integer(-1023, 1023);
    const Pt a{double(px), double(py)};
    const Pt b{double(px + k1 * vx), double(py + k1 * vy)};
    const Pt c{double(px - k2 * vy), double(py + k2 * vx)};
    for (const ExactTransform& tr : kExactTransforms) {
      const Pt ta = scaled(a, tr.s, -tr.t, tr.t), tb = scaled(b, tr.s, -tr.t, tr.t),
               tc = scaled(c, tr.s, -tr.t, tr.t);
      chk.dot(ta, tb, tc, true);
      chk.dot(ta, tc, tb, true);
    }
    chk.dot(scaled(a, 0x1p-40, 0x1p30), scaled(b, 0x1p-40, 0x1p30), scaled(c, 0x1p-40, 0x1p30));
  }
  for (int i = 0; i < 3000; ++i) {
    // Axis-parallel right angles with arbitrary doubles, and zero-length legs.
    const Pt a = rng.point(-1e3, 1e3), b = rng.point(-1e3, 1e3);
    chk.dot(a, {b[0], a[1]}, {a[0], b[1]}, true);
    chk.dot(a, {a[0], ulpStep(a[1], 1)}, {ulpStep(a[0], -1), a[1]}, true);
    chk.dot(a, a, b, true);
    chk.dot(a, b, a, true);
  }
  EXPECT_CLEAN(chk, 45000);
  EXPECT_GE(chk.zeros, 45000);
}

// ---------------------------------------------------------------------------------------
// All three at extreme (but supported) magnitudes.

TEST(Predicates, ExtremeMagnitudes) {
  Checker chk;
  Rng rng(31);
  const int exps[] = {-150, -120, 120, 150};
  const double twoPi = 6.283185307179586;
  for (int e : exps) {
    const double s = std::ldexp(1.0, e);
    for (int i = 0; i < 1500; ++i) {
      const Pt a = scaled(rng.point(), s), b = scaled(rng.point(), s);
      const double t = rng.uniform(-1, 2);
      const Pt c{ulpStep(a[0] + t * (b[0] - a[0]), int(rng.integer(-1, 1))),
                 ulpStep(a[1] + t * (b[1] - a[1]), int(rng.integer(-1, 1)))};
      chk.orient(a, b, c);
      chk.dot(a, b, {ulpStep(a[0] - t * (b[1] - a[1]), int(rng.integer(-1, 1))),
                     a[1] + t * (b[0] - a[0])});
      Pt p[4];
      for (Pt& q : p) {
        const double th = rng.uniform(0, twoPi);
        q = {s * (0.5 + 0.25 * std::cos(th)), s * (-0.25 + 0.25 * std::sin(th))};
      }
      chk.incircle(p[0], p[1], p[2], p[3]);
      chk.incircle(scaled(rng.point(), s), scaled(rng.point(), s), scaled(rng.point(), s),
                   scaled(rng.point(), s));
    }
  }
  EXPECT_CLEAN(chk, 20000);
}

// sin, cos and atan2 built from +, -, *, / (portable_math.h): close to the maths library's,
// and the same bits in every build (the values below are pinned, so the WebAssembly run of
// this suite checks that its build rounds them exactly as the native one does).
TEST(PortableMath, CloseToTheMathsLibrary) {
  using namespace acutemesh::detail;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> angle(-7, 7), coordinate(-1e3, 1e3);
  for (int i = 0; i < 200000; ++i) {
    double x = angle(rng), s = 0, c = 0;
    portableSinCos(x, s, c);
    ASSERT_NEAR(s, std::sin(x), 4e-16) << x;
    ASSERT_NEAR(c, std::cos(x), 4e-16) << x;
    double y = coordinate(rng), z = coordinate(rng);
    if (i % 5 == 0) y = 0;
    if (i % 7 == 0) z = 0;
    if (i % 11 == 0) y = z;
    ASSERT_NEAR(portableAtan2(y, z), std::atan2(y, z), 8e-16) << y << " " << z;
  }
  EXPECT_EQ(portableAtan2(0, 0), 0);
  EXPECT_EQ(portableAtan2(0, -1), M_PI);
  EXPECT_EQ(portableAtan2(1, 0), M_PI / 2);
  EXPECT_EQ(portableAtan2(-1, -1), -3 * M_PI / 4);
}

TEST(PortableMath, SameBitsInEveryBuild) {
  using namespace acutemesh::detail;
  double s = 0, c = 0;
  portableSinCos(1.0, s, c);
  EXPECT_EQ(s, 0x1.aed548f090ceep-1);
  EXPECT_EQ(c, 0x1.14a280fb5068cp-1);
  portableSinCos(-5.5, s, c);
  EXPECT_EQ(s, 0x1.693c94e0ab057p-1);
  EXPECT_EQ(c, 0x1.6ad6c3c07d448p-1);
  EXPECT_EQ(portableAtan2(1, 2), 0x1.dac670561bb5p-2);
  EXPECT_EQ(portableAtan2(-3, -0.25), -0x1.a76873ac2bc7cp+0);
  EXPECT_EQ(portableCos(89.5 * M_PI / 180), 0x1.1df37c4954c0bp-7);
}

}  // namespace
