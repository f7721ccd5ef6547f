// What every part of validate() reads besides the mesh: the input, the options it was meshed
// with, and the log its findings go to.
#pragma once

#include <cstdint>

#include "acutemesh/acutemesh.h"
#include "error_log.h"

namespace acutemesh::validation {

struct Check {
  const Pslg& in;
  const Options& opt;
  ErrorLog& log;
  uint32_t nIn = 0;  // input vertices

  const double* inP(uint32_t v) const { return &in.points[2 * size_t(v)]; }
  // Whether input segments must be chains of mesh edges (every mode but Delaunay).
  bool segmentsKept() const { return opt.mode != Mode::Delaunay; }
  // Whether the domain is the convex hull (less hole regions): Delaunay mode, and Triangle
  // fill with convexHull set or without any segment. The fill rules ignore convexHull.
  bool hullDomain() const {
    return opt.mode == Mode::Delaunay ||
           (opt.fill == FillRule::Triangle && (opt.convexHull || in.segments.empty()));
  }
};

}  // namespace acutemesh::validation
