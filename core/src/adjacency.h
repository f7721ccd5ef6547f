// The half-edge twins of an output mesh, shared by adjacency() and the output labels
// (labels.h), so that a mesh asked for both finds them once. mesh() knows them from its store
// (extractMesh, the parts' assembly) and hands them over in Mesh::adjacency.halfedges; any
// other mesh has them found from its triangles.
#pragma once

#include <cstdint>
#include <vector>

#include "acutemesh/acutemesh.h"

namespace acutemesh::detail {

struct HalfEdges {
  std::vector<int32_t> twin;         // per half-edge 3t + k: its twin, -1 on the boundary
  std::vector<int32_t> segmentEdge;  // per Mesh::segments edge: a half-edge on it, -1 none
};

// The mesh's half-edges: `twin` as given when it has one per half-edge, else found from the
// triangles.
HalfEdges halfEdges(const Mesh& mesh, std::vector<int32_t> twin = {});

// adjacency(mesh) from its half-edges (halfEdges(mesh)).
Adjacency adjacency(const Mesh& mesh, HalfEdges&& h);

}  // namespace acutemesh::detail
