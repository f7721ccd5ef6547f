// How far a rounded construction may sit off its line: the one tolerance that validate()
// grants a segment's chain and that the refinement keeps clear of.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "acutemesh/predicates.h"

namespace acutemesh::detail {

// Rounded constructions (segment crossings and split points) leave a Steiner point a few
// units in the last place off its segment, and refinement folds slivers thinner than this
// (NearEnds, build.h). The reach allowed is kRoundingUlps ulps of the largest coordinate
// involved (docs/TUNING.md).
constexpr double kRoundingUlps = 4096;
// Segment ends this near a segment but beyond the reach make slivers that refinement may not
// resolve either: a missed target near one names it (NamedCorners).
constexpr double kSliverUlps = 65536;

inline double roundingReach(const double* a, const double* b, const double* c,
                            double ulps = kRoundingUlps) {
  double m = 0;
  for (const double* p : {a, b, c}) m = std::max({m, std::fabs(p[0]), std::fabs(p[1])});
  return ulps * std::numeric_limits<double>::epsilon() *
         std::max(m, std::numeric_limits<double>::min());
}

// Whether the line ab passes through the square of half-side roundingReach (of `ulps`) around c
// (exact orientation of its corners).
inline bool nearLine(const double* a, const double* b, const double* c,
                     double ulps = kRoundingUlps) {
  double r = roundingReach(a, b, c, ulps);
  // Most points asked about are far off the line: |ab x ac| is |ab| times c's distance from
  // it, and the square reaches the line only if that is at most r (|dx| + |dy|). Twice that
  // plus the cross product's rounding error is beyond doubt (the exact test below is 4x the
  // cost and most of the segment walk's time).
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  const double px = dx * (c[1] - a[1]), py = dy * (c[0] - a[0]);
  if (std::fabs(px - py) > 2 * r * (std::fabs(dx) + std::fabs(dy)) +
                               8 * std::numeric_limits<double>::epsilon() *
                                   (std::fabs(px) + std::fabs(py)))
    return false;
  int below = 0, above = 0;
  for (double dx : {-r, r})
    for (double dy : {-r, r}) {
      const double q[2] = {c[0] + dx, c[1] + dy};
      double o = orient2d(a, b, q);
      below += o < 0, above += o > 0;
    }
  return below < 4 && above < 4;
}

// Whether c lies within rounding reach of the segment ab (its line, inside its extent).
inline bool nearSegment(const double* a, const double* b, const double* c) {
  return nearLine(a, b, c) && dot2d(c, a, b) <= 0;
}

}  // namespace acutemesh::detail
