// Output labels: the boundary markers and region attributes of a finished mesh, by Triangle's
// rules (acutemesh.h: Mesh::vertexMarkers, segmentMarkers, triangleAttributes). They are
// found on the assembled output mesh, whichever way it was made (whole or by parts), so the
// rules live here once.
#pragma once

#include <string>
#include <vector>

#include "acutemesh/acutemesh.h"
#include "adjacency.h"

namespace acutemesh::detail {

// Fills mesh.vertexMarkers, mesh.segmentMarkers and mesh.triangleAttributes for a mesh of
// `input` (with mesh.segmentInput filled; input and mesh at the same scale). The twins in
// mesh.adjacency.halfedges, when mesh() left them there, are taken (and the adjacency
// cleared); otherwise they are found. A region point in
// no triangle is ignored with a warning naming it as `reported` (the caller's input) has it.
// Returns the mesh's half-edges, which Options::adjacency reuses.
HalfEdges labelMesh(const Pslg& input, const Pslg& reported, Mesh& mesh,
                    std::vector<std::string>& warnings);

}  // namespace acutemesh::detail
