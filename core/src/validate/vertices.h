// The checks on arrays and vertices: lengths, indices, finite coordinates, input vertices
// copied exactly, used and duplicate vertices, and each vertex's kind.
#pragma once

#include <cstdint>
#include <vector>

#include "acutemesh/acutemesh.h"
#include "check.h"
#include "error_log.h"
#include "topology.h"

namespace acutemesh::validation {

// Checks the arrays' lengths and indices, that every coordinate is finite, and that the
// mesh starts with the input vertices, exactly. False if the arrays cannot be read as a mesh
// (no later check runs then).
bool checkSizes(const Pslg& in, const Mesh& m, ErrorLog& log);

// How mesh vertices relate to input vertices and to each other.
struct VertexMap {
  std::vector<uint8_t> used;  // per vertex: some triangle uses it
  // Per input vertex: the used mesh vertex at its coordinates (itself when used), or kNone.
  // Segment endpoints go by it: a duplicate input vertex stands for its used twin.
  std::vector<uint32_t> rep;
  // Per unused vertex: the used vertex at the same coordinates, or kNone.
  std::vector<uint32_t> twinOfUnused;
};

// Logs used vertices at the same point, an unused input vertex whose duplicate the mesh
// used instead of it, and unused vertices where the whole convex hull is meshed.
VertexMap mapVertices(const Check& c, const Topology& topo);

// Logs vertices whose Mesh::vertexKind disagrees with what the checks found: whether input
// vertices are used, and (onSegment, per vertex: an input segment through it, or kNone)
// whether Steiner points lie on an input segment.
void checkKinds(const Check& c, const Topology& topo, const VertexMap& vertices,
                const std::vector<uint32_t>& onSegment);

}  // namespace acutemesh::validation
