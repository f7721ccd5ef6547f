// Repairs: every triangle that misses the target is repaired, largest first, by the rule its
// worst corner calls for:
//  - a large angle: first move one of its Steiner vertices where its whole star meets the
//    target (relocation, seed 2.2; along its segment for a vertex on one);
//  - a large angle opposite a subsegment: the apex lies in the subsegment's closed diametral
//    disk, and only splitting the subsegment helps (the boundary rule);
//  - a large angle elsewhere: a point of slice(pq) (seed 2.1), sparing the segments;
//  - a small angle: a quality point; a large area: the circumcentre (Ruppert).
// A corner that calls for a fan (Strategy::lazyFans) gets it first.
#pragma once

#include <cstdint>
#include <vector>

#include "boundary.h"
#include "fans.h"
#include "insertion.h"
#include "job.h"
#include "relocate.h"
#include "repair_queue.h"
#include "state.h"

namespace acutemesh::detail {

class Repair {
 public:
  Repair(RefineState& s, const Job& job, CornerFans& fans, Relocation& relocation,
         Boundary& boundary, Insertion& insertion)
      : s_(s),
        job_(job),
        fans_(fans),
        relocation_(relocation),
        boundary_(boundary),
        insertion_(insertion) {}

  // Repairs until no triangle misses the target, or a budget ends first (TargetNotMet or
  // Cancelled; the triangles left are the certificate's to count). A triangle no repair
  // changes is left too.
  StepResult repairAll();

  // Some triangle of the domain misses the target, other than those left at small input angles
  // (acrossSmallInputAngle): what refinement and the improvement rounds must not leave.
  bool missesBeyondLeft() const;
  // A skinny triangle refinement leaves: see repair.cpp.
  bool acrossSmallInputAngle(uint32_t t) const;

 private:
  static constexpr size_t kNotWeighed = SIZE_MAX;
  // weighed: repairGain's choice among t's candidates (in candidates_), if it has just weighed
  // them and nothing has changed the mesh since; kNotWeighed otherwise.
  bool repair(uint32_t t, Corner c, size_t weighed = kNotWeighed);
  int repairGain(uint32_t t, Corner c, size_t* weighed = nullptr);

  RefineState& s_;
  const Job& job_;
  CornerFans& fans_;
  Relocation& relocation_;
  Boundary& boundary_;
  Insertion& insertion_;
  RepairQueue queue_;
  Candidates candidates_;
  std::vector<uint32_t> touched_, flips_;
};

}  // namespace acutemesh::detail
