// The messages validate() returns, and the parts they are written from.
#pragma once

#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>
#include <type_traits>

#include "acutemesh/acutemesh.h"

namespace acutemesh::validation {

constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();
constexpr size_t kMaxErrors = 20;

// "(x, y)", each coordinate as the shortest decimal that reads back as it.
struct Xy {
  const double* p;
};

// "triangle 17 (4,9,12)"
struct Tri {
  size_t t;
  const uint32_t* v;
};

// Message parts, formatted as an ostream would (numbers in decimal, floating point as %g),
// but without iostreams: those pull the locale machinery into the WebAssembly build.
inline void append(std::string& s, const std::string& x) { s += x; }
inline void append(std::string& s, const char* x) { s += x; }
inline void append(std::string& s, char c) { s += c; }
template <class T>
std::enable_if_t<std::is_integral_v<T> && !std::is_same_v<T, char> && !std::is_same_v<T, bool>>
append(std::string& s, T v) {
  s += std::to_string(v);
}
template <class T>
std::enable_if_t<std::is_floating_point_v<T>> append(std::string& s, T v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", double(v));
  s += buf;
}
void append(std::string& s, Xy q);
void append(std::string& s, Tri t);

// Collects the first kMaxErrors messages; formats nothing once full, so a badly broken mesh
// costs no more than a good one.
class ErrorLog {
 public:
  explicit ErrorLog(Validation& out) : out_(out) {}
  template <class... Parts>
  void add(const Parts&... parts) {
    out_.ok = false;
    if (out_.errors.size() >= kMaxErrors) {
      ++dropped_;
      return;
    }
    std::string s;
    (append(s, parts), ...);
    out_.errors.push_back(std::move(s));
  }
  void finish() {
    if (dropped_ > 0) out_.errors.push_back("... and " + std::to_string(dropped_) + " more");
  }

 private:
  Validation& out_;
  size_t dropped_ = 0;
};

}  // namespace acutemesh::validation
