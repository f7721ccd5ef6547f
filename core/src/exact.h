// Exact integers of any size and points with rational coordinates: for the few vertices a
// double cannot hold, the exact feet of altitudes on tilted segments (Options::exactFeet).
// Schoolbook arithmetic, meant for a handful of checks per such vertex, not for meshing.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace acutemesh {
namespace detail {

class BigInt {
 public:
  BigInt() = default;
  explicit BigInt(int64_t v);
  // m * 2^shift for a double m that this makes an integer (shift >= the bits m needs).
  static BigInt fromDouble(double m, int shift);

  int sign() const { return magnitude_.empty() ? 0 : negative_ ? -1 : 1; }
  BigInt operator-() const;
  BigInt operator+(const BigInt& b) const;
  BigInt operator-(const BigInt& b) const { return *this + (-b); }
  BigInt operator*(const BigInt& b) const;
  BigInt shifted(int bits) const;  // * 2^bits; bits < 0 drops the low bits of the magnitude
  int trailingZeros() const;       // of the magnitude; 0 for zero
  bool operator==(const BigInt& b) const {
    return negative_ == b.negative_ && magnitude_ == b.magnitude_;
  }
  std::string decimal() const;
  double toDouble() const;  // nearest or next to it (for figures, not for decisions)

 private:
  static int compareMagnitude(const std::vector<uint32_t>& a, const std::vector<uint32_t>& b);
  void trim();
  bool negative_ = false;
  std::vector<uint32_t> magnitude_;  // little-endian 32-bit limbs, no leading zero limb
};

// gcd of the magnitudes (binary gcd); gcd(0, 0) = 0.
BigInt gcd(BigInt a, BigInt b);
// a / b for b dividing a exactly (a = q * b).
BigInt divideExactly(const BigInt& a, const BigInt& b);

// The point (x / w, y / w), w > 0.
struct RationalPoint {
  BigInt x, y, w;
};

RationalPoint exactPoint(const double* p);
// The foot of the perpendicular from v on the line through a and b (a != b), exactly.
RationalPoint exactFoot(const RationalPoint& v, const double* a, const double* b);
// Signs, exactly: of the orientation of p, q, r (> 0: counter-clockwise) and of
// (b - a) . (c - a) (< 0: the angle at a is obtuse).
int orientSign(const RationalPoint& p, const RationalPoint& q, const RationalPoint& r);
int dotSign(const RationalPoint& a, const RationalPoint& b, const RationalPoint& c);
// The triangle p[0], p[1], p[2] (doubles) with corner k at at[k] instead where that is not
// null: the sign of its orientation (returned) and of each corner's dot product (dots[k]).
int triangleSigns(const double* const p[3], const RationalPoint* const at[3], int dots[3]);
// For doubles a, b, c (b, c != a) and q >= 0, exactly: the sign of
// ((b - a).(c - a))^2 - q |b - a|^2 |c - a|^2. With a positive dot product, > 0 says the angle
// at a is below acos(sqrt(q)).
int cosineSquaredSign(const double* a, const double* b, const double* c, double q);
// "p/q" in lowest terms, or "p" when q is 1.
std::string rationalText(const BigInt& numerator, const BigInt& denominator);
// The reverse, for "p", "-p", "p/q" or "-p/q" (decimal digits, q > 0); false for anything else.
bool parseRational(const std::string& text, BigInt& numerator, BigInt& denominator);
// The point of Mesh::exactPoints' texts x and y; false if one is not a rational.
bool parseRationalPoint(const std::string& x, const std::string& y, RationalPoint& out);

}  // namespace detail
}  // namespace acutemesh
