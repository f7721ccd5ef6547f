// Reading inputs and writing meshes in this field's common formats. Parsers take the text
// (so the same code serves files, the CLI, and the browser) and report errors as
// "NAME:LINE: expected ..., found ..."; nothing throws. A count that promises more items than
// the text holds is an error, never a huge allocation. LINE is 1-based; an item missing at the
// end of the text is reported at the line where the text ends. Non-finite coordinates (nan,
// inf, or beyond the double range) are errors. Parsers fill `out` only on success (replacing
// its contents); things tolerated are reported in Input::warnings, also as "NAME:LINE: ...".
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "acutemesh/acutemesh.h"
#include "acutemesh/vocabulary.h"  // InputFormat, OutputFormat and their names

namespace acutemesh {

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
// attributes "<#regions>", region lines "<id> <x> <y> <attribute> [maximum area]" (into
// Pslg::regions; a negative or missing area is none, 0, as in Triangle). '#' starts a
// comment; blank lines are skipped. Indices are 0- or 1-based, as the first vertex id says
// (another first id: 1-based, with a warning, as Triangle does); segment endpoints come out
// 0-based. Vertex and segment markers (32-bit integers) go to Pslg::vertexMarkers and
// segmentMarkers when the header announces them (a marker left out is 0, as Triangle allows;
// none announced: the array stays empty); vertex attributes are ignored, and may be left out;
// more fields than the header announces is an error. The hole section may be missing at the end (no holes). A vertex count of 0 means
// the vertices are in a separate .node file: pass its text as `nodeText` and its name as
// `nodeName` (readInputFile reads BASE.node for that).
ParseResult parsePoly(std::string_view text, const std::string& name, Input& out,
                      std::string_view nodeText = {}, const std::string& nodeName = {});
ParseResult parseNode(std::string_view text, const std::string& name, Input& out);
// JSON (strict RFC 8259 syntax, nesting depth limited): one top-level object, either
//  - an acutemesh PSLG {"vertices": [[x,y],...], "segments": [[i,j],...], "holes": [[x,y],...]}
//    (segments, holes optional; "triangles" and "exactPoints", as formatJson writes them,
//    are ignored), with optional "vertexMarkers": [m,...] (one per vertex) and
//    "segmentMarkers": [m,...] (one per segment), 32-bit integers, or
//  - {"rings": [[[x,y],...],...]}: each ring closes implicitly (a repeated first point at the
//    end is dropped, with a warning) and becomes vertices plus directed segments in ring
//    order; sets Input::hasRings; optional "ringMarkers": [m,...] (one per ring) gives each
//    ring's segments that marker, or
//  Both may have "regions": [[x, y, attribute], or [x, y, attribute, maxArea], ...]
//  (Pslg::regions; maxArea >= 0, 0 none). Or
//  - a CG:SHOP 2025 instance ("points_x", "points_y", "region_boundary" (a ring of indices,
//    becomes segments), "additional_constraints" (index pairs), "instance_uid", "num_points").
// Keys of different kinds may not be mixed; unknown keys are skipped with a warning.
ParseResult parseJson(std::string_view text, const std::string& name, Input& out);

// A size file (Options::size; the CLI's --size): a JSON object with
//  - "grid": {"x0", "y0", "dx", "dy": numbers, "nx", "ny": counts, "h": nx * ny sizes, row
//    by row from (x0, y0)}: SizeField::grid, and/or
//  - "points": [[x, y, size], ...]: SizeField::points and sizes.
// Sizes must be > 0. Fills the grid and the points of `out` only on success.
ParseResult parseSizeField(std::string_view text, const std::string& name, SizeField& out,
                           std::vector<std::string>* warnings = nullptr);
// Sizes at points as a Triangle .node: each vertex's first attribute is its size (> 0), into
// SizeField::points and sizes (the "points" of a size file).
ParseResult parseSizeNode(std::string_view text, const std::string& name, SizeField& out,
                          std::vector<std::string>* warnings = nullptr);
// A size file by extension: .json (parseSizeField) or .node (parseSizeNode).
ParseResult readSizeFile(const std::string& path, SizeField& out,
                         std::vector<std::string>* warnings = nullptr);

// Reads a file by extension (.poly, .node, .json, any case); for a .poly without vertices it
// reads BASE.node beside it. Messages name the file by `path`; an unreadable file gives
// "PATH: cannot open (reason)".
ParseResult readInputFile(const std::string& path, Input& out);

// Writers return the text. Coordinates are written to read back as the same doubles
// (shortest round-trip form). .node/.ele/.poly/.edge/.neigh number vertices and items from 0
// (as Triangle's -z), which their first line states as a comment; OBJ and Gmsh are 1-based by
// definition. .poly and JSON read back (parsePoly, parseJson, fill 'triangle') as the mesh's
// own domain: they hold the mesh vertices, the mesh's segment edges followed by its boundary
// edges on no input segment (the hull edges of a convexHull or Delaunay mesh), and a hole
// point strictly inside each bounded region outside the mesh (finding them costs a
// constrained triangulation of the mesh's vertices when there are holes). OFF, OBJ, MSH and
// VTU put z = 0. SVG fits the bounding box into a 1000-unit view with y pointing up
// (coordinates rounded to 0.01), triangles in one path, segment edges drawn thicker.
// writeMeshFiles writes BASE.EXT for each format (EXT = OutputFormatInfo::extension: the
// format's name, but BASE.v2.msh for msh2); an unknown name fails before anything is written.
//
// Markers and attributes. Every writer that has markers writes them whether or not the mesh
// carries them: Mesh::vertexMarkers / segmentMarkers when they hold one per item, else 0; in
// both cases a zero marker on the mesh's boundary becomes 1 (Triangle's rule, as adjacency()
// gives its edgeMarkers). The region attribute Mesh::triangleAttributes is written when it
// holds one finite number per triangle, and not at all otherwise. The "lines" of MSH and VTU are the mesh's
// segment edges in order, then its boundary edges on no input segment (marker 1), so that
// every boundary edge is among them.
std::string formatNode(const Mesh& m);  // "<#v> 2 0 1": "i x y marker"
std::string formatEle(const Mesh& m);   // "<#t> 3 0", or "<#t> 3 1" with "i a b c attribute"
// mesh vertices (with markers), segment and boundary edges ("<#s> 1": "i a b marker", the
// boundary edges on no segment 1), holes
std::string formatPoly(const Mesh& m);
// Triangle's .edge: "<#edges> 1", then "i a b marker" for every edge of the mesh, as
// adjacency() lists them (a < b, sorted; 0 inside, a boundary edge's zero marker 1).
std::string formatEdge(const Mesh& m);
// Triangle's .neigh: "<#triangles> 3", then "i n0 n1 n2": nk the triangle opposite corner k
// across the edge they share, -1 for none.
std::string formatNeigh(const Mesh& m);
// {"vertices": [[x,y]...], "triangles": [[a,b,c]...], "segments": [...]}, "holes": [[x,y]...]
// when the mesh has holes (segments and holes as in .poly); "vertexMarkers": [m...] (one per
// vertex) and "segmentMarkers": [m...] (one per "segments" entry) when some marker is not the
// one a mesh without markers gets (1 on the boundary, 0 elsewhere: a reader without the keys
// gives those); "triangleAttributes": [a...] (one per triangle) when the mesh has them; and
// when the mesh has exact points (Options::exactFeet) "exactPoints": [[vertex, "x", "y"]...]
// (decimal rationals "p/q" or integers "p": the exact place of those vertices).
std::string formatJson(const Mesh& m);
std::string formatOff(const Mesh& m);
std::string formatObj(const Mesh& m);
std::string formatSvg(const Mesh& m);
// Gmsh MSH 4.1 ASCII ($MeshFormat 4.1 0 8, $PhysicalNames, $Entities, $Nodes, $Elements).
// Nodes: every vertex, unused ones too, node tag = vertex index + 1 (so indices agree with
// .node), in one block on surface 1. Elements: triangle i is element i + 1 (type 2), line j
// element T + j + 1 (type 1, 2-node), one block per entity. Entities: one surface per distinct
// region attribute in increasing order (one when the mesh has none), one curve per distinct
// line marker in increasing order. Physical groups, named in $PhysicalNames: per attribute
// a 2D group "attribute A" (tag A when A is a positive integer up to 2^31 - 1, else numbered
// after the largest such tag), or one group 1 "domain" without attributes (tools that keep
// only physical elements keep the triangles); per marker a 1D group "marker M" (tag M when
// positive, else -- 0, on inner segments without a marker, and negative markers -- numbered
// after the largest positive one). Every element is in a physical group.
std::string formatMsh(const Mesh& m);
// Gmsh MSH 2.2 ASCII: the same nodes, elements, tags and $PhysicalNames as formatMsh, each
// element with two tags: its physical group and its entity (elementary) tag.
std::string formatMsh2(const Mesh& m);
// VTK XML UnstructuredGrid, ASCII: every vertex a point (z = 0), the triangles (VTK_TRIANGLE)
// then the lines (VTK_LINE) as cells. PointData "marker" (Int32, per vertex); CellData
// "marker" (Int32: the line's, 0 for triangles) and, when the mesh has them, "attribute"
// (Float64: the triangle's, 0 for lines).
std::string formatVtu(const Mesh& m);

// The CG:SHOP 2025 solution of a mesh of a CG:SHOP instance with `instanceVertexCount` points
// (Input::pslg.vertexCount()), as the challenge's verifier (pyutils25) reads it:
// {"content_type": "CG_SHOP_2025_Solution", "instance_uid": UID, "steiner_points_x": [...],
// "steiner_points_y": [...], "edges": [[i,j],...]}. Steiner points are the mesh vertices from
// index instanceVertexCount on that a triangle uses, in index order; the k-th is numbered
// instanceVertexCount + k in "edges", instance vertices keep their index. Each coordinate is
// exact: a JSON integer when the double is one (any size; -0 is 0), else the string "p/q" in
// lowest terms (q a power of two); a vertex in m.exactPoints as its exact rational (a JSON
// integer, or "p/q"; a text there that is no rational leaves the double). "edges" holds every undirected edge of every triangle once,
// as [smaller, larger] sorted. The verifier adds the region boundary and constraints itself
// and rejects isolated points, so an unused instance vertex (a duplicate, or one outside the
// region) makes the solution invalid; this writes it anyway.
std::string formatCgshopSolution(const Mesh& m, const std::string& instanceUid,
                                 size_t instanceVertexCount);

// The writer of `format` above (formatNode ... formatVtu); empty for OutputFormat::Cgshop,
// which needs the instance (formatCgshopSolution).
std::string formatMesh(OutputFormat format, const Mesh& m);

// formats: names of kOutputFormats that need no instance ("node", "ele", ... "svg").
ParseResult writeMeshFiles(const Mesh& m, const std::string& base,
                           const std::vector<std::string>& formats);

// Options the caller chose on purpose, which the input policy leaves as they are.
struct ChosenOptions {
  bool fill = false;
  bool exactFeet = false;
};

// What an input's kind implies for meshing it, applied alike for every caller (the CLI, the
// JavaScript package's mesh() of a parsed input):
//  - JSON rings have no hole points: their regions are found by nesting, fill EvenOdd;
//  - a CG:SHOP 2025 instance is checked by an exact verifier, so exactSegments is on (a split
//    point a rounding off its segment would leave a sliver), and its solutions hold
//    rationals, so exactFeet is on.
// Options in `chosen` stay as they are; exactSegments is only ever turned on.
void applyInputPolicy(InputFormat format, bool hasRings, const ChosenOptions& chosen,
                      Options& options);
inline void applyInputPolicy(const Input& in, const ChosenOptions& chosen, Options& options) {
  applyInputPolicy(in.format, in.hasRings, chosen, options);
}

}  // namespace acutemesh
