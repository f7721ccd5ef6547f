// The target: whether a triangle is good enough. Acute (every angle below the bound, exactly
// at 90 degrees), non-obtuse (no angle over 90, exactly), a minimum angle, a largest area,
// sizes (Options::maxEdge, Options::size, the regions' area bounds).
// Every step asks here; nothing else decides what "bad" means.
#pragma once

#include <cmath>
#include <cstdint>

#include "acutemesh/acutemesh.h"
#include "acutemesh/predicates.h"
#include "../size_field.h"
#include "geometry.h"
#include "params.h"
#include "state.h"

namespace acutemesh::detail {

// The corner of a triangle that most misses the target.
struct Corner {
  int k = -1;         // corner index in its triangle, -1 if the triangle meets the target
  bool large = true;  // a large angle (else a small angle or too large an area)
  bool area = false;  // too large an area (and no angle out of bounds)
};

// footCorners' flag for a triangle at a foot: its other corners must be sharper than 90
// degrees by kFootSlack (as cosines), for the foot's move to its exact place.
constexpr int kNearFoot = 8;

// kFootSlack for the angle at a between b and c, in the units of dot2d(a, b, c).
inline double footSlack(const double* a, const double* b, const double* c) {
  return kFootSlack * std::sqrt(dist2(a, b) * dist2(a, c));
}

class Target {
 public:
  explicit Target(const Options& options);

  bool acute = false, nonObtuse = false;
  bool feet = false;       // Options::exactFeet in a non-obtuse run
  bool strictMax = false;  // acute with a bound below 90 degrees, checked in floating point
  double cosMax = 0, cosMin = 1;
  double cosQuality = 1;  // of the angles quality points aim for (a little over minAngle)
  double minAngle = 0, maxArea = 0;
  Sizes sizes;  // maxEdge, the size field, the regions' area bounds (compiled: size_field.h)

  // An area bound or a size: refinement inserts circumcentres where they are missed.
  bool sized() const { return maxArea > 0 || sizes.any(); }

  // Acute or non-obtuse: a bound on the largest angle, where the point count is the score.
  bool boundsLargest() const { return acute || nonObtuse; }
  // Where the point count is the score, and the points not needed are removed and the mesh
  // polished: a largest-angle bound, or a smallest angle (quality mode) without sizes or with
  // Options::optimize (with sizes or an area bound most points are the sizes' own, and the
  // polish takes seconds where refinement takes milliseconds: only when asked for), unless
  // the quality mesh is only a start for another search (QualityRun::Start).
  bool countsPoints() const {
    return boundsLargest() || (qualityCounts && minAngle > 0 && (!sized() || searches));
  }
  bool qualityCounts = true;  // (refineWithStrategies' QualityRun)
  bool searches = false;      // Options::optimize asked for
  // The angle whose dot product (of its two edges) is d breaks the largest-angle bound at 90
  // degrees: obtuse for non-obtuse, right or obtuse for acute.
  bool tooLarge(double d) const { return nonObtuse ? d < 0 : d <= 0; }

  // The worst corner of the triangle p[0], p[1], p[2] (counter-clockwise). footCorners:
  // which corners stand for exact right angles (footCorners(s, t)).
  Corner worstCorner(const double* const p[3], int footCorners = 0) const;
  Corner worstCorner(const RefineState& s, uint32_t t) const {
    const uint32_t* v = &s.T.tri[3 * t];
    const double* p[3] = {s.P(v[0]), s.P(v[1]), s.P(v[2])};
    return worstCorner(p, feet ? footCorners(s, t) : 0);
  }
  // Bit k set: corner k of t is at a segment vertex standing for the altitude foot of a vertex
  // (RefineState::footOf), between a piece of its segment and the edge to that vertex.
  // kNearFoot set: some vertex of t stands for a foot.
  int footCorners(const RefineState& s, uint32_t t) const;
  // The triangle p[0], p[1], p[2] is larger than its area bound or size allows.
  bool tooBig(const double* const p[3]) const {
    return (maxArea > 0 && 0.5 * std::fabs(orient2d(p[0], p[1], p[2])) > maxArea) ||
           (sizes.any() && sizes.ratio(p[0], p[1], p[2]) > 1);
  }
  bool tooBig(const RefineState& s, uint32_t t) const {
    const uint32_t* v = &s.T.tri[3 * t];
    const double* p[3] = {s.P(v[0]), s.P(v[1]), s.P(v[2])};
    return tooBig(p);
  }
  // Triangle slot t is a triangle of the domain that misses the target.
  bool misses(const RefineState& s, uint32_t t) const {
    return s.T.inDomain(t) && worstCorner(s, t).k >= 0;
  }
  // Every triangle of the domain around vertex a meets the target.
  bool starMeets(const RefineState& s, uint32_t a) const;
  // Some triangle of the domain misses it.
  bool anyMissed(const RefineState& s) const;
};

// Inline: the hottest test of refinement and of the improvement rounds.
inline Corner Target::worstCorner(const double* const p[3], int footCorners) const {
  if (acute || nonObtuse) {
    if (!(footCorners & kNearFoot)) {
      // (The three corners at once, sharing their coordinate differences.)
      double d[3];
      cornerDots(p[0], p[1], p[2], d);
      for (int k = 0; k < 3; ++k)
        if (tooLarge(d[k])) return {k, true};
    } else {
      for (int k = 0; k < 3; ++k) {
        const double *a = p[k], *b = p[(k + 1) % 3], *c = p[(k + 2) % 3];
        const double d = dot2d(a, b, c), slack = footSlack(a, b, c);
        if ((footCorners >> k & 1) ? d < -slack : d < slack) return {k, true};
      }
    }
    if (acute && strictMax) {
      for (int k = 0; k < 3; ++k) {
        const double *a = p[k], *b = p[(k + 1) % 3], *c = p[(k + 2) % 3];
        double dot = (b[0] - a[0]) * (c[0] - a[0]) + (b[1] - a[1]) * (c[1] - a[1]);
        if (dot <= cosMax * std::sqrt(dist2(a, b) * dist2(a, c))) return {k, true};
      }
    }
  }
  if (minAngle > 0) {
    for (int k = 0; k < 3; ++k) {
      const double *a = p[k], *b = p[(k + 1) % 3], *c = p[(k + 2) % 3];
      double dot = (b[0] - a[0]) * (c[0] - a[0]) + (b[1] - a[1]) * (c[1] - a[1]);
      if (dot > cosMin * std::sqrt(dist2(a, b) * dist2(a, c))) return {k, false};
    }
  }
  if (tooBig(p)) return {0, false, true};
  return {};
}

}  // namespace acutemesh::detail
