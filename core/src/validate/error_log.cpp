#include "error_log.h"

#include <cstdlib>

namespace acutemesh::validation {
namespace {

// The shortest decimal that reads back as exactly x.
std::string exact(double x) {
  char buf[32];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, x);
    if (std::strtod(buf, nullptr) == x) break;
  }
  return buf;
}

}  // namespace

void append(std::string& s, Xy q) { s += '(' + exact(q.p[0]) + ", " + exact(q.p[1]) + ')'; }

void append(std::string& s, Tri t) {
  s += "triangle " + std::to_string(t.t) + " (" + std::to_string(t.v[0]) + ',' +
       std::to_string(t.v[1]) + ',' + std::to_string(t.v[2]) + ')';
}

}  // namespace acutemesh::validation
