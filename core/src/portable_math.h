// sin, cos and atan2 from +, -, *, / alone, so that every build rounds them alike.
//
// The WebAssembly build must make the very meshes the native one makes, and the two link
// different maths libraries: glibc's and Emscripten's musl-based libm need not round sin, cos
// or atan2 alike (nor hypot, pow, exp2, log2). IEEE 754 rounds +, -, *, / and sqrt correctly
// everywhere, and the core is compiled without fused multiply-add, so a fixed sequence of
// those operations gives the same bits on every platform. Accuracy: within a few units in the
// last place (tests/cpp/test_predicates.cpp, PortableMath), plenty for where they are used (corner
// fans' directions and arc points, angle bounds' cosines).
#pragma once

#include <cmath>
#include <initializer_list>

namespace acutemesh::detail {

namespace portable {
// pi/2 split into a head with few enough bits that k * head is exact for the k used here,
// and the rest (Cody and Waite's reduction).
constexpr double kHalfPiHead = 1.5707963267341256141662597656250;  // 33 bits
constexpr double kHalfPiTail = 6.0771005065061922267e-11;
constexpr double kHalfPi = 1.5707963267948966192, kPi = 3.1415926535897932385;
constexpr double kSixthPi = 0.52359877559829887308;
constexpr double kSqrt3 = 1.7320508075688772935;
constexpr double kTanTwelfthPi = 0.26794919243112270647;  // tan(pi/12) = 2 - sqrt(3)

// Taylor series on |r| <= pi/4, Horner's scheme: the first term left out is under 2^-60 of
// the result.
inline double sinReduced(double r) {
  double r2 = r * r, s = 1.0 / 355687428096000.0;  // 1/17!
  for (double c : {-1.0 / 1307674368000.0, 1.0 / 6227020800.0, -1.0 / 39916800.0, 1.0 / 362880.0,
                   -1.0 / 5040.0, 1.0 / 120.0, -1.0 / 6.0})
    s = s * r2 + c;
  return r + r * r2 * s;
}
inline double cosReduced(double r) {
  double r2 = r * r, s = -1.0 / 6402373705728000.0;  // -1/18!
  for (double c : {1.0 / 20922789888000.0, -1.0 / 87178291200.0, 1.0 / 479001600.0,
                   -1.0 / 3628800.0, 1.0 / 40320.0, -1.0 / 720.0, 1.0 / 24.0})
    s = s * r2 + c;
  return 1.0 - 0.5 * r2 + r2 * r2 * s;
}
// atan z for |z| <= tan(pi/12): its alternating series to z^31 (the next term is under
// 2^-60 of the result).
inline double atanReduced(double z) {
  double z2 = z * z, s = 0;
  for (int k = 15; k >= 1; --k) s = s * z2 + ((k & 1) ? -1.0 : 1.0) / double(2 * k + 1);
  return z + z * z2 * s;
}
}  // namespace portable

// sin and cos of x (radians, |x| < 2^20: beyond that the reduction loses bits; the core's
// angles are within a few turns).
inline void portableSinCos(double x, double& sine, double& cosine) {
  double k = std::nearbyint(x / portable::kHalfPi);
  double r = (x - k * portable::kHalfPiHead) - k * portable::kHalfPiTail;
  double s = portable::sinReduced(r), c = portable::cosReduced(r);
  switch (int(std::fmod(k, 4.0) + 4) % 4) {
    case 0: sine = s, cosine = c; break;
    case 1: sine = c, cosine = -s; break;
    case 2: sine = -s, cosine = -c; break;
    default: sine = -c, cosine = s; break;
  }
}
inline double portableCos(double x) {
  double s, c;
  portableSinCos(x, s, c);
  return c;
}

// atan2(y, x) in [-pi, pi], with atan2(0, 0) = 0.
inline double portableAtan2(double y, double x) {
  double ay = std::fabs(y), ax = std::fabs(x);
  if (ay == 0 && ax == 0) return 0;
  bool swapped = ay > ax;
  double t = swapped ? ax / ay : ay / ax;  // in [0, 1]
  double angle;
  if (t > portable::kTanTwelfthPi)  // atan t = pi/6 + atan((t sqrt3 - 1) / (t + sqrt3))
    angle = portable::kSixthPi + portable::atanReduced((t * portable::kSqrt3 - 1) / (t + portable::kSqrt3));
  else
    angle = portable::atanReduced(t);
  if (swapped) angle = portable::kHalfPi - angle;
  if (x < 0) angle = portable::kPi - angle;
  return y < 0 ? -angle : angle;
}

}  // namespace acutemesh::detail
