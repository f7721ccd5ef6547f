// Bounds below 90 degrees: the largest angle brought down by moving points, not only by adding
// them. Delaunay refinement toward a bound under 90 need not end (the circumcentre of a
// triangle whose largest angle is 80 degrees makes edges shorter than the triangle's own, and
// so on), so the descent works on a mesh of good shape and alternates:
//  1. every Steiner point moved to where the largest angle of its star is smallest (a free
//     point within its link, a point on a segment along the segment), each move followed by
//     Delaunay flips around it;
//  2. for each triangle still over the bound one point more: its circumcentre, or a split of
//     the subsegment that point would encroach (Insertion's rules).
// It stops when every triangle meets the target, when rounds stop lowering the number of
// triangles that miss it, or at the Steiner limit or the budget.
#pragma once

#include <cstdint>
#include <vector>

#include "insertion.h"
#include "job.h"
#include "relocate.h"
#include "state.h"

namespace acutemesh::detail {

class AngleDescent {
 public:
  // `moves`: how many more moves (step 2) may be tried, counted down across descents (a work
  // budget that makes the same mesh on every machine, as a time limit would not).
  AngleDescent(RefineState& s, const Job& job, Insertion& insertion, Boundary& boundary,
               Relocation& relocation, uint64_t& moves)
      : s_(s),
        job_(job),
        insertion_(insertion),
        boundary_(boundary),
        relocation_(relocation),
        movesLeft_(moves) {}

  // Rounds as above; true if every triangle of the domain then meets the target.
  bool run();
  // One sweep of step 1 over every Steiner point; the number of points moved.
  size_t smooth();

 private:
  bool gather(uint32_t v);
  bool margins(std::vector<double>& out) const;
  bool marginsAt(uint32_t v, const double* p, std::vector<double>& out);
  static bool better(const std::vector<double>& a, bool aValid, const std::vector<double>& b,
                     bool bValid);
  bool settleAt(uint32_t v, const double* p);
  bool optimiseFree(uint32_t v);
  bool optimiseOnSegment(uint32_t v);
  struct Move {
    enum Kind : uint8_t { Insert, Split, Remove } kind;
    uint32_t t;     // the triangle it is for
    uint32_t what;  // Split: the edge; Remove: the vertex
    double x, y;    // Insert: where
  };
  void movesFor(uint32_t t, std::vector<Move>& out) const;
  bool apply(const Move& m);
  bool insertFree(uint32_t from, const double* x);
  uint32_t worstNear();
  bool fix(uint32_t t, int depth, double& now);
  size_t repair(int depth);
  bool optimise(uint32_t v);
  double violation() const;
  void smoothAround(const std::vector<uint32_t>& touched);
  uint32_t longestEdge(uint32_t t) const;
  size_t flipPass();
  bool flipIfBetter(uint32_t e);
  size_t missed() const;

  RefineState& s_;
  const Job& job_;
  Insertion& insertion_;
  Boundary& boundary_;
  Relocation& relocation_;
  uint64_t& movesLeft_;
  // The star of the vertex being moved: its triangles, and whether each is in the domain.
  std::vector<uint32_t> star_;
  std::vector<uint8_t> starInside_;
  uint32_t seg_[2] = {kNone, kNone};  // its neighbours along its segment (segment points)
  uint32_t segment_ = kNone;
  std::vector<double> best_, try_, first_;  // margins (scratch)
  std::vector<RefineState> saved_;          // fix()'s, one per depth
  std::vector<uint32_t> touched_, near_;
};

}  // namespace acutemesh::detail
