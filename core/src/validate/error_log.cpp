#include "error_log.h"

#include "../build.h"

namespace acutemesh::validation {

void append(std::string& s, Xy q) {
  s += '(' + detail::shortestText(q.p[0]) + ", " + detail::shortestText(q.p[1]) + ')';
}

void append(std::string& s, Tri t) {
  s += "triangle " + std::to_string(t.t) + " (" + std::to_string(t.v[0]) + ',' +
       std::to_string(t.v[1]) + ',' + std::to_string(t.v[2]) + ')';
}

}  // namespace acutemesh::validation
