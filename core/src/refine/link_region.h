// The room a link leaves: the convex region of points p for which every triangle (p, x, y)
// over an edge x->y of the link is counter-clockwise with its angles at x and y within the
// target (Erten & Üngör 2.2: the intersection of the link edges' slabs and the link's kernel).
// Relocation looks for a vertex's new place in it, a merge for the one point that can stand in
// for two. (The angle at p is no half-plane: the exact test of the star decides.)
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "state.h"
#include "target.h"

namespace acutemesh::detail {

class LinkRegion {
 public:
  LinkRegion(const RefineState& s, const Target& target) : s_(s), target_(target) {}

  // The link's edges x->y, counter-clockwise as seen from p; filled by the caller.
  std::vector<std::array<uint32_t, 2>> edges;

  // Acute and non-obtuse: false where the region is surely empty. Where two link edges x->y,
  // y->z turn right at y (acute: or go straight on), a point p left of both makes angles at y
  // in (p, x, y) and (p, y, z) summing to at least 180 degrees. Exact, so giving up here only
  // gives up moves the exact test would refuse.
  bool leavesRoom() const;
  // Clips the region (into corners()) from the bounding box of the edges' ends: p left of each
  // x->y and inside its slab, (p-x).(y-x) > 0 and (p-y).(x-y) > 0 for 90 degrees; with `wedges`
  // (a bound below 90) the slab narrows to a wedge whose sides are x->y turned by the bound
  // about x (counter-clockwise) and about y (clockwise); with a minimum angle alpha, p also
  // lies beyond x->y turned by alpha about x and about y. Empty if there is no such point.
  void clip(bool wedges);
  const std::vector<std::array<double, 2>>& corners() const { return corners_; }
  // The mean of the corners (inside the region, which is convex), if it is a region at all.
  bool centroid(double* out) const;

 private:
  const RefineState& s_;
  const Target& target_;
  std::vector<std::array<double, 2>> corners_;
  // clip()'s scratch (two polygons, each corner's side), only ever grown: growing a vector of
  // arrays zeroes the new elements.
  std::vector<std::array<double, 2>> work_;
  std::vector<double> side_;
};

}  // namespace acutemesh::detail
