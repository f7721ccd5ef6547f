// Exact certificates of a largest angle below a bound, for triangles of doubles: the meaning of
// Stats::certified and Stats::angleBound in acute mode. A floating-point filter decides nearly
// every corner; the few it leaves are decided with exact integers (exact.h).
#pragma once

#include <functional>

#include "acutemesh/acutemesh.h"

namespace acutemesh::detail {

// "Every angle is below `degrees`" (60 <= degrees <= 90), exactly for the doubles given. At 90
// the sign of the dot product decides. Below 90, an angle is below the bound when the dot
// product u.v is positive and (u.v)^2 > q |u|^2 |v|^2, with q a double a hair above cos^2 of
// the bound: the certificate holds for a bound under 1e-12 degrees smaller than the one asked
// for, so it is sound for that one.
class AngleCheck {
 public:
  explicit AngleCheck(double degrees);
  double degrees() const { return degrees_; }
  // The angle at a of triangle a, b, c.
  bool cornerBelow(const double* a, const double* b, const double* c) const;
  bool triangleBelow(const double* const p[3]) const;

 private:
  double degrees_;
  double cos2_;  // q above
};

// Whether every angle of every triangle of `mesh` is below the bound of `check`.
bool meshBelow(const Mesh& mesh, const AngleCheck& check);

// For a mesh whose largest angle, measured in floating point, is `largest`: the lowest tenth of
// a degree above it that every angle is certified below (`below(bound)`, exact), and 90 if that
// is none below 90 (for a mesh the caller knows is acute). The bound --max-angle auto reports.
double tenthBound(double largest, const std::function<bool(double)>& below);

}  // namespace acutemesh::detail
