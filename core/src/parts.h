// Acute and non-obtuse meshes part by part. A domain of several parts (its connected pieces:
// a country's islands, each with its lakes) is meshed as that many problems of their own, on
// threads, and the meshes put together: segments bound every part, so no point one part makes
// changes another, and each part gets the strategy that suits it best and a polish of its own
// size (issue 25: whole runs over a whole country grow faster than the output and copy it all).
#pragma once

#include <cstdint>
#include <vector>

#include "acutemesh/acutemesh.h"
#include "build.h"
#include "triangulation.h"

namespace acutemesh::detail {

// mesh() below the coordinate scaling (mesh.cpp): the input was scaled by 2^-exponent;
// byParts false for a part's own run.
Result meshInRange(const Pslg& input, const Options& options, int exponent, bool byParts);

// Meshes T's domain (`inside`, from input; T's vertex k < inputOf.size() is input vertex
// inputOf[k]) part by part toward `target` (acute or non-obtuse) into result.mesh, with
// result.status and message Cancelled when a part's run was (saying whether every part met the
// target), TargetNotMet when one missed it as the time limit ran out (other misses are the
// caller's certificate's). False, touching nothing, when the domain does not go by parts:
// one part, too small (kPartsFrom), a part bounded where no segment lies (a kept hull),
// options a part cannot share (a Steiner cap, exact feet). Once the parts run, T is released
// (emptied); false after that means a part's run refused its input (a fault): the caller
// triangulates the domain again and meshes it whole.
bool meshByParts(Triangulation& T, const std::vector<uint8_t>& inside, const Pslg& input,
                 const std::vector<uint32_t>& inputOf, const Options& target,
                 const Budget& budget, Result& result);

}  // namespace acutemesh::detail
