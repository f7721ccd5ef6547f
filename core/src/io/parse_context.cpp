#include "parse_context.h"

#include <cstdio>

namespace acutemesh::io {

ParseResult failure(std::string message) {
  ParseResult r;
  r.ok = false;
  r.message = std::move(message);
  return r;
}

std::string printable(std::string_view t, size_t max) {
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

std::string quote(std::string_view t) { return "'" + printable(t) + "'"; }

}  // namespace acutemesh::io
