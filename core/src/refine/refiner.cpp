#include "refiner.h"

namespace acutemesh::detail {

StepResult Refiner::run() {
  const Target& target = job_.target;
  if (target.nonObtuse && job_.strategy.cutAtFeetFirst) boundary_.cutAtFeet();
  if (target.boundsLargest()) fans_.buildAll();
  StepResult result;
  {
    const ProgressRelay::Part repairs(job_.progressRelay(), 0, kRepairShare);
    result = repair_.repairAll();
  }
  const ProgressRelay::Part removals(job_.progressRelay(), kRepairShare, 1);
  // Where the point count is the score (Target::countsPoints): remove what is not needed. The
  // fans have done their work once the target is met: their points may go too, as long as
  // what fills their place meets the target. Putting a vertex back can differ from its old
  // star where vertices are cocircular, so whatever that spoilt is repaired again.
  if (result.ok() && target.countsPoints()) {
    s_.releaseChords();
    for (size_t v = 0; v < s_.role.size(); ++v) {
      if (s_.role[v] == kArc) s_.role[v] = kFree;
      s_.fanCenter[v] = kNone;
    }
    if (!repair_.missesBeyondLeft()) reduce_.removeSteinerPoints();
    result = repair_.repairAll();
  }
  s_.releaseChords();  // (when a budget cut the run short)
  return result;
}

}  // namespace acutemesh::detail
