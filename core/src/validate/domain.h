// The meshed domain: where its boundary may run, and the points that must lie outside it.
// (The fill rules' regions are checked in winding.h.)
#pragma once

#include "check.h"
#include "query_grid.h"
#include "segment_walk.h"
#include "topology.h"
#include "vertices.h"

namespace acutemesh::validation {

// Logs each boundary edge that lies neither on an input segment (modes other than Delaunay)
// nor on the convex hull of the input vertices (where the domain is the hull).
void checkBoundaryEdges(const Check& c, const Topology& topo, const VertexMap& vertices,
                        const SegmentEdges& edges);

// The points to locate among the triangles: unused vertices without a used twin, and
// (Triangle fill) the hole points. Logs hole points that are not finite.
QueryGrid pointsToLocate(const Check& c, const Topology& topo, const VertexMap& vertices);

// Logs unused vertices that lie in a triangle, and hole points (Triangle fill) inside a
// triangle or on an unconstrained edge between two.
void locatePoints(const Check& c, const Topology& topo, const SegmentEdges& edges,
                  const QueryGrid& points);

}  // namespace acutemesh::validation
