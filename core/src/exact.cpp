#include "exact.h"

#include <algorithm>
#include <climits>
#include <cmath>

namespace acutemesh {
namespace detail {

BigInt::BigInt(int64_t v) {
  negative_ = v < 0;
  uint64_t m = v < 0 ? 0 - static_cast<uint64_t>(v) : static_cast<uint64_t>(v);
  while (m) {
    magnitude_.push_back(static_cast<uint32_t>(m));
    m >>= 32;
  }
}

BigInt BigInt::fromDouble(double m, int shift) {
  if (m == 0 || !std::isfinite(m)) return BigInt();
  int e = 0;
  const double f = std::frexp(std::fabs(m), &e);
  BigInt r(static_cast<int64_t>(std::ldexp(f, 53)));  // exact: 53 bits
  r = r.shifted(e - 53 + shift);
  r.negative_ = m < 0;
  return r;
}

BigInt BigInt::operator-() const {
  BigInt r = *this;
  if (!r.magnitude_.empty()) r.negative_ = !r.negative_;
  return r;
}

int BigInt::compareMagnitude(const std::vector<uint32_t>& a, const std::vector<uint32_t>& b) {
  if (a.size() != b.size()) return a.size() < b.size() ? -1 : 1;
  for (size_t i = a.size(); i-- > 0;)
    if (a[i] != b[i]) return a[i] < b[i] ? -1 : 1;
  return 0;
}

void BigInt::trim() {
  while (!magnitude_.empty() && magnitude_.back() == 0) magnitude_.pop_back();
  if (magnitude_.empty()) negative_ = false;
}

BigInt BigInt::operator+(const BigInt& b) const {
  BigInt r;
  if (negative_ == b.negative_) {
    r.negative_ = negative_;
    const size_t n = std::max(magnitude_.size(), b.magnitude_.size());
    r.magnitude_.resize(n + 1);
    uint64_t carry = 0;
    for (size_t i = 0; i < n; ++i) {
      carry += uint64_t(i < magnitude_.size() ? magnitude_[i] : 0) +
               (i < b.magnitude_.size() ? b.magnitude_[i] : 0);
      r.magnitude_[i] = static_cast<uint32_t>(carry);
      carry >>= 32;
    }
    r.magnitude_[n] = static_cast<uint32_t>(carry);
  } else {
    // |larger| - |smaller|, with the larger one's sign.
    const bool thisLarger = compareMagnitude(magnitude_, b.magnitude_) >= 0;
    const BigInt& big = thisLarger ? *this : b;
    const BigInt& small = thisLarger ? b : *this;
    r.negative_ = big.negative_;
    r.magnitude_.resize(big.magnitude_.size());
    int64_t borrow = 0;
    for (size_t i = 0; i < big.magnitude_.size(); ++i) {
      int64_t d = int64_t(big.magnitude_[i]) - (i < small.magnitude_.size() ? small.magnitude_[i] : 0) - borrow;
      borrow = d < 0;
      r.magnitude_[i] = static_cast<uint32_t>(d + (borrow << 32));
    }
  }
  r.trim();
  return r;
}

BigInt BigInt::operator*(const BigInt& b) const {
  BigInt r;
  if (magnitude_.empty() || b.magnitude_.empty()) return r;
  r.magnitude_.assign(magnitude_.size() + b.magnitude_.size(), 0);
  for (size_t i = 0; i < magnitude_.size(); ++i) {
    uint64_t carry = 0;
    for (size_t j = 0; j < b.magnitude_.size(); ++j) {
      carry += uint64_t(magnitude_[i]) * b.magnitude_[j] + r.magnitude_[i + j];
      r.magnitude_[i + j] = static_cast<uint32_t>(carry);
      carry >>= 32;
    }
    r.magnitude_[i + b.magnitude_.size()] = static_cast<uint32_t>(carry);
  }
  r.negative_ = negative_ != b.negative_;
  r.trim();
  return r;
}

BigInt BigInt::shifted(int bits) const {
  BigInt r;
  if (magnitude_.empty()) return r;
  r.negative_ = negative_;
  if (bits >= 0) {
    const size_t limbs = size_t(bits) / 32, rest = size_t(bits) % 32;
    r.magnitude_.assign(limbs, 0);
    uint32_t carry = 0;
    for (uint32_t limb : magnitude_) {
      r.magnitude_.push_back(rest ? (limb << rest) | carry : limb);
      carry = rest ? limb >> (32 - rest) : 0;
    }
    r.magnitude_.push_back(carry);
  } else {
    const size_t limbs = size_t(-bits) / 32, rest = size_t(-bits) % 32;
    for (size_t i = limbs; i < magnitude_.size(); ++i) {
      uint32_t high = i + 1 < magnitude_.size() ? magnitude_[i + 1] : 0;
      r.magnitude_.push_back(rest ? (magnitude_[i] >> rest) | (high << (32 - rest)) : magnitude_[i]);
    }
  }
  r.trim();
  return r;
}

int BigInt::trailingZeros() const {
  for (size_t i = 0; i < magnitude_.size(); ++i) {
    if (magnitude_[i] == 0) continue;
    int z = 0;
    while (((magnitude_[i] >> z) & 1) == 0) ++z;
    return int(32 * i) + z;
  }
  return 0;
}

std::string BigInt::decimal() const {
  if (magnitude_.empty()) return "0";
  std::vector<uint32_t> m = magnitude_;
  std::string digits;
  while (!m.empty()) {
    uint64_t rest = 0;  // m /= 10^9, the remainder in rest
    for (size_t i = m.size(); i-- > 0;) {
      uint64_t cur = (rest << 32) | m[i];
      m[i] = static_cast<uint32_t>(cur / 1000000000u);
      rest = cur % 1000000000u;
    }
    while (!m.empty() && m.back() == 0) m.pop_back();
    for (int k = 0; k < 9 && (!m.empty() || rest); ++k) {
      digits += char('0' + rest % 10);
      rest /= 10;
    }
  }
  if (negative_) digits += '-';
  std::reverse(digits.begin(), digits.end());
  return digits;
}

double BigInt::toDouble() const {
  double r = 0;
  for (size_t i = magnitude_.size(); i-- > 0;) r = r * 4294967296.0 + magnitude_[i];
  return negative_ ? -r : r;
}

BigInt gcd(BigInt a, BigInt b) {
  if (a.sign() < 0) a = -a;
  if (b.sign() < 0) b = -b;
  if (a.sign() == 0) return b;
  if (b.sign() == 0) return a;
  const int common = std::min(a.trailingZeros(), b.trailingZeros());
  a = a.shifted(-a.trailingZeros());
  for (;;) {
    b = b.shifted(-b.trailingZeros());
    if ((a - b).sign() > 0) std::swap(a, b);
    b = b - a;  // both odd: even, or zero
    if (b.sign() == 0) return a.shifted(common);
  }
}

BigInt divideExactly(const BigInt& a, const BigInt& b) {
  // Binary long division of the magnitudes: the remainder is zero by assumption.
  BigInt num = a.sign() < 0 ? -a : a, den = b.sign() < 0 ? -b : b;
  BigInt quotient;
  int bits = 0;
  while ((den.shifted(bits + 1) - num).sign() <= 0) ++bits;
  for (; bits >= 0; --bits) {
    BigInt part = den.shifted(bits);
    if ((num - part).sign() >= 0) {
      num = num - part;
      quotient = quotient + BigInt(1).shifted(bits);
    }
  }
  return (a.sign() < 0) != (b.sign() < 0) ? -quotient : quotient;
}

namespace {
// The exponent of the lowest set bit of v (v = odd * 2^result); INT_MAX for 0.
int lowestBit(double v) {
  if (v == 0 || !std::isfinite(v)) return INT_MAX;
  int e = 0;
  uint64_t m = static_cast<uint64_t>(std::ldexp(std::frexp(std::fabs(v), &e), 53));
  int k = e - 53;
  while ((m & 1) == 0) m >>= 1, ++k;
  return k;
}

// The shift that makes every one of these doubles an integer.
int commonShift(std::initializer_list<double> values) {
  int lowest = INT_MAX;
  for (double v : values) lowest = std::min(lowest, lowestBit(v));
  return lowest == INT_MAX ? 0 : std::max(0, -lowest);
}
}  // namespace

RationalPoint exactPoint(const double* p) {
  const int s = commonShift({p[0], p[1]});
  return {BigInt::fromDouble(p[0], s), BigInt::fromDouble(p[1], s), BigInt(1).shifted(s)};
}

RationalPoint exactFoot(const RationalPoint& v, const double* a, const double* b) {
  // On the grid of 2^-s, A + t (B - A) with t = (V - A).(B - A) / |B - A|^2, V = (vx, vy) / vw:
  // N = (vx 2^s - ax vw, vy 2^s - ay vw).(dx, dy), D = dx^2 + dy^2 (grid units), and
  // t = N / (vw D) and F = (ax vw D + N dx, ay vw D + N dy) / (2^s vw D).
  const int s = commonShift({a[0], a[1], b[0], b[1]});
  const BigInt ax = BigInt::fromDouble(a[0], s), ay = BigInt::fromDouble(a[1], s);
  const BigInt dx = BigInt::fromDouble(b[0], s) - ax, dy = BigInt::fromDouble(b[1], s) - ay;
  const BigInt n = (v.x.shifted(s) - ax * v.w) * dx + (v.y.shifted(s) - ay * v.w) * dy;
  const BigInt vwd = v.w * (dx * dx + dy * dy);
  return {ax * vwd + n * dx, ay * vwd + n * dy, vwd.shifted(s)};
}

int orientSign(const RationalPoint& p, const RationalPoint& q, const RationalPoint& r) {
  // det [[px py pw] [qx qy qw] [rx ry rw]] / (pw qw rw), every w > 0.
  const BigInt det = p.x * (q.y * r.w - q.w * r.y) - p.y * (q.x * r.w - q.w * r.x) +
                     p.w * (q.x * r.y - q.y * r.x);
  return det.sign();
}

int dotSign(const RationalPoint& a, const RationalPoint& b, const RationalPoint& c) {
  // (b - a).(c - a) times aw^2 bw cw > 0.
  const BigInt bx = b.x * a.w - a.x * b.w, by = b.y * a.w - a.y * b.w;
  const BigInt cx = c.x * a.w - a.x * c.w, cy = c.y * a.w - a.y * c.w;
  return (bx * cx + by * cy).sign();
}

int triangleSigns(const double* const p[3], const RationalPoint* const at[3], int dots[3]) {
  RationalPoint q[3];
  for (int k = 0; k < 3; ++k) q[k] = at[k] ? *at[k] : exactPoint(p[k]);
  for (int k = 0; k < 3; ++k) dots[k] = dotSign(q[k], q[(k + 1) % 3], q[(k + 2) % 3]);
  return orientSign(q[0], q[1], q[2]);
}

int cosineSquaredSign(const double* a, const double* b, const double* c, double q) {
  // On the grid of 2^-s every coordinate is an integer, and q = Q 2^-t.
  const int s = commonShift({a[0], a[1], b[0], b[1], c[0], c[1]}), t = commonShift({q});
  const BigInt ax = BigInt::fromDouble(a[0], s), ay = BigInt::fromDouble(a[1], s);
  const BigInt ux = BigInt::fromDouble(b[0], s) - ax, uy = BigInt::fromDouble(b[1], s) - ay;
  const BigInt vx = BigInt::fromDouble(c[0], s) - ax, vy = BigInt::fromDouble(c[1], s) - ay;
  const BigInt dot = ux * vx + uy * vy;
  const BigInt lengths = (ux * ux + uy * uy) * (vx * vx + vy * vy);
  return ((dot * dot).shifted(t) - BigInt::fromDouble(q, t) * lengths).sign();
}

std::string rationalText(const BigInt& numerator, const BigInt& denominator) {
  BigInt p = numerator, q = denominator;
  if (q.sign() < 0) p = -p, q = -q;
  const BigInt g = gcd(p, q);
  if (g.sign() != 0 && !(g == BigInt(1))) p = divideExactly(p, g), q = divideExactly(q, g);
  return q == BigInt(1) ? p.decimal() : p.decimal() + "/" + q.decimal();
}

bool parseRational(const std::string& text, BigInt& numerator, BigInt& denominator) {
  numerator = BigInt(0), denominator = BigInt(1);
  BigInt* part = &numerator;
  bool digits = false;
  const size_t start = !text.empty() && text[0] == '-';
  for (size_t i = start; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '/' && part == &numerator && digits) {
      part = &(denominator = BigInt(0));
      digits = false;
    } else if (c >= '0' && c <= '9') {
      *part = *part * BigInt(10) + BigInt(c - '0');
      digits = true;
    } else {
      return false;
    }
  }
  if (start) numerator = -numerator;
  return digits && denominator.sign() > 0;
}

bool parseRationalPoint(const std::string& x, const std::string& y, RationalPoint& out) {
  BigInt xn, xd, yn, yd;
  if (!parseRational(x, xn, xd) || !parseRational(y, yn, yd)) return false;
  out = {xn * yd, yn * xd, xd * yd};
  return true;
}

}  // namespace detail
}  // namespace acutemesh
