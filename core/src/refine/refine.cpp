// refine(): refinement toward options' target, with the fallbacks that keep every run ending
// in the best certified mesh it can:
//  - a bound below 90 degrees (or auto) is refineBelow90's: anytime, from the acute mesh down,
//    so a run that falls short still ends acute and certified (TargetNotMet);
//  - a minimum angle above kSureMinAngle, where Delaunay refinement need not terminate: a run
//    that uses half the budget is made again to kSureMinAngle;
//  - sizes (acute, non-obtuse) the Steiner budget cannot meet: the angle target alone;
//  - exact feet (non-obtuse): should some triangle around them not be right at their exact
//    positions after all, the run is made again without them; not when a budget stopped it
//    (the certificate counts what is left).
#include <algorithm>

#include "../build.h"
#include "../size_field.h"
#include "geometry.h"
#include "params.h"
#include "below90.h"
#include "strategies.h"
#include "target.h"

namespace acutemesh::detail {
namespace {

// One refinement of `start` into T, with freeVertex and exact as refine() leaves them;
// releaseStart as refineWithStrategies has it.
RefineOutcome refineOnce(const RefineState& start, const Pslg& input, const Options& options,
                         const Budget& budget, uint32_t steinerCap, Triangulation& T,
                         std::vector<uint8_t>& freeVertex, std::vector<ExactVertex>& exact,
                         RefineState* releaseStart = nullptr) {
  RefineState best;
  RefineOutcome outcome = refineWithStrategies(start, input, options, budget, steinerCap, best,
                                               exact, releaseStart);
  best.markFree(freeVertex);
  T = std::move(best.T);
  return outcome;
}

// Acute or non-obtuse with sizes: sizes too small for the Steiner budget leave a mesh that
// meets neither target; then the angle target alone is met from the start, which needs far
// fewer points, and that mesh is the one returned (TargetNotMet, saying so).
StepResult refineSized(const RefineState& start, const Pslg& input, const Options& options,
                       const Budget& budget, Triangulation& T, std::vector<uint8_t>& freeVertex,
                       std::vector<ExactVertex>& exact) {
  RefineState best;
  RefineOutcome o = refineWithStrategies(start, input, options, budget, 0, best, exact);
  Options angles = options;
  angles.maxArea = 0, angles.maxEdge = 0, angles.size = SizeField{};
  if (o.met || o.result.status == Status::Cancelled || budget.stop() ||
      !Target(angles).anyMissed(best)) {
    best.markFree(freeVertex);
    T = std::move(best.T);
    return o.result;
  }
  best = RefineState{};
  const StepResult plain = refineOnce(start, input, angles, budget, 0, T, freeVertex, exact).result;
  if (!plain.ok()) return plain;
  return {Status::TargetNotMet,
          "the sizes asked for need more Steiner points than the budget allows: the mesh meets "
          "the angle target but not the sizes (a larger maxSteiner, or larger sizes)"};
}

}  // namespace

StepResult refine(Triangulation& T, const Pslg& input, const Options& options, const Budget& budget,
                  std::vector<uint8_t>& freeVertex, std::vector<ExactVertex>& exact) {
  exact.clear();
  RefineState start = RefineState::start(std::move(T), input.vertexCount());
  if (options.exactFeet && options.mode == Mode::NonObtuse) {
    RefineOutcome o = refineOnce(start, input, options, budget, 0, T, freeVertex, exact);
    if (o.feetHeld || !o.met || !o.result.ok() || budget.stop()) return o.result;
    Options plain = options;
    plain.exactFeet = false;
    return refineOnce(start, input, plain, budget, 0, T, freeVertex, exact).result;
  }
  if (options.mode == Mode::Acute && (options.maxAngle < 90 || options.maxAngle == kAutoMaxAngle)) {
    // Progress: refineBelow90's own fractions (its starts and levels), not those of the
    // refinements it runs.
    const ProgressRelay::Scope level(budget.progress());
    RefineState best;
    StepResult result = refineBelow90(start, input, options, budget, best, exact);
    best.markFree(freeVertex);
    T = std::move(best.T);
    return result;
  }
  if (options.mode != Mode::Quality && Target(options).sized())
    return refineSized(start, input, options, budget, T, freeVertex, exact);
  if (options.mode != Mode::Quality || options.minAngle <= kSureMinAngle)
    return refineOnce(start, input, options, budget, 0, T, freeVertex, exact, &start).result;
  const uint32_t half = uint32_t(std::clamp(
      steinerBudget(input, options, sizeDemand(start.T, options)) / 2, 1.0, double(kMaxVertices)));
  RefineOutcome o = refineOnce(start, input, options, budget, half, T, freeVertex, exact);
  if (o.result.ok() || o.result.status == Status::Cancelled || budget.stop()) return o.result;
  Options sure = options;
  // Quality: a run that ended short of the target for lack of points (not for input angles
  // below it, which no point mends) has been wandering.
  if (T.vertexCount() < start.T.vertexCount() + half) return o.result;
  sure.minAngle = kSureMinAngle;
  o = refineOnce(start, input, sure, budget, 0, T, freeVertex, exact);
  if (o.result.status == Status::Cancelled) return o.result;
  return {Status::TargetNotMet, "a minimum angle of " + degreesText(options.minAngle) +
                                    " was not reached with half the Steiner budget; the mesh is "
                                    "refined to " +
                                    degreesText(kSureMinAngle) +
                                    (o.result.ok() ? "" : " (" + o.result.message + ")")};
}

}  // namespace acutemesh::detail
