// One refinement run: one strategy on one refinement state, with the steps wired together.
// strategies.cpp makes a Refiner per strategy (each on its own copy of the state), and polish
// one more for the second half of a round in halves.
#pragma once

#include "boundary.h"
#include "cavity.h"
#include "fans.h"
#include "insertion.h"
#include "job.h"
#include "polish.h"
#include "reduce.h"
#include "relocate.h"
#include "repair.h"
#include "state.h"

namespace acutemesh::detail {

class Refiner {
 public:
  Refiner(RefineState& s, const Job& job)
      : s_(s),
        job_(job),
        cavity_(s, job_),
        boundary_(s, job_, cavity_),
        insertion_(s, job_, cavity_, boundary_),
        fans_(s, job_),
        relocation_(s, job_),
        repair_(s, job_, fans_, relocation_, boundary_, insertion_),
        reduce_(s, job_, relocation_, insertion_),
        polish_(s, job_, relocation_, reduce_, repair_) {}
  Refiner(const Refiner&) = delete;
  Refiner& operator=(const Refiner&) = delete;

  // The strategy's steps: cuts at feet and corner fans (acute, non-obtuse), repairs until the
  // target is met, then (Target::countsPoints) the Steiner points that are not needed removed.
  StepResult run();
  // Improvement rounds (Target::countsPoints; on a mesh that meets the target).
  void polish() { polish_.run(); }
  Reduce& reduce() { return reduce_; }
  Insertion& insertion() { return insertion_; }
  Boundary& boundary() { return boundary_; }
  Polish& polisher() { return polish_; }
  Repair& repairs() { return repair_; }

 private:
  RefineState& s_;
  const Job job_;  // (the steps below keep a reference to this copy)
  Cavity cavity_;
  Boundary boundary_;
  Insertion insertion_;
  CornerFans fans_;
  Relocation relocation_;
  Repair repair_;
  Reduce reduce_;
  Polish polish_;
};

}  // namespace acutemesh::detail
