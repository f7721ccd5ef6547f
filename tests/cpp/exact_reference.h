// Slow exact reference for the geometric predicates, for tests only.
//
// Every finite double is m * 2^e with an integer m (|m| < 2^53). Scaling all inputs of one
// predicate by 2^-E, where E is the smallest exponent among them, turns them into integers
// without changing the sign of any homogeneous polynomial of them, so the determinants can
// be evaluated exactly in arbitrary-precision integer arithmetic. Deliberately simple (sign +
// magnitude on 32-bit limbs, schoolbook multiplication) and independent of the expansion
// arithmetic it checks.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace exactref {

class BigInt {
 public:
  BigInt() = default;
  explicit BigInt(int64_t v) {
    neg_ = v < 0;
    uint64_t m = neg_ ? uint64_t(0) - uint64_t(v) : uint64_t(v);
    while (m != 0) {
      mag_.push_back(uint32_t(m & 0xffffffffu));
      m >>= 32;
    }
  }

  int sign() const { return mag_.empty() ? 0 : (neg_ ? -1 : 1); }

  // *this * 2^bits, bits >= 0.
  BigInt shl(int bits) const {
    BigInt r;
    if (mag_.empty()) return r;
    const int limbs = bits / 32;
    const int rem = bits % 32;
    r.neg_ = neg_;
    r.mag_.assign(size_t(limbs), 0u);
    uint32_t carry = 0;
    for (uint32_t limb : mag_) {
      const uint64_t v = (uint64_t(limb) << rem) | carry;
      r.mag_.push_back(uint32_t(v & 0xffffffffu));
      carry = rem == 0 ? 0u : uint32_t(uint64_t(limb) >> (32 - rem));
    }
    if (carry != 0) r.mag_.push_back(carry);
    return r;
  }

  BigInt operator-() const {
    BigInt r = *this;
    if (!r.mag_.empty()) r.neg_ = !r.neg_;
    return r;
  }

  friend BigInt operator+(const BigInt& a, const BigInt& b) {
    if (a.neg_ == b.neg_) {
      BigInt r;
      r.neg_ = a.neg_;
      r.mag_ = addMag(a.mag_, b.mag_);
      r.trim();
      return r;
    }
    const int c = cmpMag(a.mag_, b.mag_);
    if (c == 0) return BigInt();
    BigInt r;
    if (c > 0) {
      r.neg_ = a.neg_;
      r.mag_ = subMag(a.mag_, b.mag_);
    } else {
      r.neg_ = b.neg_;
      r.mag_ = subMag(b.mag_, a.mag_);
    }
    r.trim();
    return r;
  }

  friend BigInt operator-(const BigInt& a, const BigInt& b) { return a + (-b); }

  friend BigInt operator*(const BigInt& a, const BigInt& b) {
    BigInt r;
    if (a.mag_.empty() || b.mag_.empty()) return r;
    r.mag_.assign(a.mag_.size() + b.mag_.size(), 0u);
    for (size_t i = 0; i < a.mag_.size(); ++i) {
      uint64_t carry = 0;
      for (size_t j = 0; j < b.mag_.size(); ++j) {
        const uint64_t cur = uint64_t(a.mag_[i]) * b.mag_[j] + r.mag_[i + j] + carry;
        r.mag_[i + j] = uint32_t(cur & 0xffffffffu);
        carry = cur >> 32;
      }
      size_t k = i + b.mag_.size();
      while (carry != 0) {
        const uint64_t cur = uint64_t(r.mag_[k]) + carry;
        r.mag_[k] = uint32_t(cur & 0xffffffffu);
        carry = cur >> 32;
        ++k;
      }
    }
    r.neg_ = a.neg_ != b.neg_;
    r.trim();
    return r;
  }

 private:
  using Mag = std::vector<uint32_t>;

  void trim() {
    while (!mag_.empty() && mag_.back() == 0) mag_.pop_back();
    if (mag_.empty()) neg_ = false;
  }

  static int cmpMag(const Mag& a, const Mag& b) {
    if (a.size() != b.size()) return a.size() < b.size() ? -1 : 1;
    for (size_t i = a.size(); i-- > 0;) {
      if (a[i] != b[i]) return a[i] < b[i] ? -1 : 1;
    }
    return 0;
  }

  static Mag addMag(const Mag& a, const Mag& b) {
    const Mag& lo = a.size() < b.size() ? a : b;
    const Mag& hi = a.size() < b.size() ? b : a;
    Mag r(hi.size() + 1, 0u);
    uint64_t carry = 0;
    for (size_t i = 0; i < hi.size(); ++i) {
      const uint64_t cur = uint64_t(hi[i]) + (i < lo.size() ? lo[i] : 0u) + carry;
      r[i] = uint32_t(cur & 0xffffffffu);
      carry = cur >> 32;
    }
    r[hi.size()] = uint32_t(carry);
    return r;
  }

  // a - b with |a| >= |b|.
  static Mag subMag(const Mag& a, const Mag& b) {
    Mag r(a.size(), 0u);
    int64_t borrow = 0;
    for (size_t i = 0; i < a.size(); ++i) {
      int64_t cur = int64_t(a[i]) - (i < b.size() ? int64_t(b[i]) : 0) - borrow;
      borrow = cur < 0 ? 1 : 0;
      if (cur < 0) cur += int64_t(1) << 32;
      r[i] = uint32_t(cur);
    }
    return r;
  }

  bool neg_ = false;
  Mag mag_;
};

// Converts a list of finite doubles to BigInts sharing one power-of-two scale factor.
inline std::vector<BigInt> toCommonScale(const std::vector<double>& xs) {
  std::vector<int64_t> mant(xs.size());
  std::vector<int> expo(xs.size());
  int minExp = 0;
  bool any = false;
  for (size_t i = 0; i < xs.size(); ++i) {
    if (xs[i] == 0.0) {
      mant[i] = 0;
      expo[i] = 0;
      continue;
    }
    int k = 0;
    const double f = std::frexp(xs[i], &k);  // xs[i] = f * 2^k, 0.5 <= |f| < 1
    mant[i] = int64_t(std::ldexp(f, 53));     // exact: an integer below 2^53
    expo[i] = k - 53;
    minExp = any ? std::min(minExp, expo[i]) : expo[i];
    any = true;
  }
  std::vector<BigInt> out;
  out.reserve(xs.size());
  for (size_t i = 0; i < xs.size(); ++i) {
    out.push_back(mant[i] == 0 ? BigInt() : BigInt(mant[i]).shl(expo[i] - minExp));
  }
  return out;
}

// Exact sign of (ax - cx)(by - cy) - (ay - cy)(bx - cx).
inline int orient2dSign(const double* a, const double* b, const double* c) {
  const auto v = toCommonScale({a[0], a[1], b[0], b[1], c[0], c[1]});
  const BigInt acx = v[0] - v[4], acy = v[1] - v[5];
  const BigInt bcx = v[2] - v[4], bcy = v[3] - v[5];
  return (acx * bcy - acy * bcx).sign();
}

// Exact sign of the incircle determinant
//   | adx ady adx^2+ady^2 |
//   | bdx bdy bdx^2+bdy^2 |   with pdx = px - dx, pdy = py - dy.
//   | cdx cdy cdx^2+cdy^2 |
inline int incircleSign(const double* a, const double* b, const double* c, const double* d) {
  const auto v = toCommonScale({a[0], a[1], b[0], b[1], c[0], c[1], d[0], d[1]});
  const BigInt adx = v[0] - v[6], ady = v[1] - v[7];
  const BigInt bdx = v[2] - v[6], bdy = v[3] - v[7];
  const BigInt cdx = v[4] - v[6], cdy = v[5] - v[7];
  const BigInt alift = adx * adx + ady * ady;
  const BigInt blift = bdx * bdx + bdy * bdy;
  const BigInt clift = cdx * cdx + cdy * cdy;
  const BigInt det = alift * (bdx * cdy - cdx * bdy) + blift * (cdx * ady - adx * cdy) +
                     clift * (adx * bdy - bdx * ady);
  return det.sign();
}

// Exact sign of (b - a) . (c - a).
inline int dot2dSign(const double* a, const double* b, const double* c) {
  const auto v = toCommonScale({a[0], a[1], b[0], b[1], c[0], c[1]});
  return ((v[2] - v[0]) * (v[4] - v[0]) + (v[3] - v[1]) * (v[5] - v[1])).sign();
}

}  // namespace exactref
