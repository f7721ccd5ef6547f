// Input parsing: Triangle's .node/.poly and JSON (acutemesh PSLG, rings, CG:SHOP 2025).
//
// Everything works on a string_view of the whole text: no iostreams, no exceptions, no
// allocation driven by a count the text cannot back up. Errors read "NAME:LINE: expected X,
// found Y"; things tolerated go to Input::warnings in the same form.
#include "acutemesh/io.h"

#include <cerrno>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <new>
#include <stdexcept>
#include <utility>

// Floating-point std::from_chars where the library has it (libstdc++ >= 11, MSVC); strtod
// otherwise (Emscripten's older libc++). It only serves the rare numbers the fast path below
// leaves (more than 19 digits, subnormals, far exponents). For testing on any platform:
// ACUTEMESH_NO_FLOAT_CHARCONV forces strtod; ACUTEMESH_IO_PORTABLE turns off __int128, the
// clz builtin and the 8-digits-at-once loads.
#if defined(__cpp_lib_to_chars) && !defined(ACUTEMESH_NO_FLOAT_CHARCONV)
#define ACUTEMESH_FLOAT_FROM_CHARS 1
#else
#define ACUTEMESH_FLOAT_FROM_CHARS 0
#endif

namespace acutemesh {
namespace {

constexpr uint64_t kMaxIndexCount = std::numeric_limits<uint32_t>::max();

// ------------------------------------------------------------------------------------------
// Errors and warnings

struct Ctx {
  const std::string& name;
  std::vector<std::string>* warnings;
  std::string message;

  bool fail(size_t line, const std::string& what) {
    message = name + ":" + std::to_string(line) + ": " + what;
    return false;
  }
  void warn(size_t line, const std::string& what) {
    if (warnings) warnings->push_back(name + ":" + std::to_string(line) + ": " + what);
  }
};

ParseResult failure(std::string message) {
  ParseResult r;
  r.ok = false;
  r.message = std::move(message);
  return r;
}

// Input text as it may appear in a one-line message: control characters, DEL and bytes
// above 0x7F (random bytes, or UTF-8 that a terminal may not show) become \xNN, so a message
// never breaks its line or carries a terminal escape; shortened to `max` bytes of input.
std::string printable(std::string_view t, size_t max = 40) {
  std::string s;
  const size_t n = t.size() > max ? max : t.size();
  for (size_t i = 0; i < n; ++i) {
    const unsigned char ch = static_cast<unsigned char>(t[i]);
    if (ch < 0x20 || ch >= 0x7F) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02X", ch);
      s += buf;
    } else {
      s += static_cast<char>(ch);
    }
  }
  if (t.size() > max) s += "...";
  return s;
}

// A token quoted for a message.
std::string quote(std::string_view t) { return "'" + printable(t) + "'"; }

// ------------------------------------------------------------------------------------------
// Numbers

enum class NumErr { Ok, NotNumber, NonFinite, OutOfRange };

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

inline bool isDigit(char c) { return c >= '0' && c <= '9'; }

// Exactly rounded decimal-to-double conversion of the common case, to avoid the library's
// cost per number (from_chars ~40 ns, strtod ~140 ns): Clinger's fast path for mantissas up
// to 2^53 with small exponents, then the Eisel-Lemire algorithm (as in fast_float) for up to
// 19 significant digits and exponents in [-64, 64]. Anything else (more digits, subnormals,
// overflow, far exponents, the rare undecided product) goes to convertDouble.

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
const double kExact10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                           1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                           1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
#else
#define ACUTEMESH_CLINGER 0
#endif

#if ((defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__) || \
     defined(_MSC_VER)) &&                                                      \
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

// The longest prefix of [b, e) in the decimal grammar strtod reads, minus hex and inf/nan:
// [+-] (digits [. digits] | . digits) [(e|E) [+-] digits]. Sets `stop` after it. NotNumber
// when no such prefix exists or an exponent has no digits; NonFinite for "inf"/"nan".
NumErr parseDecimalPrefix(const char* b, const char* e, const char*& stop, double& v) {
  const char* p = b;
  stop = b;
  bool neg = false;
  if (p < e && (*p == '+' || *p == '-')) {
    neg = *p == '-';
    ++p;
  }
  const char* mantissa = p;
  uint64_t w = 0;
  while (p < e && *p == '0') ++p;  // leading zeros
  const char* sigStart = p;
  p = readDigits(p, e, w);
  ptrdiff_t sig = p - sigStart;  // significant digits
  ptrdiff_t digits = p - mantissa;
  int64_t exp10 = 0;
  if (p < e && *p == '.') {
    ++p;
    const char* frac = p;
    if (sig == 0)
      while (p < e && *p == '0') ++p;
    const char* fsig = p;
    p = readDigits(p, e, w);
    sig += p - fsig;
    digits += p - frac;
    exp10 = -(p - frac);
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
    exp10 += eneg ? -x : x;
  }
  stop = p;
  if (sig == 0) {
    v = neg ? -0.0 : 0.0;
    return NumErr::Ok;
  }
  if (sig <= 19) {
#if ACUTEMESH_CLINGER
    if (w <= (uint64_t(1) << 53) && exp10 >= -22 && exp10 <= 22) {
      double x = static_cast<double>(w);
      x = exp10 < 0 ? x / kExact10[-exp10] : x * kExact10[exp10];
      v = neg ? -x : x;
      return NumErr::Ok;
    }
#endif
    double x;
    if (exp10 >= kMinPow5 && exp10 <= kMaxPow5 && eiselLemire(w, static_cast<int>(exp10), x)) {
      v = neg ? -x : x;
      return NumErr::Ok;
    }
  }
  if (*b == '+') ++b;  // from_chars takes no '+'
  return convertDouble(b, p, v);
}

// A whole token (see parseDecimalPrefix).
inline NumErr parseDecimal(const char* b, const char* e, double& v) {
  const char* stop;
  double x;
  NumErr r = parseDecimalPrefix(b, e, stop, x);
  if (r == NumErr::Ok && stop != e) return NumErr::NotNumber;
  if (r == NumErr::Ok) v = x;
  return r;
}

inline NumErr parseFieldDouble(std::string_view t, double& v) {
  return parseDecimal(t.data(), t.data() + t.size(), v);
}

// The longest prefix [+-]digits of [b, e); false if there is none or it overflows int64.
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

// [+-]digits, whole token, in int64 range.
bool parseFieldInt(std::string_view t, int64_t& v) {
  const char* stop;
  return parseIntPrefix(t.data(), t.data() + t.size(), stop, v) && stop == t.data() + t.size();
}

// ------------------------------------------------------------------------------------------
// Triangle's line-oriented files

inline bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// Yields the lines that have content once the '#' comment is cut off.
struct Lines {
  std::string_view text;
  size_t pos = 0;
  size_t lineNo = 0;      // line number of the line last returned
  size_t nextLineNo = 1;  // line number of the line starting at pos

  explicit Lines(std::string_view t) : text(t) {}

  bool next(std::string_view& content) {
    const char* base = text.data();
    const size_t size = text.size();
    while (pos < size) {
      const char* b = base + pos;
      const size_t rem = size - pos;
      const char* nl = static_cast<const char*>(std::memchr(b, '\n', rem));
      size_t len = nl ? static_cast<size_t>(nl - b) : rem;
      pos += nl ? len + 1 : len;
      lineNo = nextLineNo++;
      const char* hash = static_cast<const char*>(std::memchr(b, '#', len));
      if (hash) len = static_cast<size_t>(hash - b);
      size_t i = 0;
      while (i < len && isBlank(b[i])) ++i;
      if (i < len) {
        content = std::string_view(b + i, len - i);
        return true;
      }
    }
    return false;
  }

  size_t remaining() const { return text.size() - pos; }

  // The common vertex line "<id> <x> <y> [marker]" (no attributes, no comment; the marker
  // only when `marker`) parsed in one pass. Returns false, consuming nothing, for anything
  // else: the caller then reads the line with next() and the general, checking code.
  bool fastVertexLine(bool marker, int64_t& id, double& x, double& y) {
    const char* const base = text.data();
    const char* const e = base + text.size();
    const char* p = base + pos;
    while (p < e && (*p == ' ' || *p == '\t')) ++p;
    const char* d = p;
    uint64_t v = 0;
    while (p < e && isDigit(*p) && p - d < 18) {
      v = v * 10 + static_cast<unsigned>(*p - '0');
      ++p;
    }
    if (p == d || p == e || (*p != ' ' && *p != '\t')) return false;
    while (p < e && (*p == ' ' || *p == '\t')) ++p;
    const char* stop;
    if (parseDecimalPrefix(p, e, stop, x) != NumErr::Ok || stop == e ||
        (*stop != ' ' && *stop != '\t'))
      return false;
    p = stop;
    while (p < e && (*p == ' ' || *p == '\t')) ++p;
    if (parseDecimalPrefix(p, e, stop, y) != NumErr::Ok) return false;
    p = stop;
    while (p < e && (*p == ' ' || *p == '\t')) ++p;
    if (marker && p < e && (isDigit(*p) || *p == '-')) {
      const char* m = p;
      if (*p == '-') ++p;
      while (p < e && isDigit(*p) && p - m < 18) ++p;
      if (p == m + (*m == '-') || (p < e && *p != ' ' && *p != '\t' && *p != '\r' && *p != '\n'))
        return false;
      while (p < e && (*p == ' ' || *p == '\t')) ++p;
    }
    if (p < e && *p == '\r') ++p;
    if (p < e) {
      if (*p != '\n') return false;
      ++p;
    }
    id = static_cast<int64_t>(v);
    pos = static_cast<size_t>(p - base);
    lineNo = nextLineNo++;
    return true;
  }

  // The line number at the end of the text (where a missing item was expected).
  size_t eofLine() const {
    if (text.empty()) return 1;
    return text.back() == '\n' ? nextLineNo : nextLineNo - 1;
  }
};

// Whitespace-separated fields of one line's content.
struct Fields {
  const char* p;
  const char* e;
  explicit Fields(std::string_view line) : p(line.data()), e(line.data() + line.size()) {}

  // Skips blanks; true if a field follows.
  bool more() {
    const char* q = p;  // locals in loops: a char read may alias the members
    const char* end = e;
    while (q < end && isBlank(*q)) ++q;
    p = q;
    return q != end;
  }
  // The field at p, not consumed (for messages).
  std::string_view peek() const {
    const char* q = p;
    const char* end = e;
    while (q < end && !isBlank(*q)) ++q;
    return std::string_view(p, static_cast<size_t>(q - p));
  }
  bool next(std::string_view& tok) {
    if (!more()) return false;
    tok = peek();
    p += tok.size();
    return true;
  }
  // An integer field at p (after more()), consumed when it is one.
  bool integer(int64_t& v) {
    const char* stop;
    int64_t x;
    if (!parseIntPrefix(p, e, stop, x) || (stop != e && !isBlank(*stop))) return false;
    p = stop;
    v = x;
    return true;
  }
  // A number field at p (after more()), consumed when it is one.
  NumErr number(double& v) {
    const char* stop;
    double x;
    const NumErr r = parseDecimalPrefix(p, e, stop, x);
    if (r != NumErr::Ok) return r;
    if (stop != e && !isBlank(*stop)) return NumErr::NotNumber;
    p = stop;
    v = x;
    return NumErr::Ok;
  }
};

// A line with at least `minBytes` characters plus a line break per item: how many items
// `remaining` bytes can hold at most.
uint64_t maxItems(size_t remaining, size_t minBytes) {
  return (static_cast<uint64_t>(remaining) + 1) / (minBytes + 1);
}

// Reads a count field (non-negative integer). Absent fields take `def` when `optional`.
bool readCount(Fields& f, Ctx& c, size_t line, const std::string& what, bool optional,
               uint64_t def, uint64_t& v) {
  std::string_view tok;
  if (!f.next(tok)) {
    if (optional) {
      v = def;
      return true;
    }
    return c.fail(line, "expected " + what + ", found end of line");
  }
  int64_t x;
  if (!parseFieldInt(tok, x) || x < 0)
    return c.fail(line, "expected " + what + " (a non-negative integer), found " + quote(tok));
  v = static_cast<uint64_t>(x);
  return true;
}

bool noMoreFields(Fields& f, Ctx& c, size_t line, const std::string& expected) {
  std::string_view tok;
  if (f.next(tok))
    return c.fail(line, "expected " + expected + ", found an extra field " + quote(tok));
  return true;
}

bool readMarkerCount(Fields& f, Ctx& c, size_t line, uint64_t& v) {
  if (!readCount(f, c, line, "the number of boundary markers", true, 0, v)) return false;
  if (v > 1) return c.fail(line, "expected 0 or 1 boundary markers, found " + std::to_string(v));
  return true;
}

bool coordError(Fields& f, Ctx& c, size_t line, const char* what, NumErr e) {
  if (f.p == f.e) return c.fail(line, std::string("expected ") + what + ", found end of line");
  const std::string tok = quote(f.peek());
  switch (e) {
    case NumErr::NonFinite:
      return c.fail(line, std::string("expected a finite ") + what + ", found " + tok);
    case NumErr::OutOfRange:
      return c.fail(line, std::string("expected ") + what + " within double range, found " + tok);
    default:
      break;
  }
  return c.fail(line, std::string("expected ") + what + " (a number), found " + tok);
}

// A coordinate field: finite double.
inline bool readCoord(Fields& f, Ctx& c, size_t line, const char* what, double& v) {
  if (!f.more()) return coordError(f, c, line, what, NumErr::NotNumber);
  const NumErr e = f.number(v);
  return e == NumErr::Ok || coordError(f, c, line, what, e);
}

// A leading item id: an integer (ignored except for a vertex list's first id).
inline bool readId(Fields& f, Ctx& c, size_t line, const char* what, int64_t& id) {
  // The line has content, so there is a first field.
  if (f.more() && f.integer(id)) return true;
  return c.fail(line, std::string("expected ") + what + " number (an integer), found " +
                          quote(f.peek()));
}

// Optional trailing fields: up to `attrs` numbers then up to `markers` integers.
bool readExtras(Fields& f, Ctx& c, size_t line, uint64_t attrs, uint64_t markers,
                const std::string& layout) {
  std::string_view tok;
  for (uint64_t i = 0; i < attrs + markers; ++i) {
    if (!f.next(tok)) return true;  // Triangle lets attributes and markers default to 0
    if (i < attrs) {
      double d;
      NumErr e = parseFieldDouble(tok, d);
      if (e == NumErr::NotNumber)
        return c.fail(line, "expected attribute " + std::to_string(i + 1) +
                                " (a number), found " + quote(tok));
    } else {
      int64_t m;
      if (!parseFieldInt(tok, m))
        return c.fail(line, "expected a boundary marker (an integer), found " + quote(tok));
    }
  }
  return noMoreFields(f, c, line, layout);
}

std::string vertexLayout(uint64_t attrs, uint64_t markers) {
  std::string s = "'<id> <x> <y>";
  if (attrs) s += " [" + std::to_string(attrs) + (attrs == 1 ? " attribute]" : " attributes]");
  if (markers) s += " [marker]";
  return s + "'";
}

struct VertexList {
  uint32_t first = 0;  // number of the first vertex: 0 or 1
  size_t count = 0;
};

// The "<#vertices> <dim> <#attributes> <#markers>" line.
struct NodeHeader {
  uint64_t count = 0, attrs = 0, markers = 0;
  size_t line = 0;
};

bool readNodeHeader(Lines& L, Ctx& c, NodeHeader& h) {
  std::string_view line;
  const char* expected =
      "the header '<#vertices> <dimension> <#attributes> <#boundary markers>'";
  if (!L.next(line)) return c.fail(L.eofLine(), std::string("expected ") + expected +
                                                     ", found end of file");
  h.line = L.lineNo;
  Fields f(line);
  uint64_t dim;
  if (!readCount(f, c, h.line, "the number of vertices", false, 0, h.count) ||
      !readCount(f, c, h.line, "the dimension", true, 2, dim))
    return false;
  if (dim != 2) return c.fail(h.line, "expected dimension 2, found " + std::to_string(dim));
  if (!readCount(f, c, h.line, "the number of attributes", true, 0, h.attrs) ||
      !readMarkerCount(f, c, h.line, h.markers) || !noMoreFields(f, c, h.line, expected))
    return false;
  if (h.count > kMaxIndexCount)
    return c.fail(h.line, "expected at most " + std::to_string(kMaxIndexCount) +
                              " vertices, found " + std::to_string(h.count));
  return true;
}

// The vertex lines after a header, appended to `pts` (the caller's vector is empty).
bool readVertexLines(Lines& L, Ctx& c, const NodeHeader& h, std::vector<double>& pts,
                     VertexList& vl) {
  const uint64_t room = maxItems(L.remaining(), 5);  // "0 0 0"
  if (h.count > room)
    return c.fail(h.line, "expected a vertex count the rest of the text can hold (at most " +
                              std::to_string(room) + "), found " + std::to_string(h.count));
  pts.reserve(static_cast<size_t>(h.count) * 2);
  const std::string layout = vertexLayout(h.attrs, h.markers);
  bool warnedIds = false;
  std::string_view line;
  for (uint64_t i = 0; i < h.count; ++i) {
    int64_t id;
    double x, y;
    const bool fast = L.fastVertexLine(h.attrs == 0 && h.markers == 1, id, x, y);
    if (!fast && !L.next(line))
      return c.fail(L.eofLine(), "expected vertex line " + std::to_string(i + 1) + " of " +
                                     std::to_string(h.count) + " " + layout +
                                     ", found end of file");
    const size_t ln = L.lineNo;
    Fields f(line);
    if (!fast && !readId(f, c, ln, "a vertex", id)) return false;
    if (i == 0) {
      if (id == 0 || id == 1) {
        vl.first = static_cast<uint32_t>(id);
      } else {
        vl.first = 1;
        c.warn(ln, "expected the first vertex numbered 0 or 1, found " + std::to_string(id) +
                       "; indices taken as 1-based, as Triangle does");
      }
    } else if (!warnedIds && id != static_cast<int64_t>(vl.first + i)) {
      warnedIds = true;
      c.warn(ln, "expected vertex number " + std::to_string(vl.first + i) + ", found " +
                     std::to_string(id) + "; vertices are numbered by their position");
    }
    if (!fast && (!readCoord(f, c, ln, "x coordinate", x) ||
                  !readCoord(f, c, ln, "y coordinate", y) ||
                  !readExtras(f, c, ln, h.attrs, h.markers, layout)))
      return false;
    pts.push_back(x);
    pts.push_back(y);
  }
  vl.count = static_cast<size_t>(h.count);
  return true;
}

void warnTrailing(Lines& L, Ctx& c, const char* after) {
  std::string_view line;
  if (L.next(line)) c.warn(L.lineNo, std::string("ignored the text after ") + after);
}

bool parseNodeInto(std::string_view text, Ctx& c, std::vector<double>& pts, VertexList& vl,
                   bool warnTrail) {
  Lines L(text);
  NodeHeader h;
  if (!readNodeHeader(L, c, h) || !readVertexLines(L, c, h, pts, vl)) return false;
  if (warnTrail) warnTrailing(L, c, "the vertices");
  return true;
}

std::string indexRange(const VertexList& vl) {
  if (vl.count == 0) return "a vertex number (there are no vertices)";
  return "a vertex number in [" + std::to_string(vl.first) + ", " +
         std::to_string(vl.first + vl.count - 1) + "]";
}

bool readEndpoint(Fields& f, Ctx& c, size_t line, const VertexList& vl, uint32_t& out) {
  if (!f.more()) return c.fail(line, "expected " + indexRange(vl) + ", found end of line");
  const std::string_view tok = f.peek();
  int64_t v;
  if (!f.integer(v) || v < static_cast<int64_t>(vl.first) ||
      v >= static_cast<int64_t>(vl.first + vl.count))
    return c.fail(line, "expected " + indexRange(vl) + ", found " + quote(tok));
  out = static_cast<uint32_t>(v - vl.first);
  return true;
}

// Reads a "<#items> ..." line: returns false with an error, sets `present` false at EOF when
// the section may be absent.
bool readSectionHeader(Lines& L, Ctx& c, const char* expected, bool mayBeAbsent,
                       bool& present, size_t& line, Fields& f) {
  std::string_view content;
  if (!L.next(content)) {
    present = false;
    if (mayBeAbsent) return true;
    return c.fail(L.eofLine(), std::string("expected ") + expected + ", found end of file");
  }
  present = true;
  line = L.lineNo;
  f = Fields(content);
  return true;
}

bool checkRoom(Lines& L, Ctx& c, size_t line, uint64_t count, size_t minBytes,
               const char* items) {
  const uint64_t room = maxItems(L.remaining(), minBytes);
  if (count > room)
    return c.fail(line, std::string("expected a ") + items +
                            " count the rest of the text can hold (at most " +
                            std::to_string(room) + "), found " + std::to_string(count));
  return true;
}

bool parsePolyImpl(std::string_view text, Ctx& c, Input& in, std::string_view nodeText,
                   const std::string& nodeName) {
  Lines L(text);
  NodeHeader h;
  VertexList vl;
  if (!readNodeHeader(L, c, h)) return false;
  if (h.count == 0) {
    if (nodeText.empty() && nodeName.empty())
      return c.fail(h.line,
                    "expected vertices (a count of 0 says they are in a .node file), found "
                    "no .node text");
    Ctx nc{nodeName, c.warnings, {}};
    if (!parseNodeInto(nodeText, nc, in.pslg.points, vl, true)) {
      c.message = nc.message;
      return false;
    }
  } else if (!readVertexLines(L, c, h, in.pslg.points, vl)) {
    return false;
  }

  // Segments.
  bool present;
  size_t line = 0;
  Fields f{std::string_view()};
  uint64_t count, markers;
  const char* segHeader = "the segment header '<#segments> <#boundary markers>'";
  if (!readSectionHeader(L, c, segHeader, false, present, line, f) ||
      !readCount(f, c, line, "the number of segments", false, 0, count) ||
      !readMarkerCount(f, c, line, markers) || !noMoreFields(f, c, line, segHeader) ||
      !checkRoom(L, c, line, count, 5, "segment"))
    return false;
  const std::string segLayout =
      markers ? "'<id> <endpoint> <endpoint> [marker]'" : "'<id> <endpoint> <endpoint>'";
  in.pslg.segments.reserve(static_cast<size_t>(count) * 2);
  std::string_view content;
  for (uint64_t i = 0; i < count; ++i) {
    if (!L.next(content))
      return c.fail(L.eofLine(), "expected segment line " + std::to_string(i + 1) + " of " +
                                     std::to_string(count) + " " + segLayout +
                                     ", found end of file");
    const size_t ln = L.lineNo;
    Fields g(content);
    int64_t id;
    uint32_t a, b;
    if (!readId(g, c, ln, "a segment", id) || !readEndpoint(g, c, ln, vl, a) ||
        !readEndpoint(g, c, ln, vl, b) || !readExtras(g, c, ln, 0, markers, segLayout))
      return false;
    in.pslg.segments.push_back(a);
    in.pslg.segments.push_back(b);
  }

  // Holes: the section may be missing at the end of the file.
  const char* holeHeader = "the hole count '<#holes>'";
  if (!readSectionHeader(L, c, holeHeader, true, present, line, f)) return false;
  if (!present) return true;
  if (!readCount(f, c, line, "the number of holes", false, 0, count) ||
      !noMoreFields(f, c, line, holeHeader) || !checkRoom(L, c, line, count, 5, "hole"))
    return false;
  in.pslg.holes.reserve(static_cast<size_t>(count) * 2);
  for (uint64_t i = 0; i < count; ++i) {
    if (!L.next(content))
      return c.fail(L.eofLine(), "expected hole line " + std::to_string(i + 1) + " of " +
                                     std::to_string(count) + " '<id> <x> <y>', found end of file");
    const size_t ln = L.lineNo;
    Fields g(content);
    int64_t id;
    double x, y;
    if (!readId(g, c, ln, "a hole", id) || !readCoord(g, c, ln, "hole x coordinate", x) ||
        !readCoord(g, c, ln, "hole y coordinate", y) ||
        !noMoreFields(g, c, ln, "'<id> <x> <y>'"))
      return false;
    in.pslg.holes.push_back(x);
    in.pslg.holes.push_back(y);
  }

  // Optional regional attributes and area constraints: checked for form, then ignored.
  const char* regionHeader = "the regional attribute count '<#regions>'";
  if (!readSectionHeader(L, c, regionHeader, true, present, line, f)) return false;
  if (!present) return true;
  if (!readCount(f, c, line, "the number of regional attributes", false, 0, count) ||
      !noMoreFields(f, c, line, regionHeader) || !checkRoom(L, c, line, count, 7, "region"))
    return false;
  const char* regionLayout = "'<id> <x> <y> <attribute> [maximum area]'";
  for (uint64_t i = 0; i < count; ++i) {
    if (!L.next(content))
      return c.fail(L.eofLine(), "expected region line " + std::to_string(i + 1) + " of " +
                                     std::to_string(count) + " " + regionLayout +
                                     ", found end of file");
    const size_t ln = L.lineNo;
    Fields g(content);
    int64_t id;
    double x, y, attr;
    if (!readId(g, c, ln, "a region", id) || !readCoord(g, c, ln, "region x coordinate", x) ||
        !readCoord(g, c, ln, "region y coordinate", y) ||
        !readCoord(g, c, ln, "regional attribute", attr) ||
        !readExtras(g, c, ln, 1, 0, regionLayout))
      return false;
  }
  warnTrailing(L, c, "the regional attributes");
  return true;
}

// ------------------------------------------------------------------------------------------
// JSON

constexpr int kMaxJsonDepth = 200;

class JsonReader {
 public:
  JsonReader(std::string_view s, Ctx& c) : s_(s), c_(c) {
    if (s_.size() >= 3 && static_cast<unsigned char>(s_[0]) == 0xEF &&
        static_cast<unsigned char>(s_[1]) == 0xBB && static_cast<unsigned char>(s_[2]) == 0xBF)
      p_ = 3;  // UTF-8 byte order mark
  }

  size_t line() const { return line_; }
  Ctx& ctx() { return c_; }

  void ws() {
    const size_t n = s_.size();
    while (p_ < n) {
      const char ch = s_[p_];
      if (ch == '\n') {
        ++line_;
        ++p_;
      } else if (ch == ' ' || ch == '\t' || ch == '\r') {
        ++p_;
      } else {
        break;
      }
    }
  }

  // After ws(): the next character, or 0 at the end.
  char peek() const { return p_ < s_.size() ? s_[p_] : '\0'; }
  bool atEnd() const { return p_ >= s_.size(); }
  void advance() { ++p_; }

  // Describes the token at position `pos` for "found ...".
  std::string found(size_t pos) const {
    if (pos >= s_.size()) return "end of text";
    const char ch = s_[pos];
    if (ch == '"') {
      size_t e = pos + 1;
      while (e < s_.size() && s_[e] != '"' && s_[e] != '\n' && e - pos < 40) {
        if (s_[e] == '\\' && e + 1 < s_.size()) ++e;
        ++e;
      }
      std::string_view t = s_.substr(pos, e - pos + (e < s_.size() && s_[e] == '"' ? 1 : 0));
      return "the string " + printable(t, 42);
    }
    if (ch == '{' || ch == '}' || ch == '[' || ch == ']' || ch == ',' || ch == ':')
      return std::string("'") + ch + "'";
    size_t e = pos;
    while (e < s_.size() && e - pos < 40) {
      const char d = s_[e];
      if (!((d >= '0' && d <= '9') || (d >= 'a' && d <= 'z') || (d >= 'A' && d <= 'Z') ||
            d == '-' || d == '+' || d == '.' || d == '_'))
        break;
      ++e;
    }
    if (e > pos) return quote(s_.substr(pos, e - pos));
    char buf[32];
    std::snprintf(buf, sizeof buf, "the byte 0x%02X", static_cast<unsigned char>(ch));
    return buf;
  }

  bool fail(const std::string& expected) { return failAt(p_, expected); }
  bool failAt(size_t pos, const std::string& expected) {
    return c_.fail(line_, "expected " + expected + ", found " + found(pos));
  }

  bool expect(char ch, const char* expected) {
    ws();
    if (peek() == ch) {
      ++p_;
      return true;
    }
    return fail(expected);
  }
  // The same, with the expectation in pieces put together only on failure.
  bool expect(char ch, const char* a, const char* b, const char* c) {
    ws();
    if (peek() == ch) {
      ++p_;
      return true;
    }
    return fail(std::string(a) + b + c);
  }

  bool string(std::string& out, const char* expected) {
    ws();
    if (peek() != '"') return fail(expected);
    out.clear();
    const size_t start = p_;
    ++p_;
    const size_t n = s_.size();
    while (true) {
      if (p_ >= n) return failAt(start, "a closing '\"' of the string");
      const unsigned char ch = static_cast<unsigned char>(s_[p_]);
      if (ch == '"') {
        ++p_;
        return true;
      }
      if (ch < 0x20) {
        if (ch == '\n') return c_.fail(line_, "expected '\"' closing the string, found end of line");
        return c_.fail(line_, "expected a string character, found a control character");
      }
      if (ch != '\\') {
        out += static_cast<char>(ch);
        ++p_;
        continue;
      }
      if (p_ + 1 >= n) return failAt(start, "a closing '\"' of the string");
      const char esc = s_[p_ + 1];
      p_ += 2;
      switch (esc) {
        case '"': out += '"'; break;
        case '\\': out += '\\'; break;
        case '/': out += '/'; break;
        case 'b': out += '\b'; break;
        case 'f': out += '\f'; break;
        case 'n': out += '\n'; break;
        case 'r': out += '\r'; break;
        case 't': out += '\t'; break;
        case 'u': {
          uint32_t cp;
          if (!hex4(cp)) return false;
          if (cp >= 0xD800 && cp <= 0xDBFF) {
            uint32_t lo;
            if (p_ + 1 >= n || s_[p_] != '\\' || s_[p_ + 1] != 'u')
              return c_.fail(line_, "expected a low surrogate '\\uDC00'-'\\uDFFF' after a high "
                                    "surrogate, found none");
            p_ += 2;
            if (!hex4(lo)) return false;
            if (lo < 0xDC00 || lo > 0xDFFF)
              return c_.fail(line_, "expected a low surrogate '\\uDC00'-'\\uDFFF', found a "
                                    "different escape");
            cp = 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00);
          } else if (cp >= 0xDC00 && cp <= 0xDFFF) {
            return c_.fail(line_, "expected a high surrogate before a low one, found a lone "
                                  "low surrogate");
          }
          appendUtf8(out, cp);
          break;
        }
        default:
          return c_.fail(line_, std::string("expected an escape (\\\" \\\\ \\/ \\b \\f \\n \\r "
                                            "\\t \\uXXXX), found '\\") +
                                printable(std::string_view(&esc, 1)) + "'");
      }
    }
  }

  // Scans a JSON number at the current position without consuming it.
  bool scanNumber(size_t& end, bool& integral) {
    const size_t n = s_.size();
    size_t q = p_;
    integral = true;
    if (q < n && s_[q] == '-') ++q;
    if (q >= n || !isDigit(s_[q])) return false;
    if (s_[q] == '0') {
      ++q;
    } else {
      while (q < n && isDigit(s_[q])) ++q;
    }
    if (q < n && s_[q] == '.') {
      integral = false;
      ++q;
      if (q >= n || !isDigit(s_[q])) return false;
      while (q < n && isDigit(s_[q])) ++q;
    }
    if (q < n && (s_[q] == 'e' || s_[q] == 'E')) {
      integral = false;
      ++q;
      if (q < n && (s_[q] == '+' || s_[q] == '-')) ++q;
      if (q >= n || !isDigit(s_[q])) return false;
      while (q < n && isDigit(s_[q])) ++q;
    }
    // A number runs into nothing but a delimiter: "1x" or "01" is not a number.
    if (q < n) {
      const char d = s_[q];
      if (!(d == ',' || d == ']' || d == '}' || d == ' ' || d == '\t' || d == '\n' ||
            d == '\r'))
        return false;
    }
    end = q;
    return true;
  }

  bool number(double& v, const char* expected) {
    ws();
    size_t end;
    bool integral;
    if (!scanNumber(end, integral)) return fail(std::string(expected) + " (a number)");
    NumErr e = parseDecimal(s_.data() + p_, s_.data() + end, v);
    if (e == NumErr::OutOfRange) return fail(std::string(expected) + " within double range");
    if (e != NumErr::Ok) return fail(std::string(expected) + " (a number)");
    p_ = end;
    return true;
  }

  // A non-negative integer below 2^32 (vertex index or count).
  bool index(uint64_t& v, const char* expected) {
    ws();
    size_t end;
    bool integral;
    if (!scanNumber(end, integral) || !integral || s_[p_] == '-') return fail(expected);
    std::from_chars_result r = std::from_chars(s_.data() + p_, s_.data() + end, v);
    if (r.ec != std::errc() || v > kMaxIndexCount) return fail(expected);
    p_ = end;
    return true;
  }

  // Parses and discards any value (validating it).
  bool skipValue(int depth) {
    ws();
    if (depth > kMaxJsonDepth)
      return fail("nesting at most " + std::to_string(kMaxJsonDepth) + " deep");
    const char ch = peek();
    if (ch == '{') {
      ++p_;
      ws();
      if (peek() == '}') {
        ++p_;
        return true;
      }
      while (true) {
        if (!string(scratch_, "a key string") || !expect(':', "':' after the key") ||
            !skipValue(depth + 1))
          return false;
        ws();
        if (peek() == ',') {
          ++p_;
          continue;
        }
        if (peek() == '}') {
          ++p_;
          return true;
        }
        return fail("',' or '}'");
      }
    }
    if (ch == '[') {
      ++p_;
      ws();
      if (peek() == ']') {
        ++p_;
        return true;
      }
      while (true) {
        if (!skipValue(depth + 1)) return false;
        ws();
        if (peek() == ',') {
          ++p_;
          continue;
        }
        if (peek() == ']') {
          ++p_;
          return true;
        }
        return fail("',' or ']'");
      }
    }
    if (ch == '"') {
      return string(scratch_, "a value");
    }
    for (const char* word : {"true", "false", "null"}) {
      const size_t len = std::strlen(word);
      if (s_.substr(p_, len) == word) {
        size_t q = p_ + len;
        if (q < s_.size() && ((s_[q] >= 'a' && s_[q] <= 'z') || isDigit(s_[q])))
          return fail("a value");
        p_ = q;
        return true;
      }
    }
    size_t end;
    bool integral;
    if (scanNumber(end, integral)) {
      p_ = end;
      return true;
    }
    return fail("a value");
  }

  // Calls elem() per element of an array; `what` names the array for messages.
  template <class F>
  bool array(const char* what, F&& elem) {
    ws();
    if (peek() != '[') return fail(std::string("'[' starting ") + what);
    ++p_;
    ws();
    if (peek() == ']') {
      ++p_;
      return true;
    }
    while (true) {
      if (!elem()) return false;
      ws();
      const char ch = peek();
      if (ch == ',') {
        ++p_;
        continue;
      }
      if (ch == ']') {
        ++p_;
        return true;
      }
      return fail(std::string("',' or ']' in ") + what);
    }
  }

 private:
  bool hex4(uint32_t& v) {
    v = 0;
    for (int i = 0; i < 4; ++i) {
      if (p_ >= s_.size()) return c_.fail(line_, "expected 4 hex digits after '\\u', found end of text");
      const char h = s_[p_];
      uint32_t d;
      if (h >= '0' && h <= '9') d = static_cast<uint32_t>(h - '0');
      else if (h >= 'a' && h <= 'f') d = static_cast<uint32_t>(h - 'a' + 10);
      else if (h >= 'A' && h <= 'F') d = static_cast<uint32_t>(h - 'A' + 10);
      else return c_.fail(line_, "expected 4 hex digits after '\\u', found '" +
                               printable(std::string_view(&h, 1)) + "'");
      v = v * 16 + d;
      ++p_;
    }
    return true;
  }

  static void appendUtf8(std::string& out, uint32_t cp) {
    if (cp < 0x80) {
      out += static_cast<char>(cp);
    } else if (cp < 0x800) {
      out += static_cast<char>(0xC0 | (cp >> 6));
      out += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
      out += static_cast<char>(0xE0 | (cp >> 12));
      out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
      out += static_cast<char>(0xF0 | (cp >> 18));
      out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
      out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (cp & 0x3F));
    }
  }

  std::string_view s_;
  Ctx& c_;
  size_t p_ = 0;
  size_t line_ = 1;
  std::string scratch_;  // strings skipped, kept out of skipValue's recursive frames
};

// Indices as read, with the line of each, range-checked once the vertex count is known.
struct IndexList {
  std::vector<uint64_t> values;
  std::vector<uint32_t> lines;
  void push(uint64_t v, size_t line) {
    values.push_back(v);
    lines.push_back(static_cast<uint32_t>(line));
  }
  size_t size() const { return values.size(); }
};

bool checkIndices(const IndexList& l, size_t n, const char* key, Ctx& c) {
  for (size_t i = 0; i < l.size(); ++i)
    if (l.values[i] >= n)
      return c.fail(l.lines[i], std::string("expected a vertex index in ") + key +
                                    (n ? " below " + std::to_string(n) : " (there are no vertices)") +
                                    ", found " + std::to_string(l.values[i]));
  return true;
}

enum class JsonKind { None, Pslg, Rings, Cgshop };

const char* kindName(JsonKind k) {
  switch (k) {
    case JsonKind::Pslg: return "an acutemesh PSLG (\"vertices\")";
    case JsonKind::Rings: return "rings (\"rings\")";
    case JsonKind::Cgshop: return "a CG:SHOP instance (\"points_x\")";
    case JsonKind::None: break;
  }
  return "nothing";
}

struct JsonDoc {
  JsonKind kind = JsonKind::None;
  std::string kindKey;  // the key that decided the kind
  size_t objectLine = 1;

  bool hasVertices = false, hasRings = false, hasPx = false, hasPy = false,
       hasBoundary = false, hasNumPoints = false, hasNumConstraints = false;
  size_t pyLine = 0, numPointsLine = 0, boundaryLine = 0, numConstraintsLine = 0;
  std::vector<double> points, holes, px, py;
  IndexList segments, boundary, constraints;
  std::vector<uint32_t> ringSegments;
  uint64_t numPoints = 0, numConstraints = 0;
  std::string uid;
};

bool readPoint(JsonReader& r, std::vector<double>& dst, const char* what) {
  double x, y;
  if (!r.expect('[', "'[' starting ", what, " [x, y]") || !r.number(x, "an x coordinate") ||
      !r.expect(',', "',' between x and y") || !r.number(y, "a y coordinate") ||
      !r.expect(']', "']' ending ", what, " [x, y] (exactly 2 numbers)"))
    return false;
  dst.push_back(x);
  dst.push_back(y);
  return true;
}

bool readPair(JsonReader& r, IndexList& dst, const char* what) {
  uint64_t a, b;
  r.ws();
  const size_t line = r.line();
  if (!r.expect('[', "'[' starting ", what, " [i, j]") ||
      !r.index(a, "a vertex index (a non-negative integer)") ||
      !r.expect(',', "',' between the two indices")) return false;
  r.ws();
  const size_t line2 = r.line();
  if (!r.index(b, "a vertex index (a non-negative integer)") ||
      !r.expect(']', "']' ending ", what, " [i, j] (exactly 2 indices)"))
    return false;
  dst.push(a, line);
  dst.push(b, line2);
  return true;
}

bool readRing(JsonReader& r, JsonDoc& d) {
  r.ws();
  const size_t ringLine = r.line();
  std::vector<double> ring;
  if (!r.array("a ring [[x, y], ...]", [&] { return readPoint(r, ring, "a ring point"); }))
    return false;
  size_t n = ring.size() / 2;
  if (n >= 2 && ring[0] == ring[2 * n - 2] && ring[1] == ring[2 * n - 1]) {
    --n;
    ring.resize(2 * n);
    r.ctx().warn(ringLine, "dropped the ring's last point, a repeat of its first (rings close "
                           "implicitly)");
  }
  if (n < 3)
    return r.ctx().fail(ringLine, "expected a ring of at least 3 distinct points, found " +
                                      std::to_string(n));
  const size_t base = d.points.size() / 2;
  if (base + n > kMaxIndexCount)
    return r.ctx().fail(ringLine, "expected at most " + std::to_string(kMaxIndexCount) +
                                      " vertices in all, found more");
  d.points.insert(d.points.end(), ring.begin(), ring.end());
  for (size_t i = 0; i < n; ++i) {
    d.ringSegments.push_back(static_cast<uint32_t>(base + i));
    d.ringSegments.push_back(static_cast<uint32_t>(base + (i + 1) % n));
  }
  return true;
}

JsonKind keyKind(const std::string& key) {
  if (key == "vertices" || key == "segments" || key == "holes" || key == "triangles" ||
      key == "exactPoints")
    return JsonKind::Pslg;
  if (key == "rings") return JsonKind::Rings;
  if (key == "instance_uid" || key == "num_points" || key == "points_x" || key == "points_y" ||
      key == "region_boundary" || key == "num_constraints" || key == "additional_constraints")
    return JsonKind::Cgshop;
  return JsonKind::None;
}

bool readMember(JsonReader& r, JsonDoc& d, const std::string& key, size_t keyLine) {
  Ctx& c = r.ctx();
  const JsonKind k = keyKind(key);
  if (k == JsonKind::None) {
    c.warn(keyLine, "ignored the unknown key \"" + printable(key) + "\"");
    return r.skipValue(1);
  }
  if (d.kind == JsonKind::None) {
    d.kind = k;
    d.kindKey = key;
  } else if (d.kind != k) {
    return c.fail(keyLine, std::string("expected the keys of ") + kindName(d.kind) +
                               " as \"" + d.kindKey + "\" says, found \"" + key + "\"");
  }
  // A mesh written by formatJson: its triangles and exact points are ignored.
  if (key == "triangles" || key == "exactPoints") return r.skipValue(1);
  if (key == "vertices") {
    d.hasVertices = true;
    return r.array("the \"vertices\" array", [&] { return readPoint(r, d.points, "a vertex"); });
  }
  if (key == "segments")
    return r.array("the \"segments\" array", [&] { return readPair(r, d.segments, "a segment"); });
  if (key == "holes")
    return r.array("the \"holes\" array", [&] { return readPoint(r, d.holes, "a hole"); });
  if (key == "rings") {
    d.hasRings = true;
    return r.array("the \"rings\" array", [&] { return readRing(r, d); });
  }
  if (key == "points_x" || key == "points_y") {
    std::vector<double>& dst = key == "points_x" ? d.px : d.py;
    (key == "points_x" ? d.hasPx : d.hasPy) = true;
    if (key == "points_y") d.pyLine = keyLine;
    const std::string what = "the \"" + key + "\" array";
    return r.array(what.c_str(), [&] {
      double v;
      if (!r.number(v, "a coordinate")) return false;
      dst.push_back(v);
      return true;
    });
  }
  if (key == "region_boundary") {
    d.hasBoundary = true;
    d.boundaryLine = keyLine;
    return r.array("the \"region_boundary\" array", [&] {
      uint64_t v;
      r.ws();
      const size_t ln = r.line();
      if (!r.index(v, "a vertex index (a non-negative integer)")) return false;
      d.boundary.push(v, ln);
      return true;
    });
  }
  if (key == "additional_constraints")
    return r.array("the \"additional_constraints\" array",
                   [&] { return readPair(r, d.constraints, "a constraint"); });
  if (key == "num_points" || key == "num_constraints") {
    const bool pts = key == "num_points";
    (pts ? d.hasNumPoints : d.hasNumConstraints) = true;
    (pts ? d.numPointsLine : d.numConstraintsLine) = keyLine;
    return r.index(pts ? d.numPoints : d.numConstraints, "a count (a non-negative integer)");
  }
  // instance_uid
  return r.string(d.uid, "the instance uid (a string)");
}

bool buildInput(JsonDoc& d, Ctx& c, Input& in) {
  switch (d.kind) {
    case JsonKind::None:
      return c.fail(d.objectLine, "expected the key \"vertices\", \"rings\" or \"points_x\", "
                                  "found none of them");
    case JsonKind::Pslg: {
      if (!d.hasVertices)
        return c.fail(d.objectLine, "expected the key \"vertices\" with \"" + d.kindKey +
                                        "\", found none");
      const size_t n = d.points.size() / 2;
      if (n > kMaxIndexCount)
        return c.fail(d.objectLine, "expected at most " + std::to_string(kMaxIndexCount) +
                                        " vertices, found " + std::to_string(n));
      if (!checkIndices(d.segments, n, "\"segments\"", c)) return false;
      in.format = InputFormat::JsonPslg;
      in.pslg.points = std::move(d.points);
      in.pslg.holes = std::move(d.holes);
      in.pslg.segments.assign(d.segments.values.begin(), d.segments.values.end());
      return true;
    }
    case JsonKind::Rings:
      in.format = InputFormat::JsonPslg;
      in.hasRings = true;
      in.pslg.points = std::move(d.points);
      in.pslg.segments = std::move(d.ringSegments);
      return true;
    case JsonKind::Cgshop:
      break;
  }
  if (!d.hasPx || !d.hasPy || !d.hasBoundary) {
    const char* missing = !d.hasPx ? "points_x" : !d.hasPy ? "points_y" : "region_boundary";
    return c.fail(d.objectLine, std::string("expected the key \"") + missing +
                                    "\" of a CG:SHOP instance, found none");
  }
  const size_t n = d.px.size();
  if (d.py.size() != n)
    return c.fail(d.pyLine, "expected " + std::to_string(n) +
                                " numbers in \"points_y\" (as in \"points_x\"), found " +
                                std::to_string(d.py.size()));
  if (d.hasNumPoints && d.numPoints != n)
    return c.fail(d.numPointsLine, "expected \"num_points\" equal to the " + std::to_string(n) +
                                       " points given, found " + std::to_string(d.numPoints));
  if (n > kMaxIndexCount)
    return c.fail(d.objectLine, "expected at most " + std::to_string(kMaxIndexCount) +
                                    " points, found " + std::to_string(n));
  if (!checkIndices(d.boundary, n, "\"region_boundary\"", c) ||
      !checkIndices(d.constraints, n, "\"additional_constraints\"", c))
    return false;
  std::vector<uint64_t>& ring = d.boundary.values;
  if (ring.size() >= 2 && ring.front() == ring.back()) {
    ring.pop_back();
    c.warn(d.boundaryLine, "dropped the last index of \"region_boundary\", a repeat of its "
                           "first (the ring closes implicitly)");
  }
  if (ring.size() < 3)
    return c.fail(d.boundaryLine, "expected at least 3 indices in \"region_boundary\", found " +
                                      std::to_string(ring.size()));
  if (d.hasNumConstraints && d.numConstraints != d.constraints.size() / 2)
    c.warn(d.numConstraintsLine, "\"num_constraints\" says " +
                                     std::to_string(d.numConstraints) + " but " +
                                     std::to_string(d.constraints.size() / 2) +
                                     " constraints are given; using those given");
  in.format = InputFormat::CgshopInstance;
  in.instanceUid = std::move(d.uid);
  in.pslg.points.resize(2 * n);
  for (size_t i = 0; i < n; ++i) {
    in.pslg.points[2 * i] = d.px[i];
    in.pslg.points[2 * i + 1] = d.py[i];
  }
  in.pslg.segments.reserve(2 * ring.size() + d.constraints.size());
  for (size_t i = 0; i < ring.size(); ++i) {
    in.pslg.segments.push_back(static_cast<uint32_t>(ring[i]));
    in.pslg.segments.push_back(static_cast<uint32_t>(ring[(i + 1) % ring.size()]));
  }
  for (uint64_t v : d.constraints.values) in.pslg.segments.push_back(static_cast<uint32_t>(v));
  return true;
}

bool parseJsonImpl(std::string_view text, Ctx& c, Input& in) {
  JsonReader r(text, c);
  JsonDoc d;
  r.ws();
  d.objectLine = r.line();
  if (!r.expect('{', "'{' starting the top-level JSON object")) return false;
  std::vector<std::string> seen;
  r.ws();
  if (r.peek() == '}') {
    r.advance();
  } else {
    std::string key;
    while (true) {
      r.ws();
      const size_t keyLine = r.line();
      if (!r.string(key, "a key string")) return false;
      for (const std::string& s : seen)
        if (s == key) return c.fail(keyLine, "expected each key once, found \"" + printable(key) + "\" again");
      seen.push_back(key);
      if (!r.expect(':', "':' after the key") || !readMember(r, d, key, keyLine)) return false;
      r.ws();
      if (r.peek() == ',') {
        r.advance();
        continue;
      }
      if (r.peek() == '}') {
        r.advance();
        break;
      }
      return r.fail("',' or '}' in the top-level object");
    }
  }
  r.ws();
  if (!r.atEnd()) return r.fail("end of text after the top-level object");
  return buildInput(d, c, in);
}

// ------------------------------------------------------------------------------------------
// Files

bool readWholeFile(const std::string& path, std::string& out, std::string& error) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) {
    error = path + ": cannot open (" + std::strerror(errno) + ")";
    return false;
  }
  // A first chunk, before trusting ftell (a directory opens, says LONG_MAX, then fails to
  // read); then the rest in one read when the size is known, in chunks otherwise (pipes).
  long size = -1;
  if (std::fseek(f, 0, SEEK_END) == 0) {
    size = std::ftell(f);
    if (std::fseek(f, 0, SEEK_SET) != 0) size = -1;
  }
  char buf[1 << 14];  // small: Emscripten's stack is small
  size_t got = std::fread(buf, 1, sizeof buf, f);
  out.assign(buf, got);
  if (got == sizeof buf && !std::ferror(f)) {
    if (size > static_cast<long>(got) &&
        static_cast<unsigned long>(size) < out.max_size() / 2) {
      out.resize(static_cast<size_t>(size));
      const size_t have = std::fread(&out[got], 1, out.size() - got, f);
      out.resize(got + have);
    }
    do {
      got = std::fread(buf, 1, sizeof buf, f);
      out.append(buf, got);
    } while (got == sizeof buf);
  }
  const bool bad = std::ferror(f) != 0;
  const int err = errno;
  std::fclose(f);
  if (bad) {
    error = path + ": cannot read (" + std::strerror(err) + ")";
    return false;
  }
  return true;
}

std::string lowerExtension(const std::string& path) {
  const size_t slash = path.find_last_of("/\\");
  const size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return {};
  std::string ext = path.substr(dot);
  for (char& ch : ext)
    if (ch >= 'A' && ch <= 'Z') ch = static_cast<char>(ch - 'A' + 'a');
  return ext;
}

// True if the first content line of a .poly starts with a vertex count of 0.
bool polyHasNoVertices(std::string_view text) {
  Lines L(text);
  std::string_view line, tok;
  if (!L.next(line)) return false;
  Fields f(line);
  int64_t v;
  return f.next(tok) && parseFieldInt(tok, v) && v == 0;
}

}  // namespace

ParseResult parsePoly(std::string_view text, const std::string& name, Input& out,
                      std::string_view nodeText, const std::string& nodeName) {
  Input in;
  Ctx c{name, &in.warnings, {}};
  if (!parsePolyImpl(text, c, in, nodeText, nodeName)) return failure(std::move(c.message));
  in.format = InputFormat::Poly;
  out = std::move(in);
  return {};
}

ParseResult parseNode(std::string_view text, const std::string& name, Input& out) {
  Input in;
  Ctx c{name, &in.warnings, {}};
  VertexList vl;
  if (!parseNodeInto(text, c, in.pslg.points, vl, true)) return failure(std::move(c.message));
  in.format = InputFormat::Node;
  out = std::move(in);
  return {};
}

ParseResult parseJson(std::string_view text, const std::string& name, Input& out) {
  Input in;
  Ctx c{name, &in.warnings, {}};
  if (!parseJsonImpl(text, c, in)) return failure(std::move(c.message));
  out = std::move(in);
  return {};
}

namespace {

ParseResult readInputFileOrThrow(const std::string& path, Input& out) {
  const std::string ext = lowerExtension(path);
  if (ext != ".poly" && ext != ".node" && ext != ".json")
    return failure(path + ": expected the extension .poly, .node or .json, found " +
                   (ext.empty() ? std::string("none") : "'" + ext + "'"));
  std::string text, error;
  if (!readWholeFile(path, text, error)) return failure(std::move(error));
  if (ext == ".node") return parseNode(text, path, out);
  if (ext == ".json") return parseJson(text, path, out);
  if (polyHasNoVertices(text)) {
    const std::string nodePath = path.substr(0, path.size() - 5) + ".node";
    std::string nodeText;
    if (!readWholeFile(nodePath, nodeText, error)) return failure(std::move(error));
    return parsePoly(text, path, out, nodeText, nodePath);
  }
  return parsePoly(text, path, out);
}

}  // namespace

// A file larger than memory (or a parse of it) ends with a message, not an exception.
ParseResult readInputFile(const std::string& path, Input& out) {
#if defined(__cpp_exceptions) || defined(__EXCEPTIONS)
  try {
    return readInputFileOrThrow(path, out);
  } catch (const std::bad_alloc&) {
  } catch (const std::length_error&) {
  }
  return failure(path + ": out of memory reading it");
#else
  return readInputFileOrThrow(path, out);
#endif
}

}  // namespace acutemesh
