// Candidate Steiner points for a bad triangle t (Erten & Üngör, section 2.1). With pq the
// shortest edge of t, slice(pq) is the part of t's circumdisk between the perpendiculars to
// pq at p and q; its point farthest from every vertex lies on the Voronoi diagram, so the
// candidates are the Voronoi vertices (circumcentres) met walking from t's circumcentre.
// Quality refinement's candidates are the seed authors' locally optimal Steiner points.
#pragma once

#include <cstdint>

#include "geometry.h"
#include "state.h"

namespace acutemesh::detail {

// The points of slice(pq), farthest from all vertices first; with wholeDisk (where candidates
// are weighed, Strategy::weighPoints) those of t's whole circumdisk compete.
void slicePoints(const RefineState& s, uint32_t t, bool wholeDisk, Candidates& out);

// For t, which has an angle under the bound (cosBound: the cosine of the angle aimed for):
// points where p, q, x would make a triangle with every angle at least that, inside t's
// circumdisk (so that t goes), farthest from all vertices first. Üngör's off-centre (on pq's
// bisector where the angle at x is a little over the bound; the circumcentre if that is
// nearer to pq) and the Voronoi vertices met walking from t's circumcentre inside its
// circumdisk. (Circumcentres alone, as Ruppert's, stop terminating near 34 degrees.)
void qualityPoints(const RefineState& s, uint32_t t, double cosBound, Candidates& out);

}  // namespace acutemesh::detail
