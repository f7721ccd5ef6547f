// Reading inputs and writing meshes in this field's common formats. Parsers take the text
// (so the same code serves files, the CLI, and the browser) and report errors as
// "NAME:LINE: what was expected"; nothing throws. A count that promises more items than the
// text holds is an error, never a huge allocation.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "acutemesh/acutemesh.h"

namespace acutemesh {

enum class InputFormat { Unknown, Poly, Node, JsonPslg, CgshopInstance };

struct Input {
  Pslg pslg;
  InputFormat format = InputFormat::Unknown;
  // For JSON input with "rings": the fill rule the file implies (rings have no hole points).
  bool hasRings = false;
  std::string instanceUid;  // CG:SHOP instance only
  std::vector<std::string> warnings;
};

struct ParseResult {
  bool ok = true;
  std::string message;  // "NAME:LINE: ..." when !ok
};

// Triangle's .poly: "<#vertices> <dim=2> <#attributes> <#markers>", vertex lines
// "<id> <x> <y> [attributes] [marker]", "<#segments> <#markers>", segment lines
// "<id> <a> <b> [marker]", "<#holes>", hole lines "<id> <x> <y>", optional regional
// attributes (ignored). '#' starts a comment. Indices are 0- or 1-based, as the first vertex id
// says. A vertex count of 0 means the vertices are in a separate .node file: pass its text as
// `nodeText` (the CLI reads BASE.node for that).
ParseResult parsePoly(std::string_view text, const std::string& name, Input& out,
                      std::string_view nodeText = {}, const std::string& nodeName = {});
ParseResult parseNode(std::string_view text, const std::string& name, Input& out);
// JSON: either an acutemesh PSLG {"vertices": [[x,y],...], "segments": [[i,j],...],
// "holes": [[x,y],...]} or {"rings": [[[x,y],...],...]} (closed rings, last point not
// repeated, become directed segments), or a CG:SHOP 2025 instance (has "points_x").
ParseResult parseJson(std::string_view text, const std::string& name, Input& out);

// Reads a file by extension (.poly, .node, .json); for a .poly without vertices it reads the
// .node file beside it.
ParseResult readInputFile(const std::string& path, Input& out);

// Writers return the text; writeMeshFiles writes BASE.EXT for each format.
std::string formatNode(const Mesh& m);
std::string formatEle(const Mesh& m);
std::string formatPoly(const Mesh& m);  // mesh vertices plus its segment edges
std::string formatJson(const Mesh& m);  // {"vertices": [[x,y]...], "triangles": [[a,b,c]...], "segments": [...]}
std::string formatOff(const Mesh& m);
std::string formatObj(const Mesh& m);
std::string formatSvg(const Mesh& m);

// formats: any of "node", "ele", "poly", "json", "off", "obj", "svg".
ParseResult writeMeshFiles(const Mesh& m, const std::string& base,
                           const std::vector<std::string>& formats);

}  // namespace acutemesh
