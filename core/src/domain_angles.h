// The corners of the domain, and the floor they set for the largest angle of any mesh of it.
// Bishop ("Optimal triangulation of polygons", 2021): a domain whose smallest corner is theta
// has a triangulation with every angle at most 90 - min(36, theta) / 2. For theta < 36 none
// has every angle below that (the corner's own triangles); for theta >= 36 the floor is 72,
// which some domains need and others (an equilateral triangle) do not. A corner is measured on
// the side where the triangles are: a reflex notch of a letter is 300 degrees, not 60.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "acutemesh/acutemesh.h"
#include "triangulation.h"

namespace acutemesh::detail {

// The smallest corner of the domain (degrees) of T (T.inside marks it): at each vertex, the
// angle of the domain between two consecutive walls (fixed edges, and edges between the
// domain and the rest), summed over the domain's triangles there. 360 where no corner exists
// (a vertex with one wall or none, an empty domain).
double smallestDomainAngle(const Triangulation& T);

// A corner of the domain at T's vertex `vertex`, of `degrees`.
struct DomainCorner {
  uint32_t vertex;
  double degrees;
};

// The domain's corners of at most `degrees`, the smallest at each vertex, smallest first: the
// vertices a message about thin corners names.
std::vector<DomainCorner> domainCornersBelow(const Triangulation& T, double degrees);

// The domain's thin corners (under kNamedCorner degrees), taken before refinement, for
// messages that say which input vertices a target fails at, so a user can fix the data.
// inputOf maps T's vertices to input vertices (a vertex beyond it is a segment crossing);
// coordinates are reported times 2^exponent (mesh() scales some inputs for meshing).
class NamedCorners {
 public:
  static constexpr double kNamedCorner = 60;
  NamedCorners() = default;
  // `slivers`: segment ends a hair off a segment (T's vertex, the input segment; NearEnds::close).
  NamedCorners(const Triangulation& T, const std::vector<uint32_t>& inputOf, int exponent,
               const Pslg& input, const std::vector<std::pair<uint32_t, uint32_t>>& slivers);
  // A coordinate of T (or of the mesh before it is scaled back), as the caller gave it.
  double reported(double x) const { return std::ldexp(x, exponent_); }
  // "input vertex 7 (0.5, 2), 20 degrees", the corners of at most `degrees` (the smallest
  // `most` of them, then "N in all"); empty if none.
  std::string below(double degrees, size_t most) const;
  // The corners nearest the points xy (x, y per point, as reported), each named once; a sliver
  // end nearer than any corner is named instead.
  std::string nearest(const std::vector<double>& xy) const;

 private:
  struct Named {
    uint32_t input;  // kNone: a segment crossing
    double x, y, degrees;
  };
  struct Sliver {
    uint32_t input, segment;
    double x, y, off;
  };
  std::string name(const Named& c) const;
  std::string name(const Sliver& s) const;
  std::vector<Named> corners_;  // smallest first
  std::vector<Sliver> slivers_;
  int exponent_ = 0;
};

// The floor for a largest angle, for a domain whose smallest corner is `corner` degrees: above
// 72, every mesh of it has an angle of at least this.
inline double angleFloor(double corner) { return 90 - std::min(36.0, corner) / 2; }

}  // namespace acutemesh::detail
