// Improvement rounds on a mesh that meets the target, while they take out enough Steiner
// points: smoothing (every Steiner vertex to the middle of the room its link leaves), which
// makes room for removals and merges, then removal and merging (reduce.h). On larger meshes a
// round runs in two halves at once, one on a copy of the state, whose steps are then made
// again here in order, so that every build and thread count makes the same mesh.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "job.h"
#include "reduce.h"
#include "relocate.h"
#include "repair.h"
#include "state.h"

namespace acutemesh::detail {

class Polish {
 public:
  Polish(RefineState& s, const Job& job, Relocation& relocation, Reduce& reduce, Repair& repair)
      : s_(s), job_(job), relocation_(relocation), reduce_(reduce), repair_(repair) {}

  // Rounds until one gains too little (kPolishGain and its kin, params.h). A round that ends
  // short of the target (a budget ran out) or with more points than it started with is undone.
  void run();
  // One round: smoothing, removals, merges. removeAfterMerging: the larger meshes' round (see
  // polish.cpp).
  void round(bool removeAfterMerging);
  // Options::optimize's search, on a mesh that meets the target, until `seconds` have passed
  // or the budget stops it: each try either kicks some free Steiner points (part of the way to
  // a neighbour, where their stars still meet the target) or ruins a few places (free points
  // out, refinement mends the holes), chosen by `seed`, then makes kSearchRounds rounds; a try
  // that ends with fewer points is kept, one with more (or short of the target) is undone.
  // The mesh left is the best found: never more points than it started with.
  // tries: at most that many (0: no cap); seconds 0: no time of its own (one of the two must
  // be set: the callers ask searchAsked). thin, if set, runs after each try's rounds (acute
  // targets: AngleDescent::thin, searchFewerPoints).
  void search(double seconds, uint64_t tries, uint64_t seed,
              const std::function<void()>& thin = nullptr);

 private:
  void smooth();
  void roundInHalves(int round);
  void replay(const std::vector<Step>& log, uint32_t firstNew, uint32_t made);

  RefineState& s_;
  const Job& job_;
  Relocation& relocation_;
  Reduce& reduce_;
  Repair& repair_;
  std::vector<uint32_t> order_;  // smooth()'s (RefineState::visitOrder)
};

}  // namespace acutemesh::detail
