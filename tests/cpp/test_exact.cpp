// The rational arithmetic behind exact altitude feet (core/src/exact.h), against __int128,
// std::gcd and the independent reference of exact_reference.h.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>
#include <string>

#include "exact.h"
#include "exact_reference.h"

using acutemesh::detail::BigInt;
using acutemesh::detail::RationalPoint;
namespace detail = acutemesh::detail;

namespace {

std::string text(__int128 v) {
  if (v == 0) return "0";
  const bool negative = v < 0;
  unsigned __int128 m = negative ? -static_cast<unsigned __int128>(v) : static_cast<unsigned __int128>(v);
  std::string s;
  while (m) s.insert(s.begin(), char('0' + int(m % 10))), m /= 10;
  return negative ? "-" + s : s;
}

TEST(BigInt, ArithmeticMatchesInt128) {
  std::mt19937_64 rng(7);
  for (int i = 0; i < 20000; ++i) {
    // Mixed sizes, signs and zero.
    int64_t a = int64_t(rng()) >> (rng() % 64), b = int64_t(rng()) >> (rng() % 64);
    if (i % 97 == 0) a = 0;
    if (i % 89 == 0) b = a;
    const BigInt A(a), B(b);
    EXPECT_EQ((A * B).decimal(), text(__int128(a) * b));
    EXPECT_EQ((A + B).decimal(), text(__int128(a) + b));
    EXPECT_EQ((A - B).decimal(), text(__int128(a) - b));
    EXPECT_EQ((-A).decimal(), text(-__int128(a)));
    const int s = int(rng() % 60);
    EXPECT_EQ(A.shifted(s).decimal(), text(__int128(a) * (__int128(1) << s)));
    if (a >= 0) {
      EXPECT_EQ(A.shifted(-s).decimal(), text(__int128(a) >> s));
    }
    EXPECT_EQ((A * B).sign(), a == 0 || b == 0 ? 0 : (a < 0) == (b < 0) ? 1 : -1);
  }
}

TEST(BigInt, GcdAndExactDivision) {
  std::mt19937_64 rng(8);
  for (int i = 0; i < 5000; ++i) {
    const uint64_t g = rng() % 100000 + 1, a = (rng() % 1000000) * g, b = (rng() % 1000000) * g;
    const BigInt G = detail::gcd(BigInt(int64_t(a)), BigInt(-int64_t(b)));
    EXPECT_EQ(G.decimal(), std::to_string(std::gcd(a, b)));
    if (G.sign()) {
      EXPECT_EQ(detail::divideExactly(BigInt(-int64_t(a)), G).decimal(),
                text(-__int128(a / std::gcd(a, b))));
    }
  }
  // Beyond 64 bits: (2^80 * 3 * 5) and (2^70 * 5 * 7) share 2^70 * 5.
  const BigInt a = BigInt(15).shifted(80), b = BigInt(35).shifted(70);
  EXPECT_EQ(detail::gcd(a, b).decimal(), BigInt(5).shifted(70).decimal());
  EXPECT_EQ(detail::divideExactly(a, detail::gcd(a, b)).decimal(), "3072");  // 3 * 2^10
  EXPECT_EQ(detail::gcd(BigInt(0), BigInt(0)).sign(), 0);
}

TEST(BigInt, FromDoubleIsExact) {
  EXPECT_EQ(BigInt::fromDouble(0.1, 55).decimal(), "3602879701896397");  // 0.1 = that / 2^55
  EXPECT_EQ(BigInt::fromDouble(-3.0, 0).decimal(), "-3");
  EXPECT_EQ(BigInt::fromDouble(std::ldexp(1.0, 100), 0).decimal(), "1267650600228229401496703205376");
  EXPECT_EQ(BigInt::fromDouble(std::ldexp(3.0, -40), 40).decimal(), "3");
  EXPECT_EQ(BigInt::fromDouble(0.0, 10).sign(), 0);
}

TEST(Rational, TextInLowestTerms) {
  EXPECT_EQ(detail::rationalText(BigInt(6), BigInt(4)), "3/2");
  EXPECT_EQ(detail::rationalText(BigInt(-6), BigInt(3)), "-2");
  EXPECT_EQ(detail::rationalText(BigInt(6), BigInt(-4)), "-3/2");
  EXPECT_EQ(detail::rationalText(BigInt(0), BigInt(5)), "0");
  EXPECT_EQ(detail::rationalText(BigInt(7), BigInt(1)), "7");
}

TEST(Rational, TextReadsBack) {
  BigInt p, q;
  for (const char* s : {"0", "7", "-7", "3/2", "-3/2", "123456789012345678901234567891/7"}) {
    ASSERT_TRUE(detail::parseRational(s, p, q)) << s;
    EXPECT_EQ(detail::rationalText(p, q), s);
  }
  for (const char* s : {"", "-", "/2", "1/", "1/0", "1/-2", "1.5", "1e3", " 1", "1/2/3", "--1"})
    EXPECT_FALSE(detail::parseRational(s, p, q)) << s;
  RationalPoint r;
  ASSERT_TRUE(detail::parseRationalPoint("1/2", "-2/3", r));
  EXPECT_EQ(detail::rationalText(r.x, r.w), "1/2");
  EXPECT_EQ(detail::rationalText(r.y, r.w), "-2/3");
  EXPECT_FALSE(detail::parseRationalPoint("1/2", "x", r));
}

TEST(Rational, FootOfAnAltitude) {
  // (0, 1) on the line through (0, 0) and (3, 1): t = 1/10, the foot (3/10, 1/10).
  const double v[2] = {0, 1}, a[2] = {0, 0}, b[2] = {3, 1};
  const RationalPoint f = detail::exactFoot(detail::exactPoint(v), a, b);
  EXPECT_EQ(detail::rationalText(f.x, f.w), "3/10");
  EXPECT_EQ(detail::rationalText(f.y, f.w), "1/10");
  // On a tilted line through doubles, from doubles and from a foot: on the line, and the
  // altitude at right angles to it, exactly.
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> coordinate(-1000, 1000);
  for (int i = 0; i < 300; ++i) {
    const double p[2] = {coordinate(rng), coordinate(rng)}, q[2] = {coordinate(rng), coordinate(rng)};
    const double w[2] = {std::round(coordinate(rng)), 0.125 * std::round(coordinate(rng))};
    const RationalPoint A = detail::exactPoint(p), B = detail::exactPoint(q), W = detail::exactPoint(w);
    const RationalPoint F = detail::exactFoot(W, p, q);
    EXPECT_EQ(detail::orientSign(A, B, F), 0);
    EXPECT_EQ(detail::dotSign(F, W, B), 0);
    // The foot of the foot on a second line (feet of feet, as chains of them need).
    const RationalPoint G = detail::exactFoot(F, w, q);
    EXPECT_EQ(detail::orientSign(W, B, G), 0);
    EXPECT_EQ(detail::dotSign(G, F, B), 0);
  }
}

TEST(Rational, SignsMatchTheReference) {
  std::mt19937_64 rng(10);
  std::uniform_real_distribution<double> coordinate(-1, 1);
  for (int i = 0; i < 3000; ++i) {
    double p[3][2];
    for (auto& x : p) x[0] = coordinate(rng), x[1] = coordinate(rng);
    if (i % 3 == 0) {  // exactly in line, or at right angles: the signs' zero
      p[2][0] = p[0][0] + 2 * (p[1][0] - p[0][0]), p[2][1] = p[0][1] + 2 * (p[1][1] - p[0][1]);
      p[2][0] = std::ldexp(std::round(std::ldexp(p[2][0], 20)), -20);
      p[2][1] = std::ldexp(std::round(std::ldexp(p[2][1], 20)), -20);
    }
    const RationalPoint a = detail::exactPoint(p[0]), b = detail::exactPoint(p[1]), c = detail::exactPoint(p[2]);
    EXPECT_EQ(detail::orientSign(a, b, c), exactref::orient2dSign(p[0], p[1], p[2]));
    EXPECT_EQ(detail::dotSign(a, b, c), exactref::dot2dSign(p[0], p[1], p[2]));
  }
}

}  // namespace
