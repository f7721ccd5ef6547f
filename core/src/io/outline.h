// What a PSLG written from a mesh (.poly, JSON) needs besides the mesh's segment edges to read
// back as the mesh's own domain under fill 'triangle': every boundary edge as a segment, and a
// point inside each hole.
#pragma once

#include <cstdint>
#include <vector>

#include "acutemesh/acutemesh.h"

namespace acutemesh::io {

struct Outline {
  // a, b per boundary edge of the mesh that is not among its segment edges (the hull edges a
  // convexHull or Delaunay mesh has), the mesh on its left.
  std::vector<uint32_t> boundary;
  // x, y per hole: a point strictly inside each bounded region of the plane outside the mesh.
  std::vector<double> holes;
};

// The outline of a valid mesh (triangles counter-clockwise, no two overlapping). For other
// meshes it is a best effort: an edge or region it cannot place gets nothing.
Outline outlineOf(const Mesh& m);

}  // namespace acutemesh::io
