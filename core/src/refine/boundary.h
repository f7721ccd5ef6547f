// The boundary rule: a triangle on a subsegment is acute at the opposite corner only if no
// vertex lies in the subsegment's closed diametral disk, so an encroached subsegment is split.
// Where: next to an input vertex at a power of two from it (concentric shells, so that the
// pieces around a small corner match), else the midpoint; or at the altitude foot of the
// encroaching vertex (non-obtuse: two right triangles with one point); or, weighed, where it
// leaves the fewest bad triangles. A chord of a corner fan is split on its arc.
#pragma once

#include <cstdint>
#include <vector>

#include "cavity.h"
#include "job.h"
#include "state.h"

namespace acutemesh::detail {

class Boundary {
 public:
  Boundary(RefineState& s, const Job& job, Cavity& cavity) : s_(s), job_(job), cavity_(cavity) {}

  // Splits the subsegment of fixed half-edge e at `preferred` (a fraction of the way from the
  // edge's first end) when given and well inside, else by the shell rule. footOf: the vertex
  // whose altitude foot `preferred` is.
  bool splitSubsegment(uint32_t e, double preferred = -1, uint32_t footOf = kNone);
  // Splits the subsegment opposite corner k of t at the foot of the altitude from k.
  bool splitAtFoot(uint32_t t, int k);
  // Splits the subsegment of e, encroached by apex, where that leaves the fewest bad
  // triangles (Strategy::weighPoints).
  bool splitWeighed(uint32_t e, uint32_t apex);
  // Non-obtuse (Strategy::cutAtFeetFirst): every triangle obtuse opposite a subsegment cut at
  // the foot of its altitude, before the fans.
  void cutAtFeet();

 private:
  double shellRatio(uint32_t e) const;
  double splitRatio(uint32_t e, double preferred) const {
    return preferred > 0.01 && preferred < 0.99 ? preferred : shellRatio(e);
  }
  bool splitChord(uint32_t e);
  bool openOuterSliver(uint32_t e);

  RefineState& s_;
  const Job& job_;
  Cavity& cavity_;
  std::vector<uint32_t> flips_;
};

}  // namespace acutemesh::detail
