// Fewer Steiner points on a mesh that meets the target: a Steiner point goes if the triangles
// that then fill its place meet the target (after moving their vertices, as relocation does);
// two neighbouring Steiner points become one where one point can stand in for both. What does
// not work out is put back as it was.
#pragma once

#include <cstdint>
#include <vector>

#include "insertion.h"
#include "job.h"
#include "link_region.h"
#include "relocate.h"
#include "state.h"

namespace acutemesh::detail {

// One step of an improvement round, as logged by a round's second half for replay (polish.h).
struct Step {
  enum Kind : uint8_t { Move, Remove, Merge } kind;
  uint32_t u, w, made;  // the vertex moved or removed; the pair merged and the point made
  double x, y;          // where it moved
};

// Which Steiner points the passes may touch, and where they log what they did: all and
// nowhere, except in the halves of a round in halves (polish.h).
struct Scope {
  const std::vector<uint8_t>* mine = nullptr;
  std::vector<Step>* log = nullptr;
  bool owns(uint32_t v) const { return !mine || v >= mine->size() || (*mine)[v]; }
  void record(const Step& step) const {
    if (log) log->push_back(step);
  }
};

class Reduce {
 public:
  Reduce(RefineState& s, const Job& job, Relocation& relocation, Insertion& insertion)
      : s_(s), job_(job), relocation_(relocation), insertion_(insertion), region_(s, job.target) {}

  Scope scope;

  // Passes of removals (merges) until one gains nothing, at most `passes`; the first tries
  // the vertices `due` marks (default: all), later ones only those whose surroundings a
  // success has changed since their last try (the rest would fail the same way again).
  void removeSteinerPoints(const std::vector<uint8_t>* due = nullptr, int passes = kRemovalPasses);
  void mergeSteinerPoints(const std::vector<uint8_t>* due = nullptr, int passes = 1);
  // Steiner vertex v taken out if it can be; false, changing nothing, otherwise.
  bool removePoint(uint32_t v);
  // Neighbours u and w (both free, or both on one segment) made one point if they can be (the
  // point is the last vertex then); false, changing nothing, where either is gone or they are
  // no longer neighbours.
  bool mergePair(uint32_t u, uint32_t w);

 private:
  bool sizesAllowRemoving(uint32_t v) const;
  struct Moved {
    uint32_t vertex;
    double x, y;
  };
  bool holeMeetsTarget();
  void undoMoves();
  // Runs a removal with the store recording the triangles it writes; they become hole_.
  template <class Removal>
  bool recordingHole(Removal removal) {
    touched_.clear();
    s_.T.touched = &touched_;
    bool removed = removal();
    s_.T.touched = nullptr;
    if (removed) hole_ = touched_;
    return removed;
  }
  bool tryRemove(uint32_t v);
  bool tryRemoveFromSegment(uint32_t v);
  bool tryMerge(uint32_t u, uint32_t w);
  int tryMergedPoint(const double* x);
  bool tryMergeOnSegment(uint32_t u, uint32_t w);
  int tryPointOnSegment(const double* x, uint32_t footOf, const uint32_t* ends);
  bool mergePoint(uint32_t u, uint32_t w, double* out);
  void markChanged();
  void markDue(const std::vector<uint8_t>* due);
  uint32_t mergePass();
  // (done: the share of the current pass gone through, for progress.)
  bool shouldStop(double done);

  RefineState& s_;
  const Job& job_;
  Relocation& relocation_;
  Insertion& insertion_;
  LinkRegion region_;  // mergePoint's
  std::vector<uint32_t> touched_, hole_, partners_;
  std::vector<Moved> moved_;    // by holeMeetsTarget, for undoMoves
  std::vector<uint8_t> dirty_;  // per vertex: worth another removal / merge try
  std::vector<uint32_t> order_, rank_;  // the passes' RefineState::visitOrder, and its inverse
  Candidates candidates_;
  uint32_t attempts_ = 0;  // removal and merge attempts so far (shouldStop)
};

}  // namespace acutemesh::detail
