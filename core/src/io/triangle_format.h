// Triangle's .node and .poly readers: parsePoly and parseNode (acutemesh/io.h), and what
// readInputFile needs to know before it parses a .poly.
#pragma once

#include <string_view>

namespace acutemesh::io {

// True if the first content line of a .poly starts with a vertex count of 0 (its vertices
// are in the .node file beside it).
bool polyHasNoVertices(std::string_view text);

}  // namespace acutemesh::io
