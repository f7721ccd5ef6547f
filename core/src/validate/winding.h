// The fill rules' regions: under EvenOdd / NonZero every triangle must lie where the rule
// keeps the plane, and what lies beyond each boundary edge where it leaves it out.
#pragma once

#include "check.h"
#include "segment_walk.h"
#include "topology.h"

namespace acutemesh::validation {

// Checks the regions of EvenOdd / NonZero fill (nothing in Delaunay mode or with Triangle
// fill). Winding numbers are constant inside each triangle and change across an edge by the
// input segments along it, so one ray cast per connected piece of the mesh fixes them all.
// Checked only where they are defined: segments closing into cycles (NonZero), or meeting
// every point an even number of times (EvenOdd, where only parity counts).
void checkFillRule(const Check& c, const Topology& topo, const SegmentEdges& edges);

}  // namespace acutemesh::validation
