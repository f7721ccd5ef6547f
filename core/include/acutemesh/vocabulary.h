// The names of acutemesh's enums, written once: the CLI's options and help, the JavaScript
// package (its argument checks, its types, the tables it exports as `vocabulary`) and the web
// page all read them from here. Each table lists every value of its enum with the name the
// CLI and JavaScript spell it by and a one-line description; tables are in enum order.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "acutemesh/acutemesh.h"

namespace acutemesh {

// The kind of text an Input was read from (io.h).
enum class InputFormat { Unknown, Poly, Node, JsonPslg, CgshopInstance };

// What a mesh can be written as (io.h: formatMesh, writeMeshFiles, formatCgshopSolution).
enum class OutputFormat { Node, Ele, Poly, Edge, Neigh, Json, Off, Obj, Svg, Msh, Msh2, Vtu, Cgshop };

template <class Enum>
struct Named {
  Enum value;
  const char* name;         // as the CLI and the JavaScript package spell it
  const char* description;  // one line, for help texts and menus
};

inline constexpr Named<Mode> kModes[] = {
    {Mode::Delaunay, "delaunay", "Delaunay triangulation of the vertices (segments, holes ignored)"},
    {Mode::Cdt, "cdt", "constrained Delaunay triangulation of the domain"},
    {Mode::Quality, "quality",
     "refine until every angle >= the min angle and every area <= the max area (min angle 20 "
     "when neither is given)"},
    {Mode::NonObtuse, "nonobtuse", "refine until every angle <= 90 degrees (certified)"},
    {Mode::Acute, "acute", "refine until every angle < the max angle (default 90; certified)"},
};

inline constexpr Named<FillRule> kFillRules[] = {
    {FillRule::Triangle, "triangle",
     "Triangle's rule: the convex hull minus what is reachable from outside or from a hole "
     "point without crossing a segment"},
    {FillRule::EvenOdd, "evenodd", "regions inside an odd number of rings (the default for JSON rings)"},
    {FillRule::NonZero, "nonzero", "regions with non-zero winding number (segments are directed)"},
};

inline constexpr Named<Status> kStatuses[] = {
    {Status::Ok, "ok", "the mesh meets the target"},
    {Status::TargetNotMet, "target-not-met", "a budget ended or the target cannot be met: the best mesh so far"},
    {Status::BadInput, "bad-input", "malformed or degenerate input; the message says which item"},
    {Status::Cancelled, "cancelled", "stopped by Options::cancel: the best mesh so far"},
};

inline constexpr Named<VertexKind> kVertexKinds[] = {
    {kInputVertex, "input", "copied from the input"},
    {kUnusedVertex, "unused", "an input vertex no triangle uses (a duplicate, or outside the domain)"},
    {kSegmentVertex, "segment", "a Steiner point on an input segment"},
    {kFreeVertex, "free", "a Steiner point on no input segment"},
};

inline constexpr Named<InputFormat> kInputFormats[] = {
    {InputFormat::Unknown, "unknown", "not read from a file: no input policy applies"},
    {InputFormat::Poly, "poly", "Triangle's .poly"},
    {InputFormat::Node, "node", "Triangle's .node (a point set)"},
    {InputFormat::JsonPslg, "json", "acutemesh JSON: a PSLG, or rings"},
    {InputFormat::CgshopInstance, "cgshop", "a CG:SHOP 2025 instance (JSON)"},
};

struct OutputFormatInfo {
  OutputFormat value;
  const char* name;
  const char* extension;    // appended to the base name, dot included
  const char* mediaType;    // for downloads
  bool roundsExactPoints;   // holds coordinates as doubles: Mesh::exactPoints come out rounded
  bool needsInstance;       // the CG:SHOP instance's uid and size, not the mesh alone
  const char* description;
};

inline constexpr OutputFormatInfo kOutputFormats[] = {
    {OutputFormat::Node, "node", ".node", "text/plain", true, false,
     "Triangle's .node: the vertices and their boundary markers"},
    {OutputFormat::Ele, "ele", ".ele", "text/plain", false, false,
     "Triangle's .ele: the triangles (and their region attributes)"},
    {OutputFormat::Poly, "poly", ".poly", "text/plain", true, false,
     "Triangle's .poly: the vertices and the edges on input segments, with markers"},
    {OutputFormat::Edge, "edge", ".edge", "text/plain", false, false,
     "Triangle's .edge: every edge with its boundary marker"},
    {OutputFormat::Neigh, "neigh", ".neigh", "text/plain", false, false,
     "Triangle's .neigh: each triangle's three neighbours"},
    {OutputFormat::Json, "json", ".json", "application/json", false, false,
     "acutemesh JSON: vertices, triangles, segment edges and exact points"},
    {OutputFormat::Off, "off", ".off", "text/plain", true, false, "OFF (z = 0)"},
    {OutputFormat::Obj, "obj", ".obj", "model/obj", true, false, "Wavefront OBJ (z = 0)"},
    {OutputFormat::Svg, "svg", ".svg", "image/svg+xml", true, false, "an SVG picture of the mesh"},
    {OutputFormat::Msh, "msh", ".msh", "text/plain", true, false,
     "Gmsh MSH 4.1: regions and markers as physical groups"},
    // BASE.v2.msh: beside BASE.msh, and still .msh for the readers that go by extension.
    {OutputFormat::Msh2, "msh2", ".v2.msh", "text/plain", true, false,
     "Gmsh MSH 2.2 (older tools): regions and markers as physical groups"},
    {OutputFormat::Vtu, "vtu", ".vtu", "application/xml", true, false,
     "VTK XML unstructured grid (ParaView): markers and attributes as cell and point data"},
    {OutputFormat::Cgshop, "cgshop", ".solution.json", "application/json", false, true,
     "a CG:SHOP 2025 solution (CG:SHOP input only)"},
};

// The name of a value ("?" for a number outside its enum).
const char* nameOf(Mode value);
const char* nameOf(FillRule value);
const char* nameOf(Status value);
const char* nameOf(VertexKind value);
const char* nameOf(InputFormat value);
const char* nameOf(OutputFormat value);
const OutputFormatInfo& infoOf(OutputFormat value);

// Looks a name up (exactly, case and all): true and `out` set when found. Otherwise false,
// and `message` (when given) says so with the names to choose from and the nearest one when a
// slip of a letter or two explains the difference:
//   unknown mode 'non-obtuse' (delaunay, cdt, quality, nonobtuse, acute): did you mean 'nonobtuse'?
bool parseName(std::string_view name, Mode& out, std::string* message = nullptr);
bool parseName(std::string_view name, FillRule& out, std::string* message = nullptr);
bool parseName(std::string_view name, InputFormat& out, std::string* message = nullptr);
bool parseName(std::string_view name, OutputFormat& out, std::string* message = nullptr);

}  // namespace acutemesh
