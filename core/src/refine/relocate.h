// Relocation (Erten & Üngör 2.2): a Steiner vertex moves, keeping its star's topology, to
// where every triangle of its star meets the target. A free vertex goes anywhere in the room
// its link leaves (LinkRegion); a vertex on a segment slides along the segment. Refinement
// tries this before adding a point; the improvement rounds use it to smooth the mesh and to
// mend the hole a removal or merge leaves.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "job.h"
#include "link_region.h"
#include "state.h"

namespace acutemesh::detail {

class Relocation {
 public:
  Relocation(RefineState& s, const Job& job) : s_(s), job_(job), region_(s, job.target) {}

  // Moves free vertex a where its whole star meets the target; false (a stays) if no place
  // tried does.
  bool relocate(uint32_t a);
  // Moves a Steiner vertex on a segment along it (between its neighbours there) likewise.
  bool slide(uint32_t a);
  // relocate(), or where a strict bound below 90 is not in play, slide(): how repairs and
  // smoothing move a vertex.
  bool move(uint32_t a) { return relocate(a) || (!job_.target.strictMax && slide(a)); }
  // Moves Steiner vertex v to `to` (on its segment's line for a segment vertex) and settles it
  // there if its star then meets the target, with the checks relocate() and slide() make;
  // else v stays.
  bool tryMoveTo(uint32_t v, const double* to);
  // After an improvement round moved v: its star legalized where something may flip.
  void settle(uint32_t v);
  // Restores the Delaunay property around vertex a after it moved.
  void legalizeStar(uint32_t a);

 private:
  bool freeStar(uint32_t a);
  bool segmentStar(uint32_t a, uint32_t spokes[2]);
  bool place(uint32_t a, double x, double y);
  bool insideOneDiametralDisk(const std::vector<std::array<double, 2>>& poly) const;
  bool ontoPerpendicular(uint32_t a, const double* old);
  bool nearFixedLinkEdge(uint32_t a, const double* x) const;
  bool slideStretches(double tp, double tq, const SegmentLine& line, double margin);

  RefineState& s_;
  const Job& job_;
  LinkRegion region_;
  std::vector<uint32_t> ring_;       // the link of the vertex being moved (counter-clockwise)
  std::vector<uint8_t> ringInside_;  // per triangle of its star: in the domain
  std::vector<uint32_t> flips_;
  std::vector<std::array<double, 2>> stretches_, cut_;  // slideStretches' answer and scratch
};

}  // namespace acutemesh::detail
