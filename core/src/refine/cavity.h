// The cavity of a candidate point x: the triangles whose circumcircles hold x, which give way
// to x when it goes in. Before inserting, refinement asks it what x would encroach (a
// subsegment on its rim in whose diametral disk x lies) and how many bad triangles x would
// leave (badChange), to weigh candidates against each other.
#pragma once

#include <cstdint>
#include <vector>

#include "job.h"
#include "state.h"

namespace acutemesh::detail {

class Cavity {
 public:
  Cavity(RefineState& s, const Job& job) : s_(s), job_(job) {}

  // The subsegment on the rim of x's cavity that x encroaches (the longest if several), and
  // the first fixed edge x lies beyond; kNone where none.
  struct Rim {
    uint32_t encroached, beyond;
  };
  // The cavity of x seen from triangle `from` (x in its circumdisk), into triangles().
  Rim examine(uint32_t from, const double* x);
  // How many more triangles miss the target once x goes into the cavity just examined (for a
  // point that encroaches nothing), or once x splits the subsegment of fixed half-edge `split`
  // (splitChange), standing for footOf's altitude foot where given.
  int badChange(const double* x, uint32_t split = kNone, uint32_t footOf = kNone) const;
  // The same for m splitting the subsegment of fixed half-edge e: the cavities on both of its
  // sides give way to triangles joining m to their rims.
  int splitChange(uint32_t e, const double* m, uint32_t footOf);
  const std::vector<uint32_t>& triangles() const { return cavity_; }
  bool tooLarge() const { return cavity_.size() > kCavityExamined; }

 private:
  Rim grow(const double* x);

  RefineState& s_;
  const Job& job_;
  std::vector<uint32_t> cavity_;
};

}  // namespace acutemesh::detail
