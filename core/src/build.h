// The construction steps of mesh(), in the order it runs them. Each reports failure as a
// Status plus a one-line message and never throws.
#pragma once

#include <atomic>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "acutemesh/acutemesh.h"
#include "acutemesh/predicates.h"
#include "exact.h"
#include "progress.h"
#include "triangulation.h"

namespace acutemesh::detail {

// Time limit and cancel flag of one mesh() call, polled by long loops; each poll also lets
// the progress relay (when there is one) report, so a callback that cancels is heard soon.
class Budget {
 public:
  explicit Budget(const Options& o, ProgressRelay* progress = nullptr)
      : cancel_(o.cancel), start_(std::chrono::steady_clock::now()), limit_(o.timeLimit),
        progress_(progress) {}
  double elapsed() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }
  bool cancelled() const {
    if (progress_) progress_->poll();
    return cancel_ && cancel_->load(std::memory_order_relaxed);
  }
  bool outOfTime() const { return limit_ > 0 && elapsed() > limit_; }
  bool stop() const { return cancelled() || outOfTime(); }

 private:
  const std::atomic<bool>* cancel_;
  std::chrono::steady_clock::time_point start_;
  double limit_;
  ProgressRelay* progress_;

 public:
  // The relay, for the steps that note their progress (null without Options::progress).
  ProgressRelay* progress() const { return progress_; }
};

struct StepResult {
  Status status = Status::Ok;
  std::string message;
  bool ok() const { return status == Status::Ok; }
};

// Delaunay triangulation of `points` (x, y interleaved). The vertices are stored in T in
// insertion order (along a Hilbert curve): inputOf[k] is the input index of T's vertex k,
// canonical[i] the vertex that input vertex i ended up as (its own, or that of an earlier
// vertex with identical coordinates, which then stays unconnected).
StepResult buildDelaunay(Triangulation& T, const std::vector<double>& points,
                         std::vector<uint32_t>& canonical, std::vector<uint32_t>& inputOf,
                         const Budget& budget);

// buildDelaunay's steps, shared with triangulateAlongSegments: T's vertices k = 0, 1, ... at
// points[inputOf[k]], none connected yet; and the first triangle among T's vertices below
// `end`: vertex 0, the next distinct one (b), the next not on a line with both (c), kNone
// where there is none.
void placeVertices(Triangulation& T, const std::vector<double>& points,
                   const std::vector<uint32_t>& inputOf);
void firstTriangle(const Triangulation& T, uint32_t end, uint32_t& b, uint32_t& c);

// Segment ends within rounding reach of another segment, strictly inside it: mostly the tips
// of spikes and slivers thinner than the reach (digitising artefacts), which no refinement
// resolves. insertSegments lists them in `found` (vertex in T, the input segment it lies on)
// and, with `snap` (refinement modes), runs the segment through each, folding the sliver.
struct NearEnds {
  bool snap = false;
  std::vector<std::pair<uint32_t, uint32_t>> found;
  // Ends beyond the reach but within kSliverUlps, never snapped: a message about a missed
  // target names those near it.
  std::vector<std::pair<uint32_t, uint32_t>> close;
};
// How far point p lies off the line of input segment `segment` (in input units).
inline double offSegment(const Pslg& input, uint32_t segment, const double* p) {
  const double* a = &input.points[2 * size_t(input.segments[2 * size_t(segment)])];
  const double* b = &input.points[2 * size_t(input.segments[2 * size_t(segment) + 1])];
  return std::fabs(orient2d(a, b, p)) / std::hypot(b[0] - a[0], b[1] - a[1]);
}

// Inserts every input segment as a chain of fixed edges, splitting it at vertices that lie
// on it and at crossings with other segments (adding the crossing points as vertices).
StepResult insertSegments(Triangulation& T, const Pslg& input,
                          const std::vector<uint32_t>& canonical, Stats& stats,
                          const Budget& budget, NearEnds& nearEnds);

// Whether the segments are better inserted along with their ends (triangulateAlongSegments):
// from kAlongSegmentsFrom segments, mostly in chains (each starting where the one before
// ended, as rings and polylines are listed), and long against the vertices' spacing (the
// square root of the bounding box's area per vertex), where each would cross many edges of
// the Delaunay triangulation of all the vertices. Maps' coastlines are short against it
// (0.02-0.15) and their segments are mostly Delaunay edges already; a 10^5-edge star
// polygon's are 26 times longer.
constexpr size_t kAlongSegmentsFrom = 16384;
bool alongSegmentsPays(const Pslg& input);

// buildDelaunay and insertSegments in one pass, as CGAL inserts a polyline: each segment's
// ends are inserted (from where the vertex before went in), then the segment, which then
// crosses only what the vertices before it made (usually nothing: it is an edge already);
// the vertices on no segment come last. The same triangulation as the two steps, up to ties
// among cocircular vertices. T's vertices are the segment ends in the order the segments
// first name them, then the rest along the curve. Sets `declined` (T then holds no result)
// where the input needs the general way: a vertex lies within rounding reach of a segment
// inserted before it (insertSegments would run the segment through it, or list it in
// nearEnds) or at a crossing point made before it, a segment crosses one on the hull so far, every
// segment end lies on one line, or anything else fails.
StepResult triangulateAlongSegments(Triangulation& T, const Pslg& input,
                                    std::vector<uint32_t>& canonical,
                                    std::vector<uint32_t>& inputOf, Stats& stats,
                                    const Budget& budget, NearEnds& nearEnds, bool& declined);

// Marks which triangles belong to the domain (per triangle slot: 1 inside, 0 outside or
// ghost or free), following options.fill / convexHull and (Triangle fill) the input's hole
// points. Fill rules need T.trackWinding (and its `wind`).
std::vector<uint8_t> classifyDomain(const Triangulation& T, const Pslg& input,
                                    const Options& options, bool keepHull,
                                    std::vector<std::string>& warnings);

// A vertex of T whose exact position is a rational a double cannot hold (Options::exactFeet):
// T holds a double on the same segment line within rounding of it.
struct ExactVertex {
  uint32_t vertex;
  RationalPoint at;
};

// Refines T (with T.inside set to the domain) toward options' target: acute / non-obtuse /
// quality. The vertices it adds on no input segment are marked in freeVertex (the rest lie
// on input segments). Returns TargetNotMet or Cancelled when a budget
// stops it; triangles it could not repair are left for the caller's certificate to count.
// With options.exactFeet (non-obtuse), the vertices standing for exact altitude feet are
// listed in `exact` with those positions; every triangle around them has been checked exactly
// there (unless a budget stopped the run: the caller's certificate counts).
StepResult refine(Triangulation& T, const Pslg& input, const Options& options,
                  const Budget& budget, std::vector<uint8_t>& freeVertex,
                  std::vector<ExactVertex>& exact);

// Options::optimize's search was asked for (seconds or tries).
inline bool searchAsked(const Options& options) {
  return options.optimize > 0 || options.optimizeTries > 0;
}

// The predicates are exact while products of coordinate differences neither overflow nor
// underflow: every non-zero coordinate within about 2^-166 .. 2^166 (see predicates.h).
// CoordinateRange collects the binary exponents (frexp) of the largest and of the smallest
// non-zero magnitude; exactScale picks the power of two to divide by: 0 when the largest is
// within 2^+-64 and the smallest above 2^-166 (most inputs), else one that brings the largest
// near 1 (or to 2^64 when the spread needs it). False when no power of two does: the
// coordinates are more than 2^230 apart in magnitude. scaleExactly multiplies by
// 2^exponent, false if a non-zero value would lose bits (become subnormal).
struct CoordinateRange {
  int largest = 0, smallest = 0;  // frexp exponents; meaningless while empty
  bool empty = true;
  bool finite = true;
  void add(const std::vector<double>& xy);
};
bool exactScale(const CoordinateRange& range, int& exponent);
std::string rangeMessage(const CoordinateRange& range);
// An angle for messages: "40 degrees", "16.4926 degrees"; one a hair under 90 is never
// printed as 90 ("89.999999999977121 degrees").
std::string degreesText(double degrees);
// A decimal of 6 or more digits that reads back as exactly x, for coordinates in messages.
std::string shortestText(double x);
bool scaleExactly(std::vector<double>& xy, int exponent);

}  // namespace acutemesh::detail
