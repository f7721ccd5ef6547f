// Every input segment must be a chain of mesh edges, and Mesh::segments must list exactly
// those edges. The walk that checks this also tells the domain checks which edges and
// vertices lie on segments.
#pragma once

#include <cstdint>
#include <vector>

#include "check.h"
#include "topology.h"
#include "vertices.h"

namespace acutemesh::validation {

// What the walks found. A canonical half-edge stands for its undirected edge
// (Topology::canon); in Delaunay mode nothing is walked and every entry is zero / kNone.
struct SegmentEdges {
  std::vector<uint32_t> marked;     // per canonical half-edge: walks along it (0: on no segment)
  std::vector<uint8_t> listed;      // per canonical half-edge: in Mesh::segments
  std::vector<int32_t> segCount;    // per canonical half-edge: segments along it minus against
  std::vector<uint32_t> onSegment;  // per vertex: an input segment through it, or kNone

  explicit SegmentEdges(const Topology& topo)
      : marked(3 * size_t(topo.T), 0),
        listed(3 * size_t(topo.T), 0),
        segCount(3 * size_t(topo.T), 0),
        onSegment(topo.n, kNone) {}
};

// Walks each input segment of non-zero length from end to end along mesh edges (see
// SegmentWalker) and matches the walks against Mesh::segments; logs each segment that is no
// chain of mesh edges and each listed edge on no segment, or missing from the list.
SegmentEdges walkSegments(const Check& c, const Topology& topo, const VertexMap& vertices);

}  // namespace acutemesh::validation
