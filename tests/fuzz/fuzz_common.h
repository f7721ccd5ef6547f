// Checks shared by the libFuzzer harnesses: a finding aborts with a line saying what broke,
// which libFuzzer reports as a crash and saves the input for.
#pragma once

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "acutemesh/acutemesh.h"
#include "acutemesh/io.h"

namespace fuzz {

[[noreturn]] inline void fail(const std::string& what) {
  std::fprintf(stderr, "fuzz finding: %s\n", what.c_str());
  std::abort();
}

// One line of printable ASCII: what the CLI puts on stderr.
inline bool oneLine(const std::string& s) {
  for (unsigned char c : s)
    if (c < 0x20 || c >= 0x7F) return false;
  return !s.empty();
}

// A parse either fails with "NAME:LINE: ..." on one line, or gives a well-formed PSLG.
// `other`: a second file name messages may start with (a .poly's separate .node).
inline void checkParse(const acutemesh::ParseResult& r, const acutemesh::Input& in,
                       const std::string& name, const std::string& other = "") {
  auto named = [&](const std::string& s) {
    return s.rfind(name + ":", 0) == 0 || (!other.empty() && s.rfind(other + ":", 0) == 0);
  };
  if (!r.ok) {
    if (!named(r.message)) fail("message does not start with the name: " + r.message);
    if (!oneLine(r.message)) fail("message is not one printable line");
    return;
  }
  const acutemesh::Pslg& p = in.pslg;
  if (p.points.size() % 2 || p.segments.size() % 2 || p.holes.size() % 2) fail("odd array");
  for (double x : p.points)
    if (!std::isfinite(x)) fail("non-finite coordinate accepted");
  for (double x : p.holes)
    if (!std::isfinite(x)) fail("non-finite hole accepted");
  for (uint32_t v : p.segments)
    if (v >= p.vertexCount()) fail("segment index out of range accepted");
  for (const std::string& w : in.warnings)
    if (!oneLine(w) || !named(w)) fail("bad warning: " + w);
}

}  // namespace fuzz
