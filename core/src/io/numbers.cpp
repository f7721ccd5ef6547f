// Decimal-to-double conversion, exactly rounded. The common case is converted here without
// the library's per-number cost: Clinger's fast path for mantissas up to 2^53 with small
// exponents, then the Eisel-Lemire algorithm (as in fast_float) for up to 19 significant
// digits and exponents in [-64, 64]. Anything else (more digits, subnormals, overflow, far
// exponents, the rare undecided product) goes to the library (convertDouble).
//
// Floating-point std::from_chars serves where the library has it (libstdc++ >= 11, MSVC);
// strtod otherwise (Emscripten's older libc++). For testing on any platform:
// ACUTEMESH_NO_FLOAT_CHARCONV forces strtod; ACUTEMESH_IO_PORTABLE turns off __int128, the
// clz builtin and the 8-digits-at-once loads.
#include "numbers.h"

#include <cerrno>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>

#if defined(__cpp_lib_to_chars) && !defined(ACUTEMESH_NO_FLOAT_CHARCONV)
#define ACUTEMESH_FLOAT_FROM_CHARS 1
#else
#define ACUTEMESH_FLOAT_FROM_CHARS 0
#endif

namespace acutemesh::io {
namespace {

// Converts a token already checked against the decimal grammar (optional '-', digits with an
// optional point, optional exponent; no '+', no hex, no inf/nan). Values beyond the double
// range are an error; values below it become zero, as strtod does.
NumErr convertDouble(const char* b, const char* e, double& v) {
#if ACUTEMESH_FLOAT_FROM_CHARS
  std::from_chars_result r = std::from_chars(b, e, v, std::chars_format::general);
  if (r.ec == std::errc() && r.ptr == e) return NumErr::Ok;
  if (r.ec != std::errc::result_out_of_range) return NumErr::NotNumber;
    // Out of range: overflow or underflow. Rare, so let strtod tell which.
#endif
  char small[128];
  std::string big;
  const size_t n = static_cast<size_t>(e - b);
  const char* cstr;
  if (n < sizeof small) {
    std::memcpy(small, b, n);
    small[n] = '\0';
    cstr = small;
  } else {
    big.assign(b, n);
    cstr = big.c_str();
  }
  char* end = nullptr;
  errno = 0;
  const double x = std::strtod(cstr, &end);
  if (end != cstr + n) return NumErr::NotNumber;
  if (std::isinf(x)) return NumErr::OutOfRange;  // the grammar excludes a literal "inf"
  v = x;
  return NumErr::Ok;
}

bool startsWithNoCase(const char* p, const char* e, const char* word) {
  for (; *word; ++word, ++p) {
    if (p == e) return false;
    char c = *p;
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    if (c != *word) return false;
  }
  return true;
}

struct Pow128 {
  uint64_t hi, lo;
};
constexpr int kMinPow5 = -64, kMaxPow5 = 64;
// The 128 most significant bits of 5^q, q in [-64, 64] (negative q: rounded up), generated
// exactly as fast_float's table_generation.py does.
const Pow128 kPow5[kMaxPow5 - kMinPow5 + 1] = {
    {0xa87fea27a539e9a5ULL, 0x3f2398d747b36224ULL}, {0xd29fe4b18e88640eULL, 0x8eec7f0d19a03aadULL},
    {0x83a3eeeef9153e89ULL, 0x1953cf68300424acULL}, {0xa48ceaaab75a8e2bULL, 0x5fa8c3423c052dd7ULL},
    {0xcdb02555653131b6ULL, 0x3792f412cb06794dULL}, {0x808e17555f3ebf11ULL, 0xe2bbd88bbee40bd0ULL},
    {0xa0b19d2ab70e6ed6ULL, 0x5b6aceaeae9d0ec4ULL}, {0xc8de047564d20a8bULL, 0xf245825a5a445275ULL},
    {0xfb158592be068d2eULL, 0xeed6e2f0f0d56712ULL}, {0x9ced737bb6c4183dULL, 0x55464dd69685606bULL},
    {0xc428d05aa4751e4cULL, 0xaa97e14c3c26b886ULL}, {0xf53304714d9265dfULL, 0xd53dd99f4b3066a8ULL},
    {0x993fe2c6d07b7fabULL, 0xe546a8038efe4029ULL}, {0xbf8fdb78849a5f96ULL, 0xde98520472bdd033ULL},
    {0xef73d256a5c0f77cULL, 0x963e66858f6d4440ULL}, {0x95a8637627989aadULL, 0xdde7001379a44aa8ULL},
    {0xbb127c53b17ec159ULL, 0x5560c018580d5d52ULL}, {0xe9d71b689dde71afULL, 0xaab8f01e6e10b4a6ULL},
    {0x9226712162ab070dULL, 0xcab3961304ca70e8ULL}, {0xb6b00d69bb55c8d1ULL, 0x3d607b97c5fd0d22ULL},
    {0xe45c10c42a2b3b05ULL, 0x8cb89a7db77c506aULL}, {0x8eb98a7a9a5b04e3ULL, 0x77f3608e92adb242ULL},
    {0xb267ed1940f1c61cULL, 0x55f038b237591ed3ULL}, {0xdf01e85f912e37a3ULL, 0x6b6c46dec52f6688ULL},
    {0x8b61313bbabce2c6ULL, 0x2323ac4b3b3da015ULL}, {0xae397d8aa96c1b77ULL, 0xabec975e0a0d081aULL},
    {0xd9c7dced53c72255ULL, 0x96e7bd358c904a21ULL}, {0x881cea14545c7575ULL, 0x7e50d64177da2e54ULL},
    {0xaa242499697392d2ULL, 0xdde50bd1d5d0b9e9ULL}, {0xd4ad2dbfc3d07787ULL, 0x955e4ec64b44e864ULL},
    {0x84ec3c97da624ab4ULL, 0xbd5af13bef0b113eULL}, {0xa6274bbdd0fadd61ULL, 0xecb1ad8aeacdd58eULL},
    {0xcfb11ead453994baULL, 0x67de18eda5814af2ULL}, {0x81ceb32c4b43fcf4ULL, 0x80eacf948770ced7ULL},
    {0xa2425ff75e14fc31ULL, 0xa1258379a94d028dULL}, {0xcad2f7f5359a3b3eULL, 0x096ee45813a04330ULL},
    {0xfd87b5f28300ca0dULL, 0x8bca9d6e188853fcULL}, {0x9e74d1b791e07e48ULL, 0x775ea264cf55347eULL},
    {0xc612062576589ddaULL, 0x95364afe032a819eULL}, {0xf79687aed3eec551ULL, 0x3a83ddbd83f52205ULL},
    {0x9abe14cd44753b52ULL, 0xc4926a9672793543ULL}, {0xc16d9a0095928a27ULL, 0x75b7053c0f178294ULL},
    {0xf1c90080baf72cb1ULL, 0x5324c68b12dd6339ULL}, {0x971da05074da7beeULL, 0xd3f6fc16ebca5e04ULL},
    {0xbce5086492111aeaULL, 0x88f4bb1ca6bcf585ULL}, {0xec1e4a7db69561a5ULL, 0x2b31e9e3d06c32e6ULL},
    {0x9392ee8e921d5d07ULL, 0x3aff322e62439fd0ULL}, {0xb877aa3236a4b449ULL, 0x09befeb9fad487c3ULL},
    {0xe69594bec44de15bULL, 0x4c2ebe687989a9b4ULL}, {0x901d7cf73ab0acd9ULL, 0x0f9d37014bf60a11ULL},
    {0xb424dc35095cd80fULL, 0x538484c19ef38c95ULL}, {0xe12e13424bb40e13ULL, 0x2865a5f206b06fbaULL},
    {0x8cbccc096f5088cbULL, 0xf93f87b7442e45d4ULL}, {0xafebff0bcb24aafeULL, 0xf78f69a51539d749ULL},
    {0xdbe6fecebdedd5beULL, 0xb573440e5a884d1cULL}, {0x89705f4136b4a597ULL, 0x31680a88f8953031ULL},
    {0xabcc77118461cefcULL, 0xfdc20d2b36ba7c3eULL}, {0xd6bf94d5e57a42bcULL, 0x3d32907604691b4dULL},
    {0x8637bd05af6c69b5ULL, 0xa63f9a49c2c1b110ULL}, {0xa7c5ac471b478423ULL, 0x0fcf80dc33721d54ULL},
    {0xd1b71758e219652bULL, 0xd3c36113404ea4a9ULL}, {0x83126e978d4fdf3bULL, 0x645a1cac083126eaULL},
    {0xa3d70a3d70a3d70aULL, 0x3d70a3d70a3d70a4ULL}, {0xccccccccccccccccULL, 0xcccccccccccccccdULL},
    {0x8000000000000000ULL, 0x0000000000000000ULL}, {0xa000000000000000ULL, 0x0000000000000000ULL},
    {0xc800000000000000ULL, 0x0000000000000000ULL}, {0xfa00000000000000ULL, 0x0000000000000000ULL},
    {0x9c40000000000000ULL, 0x0000000000000000ULL}, {0xc350000000000000ULL, 0x0000000000000000ULL},
    {0xf424000000000000ULL, 0x0000000000000000ULL}, {0x9896800000000000ULL, 0x0000000000000000ULL},
    {0xbebc200000000000ULL, 0x0000000000000000ULL}, {0xee6b280000000000ULL, 0x0000000000000000ULL},
    {0x9502f90000000000ULL, 0x0000000000000000ULL}, {0xba43b74000000000ULL, 0x0000000000000000ULL},
    {0xe8d4a51000000000ULL, 0x0000000000000000ULL}, {0x9184e72a00000000ULL, 0x0000000000000000ULL},
    {0xb5e620f480000000ULL, 0x0000000000000000ULL}, {0xe35fa931a0000000ULL, 0x0000000000000000ULL},
    {0x8e1bc9bf04000000ULL, 0x0000000000000000ULL}, {0xb1a2bc2ec5000000ULL, 0x0000000000000000ULL},
    {0xde0b6b3a76400000ULL, 0x0000000000000000ULL}, {0x8ac7230489e80000ULL, 0x0000000000000000ULL},
    {0xad78ebc5ac620000ULL, 0x0000000000000000ULL}, {0xd8d726b7177a8000ULL, 0x0000000000000000ULL},
    {0x878678326eac9000ULL, 0x0000000000000000ULL}, {0xa968163f0a57b400ULL, 0x0000000000000000ULL},
    {0xd3c21bcecceda100ULL, 0x0000000000000000ULL}, {0x84595161401484a0ULL, 0x0000000000000000ULL},
    {0xa56fa5b99019a5c8ULL, 0x0000000000000000ULL}, {0xcecb8f27f4200f3aULL, 0x0000000000000000ULL},
    {0x813f3978f8940984ULL, 0x4000000000000000ULL}, {0xa18f07d736b90be5ULL, 0x5000000000000000ULL},
    {0xc9f2c9cd04674edeULL, 0xa400000000000000ULL}, {0xfc6f7c4045812296ULL, 0x4d00000000000000ULL},
    {0x9dc5ada82b70b59dULL, 0xf020000000000000ULL}, {0xc5371912364ce305ULL, 0x6c28000000000000ULL},
    {0xf684df56c3e01bc6ULL, 0xc732000000000000ULL}, {0x9a130b963a6c115cULL, 0x3c7f400000000000ULL},
    {0xc097ce7bc90715b3ULL, 0x4b9f100000000000ULL}, {0xf0bdc21abb48db20ULL, 0x1e86d40000000000ULL},
    {0x96769950b50d88f4ULL, 0x1314448000000000ULL}, {0xbc143fa4e250eb31ULL, 0x17d955a000000000ULL},
    {0xeb194f8e1ae525fdULL, 0x5dcfab0800000000ULL}, {0x92efd1b8d0cf37beULL, 0x5aa1cae500000000ULL},
    {0xb7abc627050305adULL, 0xf14a3d9e40000000ULL}, {0xe596b7b0c643c719ULL, 0x6d9ccd05d0000000ULL},
    {0x8f7e32ce7bea5c6fULL, 0xe4820023a2000000ULL}, {0xb35dbf821ae4f38bULL, 0xdda2802c8a800000ULL},
    {0xe0352f62a19e306eULL, 0xd50b2037ad200000ULL}, {0x8c213d9da502de45ULL, 0x4526f422cc340000ULL},
    {0xaf298d050e4395d6ULL, 0x9670b12b7f410000ULL}, {0xdaf3f04651d47b4cULL, 0x3c0cdd765f114000ULL},
    {0x88d8762bf324cd0fULL, 0xa5880a69fb6ac800ULL}, {0xab0e93b6efee0053ULL, 0x8eea0d047a457a00ULL},
    {0xd5d238a4abe98068ULL, 0x72a4904598d6d880ULL}, {0x85a36366eb71f041ULL, 0x47a6da2b7f864750ULL},
    {0xa70c3c40a64e6c51ULL, 0x999090b65f67d924ULL}, {0xd0cf4b50cfe20765ULL, 0xfff4b4e3f741cf6dULL},
    {0x82818f1281ed449fULL, 0xbff8f10e7a8921a4ULL}, {0xa321f2d7226895c7ULL, 0xaff72d52192b6a0dULL},
    {0xcbea6f8ceb02bb39ULL, 0x9bf4f8a69f764490ULL}, {0xfee50b7025c36a08ULL, 0x02f236d04753d5b4ULL},
    {0x9f4f2726179a2245ULL, 0x01d762422c946590ULL}, {0xc722f0ef9d80aad6ULL, 0x424d3ad2b7b97ef5ULL},
    {0xf8ebad2b84e0d58bULL, 0xd2e0898765a7deb2ULL}, {0x9b934c3b330c8577ULL, 0x63cc55f49f88eb2fULL},
    {0xc2781f49ffcfa6d5ULL, 0x3cbf6b71c76b25fbULL},
};

inline void mul64(uint64_t a, uint64_t b, uint64_t& hi, uint64_t& lo) {
#if defined(__SIZEOF_INT128__) && !defined(ACUTEMESH_IO_PORTABLE)
  __extension__ typedef unsigned __int128 U128;
  const U128 p = static_cast<U128>(a) * b;
  hi = static_cast<uint64_t>(p >> 64);
  lo = static_cast<uint64_t>(p);
#else
  const uint64_t a0 = static_cast<uint32_t>(a), a1 = a >> 32;
  const uint64_t b0 = static_cast<uint32_t>(b), b1 = b >> 32;
  const uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
  const uint64_t mid = (p00 >> 32) + static_cast<uint32_t>(p01) + static_cast<uint32_t>(p10);
  lo = (mid << 32) | static_cast<uint32_t>(p00);
  hi = p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
#endif
}

inline int leadingZeros(uint64_t x) {  // x != 0
#if (defined(__GNUC__) || defined(__clang__)) && !defined(ACUTEMESH_IO_PORTABLE)
  return __builtin_clzll(x);
#else
  int n = 0;
  while (!(x >> 63)) {
    x <<= 1;
    ++n;
  }
  return n;
#endif
}

// w * 10^q for w != 0, q in [kMinPow5, kMaxPow5], rounded to nearest even. False when the
// cheap computation cannot decide or the result is subnormal or overflows.
bool eiselLemire(uint64_t w, int q, double& out) {
  const int lz = leadingZeros(w);
  w <<= lz;
  const Pow128& p = kPow5[q - kMinPow5];
  uint64_t hi, lo;
  mul64(w, p.hi, hi, lo);
  constexpr uint64_t kMask = ~uint64_t(0) >> 55;  // 52 mantissa bits + 3
  if ((hi & kMask) == kMask) {
    uint64_t hi2, lo2;
    mul64(w, p.lo, hi2, lo2);
    lo += hi2;
    if (hi2 > lo) ++hi;
  }
  if (lo == ~uint64_t(0) && (q < -27 || q > 55)) return false;
  const int upper = static_cast<int>(hi >> 63);
  const int shift = upper + 64 - 52 - 3;
  uint64_t m = hi >> shift;
  int power2 = (((152170 + 65536) * q) >> 16) + 63 + upper - lz + 1023;
  if (power2 <= 0) return false;
  if (lo <= 1 && q >= -4 && q <= 23 && (m & 3) == 1 && (m << shift) == hi) m &= ~uint64_t(1);
  m += m & 1;
  m >>= 1;
  if (m >= (uint64_t(2) << 52)) {
    m = uint64_t(1) << 52;
    ++power2;
  }
  m &= ~(uint64_t(1) << 52);
  if (power2 >= 0x7FF) return false;
  const uint64_t bits = m | (static_cast<uint64_t>(power2) << 52);
  std::memcpy(&out, &bits, sizeof out);
  return true;
}

#if defined(FLT_EVAL_METHOD) && FLT_EVAL_METHOD == 0
#define ACUTEMESH_CLINGER 1
const double kExact10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                           1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
#else
#define ACUTEMESH_CLINGER 0
#endif

#if ((defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__) || \
     defined(_MSC_VER)) &&                                                     \
    !defined(ACUTEMESH_IO_PORTABLE)
#define ACUTEMESH_SWAR 1
// Eight ASCII digits at once (little-endian loads), as fast_float does.
inline bool isEightDigits(uint64_t v) {
  return !(((v + 0x4646464646464646ULL) | (v - 0x3030303030303030ULL)) & 0x8080808080808080ULL);
}
inline uint32_t eightDigits(uint64_t v) {
  const uint64_t mask = 0x000000FF000000FFULL;
  const uint64_t mul1 = 0x000F424000000064ULL;  // 100 + (1000000 << 32)
  const uint64_t mul2 = 0x0000271000000001ULL;  // 1 + (10000 << 32)
  v -= 0x3030303030303030ULL;
  v = (v * 10) + (v >> 8);
  v = (((v & mask) * mul1) + (((v >> 16) & mask) * mul2)) >> 32;
  return static_cast<uint32_t>(v);
}
inline bool isFourDigits(uint32_t v) {
  return !(((v + 0x46464646u) | (v - 0x30303030u)) & 0x80808080u);
}
inline uint32_t fourDigits(uint32_t v) {
  v -= 0x30303030u;
  v = (v * 10) + (v >> 8);  // byte 0: 10*d0 + d1, byte 2: 10*d2 + d3
  return (v & 0xFF) * 100 + ((v >> 16) & 0xFF);
}
#else
#define ACUTEMESH_SWAR 0
#endif

// Digits from p on, appended to w (wrapping past 19 digits: callers count and go slow).
inline const char* readDigits(const char* p, const char* e, uint64_t& w) {
#if ACUTEMESH_SWAR
  while (e - p >= 8) {
    uint64_t chunk;
    std::memcpy(&chunk, p, 8);
    if (!isEightDigits(chunk)) break;
    w = w * 100000000 + eightDigits(chunk);
    p += 8;
  }
  if (e - p >= 4) {
    uint32_t chunk;
    std::memcpy(&chunk, p, 4);
    if (isFourDigits(chunk)) {
      w = w * 10000 + fourDigits(chunk);
      p += 4;
    }
  }
#endif
  while (p < e && isDigit(*p)) {
    w = w * 10 + static_cast<unsigned>(*p - '0');
    ++p;
  }
  return p;
}

// A decimal number as read: sign, the significant digits as an integer (exact while there
// are at most 19 of them), and the power of ten that scales it.
struct Decimal {
  bool neg = false;
  uint64_t w = 0;
  ptrdiff_t sig = 0;  // significant digits
  int64_t exp10 = 0;
};

// Reads the grammar of parseDecimalPrefix from b into d, setting `end` after the number.
NumErr scanDecimal(const char* b, const char* e, Decimal& d, const char*& end) {
  const char* p = b;
  if (p < e && (*p == '+' || *p == '-')) {
    d.neg = *p == '-';
    ++p;
  }
  const char* mantissa = p;
  while (p < e && *p == '0') ++p;  // leading zeros
  const char* sigStart = p;
  p = readDigits(p, e, d.w);
  d.sig = p - sigStart;
  ptrdiff_t digits = p - mantissa;
  if (p < e && *p == '.') {
    ++p;
    const char* frac = p;
    if (d.sig == 0)
      while (p < e && *p == '0') ++p;
    const char* fsig = p;
    p = readDigits(p, e, d.w);
    d.sig += p - fsig;
    digits += p - frac;
    d.exp10 = -(p - frac);
  }
  if (digits == 0) {
    if (startsWithNoCase(mantissa, e, "inf") || startsWithNoCase(mantissa, e, "nan"))
      return NumErr::NonFinite;
    return NumErr::NotNumber;
  }
  if (p < e && (*p == 'e' || *p == 'E')) {
    ++p;
    bool eneg = false;
    if (p < e && (*p == '+' || *p == '-')) {
      eneg = *p == '-';
      ++p;
    }
    if (p == e || !isDigit(*p)) return NumErr::NotNumber;
    int64_t x = 0;
    while (p < e && isDigit(*p)) {
      if (x < 100000000) x = x * 10 + (*p - '0');
      ++p;
    }
    d.exp10 += eneg ? -x : x;
  }
  end = p;
  return NumErr::Ok;
}

}  // namespace

NumErr parseDecimalPrefix(const char* b, const char* e, const char*& stop, double& v) {
  stop = b;
  Decimal d;
  const char* p;
  const NumErr r = scanDecimal(b, e, d, p);
  if (r != NumErr::Ok) return r;
  stop = p;
  if (d.sig == 0) {
    v = d.neg ? -0.0 : 0.0;
    return NumErr::Ok;
  }
  if (d.sig <= 19) {
#if ACUTEMESH_CLINGER
    if (d.w <= (uint64_t(1) << 53) && d.exp10 >= -22 && d.exp10 <= 22) {
      double x = static_cast<double>(d.w);
      x = d.exp10 < 0 ? x / kExact10[-d.exp10] : x * kExact10[d.exp10];
      v = d.neg ? -x : x;
      return NumErr::Ok;
    }
#endif
    double x;
    if (d.exp10 >= kMinPow5 && d.exp10 <= kMaxPow5 &&
        eiselLemire(d.w, static_cast<int>(d.exp10), x)) {
      v = d.neg ? -x : x;
      return NumErr::Ok;
    }
  }
  if (*b == '+') ++b;  // from_chars takes no '+'
  return convertDouble(b, p, v);
}

bool parseIntPrefix(const char* b, const char* e, const char*& stop, int64_t& v) {
  const char* p = b;
  bool neg = false;
  if (p < e && (*p == '+' || *p == '-')) {
    neg = *p == '-';
    ++p;
  }
  const char* digits = p;
  while (p < e && *p == '0') ++p;
  const char* sig = p;
  uint64_t x = 0;
  while (p < e && isDigit(*p)) {
    x = x * 10 + static_cast<unsigned>(*p - '0');
    ++p;
  }
  if (p == digits) return false;
  constexpr uint64_t kLimit = uint64_t(std::numeric_limits<int64_t>::max());
  if (p - sig > 19 || x > kLimit + (neg ? 1 : 0))
    return false;  // int64 has at most 19 digits; 19 digits cannot wrap uint64
  stop = p;
  v = neg ? static_cast<int64_t>(0 - x) : static_cast<int64_t>(x);
  return true;
}

}  // namespace acutemesh::io
