// The descent at one bound below 90 degrees (below90.h runs it from a few starts and down
// through the bounds): the largest angle brought down by moving points as much as by adding
// them. Rounds of:
//  1. smoothing: every Steiner point moved to where its star is best (stars compared by their
//     triangles' margins to the bound, smallest first: leximin), a free point by a pattern
//     search, a point on a segment along it; then flips that lower the larger largest angle of
//     two triangles (Delaunay flips would undo the moves: an acute mesh is Delaunay anyway);
//  2. moves: for each triangle still over the bound, the first move that lowers the total
//     violation once the points around it are smoothed again (a point at an equilateral apex
//     or on the bisector of a wide corner at a vertex that cannot move, the opposite edge
//     split, the circumcentre, a Steiner vertex removed); once single moves stall, a move that
//     does not pay gets a second at the worst triangle near it. What does not pay is undone.
// It stops when every triangle meets the target, when rounds stop lowering the violation, at
// its move budget, the Steiner limit or the run's budget.
// Where it stalls, below90.cpp splits the edges of the triangles still missing the target
// (splitMissed) and runs it again: more points to move where they were lacking.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "boundary.h"
#include "insertion.h"
#include "job.h"
#include "state.h"

namespace acutemesh::detail {

class AngleDescent {
 public:
  // `moves`: how many more moves (step 2) may be tried, counted down across descents (a work
  // budget that makes the same mesh on every machine, as a time limit would not).
  AngleDescent(RefineState& s, const Job& job, Insertion& insertion, Boundary& boundary,
               uint64_t& moves)
      : s_(s), job_(job), insertion_(insertion), boundary_(boundary), movesLeft_(moves) {}

  // Rounds as above, onProgress told as it goes what part of kDescentRounds is done; true if
  // every triangle of the domain then meets the target.
  bool run(const std::function<void(double)>& onProgress);
  // One sweep of smoothing over every Steiner point; the number of points moved.
  size_t smooth();
  // Splits in the middle every edge of the triangles that miss the target: more points to
  // move where the descent stalled. The number of edges split.
  size_t splitMissed();
  // Takes out the Steiner points a met target does not need: each in turn removed, the points
  // around it smoothed again, and left out where every triangle there still meets the target.
  // The number taken out.
  size_t thin();

 private:
  bool gather(uint32_t v);
  bool margins(std::vector<double>& out) const;
  void putAt(uint32_t v, const double* p);
  bool improvesAt(uint32_t v, const double* p, bool bestValid);
  // Margins closer than this are even (better()).
  static constexpr double kEven = 1e-12;
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
  // apply(m), then smoothAround what it changed, with changed_ every vertex whose star changed
  // (each once); false where m changed nothing.
  bool applySmoothed(const Move& m);
  bool insertFree(uint32_t from, const double* x);
  uint32_t worstNear();
  bool fix(uint32_t t, int depth, double& now, double current);
  void sweeps();
  bool unstick(double& least);
  size_t repair(int depth);
  bool optimise(uint32_t v);
  double violationOf(const RefineState& s, uint32_t t) const;
  double violationAt(const double* const p[3]) const;
  double violation() const;
  double violationNearChanges(const RefineState& s);
  double violationNearChangesAt(const Journal::Mark& m);
  void smoothAround(const std::vector<uint32_t>& touched);
  uint32_t longestEdge(uint32_t t) const;
  size_t flipPass();
  bool flipIfBetter(uint32_t e);
  size_t flipAround(uint32_t v);

  RefineState& s_;
  const Job& job_;
  Insertion& insertion_;
  Boundary& boundary_;
  uint64_t& movesLeft_;
  const std::function<void(double)>* onProgress_ = nullptr;
  int round_ = 0;
  // The star of the vertex being moved: its triangles, and whether each is in the domain.
  std::vector<uint32_t> star_;
  std::vector<uint8_t> starInside_;
  uint32_t seg_[2] = {kNone, kNone};  // its neighbours along its segment (segment points)
  uint32_t segment_ = kNone;
  std::vector<double> best_, try_;  // margins (scratch)
  // fix()'s moves are tried in place and taken back through this (Triangulation::journal),
  // not on copies of the state: a move costs what it touches.
  Journal journal_;
  void clearJournal() {
    journal_.slots.clear(), journal_.edges.clear(), journal_.points.clear(), journal_.radii.clear();
  }
  // violationNearChangesAt's: per slot and vertex, 1 + the index of its first note since the
  // mark (0: none), reset after each use.
  std::vector<uint32_t> oldSlot_, oldEdge_, oldPoint_;
  std::vector<uint32_t> touched_, near_;
  // While a move is judged (fix()): every vertex whose star it changed, and the triangle slots
  // around them (scratch).
  bool recording_ = false;
  std::vector<uint32_t> changed_, slots_;
};

// Passes of AngleDescent::thin over s, which meets job's target (acute, below 90 or at it, or
// non-obtuse), until one takes out under kThinGain of its Steiner points, `passes` at most.
void thinOut(RefineState& s, const Job& job, Insertion& insertion, Boundary& boundary,
             int passes);

}  // namespace acutemesh::detail
