// Smoothing of every movable point at once, for bounds below 90 degrees (descent.h). Moving
// one point at a time to where its own star is best stalls where neighbours must move together
// (a corner's fan turned as a whole, a row of points along a segment shifted): here every Steiner
// point takes gradient steps on one smooth penalty of the whole mesh, the sum of the squared
// excess of every angle over an aim a little below the bound. Free points move freely, points
// on a segment along it; input vertices and corner fans' points stand.
#pragma once

#include <cstddef>

#include "job.h"
#include "state.h"

namespace acutemesh::detail {

// Gradient steps (at most `steps`) toward every angle of the domain under `aimDegrees`; a step
// is taken only if it lowers the penalty and leaves every triangle counter-clockwise (exact)
// with no edge shorter than the job's smallest. The number of steps taken.
size_t smoothJointly(RefineState& s, const Job& job, double aimDegrees, int steps);

}  // namespace acutemesh::detail
