// Acute refinement to a bound below 90 degrees (Options::maxAngle). Anytime: the acute mesh
// at 90 degrees comes first and is kept; then the direct refinement toward the bound (few
// points where it ends) and the descent from a quality mesh (descent.h; where the direct
// one wanders); the mesh kept is the one that meets the bound with the fewest Steiner points,
// or, where none does, the one with the smallest largest angle. A budget or a cancel returns
// the best found so far.
#pragma once

#include <cstdint>
#include <vector>

#include "../build.h"
#include "state.h"

namespace acutemesh::detail {

StepResult refineBelow90(const RefineState& start, const Pslg& input, const Options& options,
                         const Budget& budget, RefineState& out, std::vector<ExactVertex>& exact);

}  // namespace acutemesh::detail
