// Running strategies: acute and non-obtuse runs try a few boundary strategies, each on its own
// copy of the start state, and keep the one that meets the target with the fewest Steiner
// points; that one is polished. The corner fans everywhere are the safe way (they settle every
// small angle); lazy fans and altitude feet (non-obtuse) often need far fewer points but now
// and then do not finish. A later strategy stops as soon as it has used as many points as the
// best so far, so the extra runs cost little where the first is already good.
#pragma once

#include <cstdint>
#include <vector>

#include "../build.h"
#include "state.h"

namespace acutemesh::detail {

class Refiner;
struct Job;

// A quality run for its own mesh, or only as a start for another search (below90.cpp's
// starts, tuned without the removals and polish that Target::countsPoints brings).
enum class QualityRun { Mesh, Start };

// What refineWithStrategies leaves.
struct RefineOutcome {
  bool met = false;      // the best run met the target
  StepResult result;     // its result
  bool feetHeld = true;  // exact feet: every triangle around them right or sharper there
};

// The strategies for options.mode in turn (several at once where there are threads), then
// polish on the best, into `out` (its state) and `exact` (its exact feet). steinerCap (0: none)
// bounds each run's Steiner points. releaseStart: `start` itself, when the caller has no more
// use for it: it is emptied once the runs are done, so that the polish holds one state fewer.
RefineOutcome refineWithStrategies(const RefineState& start, const Pslg& input,
                                   const Options& options, const Budget& budget,
                                   uint32_t steinerCap, RefineState& out,
                                   std::vector<ExactVertex>& exact,
                                   RefineState* releaseStart = nullptr,
                                   QualityRun quality = QualityRun::Mesh);

// Options::optimize's search (Polish::search) on s, which meets job's target (refiner: s's):
// one chain per thread of `search` (seeds search.seed, + 1, ...), each on its own copy; the
// fewest points win (the first chain on a tie). Only the calling thread's chain reports
// progress.
void searchFewerPoints(RefineState& s, Refiner& refiner, const Job& job, const Options& search);

// The Steiner points a run may make: Options::maxSteiner, or without a budget from the caller
// kSteinerPerInputVertex per input vertex, at least kSteinerAtLeast, and with area or size
// bounds room for about twice the triangles they ask for (`demand`, sizeDemand's).
double steinerBudget(const Pslg& input, const Options& options, double demand);

}  // namespace acutemesh::detail
