#include "angle_bound.h"

#include <algorithm>
#include <cmath>

#include "acutemesh/predicates.h"
#include "exact.h"
#include "portable_math.h"

namespace acutemesh::detail {
namespace {

// The filter's margin, relative to |u|^2 |v|^2: the rounding error of (u.v)^2 - q |u|^2 |v|^2
// computed from double differences is a few units in the last place of that, so a margin this
// wide decides only right answers; and beyond it |u.v| > 1e-5 |u| |v|, so the sign of the dot
// product computed in floating point is right too.
constexpr double kFilter = 1e-10;

}  // namespace

AngleCheck::AngleCheck(double degrees) : degrees_(degrees) {
  // cos B as sin(90 - B): 90 - B is exact, so the cosine is within a few ulps even near 90
  // degrees, where cos(B) itself would inherit the rounding of B in radians many times over.
  // Squared, within a dozen ulps; 1e-14 above it is above cos^2 B for sure, and moves the
  // bound certified by under 1e-12 degrees (1e-14 / (2 tan B) radians).
  double sine, cosine;
  portableSinCos((90 - degrees) * (portable::kPi / 180), sine, cosine);
  cos2_ = sine * sine * (1 + 1e-14);
}

bool AngleCheck::cornerBelow(const double* a, const double* b, const double* c) const {
  if (degrees_ >= 90) return dot2d(a, b, c) > 0;
  const double ux = b[0] - a[0], uy = b[1] - a[1], vx = c[0] - a[0], vy = c[1] - a[1];
  const double dot = ux * vx + uy * vy, lengths = (ux * ux + uy * uy) * (vx * vx + vy * vy);
  const double gap = dot * dot - cos2_ * lengths;
  if (gap > kFilter * lengths) return dot > 0;
  if (gap < -kFilter * lengths) return false;
  return dot2d(a, b, c) > 0 && cosineSquaredSign(a, b, c, cos2_) > 0;
}

bool AngleCheck::triangleBelow(const double* const p[3]) const {
  for (int k = 0; k < 3; ++k)
    if (!cornerBelow(p[k], p[(k + 1) % 3], p[(k + 2) % 3])) return false;
  return true;
}

bool meshBelow(const Mesh& mesh, const AngleCheck& check) {
  for (size_t t = 0; t < mesh.triangleCount(); ++t) {
    const double* p[3];
    for (int k = 0; k < 3; ++k) p[k] = &mesh.points[2 * size_t(mesh.triangles[3 * t + k])];
    if (!check.triangleBelow(p)) return false;
  }
  return true;
}

double tenthBound(double largest, const std::function<bool(double)>& below) {
  // The floating-point largest angle is off by far less than a tenth: the first tenth above it
  // is nearly always certified, the next one otherwise.
  for (int tenths = std::max(601, int(std::floor(largest * 10)) + 1); tenths < 900; ++tenths)
    if (below(tenths / 10.0)) return tenths / 10.0;
  return 90;
}

}  // namespace acutemesh::detail
