// The corners of the domain, and the floor they set for the largest angle of any mesh of it.
// Bishop ("Optimal triangulation of polygons", 2021): a domain whose smallest corner is theta
// has a triangulation with every angle at most 90 - min(36, theta) / 2. For theta < 36 none
// has every angle below that (the corner's own triangles); for theta >= 36 the floor is 72,
// which some domains need and others (an equilateral triangle) do not. A corner is measured on
// the side where the triangles are: a reflex notch of a letter is 300 degrees, not 60.
#pragma once

#include <algorithm>

#include "triangulation.h"

namespace acutemesh::detail {

// The smallest corner of the domain (degrees) of T (T.inside marks it): at each vertex, the
// angle of the domain between two consecutive walls (fixed edges, and edges between the
// domain and the rest), summed over the domain's triangles there. 360 where no corner exists
// (a vertex with one wall or none, an empty domain).
double smallestDomainAngle(const Triangulation& T);

// The floor for a largest angle, for a domain whose smallest corner is `corner` degrees: above
// 72, every mesh of it has an angle of at least this.
inline double angleFloor(double corner) { return 90 - std::min(36.0, corner) / 2; }

}  // namespace acutemesh::detail
