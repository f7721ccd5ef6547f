// acutemesh: Delaunay, constrained Delaunay and acute/non-obtuse triangulation of planar
// straight-line graphs. One entry point, `mesh()`, flat arrays in and out.
//
// Conventions shared by every function in this header:
//  - Coordinates are interleaved doubles: x0, y0, x1, y1, ...
//  - Index lists are flat uint32: segments a0, b0, a1, b1, ...; triangles a, b, c, ... (CCW).
//  - Mesh vertex i equals input vertex i for every i < input vertex count (exact copy), so
//    input indices stay valid in the output. A duplicate input vertex, or one outside the
//    domain, is kept at its index but used by no triangle. Steiner points follow the input.
//  - Nothing throws and nothing aborts: failures come back as a Status with a message.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace acutemesh {

// Process exit codes of the CLI use the same numbers.
enum class Status : int {
  Ok = 0,
  TargetNotMet = 1,  // a budget ended first; the best mesh so far is returned
  BadInput = 2,      // malformed or degenerate input; message says which item and why
  Cancelled = 3,     // Options::cancel was set; the best mesh so far is returned
};

enum class Mode {
  Delaunay,   // Delaunay triangulation of the vertices; segments and holes ignored
  Cdt,        // constrained Delaunay triangulation of the PSLG, restricted to its domain
  Quality,    // refine until every angle >= minAngle and area <= maxArea (minAngle
              // kQualityDefaultMinAngle when no minAngle, maxArea or size is given)
  NonObtuse,  // refine until every angle <= 90 degrees (exact)
  Acute,      // refine until every angle < maxAngle (default 90), certified exactly
};

// Which triangles of the constrained triangulation form the domain.
enum class FillRule {
  Triangle,  // Triangle's semantics: remove from the convex hull inward up to segments, then
             // remove the regions containing hole points.
  EvenOdd,   // keep regions whose winding number (segments as directed edges a->b) is odd
  NonZero,   // keep regions whose winding number is non-zero
};

// A region of the domain (Triangle's regional attributes): every triangle reachable from the
// point (x, y) without crossing a segment. A later region reaching the same triangles wins,
// as in Triangle. A point outside the domain is ignored (with a warning).
struct Region {
  double x = 0, y = 0;
  double attribute = 0;  // given to the region's triangles (Mesh::triangleAttributes)
  double maxArea = 0;    // area bound inside the region (0 = none); Options::maxArea still holds
};

// A planar straight-line graph. Segments may cross, overlap, touch vertices or have zero
// length: mesh() resolves all of these (see Stats::warnings).
struct Pslg {
  std::vector<double> points;      // x, y per vertex
  std::vector<uint32_t> segments;  // a, b per segment (directed a->b: matters for NonZero)
  std::vector<double> holes;       // x, y per hole seed point (FillRule::Triangle only;
                                   // the other rules find holes by nesting)
  // Boundary markers (Triangle's): empty, or one per vertex / per segment. They come back in
  // Mesh::vertexMarkers and Mesh::segmentMarkers.
  std::vector<int32_t> vertexMarkers;
  std::vector<int32_t> segmentMarkers;
  std::vector<Region> regions;

  size_t vertexCount() const { return points.size() / 2; }
  size_t segmentCount() const { return segments.size() / 2; }
};

struct Progress {
  const char* phase;     // "delaunay", "segments", "domain", "refine", "improve", "output"
  double fraction;       // 0..1 within the phase, or -1 when unknown
  uint32_t vertices;     // current vertex count
};

// Quality mode's minimum angle when no minAngle, maxArea, maxEdge or size is given (Triangle's -q).
constexpr double kQualityDefaultMinAngle = 20.0;

// The size of the mesh's edges over the plane: h(x, y) is the longest an edge may be near
// (x, y) (a triangle is too large when its longest edge exceeds h at its centroid). Every
// source given counts; where several do, the smallest size holds. Sizes must be positive
// (+infinity: no bound there).
struct SizeField {
  // Called from the threads refinement runs on (Options::threads): it must be safe to call
  // concurrently, and should be cheap (it is called for every triangle refinement looks at).
  std::function<double(double x, double y)> function;
  // A grid of sizes: h[i + nx * j] at (x0 + i * dx, y0 + j * dy), bilinear in between, the
  // nearest border value outside. nx, ny >= 1; dx, dy > 0 (or any, for a single row/column).
  struct Grid {
    double x0 = 0, y0 = 0, dx = 1, dy = 1;
    uint32_t nx = 0, ny = 0;
    std::vector<double> h;
  } grid;
  // Sizes at scattered points (x, y per point in `points`, one size each in `sizes`): linear
  // over the points' Delaunay triangulation, the nearest hull edge's value outside it.
  std::vector<double> points, sizes;
  // The largest area a triangle may have, at its centroid (as Region::maxArea, anywhere);
  // called as `function` is. Not limited by Options::grading.
  std::function<double(double x, double y)> maxArea;

  bool empty() const { return !function && grid.h.empty() && sizes.empty() && !maxArea; }
};

// Options::maxAngle for "the lowest bound the run can certify" (acute mode only; the CLI's
// --max-angle auto). Stats::angleBound says what was reached.
constexpr double kAutoMaxAngle = 0;

struct Options {
  Mode mode = Mode::Cdt;
  FillRule fill = FillRule::Triangle;
  bool convexHull = false;        // keep every triangle of the convex hull (Triangle's -c)
  // Degrees, acute mode: every angle < maxAngle, 60 < maxAngle <= 90, or kAutoMaxAngle. A bound
  // at or below the domain's floor (Stats::angleFloor) is run as kAutoMaxAngle, said in
  // Stats::warnings, and ends TargetNotMet. Ignored by the other modes (kAutoMaxAngle there is
  // BadInput).
  double maxAngle = 90.0;
  double minAngle = 0.0;          // degrees, quality target (0 = none; see kQualityDefaultMinAngle)
  double maxArea = 0.0;           // area bound (0 = none); Region::maxArea bounds a region's
  double maxEdge = 0.0;           // longest edge allowed (0 = none), in every refinement mode
  SizeField size;                 // edge sizes over the plane (refinement modes)
  // How fast sizes may grow with distance: |grad h| <= grading (JIGSAW's gradient limit;
  // 0.2-0.5 is usual; 0 = no limit), from maxEdge, the size field and the domain's own small
  // features (each vertex's shortest edge in the constrained triangulation). Needs maxEdge or a
  // size; region area bounds are not graded.
  double grading = 0.0;
  // Fill Mesh::adjacency (twins, neighbours, edges, the boundary loops).
  bool adjacency = false;
  uint32_t maxSteiner = 0;        // Steiner point budget (0 = automatic: 50 per input vertex,
                                  // at least 20000, plus room for the area bound)
  double timeLimit = 0.0;         // seconds (0 = unlimited)
  // Seconds to spend after refinement looking for a mesh with fewer Steiner points (0: none):
  // an anytime search (random kicks and ruins, then improvement rounds; one chain per thread)
  // that keeps the best mesh meeting the target and returns it when the time is up, at
  // timeLimit or on a cancel, never one with more points than refinement made. Acute (at a
  // bound below 90 too, which it keeps; with kAutoMaxAngle, the bound reached), non-obtuse,
  // and quality with a minAngle (with sizes too: their polish, which sized quality meshes get
  // only with the search, counts within the seconds). A domain meshed by parts shares the
  // seconds out among its parts by their size.
  double optimize = 0.0;
  // Tries of that search per thread (by parts: per part and thread) at most (0: no cap);
  // either this or optimize starts it.
  // How many tries fit in the seconds depends on the machine: the same seed, threads and
  // tries make the same mesh anywhere.
  uint64_t optimizeTries = 0;
  uint64_t seed = 1;  // the search's random choices: the same seed and threads, the same tries
  // Steiner points that refinement puts on a segment lie exactly on its line wherever a
  // representable point there is near enough (as for integer coordinates): what an exact
  // checker such as the CG:SHOP 2025 verifier needs. Otherwise they are rounded (a few ulps
  // off the line, which leaves refinement some slack: CG:SHOP non-obtuse about 15% fewer points).
  bool exactSegments = false;
  // Non-obtuse: a Steiner point on a segment may stand for the exact foot of the altitude from
  // a vertex next to it, a rational a double cannot hold where the segment is tilted. Such
  // points are listed in Mesh::exactPoints with their exact coordinates (Mesh::points has a
  // double within rounding of them, on the same segment line), and the certificate is taken
  // there. For outputs that hold rationals (CG:SHOP 2025 solutions): with exactSegments,
  // CG:SHOP non-obtuse needs 60% fewer Steiner points. Ignored for inputs that have to be
  // scaled to be meshed exactly (coordinates beyond 2^+-64).
  bool exactFeet = false;
  // Threads for acute and non-obtuse refinement, which tries a few strategies at once where it
  // can, and improves a large mesh in two halves at once (0: one per hardware thread; 1: the
  // calling thread alone). The mesh is the same either way, and in every build (WebAssembly
  // runs them one after another).
  unsigned threads = 0;
  const std::atomic<bool>* cancel = nullptr;          // set to true to stop early
  // Called at the end of each phase and now and then during refinement (from the thread
  // running mesh()); keep it cheap.
  std::function<void(const Progress&)> progress;
};

// A vertex whose exact position a double cannot hold (Options::exactFeet): coordinates as
// decimal rationals "p/q" in lowest terms (q > 0), or "p" for integers.
struct ExactPoint {
  uint32_t vertex;
  std::string x, y;
};

// How a mesh's triangles connect (Options::adjacency, or adjacency(mesh)). Half-edge
// 3t + k runs from corner k of triangle t to corner (k + 1) % 3 (Delaunator's convention).
struct Adjacency {
  std::vector<int32_t> halfedges;   // per half-edge: its twin, -1 on the mesh's boundary
  std::vector<int32_t> neighbors;   // 3 per triangle: the one opposite corner k, -1 none
  std::vector<uint32_t> edges;      // a, b (a < b) per undirected edge, sorted
  // Per edge: the marker of the input segment it lies on; 0 inside the mesh, and on the
  // boundary a zero marker becomes 1 (Triangle's rule).
  std::vector<int32_t> edgeMarkers;
  // The boundary as closed loops of vertices, the mesh on each loop's left (outer boundaries
  // counter-clockwise, holes clockwise): loop i is hull[hullStarts[i] .. hullStarts[i+1]).
  std::vector<uint32_t> hull, hullStarts;
};

struct Mesh {
  std::vector<double> points;       // x, y per vertex; input vertices first, at their indices
  std::vector<uint32_t> triangles;  // a, b, c per triangle, counter-clockwise
  std::vector<uint32_t> segments;   // a, b per mesh edge lying on an input segment
  std::vector<uint32_t> segmentInput;   // per mesh segment edge: the input segment it lies on
  std::vector<uint8_t> vertexKind;  // per vertex: see VertexKind
  // Boundary markers (Triangle's rule): a vertex keeps its input marker; a Steiner point on a
  // segment, and an input vertex with marker 0 on a segment with one, take the segment's
  // (the lowest-numbered such segment's); a zero marker on the mesh's boundary becomes 1.
  std::vector<int32_t> vertexMarkers;   // per vertex
  std::vector<int32_t> segmentMarkers;  // per mesh segment edge: its input segment's marker,
                                        // a zero one on the boundary 1
  // Per triangle: the attribute of its region (Pslg::regions; 0 outside every region). Empty
  // when the input has no regions.
  std::vector<double> triangleAttributes;
  std::vector<ExactPoint> exactPoints;  // by vertex; empty unless Options::exactFeet
  Adjacency adjacency;                  // empty unless Options::adjacency

  size_t vertexCount() const { return points.size() / 2; }
  size_t triangleCount() const { return triangles.size() / 3; }
};

enum VertexKind : uint8_t {
  kInputVertex = 0,     // copied from the input
  kUnusedVertex = 1,    // input vertex used by no triangle (duplicate, or outside the domain)
  kSegmentVertex = 2,   // Steiner point on an input segment (crossings, splits)
  kFreeVertex = 3,      // Steiner point on no input segment (interior, or on a point set's hull)
};

struct PhaseTime {
  std::string phase;
  double seconds;
};

constexpr size_t kMaxMissedListed = 1000;

struct Stats {
  uint32_t inputVertices = 0, inputSegments = 0, inputHoles = 0;
  uint32_t vertices = 0, triangles = 0, segments = 0;  // of the output mesh
  uint32_t steiner = 0;             // vertices added (segment crossings count too)
  uint32_t duplicates = 0;          // input vertices merged into an earlier equal one
  double minAngle = 0, maxAngle = 0;  // degrees, over all output triangles
  uint32_t nonAcute = 0;            // triangles with a corner >= 90 degrees (exact)
  uint32_t obtuse = 0;              // triangles with a corner > 90 degrees (exact)
  bool targetMet = true;            // refinement modes: every triangle meets the target
  // With a size bound (maxEdge, size, a region's maxArea): the largest ratio over the triangles
  // of the longest edge to the size at the centroid (area bounds as sqrt(area / bound)); at
  // most 1 when every size is met. 0 without one.
  double sizeRatio = 0;
  // Checked exactly, for the doubles of the mesh: acute, every angle < angleBound; non-obtuse,
  // every angle <= 90.
  bool certified = false;
  // Acute: the bound every angle is certified strictly below (degrees): Options::maxAngle when
  // the mesh meets it; otherwise (kAutoMaxAngle, or a bound not reached) the largest angle
  // rounded up to the next tenth of a degree, at most 90. 0 when some angle is 90 or more, and
  // in the other modes.
  double angleBound = 0;
  // Smallest angle between two input segments at a vertex, on either side of them (degrees;
  // 180 when no two segments meet): outside the domain too. smallestDomainAngle is the one that
  // limits meshes.
  double smallestInputAngle = 180;
  // The smallest corner of the domain (degrees), measured inside it (a reflex notch is over
  // 180), between two input segments or the domain's edges; 360 when there is none. Every
  // mode but Delaunay. It sets angleFloor = 90 - min(36, smallestDomainAngle) / 2 (Bishop
  // 2021: every domain has a mesh with every angle at most that). Above 72 it is sharp: a corner of theta
  // forces an angle of at least 90 - theta / 2 in its triangles. At 72 (corners of 36 degrees
  // or more) some domains need 72 and others less (an equilateral triangle: 60); acutemesh does
  // not aim below it.
  double smallestDomainAngle = 360, angleFloor = 72;
  // When the target is not met: indices (into Mesh::triangles, triangle i = corners 3i..3i+2)
  // of the triangles that miss it, the first kMaxMissedListed of them.
  std::vector<uint32_t> missedTriangles;
  std::vector<PhaseTime> phases;    // wall time per phase
  double seconds = 0;               // total wall time of mesh()
  std::vector<std::string> warnings;
};

struct Result {
  Status status = Status::Ok;
  std::string message;  // empty when Ok; otherwise one line: which item, what is wrong
  Mesh mesh;
  Stats stats;
};

// Triangulates `input` as `options.mode` says.
Result mesh(const Pslg& input, const Options& options = {});

// The adjacency of any mesh (as Options::adjacency fills it): markers from mesh.segmentMarkers.
Adjacency adjacency(const Mesh& mesh);

struct Validation {
  bool ok = true;
  std::vector<std::string> errors;  // first few problems found, each naming the item
};

// Exact checks of `mesh` against `input` (predicates only, no tolerance):
//  - every triangle strictly counter-clockwise; each edge used at most once per direction,
//    so at most two triangles share an edge, with opposite orientation;
//  - no vertex star wraps around more than once (no folded or overlapping triangles);
//  - mesh vertex i == input vertex i; every used input vertex referenced by a triangle; an
//    unused input vertex lies in no triangle;
//  - every input segment of non-zero length is a chain of mesh edges through vertices on it:
//    exactly, or within rounding (a few ulps) for the points mesh() adds (segment crossings;
//    split points unless options.exactSegments);
//  - domain: every boundary edge lies on an input segment (or on the convex hull when
//    options.convexHull or mode Delaunay); no hole point (Triangle fill) lies in a triangle;
//    with EvenOdd/NonZero every triangle lies in a region the rule keeps.
Validation validate(const Pslg& input, const Mesh& mesh, const Options& options = {});

const char* version();

}  // namespace acutemesh
