// Exact feet (Options::exactFeet, non-obtuse): a Steiner point on a tilted segment may stand
// for the exact foot of the altitude from a vertex next to it, a rational point no double
// holds. While refinement runs the vertex is a double near the foot on the segment's line,
// and its angles between the segment and the edge to that vertex count as right when within
// kFootSlack of 90 degrees (Target::footCorners). Once refinement is over, each such vertex
// goes to the exact foot and every triangle around it is checked exactly there.
#pragma once

#include <cstdint>
#include <vector>

#include "../build.h"
#include "job.h"
#include "state.h"

namespace acutemesh::detail {

// Segment vertex v, just made at the altitude foot of footOf (kNone: of none), stands for
// that foot unless the double is exactly it (as on axis-parallel segments). along: another
// point of v's segment line.
inline void standForFoot(RefineState& s, const Target& target, uint32_t v, uint32_t footOf,
                         const double* along) {
  if (target.feet && footOf != kNone && dot2d(s.P(v), s.P(footOf), along) != 0)
    s.footOf[v] = footOf;
}

// Each foot vertex with a corner that counts as right goes to the exact foot of its altitude
// (into `exact`). True if every triangle around them is then right or sharper (exactly).
bool placeExactFeet(const RefineState& s, const Job& job, std::vector<ExactVertex>& exact);

}  // namespace acutemesh::detail
