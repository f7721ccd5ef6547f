// The half-edge twins of an output mesh, shared by adjacency() and the output labels
// (labels.h), so that a mesh asked for both finds them once.
#pragma once

#include <cstdint>
#include <vector>

#include "acutemesh/acutemesh.h"

namespace acutemesh::detail {

struct HalfEdges {
  std::vector<int32_t> twin;         // per half-edge 3t + k: its twin, -1 on the boundary
  std::vector<int32_t> segmentEdge;  // per Mesh::segments edge: a half-edge on it, -1 none
};

HalfEdges halfEdges(const Mesh& mesh);

// adjacency(mesh) from its half-edges (halfEdges(mesh)).
Adjacency adjacency(const Mesh& mesh, HalfEdges&& h);

}  // namespace acutemesh::detail
