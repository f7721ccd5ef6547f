// Putting a Steiner point in: a candidate that would encroach a subsegment (lie in its closed
// diametral disk) or fall beyond one is not inserted; the subsegment is split instead. Where
// candidates are weighed, the one that encroaches nothing and leaves the fewest bad triangles
// goes in.
#pragma once

#include <cstdint>

#include "boundary.h"
#include "cavity.h"
#include "geometry.h"
#include "job.h"
#include "state.h"

namespace acutemesh::detail {

class Insertion {
 public:
  Insertion(RefineState& s, const Job& job, Cavity& cavity, Boundary& boundary)
      : s_(s), job_(job), cavity_(cavity), boundary_(boundary) {}

  // Inserts x, found for triangle `from` (x lies in its circumdisk), unless it encroaches a
  // subsegment or lies beyond one: then that subsegment is split instead.
  bool insertSteiner(uint32_t from, const double* x);
  // Inserts one of the first kSliceTries candidates for t (best first) whose cavity's rim holds
  // no subsegment it encroaches (Strategy::weighPoints): the first such, or with fewestBad the
  // one that leaves the fewest bad triangles (weigh). Else the best, letting insertSteiner
  // split what it encroaches.
  bool insertSparingSegments(uint32_t t, const Candidates& points, bool fewestBad);
  // Of the first kSliceTries candidates for t, the one whose insertion leaves the fewest bad
  // triangles (ties to the earlier), of those that encroach no subsegment and lie on t's side
  // of every fixed edge (else there is no fair count); points.size() if none. `fewest`: its
  // change in bad triangles.
  size_t weigh(uint32_t t, const Candidates& points, int& fewest);
  // Inserts candidate `chosen` (weigh's choice), else (none, or it split a subsegment it
  // encroaches after all) the best.
  bool insertWeighed(uint32_t t, const Candidates& points, size_t chosen);

 private:
  // insertSteiner with x's cavity just examined.
  bool insertSteiner(uint32_t from, const double* x, Cavity::Rim rim);

  RefineState& s_;
  const Job& job_;
  Cavity& cavity_;
  Boundary& boundary_;
};

}  // namespace acutemesh::detail
