// Number parsing for the readers: decimal numbers exactly rounded to doubles, and integers,
// straight from the text (no locale, no allocation, no exceptions).
#pragma once

#include <cstdint>
#include <string_view>

namespace acutemesh::io {

enum class NumErr { Ok, NotNumber, NonFinite, OutOfRange };

inline bool isDigit(char c) { return c >= '0' && c <= '9'; }

// The longest prefix of [b, e) in the decimal grammar strtod reads, minus hex and inf/nan:
// [+-] (digits [. digits] | . digits) [(e|E) [+-] digits]. Sets `stop` after it. NotNumber
// when no such prefix exists or an exponent has no digits; NonFinite for "inf"/"nan";
// OutOfRange beyond the double range (values below it become zero, as strtod does).
NumErr parseDecimalPrefix(const char* b, const char* e, const char*& stop, double& v);

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
bool parseIntPrefix(const char* b, const char* e, const char*& stop, int64_t& v);

// [+-]digits, whole token, in int64 range.
inline bool parseFieldInt(std::string_view t, int64_t& v) {
  const char* stop;
  return parseIntPrefix(t.data(), t.data() + t.size(), stop, v) && stop == t.data() + t.size();
}

}  // namespace acutemesh::io
