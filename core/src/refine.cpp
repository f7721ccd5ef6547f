// Delaunay refinement toward a target: acute (every angle < maxAngle), non-obtuse (<= 90),
// or quality (every angle >= minAngle, area <= maxArea).
//
// A bad triangle is repaired by the rule its worst corner calls for:
//  - a large angle: first move one of its Steiner vertices where its whole star meets the
//    target (relocation, Erten & Ungor 2.2; along its segment for a vertex on one);
//  - a large angle opposite a fixed edge (a subsegment): the apex lies in the subsegment's
//    closed diametral disk, and only splitting the subsegment helps (boundary rule);
//  - a large angle elsewhere: insert the point of slice(pq) (pq the shortest edge) farthest
//    from all vertices, found on the Voronoi diagram near the triangle (Erten & Ungor 2.1);
//  - a small angle or a large area: insert the circumcentre (Ruppert).
// A Steiner point that would encroach a subsegment (lie in its closed diametral disk) or fall
// beyond one is not inserted; the subsegment is split instead. Subsegments at an input
// vertex are split at a power-of-two distance from it (concentric shells); input vertices
// with a small angle between their segments get a corner fan first (buildCornerFans).
// Acute and non-obtuse runs then remove Steiner points while the target holds
// (removeSteinerPoints); refine() tries a few boundary strategies and polishes the cheapest:
// rounds of smoothing, removal and merging of neighbouring pairs (polish).
#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <memory>
#include <mutex>
#include <string>
#if !defined(__EMSCRIPTEN__) || defined(__EMSCRIPTEN_PTHREADS__)
#include <thread>
#define ACUTEMESH_STRATEGY_THREADS 1
#endif

#include "acutemesh/predicates.h"
#include "build.h"
#include "portable_math.h"
#include "rounding.h"

namespace acutemesh::detail {
namespace {

constexpr double kDegree = M_PI / 180.0;
// Quality refinement places new points where the angles they make are this much (degrees)
// over the bound, so that rounding cannot leave them just under it.
constexpr double kQualityRoom = 0.5;
// Refinement to an area bound reserves room for the vertices it expects, up to this many.
constexpr uint32_t kReservedVerticesAtMost = 1u << 21;
// examineCavity() stops past this many triangles.
constexpr size_t kCavityExamined = 256;
// How many points of a slice are tried for one that encroaches no subsegment.
constexpr size_t kSliceTries = 3;

// kOnHull: on a boundary edge no segment lies on (hull of a point set); kept in place like
// kOnSegment, reported like kFree (no input segment holds it). kArc: on the arc of a corner
// fan (see buildCornerFans); never moved while refinement runs, an ordinary free Steiner point
// in the improvement pass.
enum VertexRole : uint8_t { kInput, kOnSegment, kOnHull, kFree, kArc };

struct Corner {
  int k = -1;         // corner index in its triangle, -1 if the triangle meets the target
  bool large = true;  // a large angle (else a small angle or too large an area)
  bool area = false;  // too large an area (and no angle out of bounds)
};

double dist2(const double* a, const double* b) {
  double dx = a[0] - b[0], dy = a[1] - b[1];
  return dx * dx + dy * dy;
}

// Circumcentre of a, b, c (floating point, relative to a for accuracy).
void circumcenter(const double* a, const double* b, const double* c, double* out) {
  double bx = b[0] - a[0], by = b[1] - a[1], cx = c[0] - a[0], cy = c[1] - a[1];
  double d = 2 * (bx * cy - by * cx);
  double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  out[0] = a[0] + (cy * b2 - by * c2) / d;
  out[1] = a[1] + (bx * c2 - cx * b2) / d;
}

// The WebAssembly build must make the very meshes the native one makes, and the two link
// different maths libraries: hypot, pow, exp2 and log2 need not round alike there (only +, -,
// *, / and sqrt are exact IEEE operations). So constructions use those alone (sin, cos and
// atan2 too: portable_math.h).
// The power of two nearest x > 0 in the log scale: round(log2 x), from x's exponent and
// whether its mantissa m (x = m 2^e, 0.5 <= m < 1) is at least sqrt(1/2).
double powerOfTwoNear(double x) {
  int e = 0;
  double m = std::frexp(x, &e);
  return std::ldexp(1.0, m >= M_SQRT1_2 ? e : e - 1);
}

// repairAll()'s queue of bad triangles. Three orders:
// - largest (squared shortest edge) first, exact (a binary heap on size, then index): acute,
//   non-obtuse and min-angle refinement come out with the fewest points this way (by factors
//   of two instead: CG:SHOP non-obtuse 3% more, A.poly acute 91 instead of 85, quality at 40
//   degrees on A.poly 127 instead of 94);
// - by factors of two, newest first within one (a stack per binary exponent of the size):
//   with an area bound, where most of the work is area refinement of large meshes. Working
//   near the last insertion keeps the mesh in cache: a million triangles in half the time;
// - fewest bad triangles left first (Strategy::fewestBadFirst): by the gain an entry carries
//   (the bad triangles its repair takes away, less those it makes), then largest first.
class RepairQueue {
 public:
  enum class Order { Largest, FactorsOfTwo, FewestBadFirst };
  struct Entry {
    int gain;  // FewestBadFirst only (0 otherwise)
    double size;
    uint32_t t;
    bool operator<(const Entry& o) const {
      return gain != o.gain ? gain < o.gain : size != o.size ? size < o.size : t < o.t;
    }
  };
  void reset(Order order) {
    rough_ = order == Order::FactorsOfTwo;
    heap_.clear();
    for (auto& b : buckets_) b.clear();
    top_ = 0;
  }
  void push(const Entry& entry) {
    if (!rough_) {
      heap_.push_back(entry);
      std::push_heap(heap_.begin(), heap_.end());
      return;
    }
    int e = 0;
    std::frexp(entry.size, &e);
    size_t b = size_t(std::clamp(e + kBias, 0, kBuckets - 1));
    if (buckets_.empty()) buckets_.resize(kBuckets);
    buckets_[b].push_back(entry);
    top_ = std::max(top_, b + 1);
  }
  bool pop(Entry& entry) {
    std::vector<Entry>* from = &heap_;
    if (rough_) {
      while (top_ > 0 && buckets_[top_ - 1].empty()) --top_;
      if (top_ == 0) return false;
      from = &buckets_[top_ - 1];
    } else {
      if (heap_.empty()) return false;
      std::pop_heap(heap_.begin(), heap_.end());
    }
    entry = from->back();
    from->pop_back();
    return true;
  }

 private:
  static constexpr int kBuckets = 2200, kBias = 1100;  // binary exponents of doubles, shifted
  bool rough_ = false;
  std::vector<Entry> heap_;
  std::vector<std::vector<Entry>> buckets_;
  size_t top_ = 0;
};

// How a run goes about the boundary. No one way wins everywhere (see refine()).
struct Strategy {
  bool cutAtFeetFirst = false;  // non-obtuse: cut slivers at altitude feet before the fans
  bool footOnSegments = false;  // non-obtuse: split an encroached subsegment at the altitude foot
  bool lazyFans = false;  // fans only at small sectors where a bad triangle turns up
  bool wideFans = false;  // fans at the smallest corners as wide as their neighbours allow
  // Non-obtuse: slide a segment vertex to the middle of the longest stretch slideStretches()
  // finds before trying a few sampled places. (Acute, CG:SHOP 67,744
  // Steiner points: exact slides everywhere 70,355; in the removal pass only 66,159 but A.poly
  // 90 instead of 85, over aCute's 86; as two more strategies 67,564, not worth the runs.)
  bool exactSlide = false;
  // Candidate points spare the segments and are weighed (see repair()): of the Voronoi
  // vertices in the bad triangle's circumdisk that encroach no subsegment, the one that leaves
  // the fewest bad triangles goes in (quality: the first that encroaches none), and a
  // subsegment split by the boundary rule goes where it leaves the fewest. Without (acute's
  // fallbacks): the seed's farthest point of the slice, whatever it encroaches, and the usual
  // split places.
  bool weighPoints = true;
  // Repair first the bad triangle whose repair leaves the fewest bad triangles (evaluated on
  // its slice's points, see insertSparingSegments), not the largest (acute and non-obtuse).
  bool fewestBadFirst = false;
  bool fallback = false;  // run only if no strategy before it met the target
};

// The domain's area where an area bound needs it (0 otherwise).
double domainArea(const Triangulation& T, const Options& options) {
  double area = 0;
  if (options.maxArea > 0)
    for (uint32_t t = 0; t < T.triangleSlots(); ++t)
      if (T.inDomain(t))
        area += 0.5 * orient2d(T.point(T.tri[3 * t]), T.point(T.tri[3 * t + 1]),
                               T.point(T.tri[3 * t + 2]));
  return area;
}

// The Steiner points a run may make: Options::maxSteiner, or without a budget from the caller
// 50 per input vertex, at least 20000, and with an area bound room for about two triangles of
// that area per unit of domain area (`area`, domainArea's).
double steinerBudget(const Pslg& input, const Options& options, double area) {
  if (options.maxSteiner) return options.maxSteiner;
  double cap = std::max(20000.0, 50.0 * double(input.vertexCount()));
  return options.maxArea > 0 ? cap + 4 * area / options.maxArea : cap;
}

#ifdef ACUTEMESH_STRATEGY_THREADS
// The threads a run may use: Options::threads, 0 meaning one per hardware thread.
unsigned threadsFor(const Options& options) {
  return options.threads ? options.threads : std::thread::hardware_concurrency();
}
#endif

// A run's Steiner limit where strategies run concurrently (refineWithStrategies): it may
// tighten while the run goes on, so the run reads it at every check, and publishes the vertex
// count it checked.
struct SteinerGate {
  std::atomic<uint32_t> limit{0};
  std::atomic<uint32_t> checked{0};
};

class Refiner {
 public:
  Refiner(Triangulation& T, const Pslg& input, const Options& options, const Budget& budget,
          const Strategy& strategy, uint32_t steinerCap)
      : T_(T), input_(input), options_(options), budget_(budget), strategy_(strategy) {
    uint32_t inputCount = uint32_t(input.vertexCount());
    role_.assign(T.vertexCount(), kOnSegment);  // crossing points made by the CDT lie on segments
    std::fill(role_.begin(), role_.begin() + inputCount, kInput);
    fanCenter_.assign(T.vertexCount(), kNone);
    footOf_.assign(T.vertexCount(), kNone);
    fanRadius_.assign(inputCount, 0);
    acute_ = options.mode == Mode::Acute;
    nonObtuse_ = options.mode == Mode::NonObtuse;
    feet_ = nonObtuse_ && options.exactFeet;
    cosMax_ = portableCos(options.maxAngle * kDegree);
    strictMax_ = acute_ && options.maxAngle < 90;
    cosMin_ = portableCos(options.minAngle * kDegree);
    cosQuality_ = portableCos(std::min(options.minAngle + kQualityRoom, 60.0) * kDegree);
    double area = domainArea(T, options);
    budgetCap_ = steinerBudget(input, options, area);
    startVertices_ = T.vertexCount();
    steinerLimit_ = steinerLimitWith(steinerCap);
    if (options.maxArea > 0) {
      // About one vertex per two triangles of a third of the bound's area, within the budget,
      // and no more than two million more: a bound far too small for the time limit must not
      // reserve gigabytes up front (it took ASan over a minute).
      double vertices = std::min({double(steinerLimit_), T.vertexCount() + 1.6 * area / options.maxArea,
                                  T.vertexCount() + double(kReservedVerticesAtMost)});
      T.reserveCapacity(size_t(vertices), 2 * size_t(vertices) + 16);
      role_.reserve(size_t(vertices));
      fanCenter_.reserve(size_t(vertices));
      footOf_.reserve(size_t(vertices));
    }
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (size_t i = 0; i < input.points.size(); ++i)
      lo[i % 2] = std::min(lo[i % 2], input.points[i]), hi[i % 2] = std::max(hi[i % 2], input.points[i]);
    double dx = hi[0] - lo[0], dy = hi[1] - lo[1];
    double diagonal = std::sqrt(dx * dx + dy * dy);  // not hypot: see powerOfTwoNear
    // Far from the origin (an input moved by 1e15) the coordinates' own resolution is coarse:
    // no edge shorter than 2^10 ulps of the largest coordinate, or split points round off
    // their segments by a visible fraction of the edge.
    double largest = std::max({-lo[0], -lo[1], hi[0], hi[1], 0.0});
    double minEdge = std::max(diagonal * std::ldexp(1.0, -24), largest * std::ldexp(1.0, -42));
    minEdge2_ = minEdge * minEdge;
    // Where the domain ends at an edge no segment lies on (point sets, --convex-hull), the
    // edge is a boundary all the same: fix it (with no segment) so the boundary rule applies.
    for (uint32_t e = 0; e < 3 * T.triangleSlots(); ++e)
      if (!T.isFree(e / 3) && T.inside[e / 3] && !T.isFixed(e) && !T.inside[T.opp[e] / 3])
        T.fixEdge(e, 0);
  }

  StepResult run();
  // The vertex count at which a run with Steiner cap steinerCap (0: none) stops.
  uint32_t steinerLimitWith(uint32_t steinerCap) const {
    double cap = steinerCap ? std::min(budgetCap_, double(steinerCap)) : budgetCap_;
    return uint32_t(std::min(double(startVertices_) + cap, double(kMaxVertices)));
  }
  // Checks the Steiner limit in gate (which the caller keeps) rather than its own, until
  // leaveGate() sets its own to that for steinerCap.
  void useGate(SteinerGate* gate) { gate_ = gate; }
  void leaveGate(uint32_t steinerCap) {
    gate_ = nullptr;
    steinerLimit_ = steinerLimitWith(steinerCap);
  }
  // Progress reports are made on the thread that called mesh() only (see Options::progress).
  void reportProgress(bool on) { reportProgress_ = on; }
  bool anyBad() const;
  StepResult runSteps();
  void polish();
  size_t liveSteiner() const;
  bool exactFeet(std::vector<ExactVertex>& out) const;
  void markFree(std::vector<uint8_t>& out) const {
    out.resize(role_.size());
    for (size_t v = 0; v < role_.size(); ++v)
      out[v] = role_[v] == kFree || role_[v] == kOnHull || role_[v] == kArc;
  }

 private:
  const double* P(uint32_t v) const { return T_.point(v); }
  Corner worstCorner(uint32_t t) const;
  // Triangle slot t is a triangle of the domain that misses the target.
  bool missesTarget(uint32_t t) const {
    return T_.inDomain(t) && worstCorner(t).k >= 0;
  }
  // footCorners: corners that may stand for exact right angles (see footCorners(t)).
  Corner worstCorner(const double* const p[3], int footCorners = 0) const;
  int footCorners(uint32_t t) const;
  bool footEdge(uint32_t e) const { return T_.isFixed(e) && !isChord(e); }
  // Segment vertex v, just made at the altitude foot of footOf (kNone: of none), stands for
  // that foot (footOf_) unless the double is exactly it (as on axis-parallel segments: then
  // no standing for is needed). along: another point of v's segment line.
  void standForFoot(uint32_t v, uint32_t footOf, const double* along) {
    if (feet_ && footOf != kNone && dot2d(P(v), P(footOf), along) != 0) footOf_[v] = footOf;
  }
  void segmentEnds(uint32_t f, uint32_t spoke, const double*& a, const double*& b) const;
  double shortestEdge2(uint32_t t) const;
  // weighed: repairGain's choice among t's candidates (in candidates_), if it has just weighed
  // them and nothing has changed the mesh since; kNotWeighed otherwise.
  static constexpr size_t kNotWeighed = SIZE_MAX;
  bool repair(uint32_t t, Corner c, size_t weighed = kNotWeighed);
  // Splits at `preferred` (a fraction of the way from the edge's first end) when given and
  // well inside, else by the shell rule.
  // footOf: the vertex whose altitude foot `preferred` is (see footOf_).
  bool splitSubsegment(uint32_t e, double preferred = -1, uint32_t footOf = kNone);
  double shellRatio(uint32_t e) const;
  double splitRatio(uint32_t e, double preferred) const {
    return preferred > 0.01 && preferred < 0.99 ? preferred : shellRatio(e);
  }
  bool splitChord(uint32_t e);
  void buildCornerFans();
  double readStar(uint32_t v);
  double sectorAngle(size_t i) const;
  double fanRadius(uint32_t v, bool onlyWhereBad);
  struct FanCentre {
    uint32_t vertex;
    double radius;
    double sector;  // its smallest domain sector (radians)
    double widest;  // kWideFan times the distance to its link (set by widenFans)
  };
  double smallestSector() const;
  void widenFans(std::vector<FanCentre>& centres) const;
  void buildFan(uint32_t v, double r);
  struct Spoke {
    uint32_t to;        // the other end of the fixed edge
    double direction;   // radians
    bool sectorInside;  // the sector from this spoke counter-clockwise to the next is in the domain
    bool sectorBad;     // ... and holds a triangle that misses the target
  };
  std::vector<Spoke> spokes_;
  void cutAtFeet();
  bool splitAtFoot(uint32_t t, int k);
  bool splitWeighed(uint32_t e, uint32_t apex);
  int splitBadChange(uint32_t e, const double* m, uint32_t footOf);
  void releaseChords();
  // The subsegment on the rim of x's cavity (seen from triangle `from`) that x encroaches,
  // the longest if several, and the first fixed edge x lies beyond; kNone where none.
  struct CavityRim {
    uint32_t encroached, beyond;
  };
  bool insertSteiner(uint32_t from, const double* x);
  // The same with x's cavity just examined (rim: examineCavity's answer, cavity_ its cavity).
  bool insertSteiner(uint32_t from, const double* x, CavityRim rim);
  CavityRim examineCavity(uint32_t from, const double* x);
  CavityRim growCavity(const double* x);
  uint32_t firstFixedCrossed(uint32_t t, const double* x, uint32_t& reached) const;
  bool freeStar(uint32_t a);
  bool segmentStar(uint32_t a, uint32_t spokes[2]);
  bool relocate(uint32_t a);
  bool linkLeavesRoom() const;
  bool insideOneDiametralDisk(const std::vector<std::array<double, 2>>& poly) const;
  bool relocateOntoPerpendicular(uint32_t a, const double* old);
  void legalizeStar(uint32_t a);
  void settleMove(uint32_t v);
  bool slide(uint32_t a);
  bool nearFixedLinkEdge(uint32_t a, const double* x) const;
  bool moveTo(uint32_t a, double x, double y);
  // The line of input segment seg (or of p-q for a hull edge, seg == kNone). Points on a
  // segment are made from it, by their parameter along it, never from rounded points on it,
  // so rounding does not accumulate along a segment.
  struct SegmentLine {
    const double *start, *end;
    double ux, uy, u2;
    double param(const double* x) const {
      return ((x[0] - start[0]) * ux + (x[1] - start[1]) * uy) / u2;
    }
    // With `exact` (Options::exactSegments) t moves to the nearest parameter with few enough
    // bits that the point lies exactly on the line, if there is one within 2^-24 of the
    // segment's length (there is for integer coordinates): the finest such.
    bool exact = false;
    void at(double t, double* out) const {
      out[0] = start[0] + t * ux, out[1] = start[1] + t * uy;
      if (!exact || orient2d(start, end, out) == 0) return;
      for (int bits = 60; bits >= 24; bits -= 2) {
        double s = std::ldexp(std::nearbyint(std::ldexp(t, bits)), -bits);
        double m[2] = {start[0] + s * ux, start[1] + s * uy};
        if (orient2d(start, end, m) == 0) {
          out[0] = m[0], out[1] = m[1];
          return;
        }
      }
    }
  };
  SegmentLine segmentLine(uint32_t seg, const double* p, const double* q) const;
  bool slideStretches(double tp, double tq, const SegmentLine& line, double margin);
  std::vector<std::array<double, 2>> slideStretches_;
  std::vector<uint8_t> ringInside_;  // per triangle of ring_ (slide, relocate): in the domain
  bool tryRemove(uint32_t v);
  bool tryRemoveFromSegment(uint32_t v);
  bool tryMerge(uint32_t u, uint32_t w);
  int tryMergedPoint(const double* x);
  bool tryMergeOnSegment(uint32_t u, uint32_t w);
  int tryPointOnSegment(const double* x, uint32_t footOf, const uint32_t* ends);
  bool mergePoint(uint32_t u, uint32_t w, double* out);
  void clipToLinkSlabs(bool wedges);
  bool clipCentroid(double* out) const;
  void markChanged();
  std::vector<uint8_t> dirty_;  // per vertex: worth another removal / merge try
  bool holeMeetsTarget();
  // Runs a removal with the store recording the triangles it writes; they become hole_.
  template <class Removal>
  bool recordingHole(Removal removal) {
    touched_.clear();
    T_.touched = &touched_;
    bool removed = removal();
    T_.touched = nullptr;
    if (removed) hole_ = touched_;
    return removed;
  }
  void undoMoves();
  struct Moved {
    uint32_t vertex;
    double x, y;
  };
  std::vector<Moved> moved_;
  // Passes of removals (merges) until one gains nothing, at most `passes`; the first tries
  // the vertices `due` marks (default: all).
  void removeSteinerPoints(const std::vector<uint8_t>* due = nullptr, int passes = 12);
  void mergeSteinerPoints(const std::vector<uint8_t>* due = nullptr, int passes = 1);
  void markDue(const std::vector<uint8_t>* due);
  uint32_t mergePass();
  bool removePoint(uint32_t v);
  bool mergePair(uint32_t u, uint32_t w);
  // One improvement round (polish), and one done in two halves at once (roundInHalves): each
  // half's round works only on the vertices mine_ marks, and one half's steps are logged
  // (log_) to be made again on the mesh (replay, replayMove).
  struct Step {
    enum Kind : uint8_t { Move, Remove, Merge } kind;
    uint32_t u, w, made;  // the vertex moved or removed; the pair merged and the point made
    double x, y;          // where it moved
  };
  void polishRound(bool removeAfterMerging);
  void roundInHalves(int round);
  void replay(const std::vector<Step>& log, uint32_t firstNew, uint32_t made);
  bool replayMove(uint32_t v, const double* to);
  bool owned(uint32_t v) const { return !mine_ || v >= mine_->size() || (*mine_)[v]; }
  const std::vector<uint8_t>* mine_ = nullptr;
  std::vector<Step>* log_ = nullptr;
  bool improvementShouldStop();
  uint32_t attempts_ = 0;  // removal and merge attempts so far (improvementShouldStop)
  void smooth();
  StepResult repairAll();
  int repairGain(uint32_t t, Corner c, size_t* weighed = nullptr);
  bool starMeetsTarget(uint32_t a) const;
  // Points of slice(pq) (pq the shortest edge of t), farthest from every vertex first: x, y
  // and that distance squared.
  void slicePoints(uint32_t t, std::vector<std::array<double, 3>>& out) const;
  std::vector<std::array<double, 3>> candidates_;  // slicePoints / qualityPoints
  void qualityPoints(uint32_t t, std::vector<std::array<double, 3>>& out) const;
  bool insertSparingSegments(uint32_t t, const std::vector<std::array<double, 3>>& points,
                             bool fewestBad);
  int badChange(const double* x, uint32_t split = kNone, uint32_t footOf = kNone) const;
  size_t weighCandidates(uint32_t t, const std::vector<std::array<double, 3>>& points, int& fewest);
  bool insertWeighed(uint32_t t, const std::vector<std::array<double, 3>>& points, size_t chosen);
  // Triangle t's shortest edge pq and its circumcircle: where the Steiner point searches start.
  struct ShortestEdge {
    const double *p, *q;
    double center[2], radius2;
  };
  ShortestEdge shortestEdge(uint32_t t) const;
  template <class Keep, class Visit>
  void walkVoronoi(uint32_t t, Keep keep, Visit visit) const;
  uint32_t addVertex(const double* p, VertexRole role, uint32_t fanCenter = kNone) {
    role_.push_back(role);
    fanCenter_.push_back(fanCenter);
    footOf_.push_back(kNone);
    return T_.addVertex(p[0], p[1]);
  }
  void dropLastVertex() {
    T_.pts.resize(T_.pts.size() - 2);
    T_.vertexEdge.pop_back();
    role_.pop_back();
    fanCenter_.pop_back();
    footOf_.pop_back();
  }
  // A chord of a corner fan: a fixed edge between two points of the same fan.
  bool isChord(uint32_t e) const {
    uint32_t c = fanCenter_[T_.tri[e]];
    return c != kNone && c == fanCenter_[T_.tri[next(e)]];
  }

  Triangulation& T_;
  const Pslg& input_;
  const Options& options_;
  const Budget& budget_;
  const Strategy strategy_;
  std::vector<uint8_t> role_;
  // Per vertex: the input vertex whose corner fan it belongs to (on its arc, or where the fan
  // meets a segment), else kNone; per fan centre, the fan's radius.
  std::vector<uint32_t> fanCenter_;
  std::vector<double> fanRadius_;
  // Per vertex (Options::exactFeet): for a segment vertex made at the altitude foot of a
  // vertex, that vertex, else kNone. Its angles between the segment and the edge to that
  // vertex count as right when within kFootSlack of it (footCorners), for the exact foot.
  std::vector<uint32_t> footOf_;
  bool acute_ = false, nonObtuse_ = false;
  bool feet_ = false;  // Options::exactFeet in a non-obtuse run
  double cosMax_ = 0, cosMin_ = 1;
  double cosQuality_ = 1;  // of the angles qualityPoint() aims for (a little over minAngle)
  bool strictMax_ = false;  // acute with a bound below 90 degrees, checked in floating point
  uint32_t steinerLimit_ = 0;
  double budgetCap_ = 0;  // Steiner points the options and defaults allow
  uint32_t startVertices_ = 0;
  SteinerGate* gate_ = nullptr;
  bool reportProgress_ = true;
  bool atSteinerLimit() {
    const uint32_t n = T_.vertexCount();
    if (!gate_) return n >= steinerLimit_;
    gate_->checked.store(n);
    return n >= gate_->limit.load();
  }
  // No edge shorter than 2^-24 of the input's extent is made: refinement that would go
  // deeper (a narrow wedge it cannot fill) stops there and leaves the triangle to the
  // certificate, instead of spiralling into rounding noise.
  double minEdge2_ = 0;
  RepairQueue queue_;
  std::vector<uint32_t> touched_, cavity_, ring_, hole_, flips_;
  std::vector<std::array<uint32_t, 2>> linkEdges_;  // clipToLinkSlabs()' input
  std::vector<std::array<double, 2>> clipPoly_;  // its output
  // Its scratch (two polygons, each corner's side), only ever grown: growing a vector of
  // arrays zeroes the new elements, 1% of all the time when it shrank after every call.
  std::vector<std::array<double, 2>> clipWork_;
  std::vector<double> clipSide_;
  std::vector<std::array<double, 2>> stretches_;  // slideStretches()' scratch
};

// The corner that most misses the target, decided exactly where the target is 90 degrees.
Corner Refiner::worstCorner(uint32_t t) const {
  const uint32_t* v = &T_.tri[3 * t];
  const double* p[3] = {P(v[0]), P(v[1]), P(v[2])};
  return worstCorner(p, feet_ ? footCorners(t) : 0);
}

// Options::exactFeet: how far from 90 degrees (as a cosine) an angle at a segment vertex
// between the segment and an edge may be and still count as right, the vertex standing for
// the exact foot of the altitude from that edge's other end. The point of a tilted segment
// nearest the foot that a double holds can be hundreds of ulps away (on a line of direction
// (553, 2) they are 553 ulps apart), which for a vertex 0.4 units off a segment 2765 long
// misses 90 degrees by about 1e-9: CG:SHOP non-obtuse needs half the points with 1e-9 or
// more, no gain at 1e-12. exactFeet() then checks every triangle at the exact foot.
constexpr double kFootSlack = 1e-7;
// kFootSlack for the angle at a between b and c, in the units of dot2d(a, b, c).
double footSlack(const double* a, const double* b, const double* c) {
  return kFootSlack * std::sqrt(dist2(a, b) * dist2(a, c));
}
// footCorners' flag for a triangle at a foot: its other corners must be sharper than 90
// degrees by kFootSlack (as cosines), for the foot's move to its exact place.
constexpr int kNearFoot = 8;

// Bit k set: corner k of t is at a segment vertex standing for the altitude foot of a vertex
// (footOf_), between a piece of its segment and the edge to that vertex. kNearFoot set: some
// vertex of t stands for a foot.
int Refiner::footCorners(uint32_t t) const {
  int mask = 0;
  const uint32_t* v = &T_.tri[3 * t];
  for (uint32_t k = 0; k < 3; ++k) {
    const uint32_t foot = footOf_[v[k]];
    if (foot == kNone) continue;
    mask |= kNearFoot;
    if ((footEdge(3 * t + k) && v[(k + 2) % 3] == foot) ||
        (footEdge(3 * t + (k + 2) % 3) && v[(k + 1) % 3] == foot))
      mask |= 1 << k;
  }
  return mask;
}

// The same for the triangle p[0], p[1], p[2] (counter-clockwise).
Corner Refiner::worstCorner(const double* const p[3], int footCorners) const {
  if (acute_ || nonObtuse_) {
    if (!(footCorners & kNearFoot)) {
      // (The three corners at once, sharing their coordinate differences: this is the
      // hottest test of the improvement rounds.)
      double d[3];
      cornerDots(p[0], p[1], p[2], d);
      for (int k = 0; k < 3; ++k)
        if (nonObtuse_ ? d[k] < 0 : d[k] <= 0) return {k, true};
    } else {
      for (int k = 0; k < 3; ++k) {
        const double *a = p[k], *b = p[(k + 1) % 3], *c = p[(k + 2) % 3];
        const double d = dot2d(a, b, c), slack = footSlack(a, b, c);
        if ((footCorners >> k & 1) ? d < -slack : d < slack) return {k, true};
      }
    }
    if (acute_ && strictMax_) {
      for (int k = 0; k < 3; ++k) {
        const double *a = p[k], *b = p[(k + 1) % 3], *c = p[(k + 2) % 3];
        double dot = (b[0] - a[0]) * (c[0] - a[0]) + (b[1] - a[1]) * (c[1] - a[1]);
        if (dot <= cosMax_ * std::sqrt(dist2(a, b) * dist2(a, c))) return {k, true};
      }
    }
  }
  if (options_.minAngle > 0) {
    for (int k = 0; k < 3; ++k) {
      const double *a = p[k], *b = p[(k + 1) % 3], *c = p[(k + 2) % 3];
      double dot = (b[0] - a[0]) * (c[0] - a[0]) + (b[1] - a[1]) * (c[1] - a[1]);
      if (dot > cosMin_ * std::sqrt(dist2(a, b) * dist2(a, c))) return {k, false};
    }
  }
  if (options_.maxArea > 0) {
    double area = 0.5 * std::fabs(orient2d(p[0], p[1], p[2]));
    if (area > options_.maxArea) return {0, false, true};
  }
  return {};
}

// Where (a fraction of the way from its first end) the subsegment of fixed half-edge e is split
// by default: next to an input vertex at a power of two from it (concentric shells), otherwise
// at the midpoint.
double Refiner::shellRatio(uint32_t e) const {
  uint32_t a = T_.tri[e], b = T_.tri[next(e)];
  if ((role_[a] == kInput) == (role_[b] == kInput)) return 0.5;
  double len = std::sqrt(dist2(P(a), P(b))), shell = powerOfTwoNear(len / 2);
  return role_[a] == kInput ? shell / len : 1 - shell / len;
}

// Splits the subsegment of fixed half-edge e, at shellRatio() unless `preferred` is given and
// well inside (splitRatio).
bool Refiner::splitSubsegment(uint32_t e, double preferred, uint32_t footOf) {
  if (isChord(e)) return splitChord(e);
  uint32_t a = T_.tri[e], b = T_.tri[next(e)];
  // Copies: adding a vertex may move the coordinate array.
  const double pa[2] = {P(a)[0], P(a)[1]}, pb[2] = {P(b)[0], P(b)[1]};
  if (dist2(pa, pb) < 4 * minEdge2_) return false;
  double s = splitRatio(e, preferred);
  uint32_t seg = T_.segment[e];
  SegmentLine line = segmentLine(seg, pa, pb);
  double ta = line.param(pa), tb = line.param(pb);
  // A rounded split point may still miss the edge; next to a sliver triangle that can put it
  // outside the edge's quadrilateral. Other split ratios are tried then.
  for (double ratio : {s, 0.5, 0.45, 0.55, 0.4, 0.6, 1 / 3.0, 2 / 3.0}) {
    double m[2];
    line.at(ta + ratio * (tb - ta), m);
    if ((m[0] == pa[0] && m[1] == pa[1]) || (m[0] == pb[0] && m[1] == pb[1])) continue;
    uint32_t v = addVertex(m, seg != kNone ? kOnSegment : kOnHull);
    if (T_.splitFixedEdge(e, v)) {
      if (ratio == preferred) standForFoot(v, footOf, pa);
      return true;
    }
    dropLastVertex();
  }
  return false;
}

// Splits a chord of a corner fan on its arc: the fan gets one more isosceles triangle.
bool Refiner::splitChord(uint32_t e) {
  uint32_t a = T_.tri[e], b = T_.tri[next(e)], c = fanCenter_[a];
  const double *pa = P(a), *pb = P(b), *pc = P(c);
  if (dist2(pa, pb) < 4 * minEdge2_) return false;
  double ra = std::sqrt(dist2(pa, pc)), rb = std::sqrt(dist2(pb, pc));
  double ux = (pa[0] - pc[0]) / ra + (pb[0] - pc[0]) / rb, uy = (pa[1] - pc[1]) / ra + (pb[1] - pc[1]) / rb;
  double scale = fanRadius_[c] / std::sqrt(ux * ux + uy * uy);
  double m[2] = {pc[0] + ux * scale, pc[1] + uy * scale};
  if (!std::isfinite(m[0]) || !std::isfinite(m[1])) return false;
  uint32_t v = addVertex(m, kArc, c);
  if (T_.splitFixedEdge(e, v)) return true;
  // The arc point lies beyond the triangle on the chord's outer side (a thin one). Insert it
  // where it lies if no segment is in between, free the chord to flip towards it, and fix
  // the chords that are there afterwards.
  uint32_t outer = T_.tri[prev(e)] == c ? T_.opp[e] / 3 : e / 3, reached = kNone;
  Location loc;
  if (firstFixedCrossed(outer, m, reached) == kNone && reached != kNone &&
      T_.inDomain(reached))
    loc = T_.locate(m, reached);
  bool placed = (loc.where == Where::InTriangle ||
                 (loc.where == Where::OnEdge && !T_.isFixed(loc.edge))) &&
                T_.insertAt(v, loc) == v;
  if (!placed) {
    dropLastVertex();
    return false;
  }
  if (uint32_t ab = T_.findEdge(a, b); ab != kNone) {
    T_.unfixEdge(ab);
    flips_.assign({ab, T_.opp[ab]});
    T_.legalize(flips_);
  }
  for (auto [x, y] : {std::pair{a, v}, std::pair{v, b}, std::pair{a, b}}) {
    uint32_t f = T_.findEdge(x, y);
    if (f != kNone && !T_.isFixed(f)) T_.fixEdge(f, 0);
  }
  return true;
}

// Corner fans. Where segments meet at a small angle, refinement alone spirals into the
// corner: points placed in or next to the wedge encroach the short subsegments at its apex,
// and their splits make the triangles there smaller still. So an input vertex with a domain
// sector under kSmallAngle (non-obtuse: kSmallAngleNonObtuse, since a right triangle settles
// a wider tip) between its segments gets a fan: every segment at it is split at
// the same distance r, and every domain sector around it is cut by points on the circle of
// radius r into isosceles triangles with apex angles of at most kFanAngle (acute). The fan's
// outer edges (chords) are fixed while refinement runs, so the fan stays as built; the rest of
// the domain meets no angle under 90 degrees there, and a chord that must be split is split on
// its arc (one more spoke). r is just under half the distance from the vertex to its link:
// the fan's disk holds no other vertex or segment, its triangles are Delaunay, and the fans
// of two vertices keep apart; the larger the fan, the less of the wedge is left to refine
// (CG:SHOP, factor 0.4 -> 0.49: non-obtuse 56,156 -> 53,149 Steiner points, acute 71,243 ->
// 67,886; fans only under 30 degrees for non-obtuse: 49,761).
namespace {
constexpr double kSmallAngle = 60 * kDegree, kSmallAngleNonObtuse = 30 * kDegree;
constexpr double kFanAngle = 80 * kDegree, kTwoPi = 2 * M_PI;
constexpr double kFanFactor = 0.49;
}  // namespace

// The fixed edges at v in counter-clockwise order into spokes_ (empty if v has none), and
// the distance from v to its link.
double Refiner::readStar(uint32_t v) {
  spokes_.clear();
  double linkDistance = INFINITY;
  const double* pv = P(v);
  uint32_t e0 = T_.vertexEdge[v], e = e0;
  bool badBeforeFirst = false;
  do {
    uint32_t t = e / 3;
    bool inside = T_.inDomain(t);
    if (T_.isFixed(e)) {
      const double* pu = P(T_.tri[next(e)]);
      spokes_.push_back({T_.tri[next(e)], portableAtan2(pu[1] - pv[1], pu[0] - pv[0]), inside, false});
    }
    bool bad = inside && worstCorner(t).k >= 0;
    (spokes_.empty() ? badBeforeFirst : spokes_.back().sectorBad) |= bad;
    if (!T_.isGhost(t)) {
      const double *b = P(T_.tri[next(e)]), *c = P(T_.tri[prev(e)]);
      double dx = c[0] - b[0], dy = c[1] - b[1];
      double s = std::clamp(((pv[0] - b[0]) * dx + (pv[1] - b[1]) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
      double q[2] = {b[0] + s * dx, b[1] + s * dy};
      linkDistance = std::min(linkDistance, std::sqrt(dist2(pv, q)));
    }
    e = T_.opp[prev(e)];
  } while (e != e0);
  if (!spokes_.empty()) spokes_.back().sectorBad |= badBeforeFirst;
  return linkDistance;
}

double Refiner::sectorAngle(size_t i) const {
  if (spokes_.size() == 1) return kTwoPi;
  double a = spokes_[(i + 1) % spokes_.size()].direction - spokes_[i].direction;
  return a <= 0 ? a + kTwoPi : a;
}

// The fan radius input vertex v calls for (0: no fan): it has a small domain sector, and with
// onlyWhereBad one that holds a triangle missing the target.
double Refiner::fanRadius(uint32_t v, bool onlyWhereBad) {
  // Non-obtuse with exact feet builds no fans: small corners are cut at altitude feet instead
  // (cutAtFeet, and the repairs' splits at feet), right angles the feet make exact. The fans'
  // arcs split the segments at small corners, and each split of a segment with a thin pocket
  // on its other side (a polygon near its hull) costs points there too: CG:SHOP non-obtuse
  // 20,257 -> 13,455 Steiner points (without exact feet the fans are needed: 95 of 150
  // solved without them).
  if (feet_) return 0;
  if (role_[v] != kInput || T_.vertexEdge[v] == kNone || fanRadius_[v] > 0) return 0;
  double link = readStar(v);
  const double smallSector = nonObtuse_ ? kSmallAngleNonObtuse : kSmallAngle;
  bool small = false;
  for (size_t i = 0; i < spokes_.size(); ++i)
    small |= spokes_[i].sectorInside && sectorAngle(i) < smallSector &&
             (spokes_[i].sectorBad || !onlyWhereBad);
  return small && std::isfinite(link) && link * link > 100 * minEdge2_ ? kFanFactor * link : 0;
}

void Refiner::buildFan(uint32_t v, double r) {
  readStar(v);
  fanRadius_[v] = r;
  const double pv[2] = {P(v)[0], P(v)[1]};
  const size_t n = spokes_.size();
  // Split each fixed edge at v that bounds a domain sector at distance r.
  std::vector<uint32_t> shell(n, kNone);
  for (size_t i = 0; i < n; ++i) {
    bool bounds = spokes_[i].sectorInside || spokes_[(i + n - 1) % n].sectorInside;
    uint32_t e = T_.findEdge(v, spokes_[i].to);
    if (!bounds || e == kNone) continue;
    const double pu[2] = {P(spokes_[i].to)[0], P(spokes_[i].to)[1]};
    SegmentLine line = segmentLine(T_.segment.empty() ? kNone : T_.segment[e], pv, pu);
    double tv = line.param(pv), tu = line.param(pu);
    double m[2];
    line.at(tv + (tu - tv) * r / std::sqrt(dist2(pv, pu)), m);
    uint32_t s = addVertex(m, T_.segment.empty() || T_.segment[e] == kNone ? kOnHull : kOnSegment, v);
    if (T_.splitFixedEdge(e, s)) shell[i] = s;
    else dropLastVertex();
  }
  // Points on the arc of each domain sector, then the chords between consecutive points.
  std::vector<uint32_t>& ring = ring_;
  for (size_t i = 0; i < n; ++i) {
    size_t j = (i + 1) % n;
    if (!spokes_[i].sectorInside || shell[i] == kNone || shell[j] == kNone) continue;
    double angle = sectorAngle(i);
    int pieces = int(std::ceil(angle / kFanAngle));
    ring.assign(1, shell[i]);
    for (int k = 1; k < pieces; ++k) {
      double a = spokes_[i].direction + angle * k / pieces;
      double sine, cosine;
      portableSinCos(a, sine, cosine);
      double x[2] = {pv[0] + r * cosine, pv[1] + r * sine};
      uint32_t w = addVertex(x, kArc, v);
      Location loc = T_.locate(x, T_.vertexEdge[v] / 3);
      if (loc.where == Where::InTriangle && T_.inside[loc.tri] && T_.insertAt(w, loc) == w) {
        ring.push_back(w);
      } else {
        dropLastVertex();
      }
    }
    ring.push_back(shell[j]);
    for (size_t k = 0; k + 1 < ring.size(); ++k) {
      uint32_t e = T_.findEdge(ring[k], ring[k + 1]);
      if (e != kNone && !T_.isFixed(e)) T_.fixEdge(e, 0);
    }
  }
}

// Fans before refinement: every radius first (from the triangulation as it is), then the fans.
// With strategy_.lazyFans only where a small sector already holds a bad triangle; repair()
// adds the others when a bad triangle turns up at such a corner.
void Refiner::buildCornerFans() {
  std::vector<FanCentre> centres;
  for (uint32_t v = 0; v < fanRadius_.size(); ++v)
    if (double r = fanRadius(v, strategy_.lazyFans))
      centres.push_back({v, r, smallestSector(), 0});  // (the star fanRadius read)
  if (strategy_.wideFans) widenFans(centres);
  for (const FanCentre& c : centres) buildFan(c.vertex, c.radius);
}

// The smallest domain sector between the spokes readStar() found.
double Refiner::smallestSector() const {
  double smallest = kTwoPi;
  for (size_t i = 0; i < spokes_.size(); ++i)
    if (spokes_[i].sectorInside) smallest = std::min(smallest, sectorAngle(i));
  return smallest;
}

// Wide fans (Strategy::wideFans). Strict acute triangles in a wedge of angle a between two
// segments are at most about as long as the wedge is wide, all but the one isosceles triangle
// of the fan at its tip: past the fan, the wedge is filled with points spaced in a ratio of
// about 1 + a, in the order of ln(R / r) / a of them for a wedge R long and a fan of radius r,
// and the grading spreads into the faces beside it. So each fan grows from kFanFactor to kWideFan
// times the distance from its corner to the link, as far as the fans around it leave room
// (two fans keep their disks kFanGap of their distance apart): the smallest corners first,
// and a fan at a corner over kYieldRatio times as wide gives up to 1 - kYield of its radius to
// a fan at a smaller one, whose room is worth far more points. CG:SHOP acute: 53,888 -> 47,429
// Steiner points (kWideFan 0.7: 48,696, 0.85: 49,510; widening only corners under 20 degrees:
// 48,477); A.poly, the plate, the airfoil, the text outlines and random points the same, Lake
// Superior 228 -> 230.
constexpr double kWideFan = 0.8, kFanGap = 0.98, kYieldRatio = 4, kYield = 0.2;

void Refiner::widenFans(std::vector<FanCentre>& centres) const {
  std::vector<size_t> order(centres.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  // (std::sort with the index as the tie-break, not std::stable_sort, whose temporary buffer
  // trips AddressSanitizer with libstdc++ 12: see validate.cpp.)
  std::sort(order.begin(), order.end(), [&](size_t i, size_t j) {
    return centres[i].sector != centres[j].sector ? centres[i].sector < centres[j].sector : i < j;
  });
  // The centres by x, so that each looks only at those within reach of its widest fan.
  std::vector<size_t> byX(centres.size());
  for (size_t i = 0; i < byX.size(); ++i) byX[i] = i;
  auto x = [&](size_t i) { return P(centres[i].vertex)[0]; };
  std::sort(byX.begin(), byX.end(),
            [&](size_t i, size_t j) { return x(i) != x(j) ? x(i) < x(j) : i < j; });
  // Each fan's widest from its link (its radius, before any neighbour shrinks it).
  double largest = 0;
  for (FanCentre& c : centres) {
    c.widest = kWideFan / kFanFactor * c.radius;
    largest = std::max(largest, c.widest);
  }
  std::vector<uint8_t> settled(centres.size(), 0);
  for (size_t i : order) {
    FanCentre& c = centres[i];
    const double reach = (c.widest + largest) / kFanGap;
    auto near = [&](auto visit) {
      auto first = std::lower_bound(byX.begin(), byX.end(), x(i) - reach,
                                    [&](size_t j, double value) { return x(j) < value; });
      for (auto it = first; it != byX.end() && x(*it) <= x(i) + reach; ++it)
        if (*it != i)
          visit(centres[*it], settled[*it], std::sqrt(dist2(P(c.vertex), P(centres[*it].vertex))));
    };
    double radius = c.widest;
    near([&](const FanCentre& other, bool otherSettled, double d) {
      const bool yields = !otherSettled && other.sector > kYieldRatio * c.sector;
      radius = std::min(radius, kFanGap * d - (yields ? kYield : 1) * other.radius);
    });
    c.radius = std::max(c.radius, radius);
    settled[i] = 1;
    near([&](FanCentre& other, bool, double d) {
      other.radius = std::min(other.radius, kFanGap * d - c.radius);
    });
  }
}

// Chords are fixed only while refinement runs; the output knows them as plain edges.
void Refiner::releaseChords() {
  for (uint32_t e = 0; e < 3 * T_.triangleSlots(); ++e)
    if (!T_.isFree(e / 3) && T_.isFixed(e) && !T_.isGhost(e / 3) && isChord(e)) T_.unfixEdge(e);
}

// Candidate points (x, y, squared distance to the nearest vertex), farthest first, ties in
// the order found: an insertion sort (a few dozen entries; the same order in every standard
// library).
void sortFarthestFirst(std::vector<std::array<double, 3>>& points) {
  for (size_t i = 1; i < points.size(); ++i)
    for (size_t j = i; j > 0 && points[j - 1][2] < points[j][2]; --j) std::swap(points[j - 1], points[j]);
}

Refiner::ShortestEdge Refiner::shortestEdge(uint32_t t) const {
  const uint32_t* v = &T_.tri[3 * t];
  int s = 0;
  for (int k = 1; k < 3; ++k)
    if (dist2(P(v[(k + 1) % 3]), P(v[(k + 2) % 3])) < dist2(P(v[(s + 1) % 3]), P(v[(s + 2) % 3])))
      s = k;
  ShortestEdge e{P(v[(s + 1) % 3]), P(v[(s + 2) % 3]), {0, 0}, 0};
  circumcenter(P(v[0]), P(v[1]), P(v[2]), e.center);
  e.radius2 = dist2(e.center, e.p);
  return e;
}

// A walk on the Voronoi diagram near t: breadth first over up to 64 triangles of the domain
// reached from t across edges no segment lies on, through those whose circumcentre c passes
// keep(c); visit(c, r2) for each of those (r2: its circumradius squared, the distance from c
// to its nearest vertices).
template <class Keep, class Visit>
void Refiner::walkVoronoi(uint32_t t, Keep keep, Visit visit) const {
  uint32_t ring[64];
  size_t head = 0, count = 0;
  ring[count++] = t;
  while (head < count) {
    uint32_t u = ring[head++];
    for (uint32_t e = 3 * u; e < 3 * u + 3; ++e) {
      uint32_t n = T_.opp[e] / 3;
      if (T_.isFixed(e) || !T_.inDomain(n) || count == 64) continue;
      if (std::find(ring, ring + count, n) != ring + count) continue;
      const uint32_t* w = &T_.tri[3 * n];
      double c[2];
      circumcenter(P(w[0]), P(w[1]), P(w[2]), c);
      if (!std::isfinite(c[0]) || !std::isfinite(c[1]) || !keep(c)) continue;
      ring[count++] = n;
      visit(c, dist2(c, P(w[0])));
    }
  }
}

// The points of slice(pq), pq the shortest edge of t, farthest from all vertices first: the
// Voronoi vertices (circumcentres) met walking from t's circumcentre while they stay in the
// slice (or in t's circumdisk, see below); each is as far from its nearest vertex as its
// triangle's circumradius.
void Refiner::slicePoints(uint32_t t, std::vector<std::array<double, 3>>& out) const {
  const ShortestEdge edge = shortestEdge(t);
  const double *p = edge.p, *q = edge.q, *center = edge.center;
  const double radius2 = edge.radius2;
  double ux = q[0] - p[0], uy = q[1] - p[1], len2 = ux * ux + uy * uy;
  // Where the candidates are weighed (Strategy::weighPoints: insertSparingSegments counts the
  // bad triangles each leaves), those of t's whole circumdisk compete, not only the slice's
  // (CG:SHOP non-obtuse 34,596 -> 33,313 Steiner points, acute 61,129 -> 58,600).
  const bool wholeDisk = strategy_.weighPoints;
  auto inSlice = [&](const double* c) {
    double along = (c[0] - p[0]) * ux + (c[1] - p[1]) * uy;
    return (wholeDisk || (along > 0 && along < len2)) && dist2(c, center) < radius2;
  };
  out.assign(1, {center[0], center[1], radius2});
  walkVoronoi(t, inSlice, [&](const double* c, double r2) { out.push_back({c[0], c[1], r2}); });
  sortFarthestFirst(out);
}


// Quality refinement's Steiner points for t, which has an angle under the bound alpha (after
// the seed's locally optimal Steiner points, Erten & Üngör 2009), best first: with pq the
// shortest edge of t, points of the region where p, q, x would make a triangle with every
// angle at least alpha, inside t's circumdisk (so that t goes), farthest from all vertices
// first (insertSparingSegments takes the first that spares the segments). Candidates are
// Üngör's off-centre (on pq's bisector where the angle at x is a little over alpha; the
// circumcentre if that is nearer to pq) and the Voronoi vertices met walking from t's
// circumcentre inside its circumdisk (each as far from every vertex as its triangle's
// circumradius). Circumcentres alone (Ruppert) stop terminating near 34 degrees.
void Refiner::qualityPoints(uint32_t t, std::vector<std::array<double, 3>>& out) const {
  const ShortestEdge edge = shortestEdge(t);
  const double *p = edge.p, *q = edge.q, *center = edge.center;
  const double radius2 = edge.radius2;
  // pq's bisector, pointing to t's side (t is counter-clockwise: left of p->q).
  double ux = q[0] - p[0], uy = q[1] - p[1], len = std::sqrt(ux * ux + uy * uy);
  double mid[2] = {0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1])}, n[2] = {-uy / len, ux / len};
  // tan(bound / 2) from the cosine by IEEE-exact operations (std::tan could round differently
  // in the WebAssembly build's libm).
  const double cosBound = cosQuality_;
  double offHeight = 0.5 * len / std::sqrt((1 - cosBound) / (1 + cosBound));
  double centerHeight = (center[0] - mid[0]) * n[0] + (center[1] - mid[1]) * n[1];
  double x[2] = {center[0], center[1]};
  if (centerHeight > offHeight) x[0] = mid[0] + offHeight * n[0], x[1] = mid[1] + offHeight * n[1];
  out.assign(1, {x[0], x[1], dist2(x, p)});  // (for the off-centre: an upper bound)
  auto atLeast = [&](const double* a, const double* b, const double* c) {  // angle bac
    double bx = b[0] - a[0], by = b[1] - a[1], cx = c[0] - a[0], cy = c[1] - a[1];
    return bx * cx + by * cy <= cosBound * std::sqrt((bx * bx + by * by) * (cx * cx + cy * cy));
  };
  auto inRegion = [&](const double* c) {
    return (c[0] - mid[0]) * n[0] + (c[1] - mid[1]) * n[1] > 0 && atLeast(p, q, c) &&
           atLeast(q, c, p) && atLeast(c, p, q);
  };
  auto inDisk = [&](const double* c) { return dist2(c, center) < radius2; };
  walkVoronoi(t, inDisk, [&](const double* c, double r2) {
    if (inRegion(c)) out.push_back({c[0], c[1], r2});
  });
  sortFarthestFirst(out);
}

Refiner::CavityRim Refiner::examineCavity(uint32_t from, const double* x) {
  cavity_.assign(1, from);
  return growCavity(x);
}

// The cavity: the triangles reachable from those in cavity_ without crossing a fixed edge
// whose circumcircle holds x (into cavity_). Fixed edges on its rim are the subsegments x
// could encroach.
Refiner::CavityRim Refiner::growCavity(const double* x) {
  uint32_t encroached = kNone, beyond = kNone;
  double encroachedLen = -1;
  for (size_t i = 0; i < cavity_.size(); ++i) {
    uint32_t t = cavity_[i];
    for (uint32_t e = 3 * t; e < 3 * t + 3; ++e) {
      uint32_t n = T_.opp[e] / 3;
      const double *a = P(T_.tri[e]), *b = P(T_.tri[next(e)]);
      if (T_.isFixed(e)) {
        double d = dot2d(x, a, b);
        bool inDisk = nonObtuse_ ? d < 0 : d <= 0;  // a right angle at x is allowed then
        if (inDisk && dist2(a, b) > encroachedLen) encroached = e, encroachedLen = dist2(a, b);
        if (orient2d(a, b, x) < 0 && beyond == kNone) beyond = e;
        continue;
      }
      if (T_.isGhost(n) || std::find(cavity_.begin(), cavity_.end(), n) != cavity_.end())
        continue;
      const uint32_t* w = &T_.tri[3 * n];
      if (incircle(P(w[0]), P(w[1]), P(w[2]), x) > 0) cavity_.push_back(n);
    }
    if (cavity_.size() > kCavityExamined) break;
  }
  return {encroached, beyond};
}

// Inserts x, found for triangle `from` (x lies in its circumdisk), unless it encroaches a
// subsegment or lies beyond one: then that subsegment is split instead.
bool Refiner::insertSteiner(uint32_t from, const double* x) {
  if (!std::isfinite(x[0]) || !std::isfinite(x[1])) return false;
  return insertSteiner(from, x, examineCavity(from, x));
}

bool Refiner::insertSteiner(uint32_t from, const double* x, CavityRim rim) {
  auto [encroached, beyond] = rim;
  if (encroached != kNone) return splitSubsegment(encroached);
  Location loc = T_.locate(x, from);
  if (loc.where == Where::Failed || loc.where == Where::OnVertex) return false;
  bool reachable = std::find(cavity_.begin(), cavity_.end(), loc.tri) != cavity_.end();
  if (!reachable || !T_.inDomain(loc.tri)) {
    if (beyond != kNone) return splitSubsegment(beyond);
    // Relocation leaves the triangulation not quite Delaunay in places, and the cavity can
    // then miss x: the straight walk from `from` to x decides instead.
    uint32_t reached = kNone, crossed = firstFixedCrossed(from, x, reached);
    if (crossed != kNone) return splitSubsegment(crossed);
    if (reached == kNone || !T_.inDomain(reached)) return false;
  }
  if (loc.where == Where::OnEdge && T_.isFixed(loc.edge)) return splitSubsegment(loc.edge);
  for (uint32_t k = 0; k < 3; ++k)
    if (dist2(x, P(T_.tri[3 * loc.tri + k])) < minEdge2_) return false;
  uint32_t v = addVertex(x, kFree);
  if (T_.insertAt(v, loc) != v) {
    dropLastVertex();
    return false;
  }
  return true;
}

// Walks the straight line from the centroid of t to x: the first fixed half-edge it crosses,
// else kNone with the triangle holding x in `reached` (kNone too if the walk meets a vertex
// or leaves the triangulation).
uint32_t Refiner::firstFixedCrossed(uint32_t t, const double* x, uint32_t& reached) const {
  const uint32_t* v = &T_.tri[3 * t];
  double g[2] = {(P(v[0])[0] + P(v[1])[0] + P(v[2])[0]) / 3, (P(v[0])[1] + P(v[1])[1] + P(v[2])[1]) / 3};
  reached = kNone;
  uint32_t entry = kNone;
  for (uint32_t steps = 0; steps < 4 * T_.triangleSlots(); ++steps) {
    uint32_t exit = kNone;
    for (uint32_t e = 3 * t; e < 3 * t + 3 && exit == kNone; ++e) {
      if (e == entry) continue;
      const double *a = P(T_.tri[e]), *b = P(T_.tri[next(e)]);
      if (orient2d(a, b, x) >= 0) continue;
      double sa = orient2d(g, x, a), sb = orient2d(g, x, b);
      if (sa == 0 || sb == 0) return kNone;
      if ((sa < 0) != (sb < 0)) exit = e;
    }
    if (exit == kNone) {
      reached = t;
      return kNone;
    }
    if (T_.isFixed(exit)) return exit;
    entry = T_.opp[exit];
    t = entry / 3;
    if (T_.isGhost(t)) return kNone;
  }
  return kNone;
}

// Restores the Delaunay property around vertex a after it moved: otherwise a triangle whose
// circumcircle now holds a keeps standing, and later insertions (whose cavities assume
// Delaunay) can miss it. Flips only touch edges next to triangles that miss the target: two
// acute triangles always meet at a locally Delaunay edge. Each star triangle gives its spoke
// from a and its link edge (the other spoke is the next triangle's): every edge once.
void Refiner::legalizeStar(uint32_t a) {
  std::vector<uint32_t>& stack = flips_;
  stack.clear();
  uint32_t e0 = T_.vertexEdge[a], e = e0;
  do {
    stack.push_back(e);
    stack.push_back(next(e));
    e = T_.opp[prev(e)];
  } while (e != e0);
  T_.legalize(stack);
}

// Every triangle around vertex a meets the target.
bool Refiner::starMeetsTarget(uint32_t a) const {
  uint32_t e0 = T_.vertexEdge[a], e = e0;
  do {
    uint32_t t = e / 3;
    if (T_.inDomain(t) && worstCorner(t).k >= 0) return false;
    e = T_.opp[prev(e)];
  } while (e != e0);
  return true;
}

Refiner::SegmentLine Refiner::segmentLine(uint32_t seg, const double* p, const double* q) const {
  const double *A = p, *B = q;
  if (seg != kNone) {
    A = &input_.points[2 * size_t(input_.segments[2 * size_t(seg)])];
    B = &input_.points[2 * size_t(input_.segments[2 * size_t(seg) + 1])];
  }
  double ux = B[0] - A[0], uy = B[1] - A[1];
  return {A, B, ux, uy, ux * ux + uy * uy, options_.exactSegments};
}

// Puts vertex a at (x, y); true if its star (link in ring_) stays a valid triangulation
// (exact) and meets the target there.
bool Refiner::moveTo(uint32_t a, double x, double y) {
  double* where = &T_.pts[2 * size_t(a)];
  where[0] = x, where[1] = y;
  // The right angle at a is what most samples fail: tested first (the answer is the same).
  if (acute_ || nonObtuse_)
    for (size_t i = 0, n = ring_.size(); i < n; ++i) {
      if (!ringInside_[i]) continue;
      double d = dot2d(where, P(ring_[i]), P(ring_[i + 1 < n ? i + 1 : 0]));
      if (nonObtuse_ ? d < 0 : d <= 0) return false;
    }
  // No edge shorter than the refinement's smallest (a slide into a stretch a few ulps long
  // left two segment vertices 40 ulps apart, too close for their subsegment to have a
  // direction).
  for (uint32_t w : ring_)
    if (dist2(where, P(w)) < minEdge2_) return false;
  for (size_t i = 0, n = ring_.size(); i < n; ++i)
    if (orient2d(P(ring_[i]), P(ring_[i + 1 < n ? i + 1 : 0]), where) <= 0) return false;
  return starMeetsTarget(a);
}

// Whether x lies within rounding reach of a fixed edge of a's link (as Triangulation::
// splitFixedEdge refuses for a new segment vertex).
bool Refiner::nearFixedLinkEdge(uint32_t a, const double* x) const {
  uint32_t e0 = T_.vertexEdge[a], e = e0;
  do {
    uint32_t link = next(e);
    if (T_.isFixed(link) && nearSegment(P(T_.tri[link]), P(T_.tri[next(link)]), x)) return true;
    e = T_.opp[prev(e)];
  } while (e != e0);
  return false;
}

// Moves a Steiner vertex on a segment along that segment (between its neighbours on it) to
// where its whole star meets the target and stays a valid triangulation: the boundary's
// counterpart of relocation. Positions are taken on the original input segment.
bool Refiner::slide(uint32_t a) {
  uint32_t spokes[2];
  if (!segmentStar(a, spokes)) return false;
  const double *p = P(T_.tri[next(spokes[0])]), *q = P(T_.tri[next(spokes[1])]);
  SegmentLine line = segmentLine(T_.segment[spokes[0]], p, q);
  double tp = line.param(p), tq = line.param(q);
  const double old[2] = {P(a)[0], P(a)[1]};
  auto tryAt = [&](double t) {
    double x[2];
    line.at(t, x);
    return moveTo(a, x[0], x[1]) && !nearFixedLinkEdge(a, x);
  };
  // With strategy_.exactSlide the middle of the longest stretch: it finds narrow ones the
  // samples below miss. (moveTo before nearFixedLinkEdge: it rejects most positions, and more
  // cheaply.)
  if (strategy_.exactSlide && slideStretches(tp, tq, line, 0)) {
    const std::array<double, 2>* longest = &slideStretches_[0];
    for (const auto& st : slideStretches_)
      if (st[1] - st[0] > (*longest)[1] - (*longest)[0]) longest = &st;
    if (tryAt(0.5 * ((*longest)[0] + (*longest)[1]))) return true;
  }
  // Only samples within the stretches (widened by a margin for rounding, also the rounding of
  // the point itself) can pass moveTo's exact test; the others are not tried (with exact
  // segments each costs exact predicates to put it on the line).
  const double reach = std::fabs(line.start[0]) + std::fabs(line.start[1]) +
                       std::fabs(line.ux) + std::fabs(line.uy);
  const double margin = 1e-9 * std::fabs(tq - tp) +
                        8 * std::numeric_limits<double>::epsilon() * reach / std::sqrt(line.u2);
  if (!slideStretches(tp, tq, line, margin)) return false;
  for (int k : {8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14}) {
    double t = tp + (tq - tp) * k / 16.0;
    bool within = false;
    for (const auto& st : slideStretches_) within |= st[0] < t && t < st[1];
    if (within && tryAt(t)) return true;
  }
  moveTo(a, old[0], old[1]);
  return false;
}

// Where along the segment line (parameter t strictly between tp and tq) a vertex with link
// ring_ keeps every star triangle counter-clockwise, and (acute, non-obtuse) those in the
// domain (ringInside_) with right or sharper angles: each
// triangle (X(t), x, y) asks t to be on one side of three values (orientation, the angles at x
// and y: linear in t) and outside the interval where the line crosses the diametral disk of
// x-y (the angle at X). Leaves the stretches of t that are left in slideStretches_ (open
// intervals, in increasing order), each bound relaxed by margin; false if there are none.
// (In floating point: moveTo() checks a point exactly.)
bool Refiner::slideStretches(double tp, double tq, const SegmentLine& line, double margin) {
  double lo = std::min(tp, tq), hi = std::max(tp, tq);
  const double s[2] = {line.start[0], line.start[1]}, d[2] = {line.ux, line.uy};
  // With a margin the bounds are relaxed by their rounding error too (err: a bound on the
  // error of a sum of two products of magnitude m), so that no point that passes the exact
  // test is left out; a constraint whose slope may be 0 by rounding then counts as none.
  const double eps = std::numeric_limits<double>::epsilon();
  auto err = [&](double m) { return margin > 0 ? 8 * eps * m : 0; };
  auto keep = [&](double f0, double f1, double m0, double m1) {  // f0 + t f1 > 0
    const double e0 = err(m0), e1 = err(m1);
    if (std::fabs(f1) > e1) {
      const double bound = -f0 / f1, slack = margin + (e0 + std::fabs(bound) * e1) / (std::fabs(f1) - e1);
      if (f1 > 0) lo = std::max(lo, bound - slack);
      else hi = std::min(hi, bound + slack);
    } else if (margin > 0 ? f0 < -e0 : !(f0 > 0)) {  // (margin: 0 may be a right angle all along)
      hi = -INFINITY;
    }
  };
  auto dot = [](const double* u, const double* v) { return u[0] * v[0] + u[1] * v[1]; };
  auto mag = [](const double* u, const double* v) {
    return std::fabs(u[0] * v[0]) + std::fabs(u[1] * v[1]);
  };
  std::vector<std::array<double, 2>>& cut = stretches_;
  cut.clear();
  for (size_t i = 0; i < ring_.size() && lo < hi; ++i) {
    const double *x = P(ring_[i]), *y = P(ring_[(i + 1) % ring_.size()]);
    double yx[2] = {y[0] - x[0], y[1] - x[1]}, sx[2] = {s[0] - x[0], s[1] - x[1]};
    double sy[2] = {s[0] - y[0], s[1] - y[1]}, xy[2] = {-yx[0], -yx[1]};
    const double yxPerp[2] = {yx[1], -yx[0]};  // X left of x->y: (X - x) . yxPerp < 0
    keep(yx[0] * sx[1] - yx[1] * sx[0], yx[0] * d[1] - yx[1] * d[0], mag(sx, yxPerp), mag(d, yxPerp));
    // Outside the domain only the orientation counts; so it does for a minimum angle alone
    // (quality), whose bounds are not taken here.
    if (!ringInside_[i] || !(acute_ || nonObtuse_)) continue;
    keep(dot(sx, yx), dot(d, yx), mag(sx, yx), mag(d, yx));  // angle at x
    keep(dot(sy, xy), dot(d, xy), mag(sy, xy), mag(d, xy));  // angle at y
    double c[2] = {s[0] - 0.5 * (x[0] + y[0]), s[1] - 0.5 * (x[1] + y[1])};
    double dd = dot(d, d), dc = dot(d, c), cc = dot(c, c), r2 = 0.25 * dot(yx, yx);
    double disc = dc * dc - dd * (cc - r2);
    if (disc > 0) {
      double root = std::sqrt(disc);
      // (Near a tangent the roots move by the square root of disc's error.)
      double slack = margin > 0 ? margin + std::sqrt(err(dc * dc + dd * (cc + r2))) / dd : 0;
      cut.push_back({(-dc - root) / dd + slack, (-dc + root) / dd - slack});
    }
  }
  std::vector<std::array<double, 2>>& stretches = slideStretches_;
  stretches.clear();
  if (!(lo < hi)) return false;
  std::sort(cut.begin(), cut.end());
  double from = lo;
  for (const auto& iv : cut) {
    if (iv[0] > from) stretches.push_back({from, std::min(iv[0], hi)});
    from = std::max(from, iv[1]);
    if (from >= hi) break;
  }
  if (from < hi) stretches.push_back({from, hi});
  return !stretches.empty();
}

// Leaves in clipPoly_ the convex region of points p for which every triangle (p, x, y) over a
// link edge x->y of linkEdges_ is counter-clockwise with angles below the bound at x and y: p
// left of x->y and inside its slab, (p-x).(y-x) > 0 and (p-y).(x-y) > 0 for 90 degrees; for a
// bound below 90 the slab narrows to a wedge whose sides are x->y turned by the bound about x
// (counter-clockwise) and about y (clockwise). (Only for acute and non-obtuse; with a minimum
// angle alpha, p also lies beyond x->y turned by alpha about x and about y: angles of at least
// alpha there.) Clipped from the bounding box of the edges' ends; empty if there is no such
// point. (The angle at p is no half-plane: moveTo checks it.)
void Refiner::clipToLinkSlabs(bool wedges) {
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (const auto& edge : linkEdges_)
    for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], P(edge[0])[k]), hi[k] = std::max(hi[k], P(edge[0])[k]);
  // Every clip adds at most one corner: the buffers are sized before the loops, which run on
  // raw pointers (the hottest loop of the improvement pass).
  const size_t clips = linkEdges_.size() * (1 + 2 * (acute_ || nonObtuse_) + 2 * (options_.minAngle > 0));
  const size_t room = 4 + clips + 1;
  if (clipWork_.size() < 2 * room) clipWork_.resize(2 * room);
  if (clipSide_.size() < room + 1) clipSide_.resize(room + 1);
  std::array<double, 2>* poly = clipWork_.data();
  std::array<double, 2>* next = poly + room;
  double* f = clipSide_.data();
  size_t n = 4;
  poly[0] = {lo[0], lo[1]}, poly[1] = {hi[0], lo[1]}, poly[2] = {hi[0], hi[1]}, poly[3] = {lo[0], hi[1]};
  auto clip = [&](double nx, double ny, double c) {  // keep n.p > c
    size_t kept = 0;
    for (size_t i = 0; i < n; ++i) {
      f[i] = nx * poly[i][0] + ny * poly[i][1] - c;
      kept += f[i] > 0;
    }
    if (kept == n) return;  // (this is where the time goes: most clips cut nothing)
    f[n] = f[0];
    size_t m = 0;
    for (size_t i = 0; i < n && kept > 0; ++i) {
      const auto &p = poly[i], &q = poly[i + 1 < n ? i + 1 : 0];
      double fp = f[i], fq = f[i + 1];
      if (fp > 0) next[m++] = p;
      if ((fp > 0) != (fq > 0) && fp != fq) {
        double s = fp / (fp - fq);
        next[m++] = {p[0] + s * (q[0] - p[0]), p[1] + s * (q[1] - p[1])};
      }
    }
    std::swap(poly, next);
    n = m;
  };
  const double c = wedges ? cosMax_ : 0, s = wedges ? std::sqrt(1 - c * c) : 1;
  const double cm = cosMin_, sm = std::sqrt(1 - cm * cm);
  for (size_t i = 0; i < linkEdges_.size() && n > 0; ++i) {
    const double *x = P(linkEdges_[i][0]), *y = P(linkEdges_[i][1]);
    double dx = y[0] - x[0], dy = y[1] - x[1];
    if (acute_ || nonObtuse_) {
      double rx = dx * c - dy * s, ry = dx * s + dy * c;   // x->y turned by the bound about x
      clip(ry, -rx, ry * x[0] - rx * x[1]);                // p right of that ray
      double qx = -dx * c - dy * s, qy = dx * s - dy * c;  // y->x turned back by it about y
      clip(-qy, qx, -qy * y[0] + qx * y[1]);               // p left of that ray
    }
    if (options_.minAngle > 0) {  // the same rays for the smallest angle, p on their far sides
      double rx = dx * cm - dy * sm, ry = dx * sm + dy * cm;
      clip(-ry, rx, -ry * x[0] + rx * x[1]);
      double qx = -dx * cm - dy * sm, qy = dx * sm - dy * cm;
      clip(qy, -qx, qy * y[0] - qx * y[1]);
    }
    clip(-dy, dx, -dy * x[0] + dx * x[1]);
  }
  clipPoly_.assign(poly, poly + n);
}

// The mean of clipPoly_'s corners (inside it, being convex), if it is a region at all.
bool Refiner::clipCentroid(double* out) const {
  if (clipPoly_.size() < 3) return false;
  out[0] = out[1] = 0;
  for (const auto& p : clipPoly_)
    out[0] += p[0] / double(clipPoly_.size()), out[1] += p[1] / double(clipPoly_.size());
  return true;
}

// The link of free vertex a in ring_ (counter-clockwise), every triangle of its star counted
// in the domain (ringInside_); false if a is no free vertex, or its star has a fixed edge or
// leaves the domain (relocate() keeps such a star's shape).
bool Refiner::freeStar(uint32_t a) {
  if (role_[a] != kFree) return false;
  uint32_t e0 = T_.vertexEdge[a], e = e0;
  ring_.clear();
  do {
    if (T_.isFixed(e) || !T_.inDomain(e / 3)) return false;
    ring_.push_back(T_.tri[next(e)]);
    e = T_.opp[prev(e)];
  } while (e != e0);
  ringInside_.assign(ring_.size(), 1);
  return true;
}

// The link of vertex a on a segment (or on a point set's hull) in ring_, which of its star's
// triangles are in the domain (ringInside_), and its two fixed edges, the pieces of one segment
// (spokes); false if a is no such vertex, its star holds a ghost, or it has other fixed edges.
bool Refiner::segmentStar(uint32_t a, uint32_t spokes[2]) {
  if (role_[a] != kOnSegment && role_[a] != kOnHull) return false;
  uint32_t count = 0, e0 = T_.vertexEdge[a], e = e0;
  ring_.clear();
  ringInside_.clear();
  do {
    if (T_.isGhost(e / 3)) return false;
    if (T_.isFixed(e)) {
      if (count == 2) return false;
      spokes[count++] = e;
    }
    ring_.push_back(T_.tri[next(e)]);
    ringInside_.push_back(T_.inside[e / 3]);
    e = T_.opp[prev(e)];
  } while (e != e0);
  return count == 2 && T_.segment[spokes[0]] == T_.segment[spokes[1]];
}

// Moves free vertex a (seed 2.2) to a point where every triangle of its star meets the
// target, keeping the star's topology: the point must lie in the kernel of a's link and in
// the slab of each link edge (angles at the link vertices below the bound; with a minimum
// angle, also at least that), outside each link edge's diametral disk (angle at a below 90).
// The slabs and the kernel are half-planes: their intersection is a convex polygon
// (clipToLinkSlabs); its centroid and points between it and the corners are tried, and the
// first whose star passes the exact test is kept.
bool Refiner::relocate(uint32_t a) {
  if (!freeStar(a)) return false;
  const std::vector<uint32_t>& ring = ring_;
  linkEdges_.clear();
  for (size_t i = 0; i < ring.size(); ++i) linkEdges_.push_back({ring[i], ring[(i + 1) % ring.size()]});
  if (!linkLeavesRoom()) return false;
  double old[2] = {P(a)[0], P(a)[1]};
  // Below 90 degrees the bound's wedges first, then the plain slabs: the angle at a is no
  // half-plane, and the wider region's samples find places the narrower one's miss.
  for (bool wedges : {strictMax_, false}) {
    clipToLinkSlabs(wedges);
    const std::vector<std::array<double, 2>>& poly = clipPoly_;
    double centroid[2];
    if (clipCentroid(centroid) && !((acute_ || nonObtuse_) && insideOneDiametralDisk(poly))) {
      if (moveTo(a, centroid[0], centroid[1])) return true;
      for (double w : {0.5, 0.25})
        for (const auto& p : poly)
          if (moveTo(a, centroid[0] + w * (p[0] - centroid[0]), centroid[1] + w * (p[1] - centroid[1])))
            return true;
    }
    if (!wedges) break;
  }
  // (CG:SHOP non-obtuse, exact segments: 36,266 -> 34,331 Steiner points.)
  if (nonObtuse_ && relocateOntoPerpendicular(a, old)) return true;
  moveTo(a, old[0], old[1]);
  return false;
}

// Acute and non-obtuse: whether the region clipToLinkSlabs would clip from linkEdges_ may be
// anything but empty. Where two of its edges x->y, y->z turn right at y (acute: or go straight
// on), a point p left of both makes angles at y in triangles (p, x, y) and (p, y, z) that sum
// to 360 degrees less the turn, at least 180 (more than 180 where they turn right), so one of
// them is right or obtuse. For relocation that is half of the regions on CG:SHOP's slowest
// acute instance, clipped to nothing at full cost (exact, so that it gives up only moves the
// exact test would refuse); mergePoint then takes the pair's midpoint, as for any empty
// region (where clipping sometimes left a rounding sliver's centre).
bool Refiner::linkLeavesRoom() const {
  if (!(acute_ || nonObtuse_)) return true;
  const size_t n = linkEdges_.size();
  for (size_t i = 0; i < n; ++i) {
    const uint32_t y = linkEdges_[i][1];
    for (size_t k = 1; k < n; ++k) {  // the next edge first: links come in order
      const auto& after = linkEdges_[(i + k) % n];
      if (after[0] != y) continue;
      const double turn = orient2d(P(linkEdges_[i][0]), P(y), P(after[1]));
      if (nonObtuse_ ? turn < 0 : turn <= 0) return false;
      break;
    }
  }
  return true;
}

// Whether every corner of convex polygon `poly` lies inside the diametral disk of one edge of
// the link in ring_, with a margin: then so does every point relocate() samples in it (convex
// combinations of the corners), and a would make an obtuse angle there, which moveTo refuses in
// acute and non-obtuse. A third of the regions clipped on CG:SHOP's slowest acute instance are
// such, and trying their samples in vain took 8% of its time. (The test only gives up moves, so
// whatever rounding does it cannot let a bad one through; no mesh we have changed by it.)
bool Refiner::insideOneDiametralDisk(const std::vector<std::array<double, 2>>& poly) const {
  const size_t n = ring_.size();
  for (size_t i = 0; i < n; ++i) {
    const double *u = P(ring_[i]), *v = P(ring_[i + 1 < n ? i + 1 : 0]);
    bool all = true;
    for (size_t k = 0; k < poly.size() && all; ++k) {
      const double ux = u[0] - poly[k][0], uy = u[1] - poly[k][1];
      const double vx = v[0] - poly[k][0], vy = v[1] - poly[k][1];
      const double scale = (std::fabs(ux) + std::fabs(uy)) * (std::fabs(vx) + std::fabs(vy));
      all = ux * vx + uy * vy < -1e-9 * scale;
    }
    if (all) return true;
  }
  return false;
}

// Non-obtuse: where the link of a (ring_) runs straight through a vertex m (m and its
// neighbours in the link exactly in line, as on a segment) the two angles at m sum to 180
// degrees, so a must stand exactly on the perpendicular at m: relocation's open slabs leave
// no room for that. Tries points of that perpendicular near a's projection on it, whose
// offsets have few bits (so that the point, and the right angles, can come out exact);
// moveTo checks them exactly.
bool Refiner::relocateOntoPerpendicular(uint32_t a, const double* old) {
  const size_t n = ring_.size();
  for (size_t i = 0; i < n; ++i) {
    const double *m = P(ring_[i]), *before = P(ring_[(i + n - 1) % n]), *after = P(ring_[(i + 1) % n]);
    if (orient2d(before, m, after) != 0) continue;
    double nx = -(after[1] - m[1]), ny = after[0] - m[0];  // to the left of m->after: a's side
    double s = ((old[0] - m[0]) * nx + (old[1] - m[1]) * ny) / (nx * nx + ny * ny);
    if (!(s > 0)) continue;
    for (int bits : {8, 12, 16, 24}) {
      int e = 0;
      std::frexp(s, &e);
      double t = std::ldexp(std::nearbyint(std::ldexp(s, bits - e)), e - bits);
      if (moveTo(a, m[0] + t * nx, m[1] + t * ny)) return true;
    }
  }
  return false;
}

bool Refiner::repair(uint32_t t, Corner c, size_t weighed) {
  // Moving vertices (relocation, the removal pass) can leave edges that are not locally
  // Delaunay; a triangle standing on one is flipped away first, since the search for a new
  // point below assumes empty circumcircles.
  flips_.assign({3 * t, 3 * t + 1, 3 * t + 2});
  size_t before = touched_.size();
  T_.legalize(flips_);
  if (touched_.size() > before) return true;
  if (strategy_.lazyFans && (acute_ || nonObtuse_)) {
    for (int k = 0; k < 3; ++k) {
      uint32_t v = T_.tri[3 * t + k];
      if (v >= fanRadius_.size()) continue;
      if (double r = fanRadius(v, true)) {
        buildFan(v, r);
        return true;
      }
    }
  }
  if (!c.area) {
    // First try to repair the triangle by moving one of its Steiner points: a free one
    // anywhere in its kernel (seed 2.2), one on a segment along the segment.
    for (int k = 0; k < 3; ++k) {
      uint32_t a = T_.tri[3 * t + k];
      if (relocate(a) || (!strictMax_ && slide(a))) {
        uint32_t e0 = T_.vertexEdge[a], e = e0;
        do {
          touched_.push_back(e / 3);
          for (uint32_t f = 3 * (e / 3); f < 3 * (e / 3) + 3; ++f) touched_.push_back(T_.opp[f] / 3);
          e = T_.opp[prev(e)];
        } while (e != e0);
        legalizeStar(a);
        return true;
      }
    }
  }
  if (c.large) {
    // The edge opposite the large angle: if it is a subsegment, the apex encroaches it.
    uint32_t opposite = 3 * t + uint32_t((c.k + 1) % 3);
    if (strategy_.weighPoints && T_.isFixed(opposite) && !isChord(opposite))
      return splitWeighed(opposite, T_.tri[3 * t + c.k]);
    if (nonObtuse_ && strategy_.footOnSegments && T_.isFixed(opposite)) return splitAtFoot(t, c.k);
    if (T_.isFixed(opposite)) return splitSubsegment(opposite);
    // The farthest point of the slice; but one that encroaches a subsegment would split it,
    // and next to a sliver each split starts a chain of feet across it: a point of the slice
    // that encroaches nothing goes first, if there is one, and of those the one that leaves
    // the fewest bad triangles.
    // (Unless repairAll has just weighed t's candidates for its gain, and nothing above has
    // changed the mesh: the same candidates, the same choice.)
    if (weighed != kNotWeighed && strategy_.weighPoints) return insertWeighed(t, candidates_, weighed);
    slicePoints(t, candidates_);
    return insertSparingSegments(t, candidates_, true);
  }
  if (!c.area) {
    qualityPoints(t, candidates_);
    return insertSparingSegments(t, candidates_, false);
  }
  const uint32_t* v = &T_.tri[3 * t];
  double x[2];
  circumcenter(P(v[0]), P(v[1]), P(v[2]), x);
  return insertSteiner(t, x);
}

// Inserts one of the first kSliceTries candidate points for t (best first) whose cavity's rim
// holds no subsegment it encroaches (Strategy::weighPoints): the first such, or with
// fewestBad the one whose new triangles leave the fewest that miss the target
// (weighCandidates). Else the best, letting insertSteiner split what it encroaches.
// (fewestBad: CG:SHOP non-obtuse 36,704 -> 35,770 Steiner points, acute 62,684 -> 62,336, A.poly
// acute 81 -> 76. Quality refinement keeps the first: the count there made A.poly at 40
// degrees 138 points instead of 99.)
bool Refiner::insertSparingSegments(uint32_t t, const std::vector<std::array<double, 3>>& points,
                                    bool fewestBad) {
  if (fewestBad && strategy_.weighPoints) {
    int fewest = 0;
    return insertWeighed(t, points, weighCandidates(t, points, fewest));
  } else {
    for (size_t i = 0; strategy_.weighPoints && i < points.size() && i < kSliceTries; ++i) {
      const double* x = points[i].data();
      if (!std::isfinite(x[0]) || !std::isfinite(x[1])) continue;
      CavityRim rim = examineCavity(t, x);
      if (rim.encroached == kNone && insertSteiner(t, x, rim)) return true;
    }
  }
  return insertSteiner(t, points[0].data());
}

// Inserts candidate `chosen` for t (weighCandidates' choice), else (none, or it split a
// subsegment it encroaches after all) the best.
bool Refiner::insertWeighed(uint32_t t, const std::vector<std::array<double, 3>>& points, size_t chosen) {
  if (chosen < points.size() && insertSteiner(t, points[chosen].data())) return true;
  return insertSteiner(t, points[0].data());
}

// Of the first kSliceTries candidate points for t, the one whose insertion leaves the fewest
// bad triangles (badChange; ties to the earlier), of those that encroach no subsegment and
// lie on t's side of every fixed edge (else there is no fair count); points.size() if none.
// `fewest`: its change.
size_t Refiner::weighCandidates(uint32_t t, const std::vector<std::array<double, 3>>& points,
                                int& fewest) {
  size_t chosen = points.size();
  fewest = 0;
  for (size_t i = 0; i < points.size() && i < kSliceTries; ++i) {
    const double* x = points[i].data();
    if (!std::isfinite(x[0]) || !std::isfinite(x[1])) continue;
    CavityRim rim = examineCavity(t, x);
    if (rim.encroached != kNone || rim.beyond != kNone || cavity_.size() > kCavityExamined) continue;
    int change = badChange(x);
    if (chosen == points.size() || change < fewest) chosen = i, fewest = change;
  }
  return chosen;
}

// How many more triangles miss the target once x goes into cavity_ (examineCavity's, for a
// point that encroaches no subsegment; splitBadChange's for a split of the subsegment of
// fixed half-edge `split`, whose two sides then give way to x): the cavity's triangles give
// way to those joining x to its rim.
int Refiner::badChange(const double* x, uint32_t split, uint32_t footOf) const {
  int change = 0;
  for (uint32_t t : cavity_) {
    change -= worstCorner(t).k >= 0;
    for (uint32_t e = 3 * t; e < 3 * t + 3; ++e) {
      if (split != kNone && (e == split || e == T_.opp[split])) continue;
      uint32_t n = T_.opp[e] / 3;
      bool rim = T_.isFixed(e) || T_.isGhost(n) ||
                 std::find(cavity_.begin(), cavity_.end(), n) == cavity_.end();
      if (!rim) continue;
      const double* p[3] = {x, P(T_.tri[e]), P(T_.tri[next(e)])};
      // A split point at footOf's foot: its corner between a piece of the subsegment and
      // the edge to footOf counts as right (footCorners).
      int foot = 0;
      if (feet_ && footOf != kNone) {
        foot = kNearFoot;
        for (uint32_t end : {T_.tri[split], T_.tri[next(split)]})
          foot |= int((T_.tri[e] == end && T_.tri[next(e)] == footOf) ||
                      (T_.tri[next(e)] == end && T_.tri[e] == footOf));
      }
      change += worstCorner(p, foot).k >= 0;
    }
  }
  return change;
}

// Size of a triangle for the processing order: its shortest edge, squared.
double Refiner::shortestEdge2(uint32_t t) const {
  const uint32_t* v = &T_.tri[3 * t];
  return std::min({dist2(P(v[0]), P(v[1])), dist2(P(v[1]), P(v[2])), dist2(P(v[2]), P(v[0]))});
}

// Splits the subsegment opposite corner k of t at the foot of the altitude from k: an obtuse
// corner there leaves two right triangles (non-obtuse) with one point.
bool Refiner::splitAtFoot(uint32_t t, int k) {
  uint32_t opposite = 3 * t + uint32_t((k + 1) % 3);
  const double *pc = P(T_.tri[3 * t + k]), *pa = P(T_.tri[opposite]), *pb = P(T_.tri[next(opposite)]);
  double ux = pb[0] - pa[0], uy = pb[1] - pa[1];
  double s = ((pc[0] - pa[0]) * ux + (pc[1] - pa[1]) * uy) / (ux * ux + uy * uy);
  return splitSubsegment(opposite, s, T_.tri[3 * t + k]);
}

// How many more triangles miss the target once m splits the subsegment of fixed half-edge e:
// the cavities on both sides (into cavity_) give way to triangles joining m to their rims.
int Refiner::splitBadChange(uint32_t e, const double* m, uint32_t footOf) {
  cavity_.clear();
  for (uint32_t side : {e, T_.opp[e]}) {
    uint32_t t = side / 3;
    if (T_.inDomain(t)) cavity_.push_back(t);
  }
  growCavity(m);
  return badChange(m, e, footOf);
}

// The boundary rule with the split point weighed (where slice points are weighed too,
// Strategy::weighPoints): of the usual place (shell or midpoint; with
// Strategy::footOnSegments the foot of the altitude), the foot of the altitude from apex and
// the tenths of the subsegment, the one that leaves the fewest bad triangles (splitBadChange;
// ties to the earlier). CG:SHOP non-obtuse 32,945 -> 30,664 Steiner points, acute 58,109 ->
// 47,382 (usual, middle, foot and thirds only: 31,263 and 48,805). Splits for a point that
// encroaches a subsegment stay as they were (weighed: 34,037 and 52,832).
bool Refiner::splitWeighed(uint32_t e, uint32_t apex) {
  const double *pa = P(T_.tri[e]), *pb = P(T_.tri[next(e)]), *pc = P(apex);
  double ux = pb[0] - pa[0], uy = pb[1] - pa[1];
  double foot = ((pc[0] - pa[0]) * ux + (pc[1] - pa[1]) * uy) / (ux * ux + uy * uy);
  double usual = nonObtuse_ && strategy_.footOnSegments ? foot : -1;
  SegmentLine line = segmentLine(T_.segment[e], pa, pb);
  double ta = line.param(pa), tb = line.param(pb);
  double best = usual;
  int fewest = INT32_MAX;
  const double ratios[] = {usual, foot, 0.5, 0.4, 0.6, 0.3, 0.7, 0.2, 0.8, 0.1, 0.9};
  for (size_t i = 0; i < std::size(ratios); ++i) {
    double r = ratios[i];
    if (i > 0 && (r == usual || !(r > 0.05 && r < 0.95))) continue;
    double m[2];
    line.at(ta + splitRatio(e, r) * (tb - ta), m);  // where splitSubsegment(e, r) splits
    int change = splitBadChange(e, m, r == foot ? apex : kNone);
    if (change < fewest) fewest = change, best = r;
  }
  return splitSubsegment(e, best, best == foot ? apex : kNone);
}

// Non-obtuse: a triangle obtuse opposite a subsegment is cut at the foot of its altitude into
// two right triangles. Done before the corner fans, it settles most slivers between segments
// with one point each, and the fans go only where that is not enough.
void Refiner::cutAtFeet() {
  for (int pass = 0; pass < 4; ++pass) {
    bool changed = false;
    for (uint32_t t = 0; t < T_.triangleSlots(); ++t) {
      if (!T_.inDomain(t)) continue;
      Corner c = worstCorner(t);
      uint32_t opposite = 3 * t + uint32_t((c.k + 1) % 3);
      if (c.k < 0 || !c.large || !T_.isFixed(opposite)) continue;
      changed |= splitAtFoot(t, c.k);
      if (atSteinerLimit()) return;
    }
    if (!changed) break;
  }
}

StepResult Refiner::run() {
  if (nonObtuse_ && strategy_.cutAtFeetFirst) cutAtFeet();
  if (acute_ || nonObtuse_) buildCornerFans();
  StepResult result = runSteps();
  releaseChords();  // runSteps releases them before improving; this covers runs cut short
  return result;
}

StepResult Refiner::runSteps() {
  StepResult result = repairAll();
  if (!result.ok()) return result;
  // Improvement (acute / non-obtuse, where the point count is the score): remove what is not
  // needed. Putting a vertex back can differ from its old star where vertices are
  // cocircular, so whatever that spoilt is repaired again.
  // The fans have done their work once the target is met: their points may go too, as long
  // as what fills their place meets the target.
  if (acute_ || nonObtuse_) {
    releaseChords();
    for (size_t v = 0; v < role_.size(); ++v) {
      if (role_[v] == kArc) role_[v] = kFree;
      fanCenter_[v] = kNone;
    }
    if (!anyBad()) removeSteinerPoints();
    result = repairAll();
  }
  return result;
}

// Rounds of smoothing, removal and merging on a mesh that meets the target, while a round
// takes out at least kPolishGain of the Steiner points (CG:SHOP non-obtuse: 72,554 points
// without polishing, 56,156 with). On a mesh of fewer than kSmallPolish Steiner points, where a
// round takes a few milliseconds, rounds go on until two in a row take out none: a round that
// gains nothing still smooths, which lets the next ones gain again (CG:SHOP non-obtuse 13,361
// -> 13,235 Steiner points, acute 54,030 -> 53,888, the slowest instances, all larger,
// unchanged; until one round gains nothing: no fewer points; all twelve rounds: 13,154 and
// 53,800, but a 230-point instance then took 80-100 ms instead of 50-65, and Lake Superior
// acute twice the time for 2 points). Non-obtuse, whose small meshes' rounds are cheaper, runs
// all twelve there: CG:SHOP non-obtuse 13,235 -> 13,154 Steiner points, its slowest instance
// as fast as before (72 ms, a 340-point mesh), the median 6.7 -> 8.9 ms; Lake Superior
// unchanged (210), A 25 -> 24. A round that ends short of the target (a budget ran out) or
// with more points than it started with is undone.
constexpr double kPolishGain = 0.005;
constexpr size_t kSmallPolish = 400;
// From kSmallPolish Steiner points on, the rounds run in two halves at once (roundInHalves):
// on 2 threads, CG:SHOP acute's instances that polish from 400 to 700 points take a fifth less
// time (point-set_150_1fb326cf, six rounds from 871 points, five of them single-threaded
// below 700: median 94 -> 75 ms), with as many points (47,704 -> 47,701; non-obtuse 13,219 ->
// 13,235). (From 700 points before.)
// Rounds in halves gain for longer (the split changes sides and the order of the work each
// round): with 0.5% a round from 700 points on, the slowest meshes ran all twelve
// (simple-polygon-exterior-20_150_7768dd44: 921 -> 874 Steiner points, 90 -> 130 ms), so there
// a round must take out kHalvesGain to go on. With 1%: CG:SHOP acute 47,393 -> 47,554 Steiner
// points, the 25 slowest instances 11% less wall time, 9 -> 3 of them over 100 ms (min of 5
// runs each). With 2% (the removals after the merges, see polishRound, saved the points it
// costs): 47,456 -> 47,585, 7.6% fewer instructions on the 25 slowest (1.5%: 47,496, -2.8%;
// 2.5%: 47,780, -14%).
constexpr size_t kHalvesGainFrom = 700;
constexpr double kHalvesGain = 0.02;
// From this many Steiner points a round must take out kLargeGain to go on: their rounds take
// the longest (CG:SHOP acute's slowest instances all start their polish with 1,100 to 1,800
// points, and it is more than half their time). CG:SHOP acute 47,593 -> 47,704 Steiner points,
// its 25 slowest instances 3.7% fewer instructions, its slowest (c0a19392) two of five rounds
// fewer. (3% for every mesh in halves: 47,868, -9.1%; the same from 900 points: 47,793, -6.9%:
// the points go with the time saved, and only the largest meshes need that time.)
constexpr size_t kLargeRoundFrom = 1000;
constexpr double kLargeGain = 0.03;
// A pair whose joint link has this many edges or more is not tried for a merge unless one
// point could stand in for both without moving its neighbours (mergePoint): such tries
// succeeded once in 240 on the 12 slowest CG:SHOP acute instances (the rest once in 36) and
// took 17% of the merging time (the merged point would have 11 or more neighbours, whose slabs
// rarely leave room). Skipping them, CG:SHOP acute takes 6% less CPU on its 25 slowest
// instances, with no more points.
constexpr size_t kMergeLinkEdges = 11;

void Refiner::polish() {
  if (!(acute_ || nonObtuse_) || anyBad()) return;
  int idleRounds = 0;  // the last rounds in a row that took out no point
  for (int round = 0; round < 12 && !budget_.stop(); ++round) {
    size_t before = liveSteiner();
    Triangulation saved = T_;
    std::vector<uint8_t> savedRoles = role_;
    if (before >= kSmallPolish)
      roundInHalves(round);
    else
      polishRound(false);
    StepResult result = repairAll();
    size_t after = liveSteiner();
    if (!result.ok() || anyBad() || after > before) {
      T_ = std::move(saved);
      role_ = std::move(savedRoles);
      fanCenter_.resize(role_.size(), kNone);
      footOf_.resize(role_.size(), kNone);
      return;
    }
    idleRounds = after == before ? idleRounds + 1 : 0;
    const bool small = after < kSmallPolish;
    if (small && nonObtuse_) continue;  // all twelve rounds (see above)
    const double gain = before >= kLargeRoundFrom  ? kLargeGain
                        : before >= kHalvesGainFrom ? kHalvesGain
                                                    : kPolishGain;
    if (small ? idleRounds == 2 : double(before - after) < gain * double(before)) return;
  }
}

// Smoothing makes the room removals and merges need: a sweep before each removal and merge step
// (against one sweep a round: CG:SHOP acute 54,476 -> 54,030 Steiner points in 12% less time on its
// 25 slowest instances, more merges succeed). On a mesh under kSmallPolish Steiner points: two
// sweeps before the removals (a sweep moves each vertex against its neighbours' old places, the
// second settles most of that), and two merge passes (four: 15% slower, no fewer points). From
// kSmallPolish (removeAfterMerging; the rounds in halves, which start there): one merge pass, then
// the removals again, as a merge changes the stars around it and removals, several times cheaper a
// success than merges, find more there. Against the small meshes' round: CG:SHOP acute 47,554 ->
// 47,456 Steiner points in 3% fewer instructions on its 25 slowest instances, non-obtuse 13,235 ->
// 13,207 (nearby orders, one or two sweeps first, one removal pass last, all came out 100-150
// points under it). On the smaller meshes it gained nothing (CG:SHOP's under 400 points: 17,488 ->
// 17,490; A acute 71 -> 72, Lake Superior 230 -> 233) and took longer (Superior acute 30 -> 38 ms,
// min of 7). (Only from kSmallPolish, and with kHalvesGain at 2%: 47,602 and 13,219.)
void Refiner::polishRound(bool removeAfterMerging) {
  if (!removeAfterMerging) {
    smooth();
    smooth();
    removeSteinerPoints();
    smooth();
    mergeSteinerPoints(nullptr, 2);
    return;
  }
  smooth();
  removeSteinerPoints();
  smooth();
  mergeSteinerPoints();
  smooth();
  removeSteinerPoints();
}

// The gain of repairing t (whose worst corner is c) for the FewestBadFirst order: the bad
// triangles the best of its slice's points that spares the segments would take away, less
// those it would make (badChange), at least -1 (also where no point counts); 1 for a
// subsegment split and for a small angle (boundary and quality repairs settle their triangle).
// `weighed`, if given, gets the candidate chosen when t's candidates were weighed (see repair).
int Refiner::repairGain(uint32_t t, Corner c, size_t* weighed) {
  if (!c.large || T_.isFixed(3 * t + uint32_t((c.k + 1) % 3))) return 1;
  slicePoints(t, candidates_);
  int fewest = 0;
  const size_t chosen = weighCandidates(t, candidates_, fewest);
  if (weighed) *weighed = chosen;
  if (chosen == candidates_.size()) return -1;
  return -std::min(fewest, 1);
}

StepResult Refiner::repairAll() {
  // Bad triangles are repaired largest first (by shortest edge). Depth-first repair of the
  // newest triangles instead lets refinement spiral into one spot; largest-first keeps the
  // vertex spacing even. Entries are re-checked when popped (a triangle may have changed);
  // in the fewest-bad-first order an entry whose gain has dropped since (its neighbours
  // changed) goes back with its new gain.
  RepairQueue& queue = queue_;
  using Order = RepairQueue::Order;
  const bool byGain = strategy_.fewestBadFirst && (acute_ || nonObtuse_) && options_.maxArea <= 0;
  queue.reset(options_.maxArea > 0 ? Order::FactorsOfTwo : byGain ? Order::FewestBadFirst : Order::Largest);
  auto push = [&](uint32_t t) {
    if (!T_.inDomain(t)) return;
    Corner c = worstCorner(t);
    if (c.k >= 0) queue.push({byGain ? repairGain(t, c) : 0, shortestEdge2(t), t});
  };
  for (uint32_t t = 0; t < T_.triangleSlots(); ++t) push(t);
  uint32_t steps = 0;
  RepairQueue::Entry entry;
  while (queue.pop(entry)) {
    if ((++steps & 255) == 0) {
      if (budget_.stop())
        return {budget_.cancelled() ? Status::Cancelled : Status::TargetNotMet,
                "time limit reached before every triangle met the target"};
      if (reportProgress_ && options_.progress && (steps & 4095) == 0)
        options_.progress({"refine", -1, T_.vertexCount()});
    }
    if (atSteinerLimit())
      return {Status::TargetNotMet, "Steiner point budget used up before every triangle met "
                                    "the target"};
    const uint32_t t = entry.t;
    if (!T_.inDomain(t) || shortestEdge2(t) != entry.size) continue;
    Corner c = worstCorner(t);
    if (c.k < 0) continue;
    size_t weighed = kNotWeighed;
    if (byGain) {
      int gain = repairGain(t, c, &weighed);
      if (gain < entry.gain) {
        queue.push({gain, entry.size, t});
        continue;
      }
    }
    touched_.clear();
    T_.touched = &touched_;
    bool changed = repair(t, c, weighed);
    T_.touched = nullptr;
    if (!changed) continue;  // left for the certificate to count
    std::sort(touched_.begin(), touched_.end());
    touched_.erase(std::unique(touched_.begin(), touched_.end()), touched_.end());
    for (uint32_t u : touched_) push(u);
    push(t);
  }
  return {};
}

// After a removal: every triangle of the hole (hole_) meets the target, or is made to by
// moving one of its vertices (relocation, or sliding along a segment). Moves are logged in
// moved_ so that a failed removal can undo them.
bool Refiner::holeMeetsTarget() {
  moved_.clear();
  for (uint32_t t : hole_) {
    if (!missesTarget(t)) continue;
    bool repaired = false;
    for (uint32_t k = 0; k < 3 && !repaired; ++k) {
      uint32_t a = T_.tri[3 * t + k];
      Moved old{a, P(a)[0], P(a)[1]};
      if (relocate(a) || slide(a)) moved_.push_back(old), repaired = true;
    }
    if (!repaired) return false;
  }
  return true;
}

void Refiner::undoMoves() {
  for (size_t i = moved_.size(); i-- > 0;) {
    T_.pts[2 * size_t(moved_[i].vertex)] = moved_[i].x;
    T_.pts[2 * size_t(moved_[i].vertex) + 1] = moved_[i].y;
  }
  moved_.clear();
}

// Removes free vertex v if the triangles that then fill its star meet the target (see
// holeMeetsTarget). Otherwise everything moved goes back and v is put back (the constrained
// Delaunay triangulation is unique, so its star returns as it was up to cocircular ties,
// which the final repair pass settles).
bool Refiner::tryRemove(uint32_t v) {
  if (!recordingHole([&] { return T_.removeVertex(v); })) return false;
  if (holeMeetsTarget()) return true;
  undoMoves();
  T_.insert(v, hole_.back());  // the last triangle written is alive and next to v's place
  return false;
}

// The same for a Steiner vertex on a segment: its two pieces become one again. If that fails,
// v goes back onto the merged piece; should even that be impossible (the piece's triangles no
// longer hold v's place), v stays out and the final repair pass mends what that spoilt.
bool Refiner::tryRemoveFromSegment(uint32_t v) {
  uint32_t ends[2];
  if (!recordingHole([&] { return T_.removeFromSegment(v, ends); })) return false;
  if (holeMeetsTarget()) return true;
  undoMoves();
  uint32_t merged = T_.findEdge(ends[0], ends[1]);
  if (merged != kNone) T_.splitFixedEdge(merged, v);
  return false;
}

// The same for consecutive Steiner points u, w on one segment: one point in their place, halfway
// between them (on the input segment's line) or, with exact feet, at the foot of the altitude
// from the vertex opposite u-w on either side. If none will do, they go back onto their piece;
// should that be impossible, what stays out is left to the final repair pass.
bool Refiner::tryMergeOnSegment(uint32_t u, uint32_t w) {
  uint32_t uw = T_.findEdge(u, w);
  if (uw == kNone || !T_.isFixed(uw) || T_.segment.empty() || T_.segment[uw] == kNone) return false;
  uint32_t seg = T_.segment[uw];
  const double pu[2] = {P(u)[0], P(u)[1]}, pw[2] = {P(w)[0], P(w)[1]};
  uint32_t apexes[2] = {kNone, kNone};
  for (int side = 0; side < 2 && feet_; ++side) {
    const uint32_t e = side ? T_.opp[uw] : uw;
    if (T_.inDomain(e / 3)) apexes[side] = T_.tri[prev(e)];
  }
  uint32_t endsU[2], endsW[2];
  touched_.clear();
  T_.touched = &touched_;
  auto putBack = [&](uint32_t v, const uint32_t* ends) {
    uint32_t piece = T_.findEdge(ends[0], ends[1]);
    if (piece != kNone) T_.splitFixedEdge(piece, v);
  };
  if (T_.removeFromSegment(u, endsU)) {
    if (T_.removeFromSegment(w, endsW)) {
      SegmentLine line = segmentLine(seg, pu, pw);
      int merged = 0;
      for (int c = 0; c < 3 && merged == 0; ++c) {
        const uint32_t footOf = c == 0 ? kNone : apexes[c - 1];
        if (c > 0 && footOf == kNone) continue;
        double x[2];
        line.at(c == 0 ? 0.5 * (line.param(pu) + line.param(pw)) : line.param(P(footOf)), x);
        merged = tryPointOnSegment(x, footOf, endsW);
      }
      if (merged == 1) return true;
      if (merged == -1) {
        T_.touched = nullptr;
        return false;
      }
      putBack(w, endsW);
    }
    putBack(u, endsU);
  }
  T_.touched = nullptr;
  return false;
}

// With a merge's points out (tryMergeOnSegment): puts one at x on the piece between ends
// (standing for footOf's altitude foot, if given and the double is not exactly it), and keeps
// it if the hole then meets the target. As tryMergedPoint: 1 kept; 0 out again; -1 stuck.
int Refiner::tryPointOnSegment(const double* x, uint32_t footOf, const uint32_t* ends) {
  const uint32_t m = addVertex(x, kOnSegment);
  const uint32_t piece = T_.findEdge(ends[0], ends[1]);
  bool removedAgain = false;
  if (piece != kNone && T_.splitFixedEdge(piece, m)) {
    standForFoot(m, footOf, P(ends[0]));
    hole_ = touched_;
    T_.touched = nullptr;
    if (holeMeetsTarget()) return 1;
    undoMoves();
    T_.touched = &touched_;
    uint32_t endsM[2];
    removedAgain = T_.removeFromSegment(m, endsM);
  }
  if (!removedAgain && T_.vertexEdge[m] != kNone) return -1;
  dropLastVertex();
  return 0;
}

// Where one point would best stand in for free neighbours u and w: the centre of the region
// where its star over their joint link would meet the target (clipToLinkSlabs), else (no such
// region, or their stars reach outside the domain) their midpoint. False if the pair is not
// worth a try: no such region around a joint link of kMergeLinkEdges edges or more.
bool Refiner::mergePoint(uint32_t u, uint32_t w, double* out) {
  out[0] = 0.5 * (P(u)[0] + P(w)[0]), out[1] = 0.5 * (P(u)[1] + P(w)[1]);
  linkEdges_.clear();
  for (uint32_t c : {u, w}) {
    uint32_t e0 = T_.vertexEdge[c], e = e0;
    do {
      if (!T_.inDomain(e / 3)) return true;
      uint32_t x = T_.tri[next(e)], y = T_.tri[prev(e)];
      if (x != u && x != w && y != u && y != w) linkEdges_.push_back({x, y});
      e = T_.opp[prev(e)];
    } while (e != e0);
  }
  if (!linkLeavesRoom()) return linkEdges_.size() < kMergeLinkEdges;
  clipToLinkSlabs(strictMax_);
  double centre[2];
  if (!clipCentroid(centre)) return linkEdges_.size() < kMergeLinkEdges;
  out[0] = centre[0], out[1] = centre[1];
  return true;
}

// With u and w out (tryMerge): puts one point at x, and keeps it if the hole then meets the
// target (holeMeetsTarget). 1: merged; 0: x is out again, the hole as it was; -1: x could not
// be taken out again and stays (the final repair pass checks).
int Refiner::tryMergedPoint(const double* x) {
  Location loc = T_.locate(x, touched_.back());
  if (loc.where != Where::InTriangle || !T_.inside[loc.tri]) return 0;
  for (uint32_t k = 0; k < 3; ++k)  // no edge shorter than refinement's smallest
    if (dist2(x, P(T_.tri[3 * loc.tri + k])) < minEdge2_) return 0;
  uint32_t m = addVertex(x, kFree);
  bool removedAgain = false;
  if (T_.insertAt(m, loc) == m) {
    hole_ = touched_;
    T_.touched = nullptr;
    if (holeMeetsTarget()) return 1;
    undoMoves();
    T_.touched = &touched_;
    removedAgain = T_.removeVertex(m);
  }
  if (!removedAgain && T_.vertexEdge[m] != kNone) return -1;
  dropLastVertex();
  return 0;
}

// Replaces two neighbouring free vertices u, w by one if the triangles around it meet the
// target (after moving vertices as holeMeetsTarget does): at mergePoint, else at the point
// refinement would weigh best for the first bad triangle of their hole (its candidates' fewest
// bad triangles left, see insertSparingSegments; CG:SHOP non-obtuse 33,313 -> 32,945 Steiner
// points, acute 58,599 -> 58,109, in about a tenth more time; the two best: 32,728 and 57,924
// in a third more). Otherwise the pair goes back. A pair mergePoint declines is not tried.
bool Refiner::tryMerge(uint32_t u, uint32_t w) {
  double mid[2];
  if (!mergePoint(u, w, mid)) return false;
  touched_.clear();
  T_.touched = &touched_;
  if (T_.removeVertex(u)) {
    if (T_.removeVertex(w)) {
      int merged = tryMergedPoint(mid);
      uint32_t bad = kNone;
      for (size_t i = 0; merged == 0 && i < touched_.size() && bad == kNone; ++i) {
        uint32_t t = touched_[i];
        if (missesTarget(t)) bad = t;
      }
      if (bad != kNone) {
        slicePoints(bad, candidates_);
        int fewest = 0;
        size_t best = weighCandidates(bad, candidates_, fewest);
        if (best < candidates_.size()) {
          const double x[2] = {candidates_[best][0], candidates_[best][1]};
          merged = tryMergedPoint(x);
        }
      }
      if (merged == 1) return true;
      if (merged == -1) {
        T_.touched = nullptr;
        return false;
      }
      T_.insert(w, touched_.back());
    }
    T_.insert(u, touched_.back());
  }
  T_.touched = nullptr;
  return false;
}

// Some triangle of the domain misses the target.
bool Refiner::anyBad() const {
  for (uint32_t t = 0; t < T_.triangleSlots(); ++t)
    if (missesTarget(t)) return true;
  return false;
}

// After a successful removal or merge: the vertices whose stars it changed (the hole's
// corners, and the neighbours of every vertex moved to repair it) are worth another try.
void Refiner::markChanged() {
  if (dirty_.size() < T_.vertexCount()) dirty_.resize(T_.vertexCount(), 1);
  for (uint32_t t : hole_) {
    if (T_.isFree(t)) continue;
    for (int k = 0; k < 3; ++k)
      if (T_.tri[3 * t + k] != kGhost) dirty_[T_.tri[3 * t + k]] = 1;
  }
  for (const Moved& m : moved_) {
    uint32_t e0 = T_.vertexEdge[m.vertex], e = e0;
    if (e0 == kNone) continue;
    do {
      if (T_.tri[next(e)] != kGhost) dirty_[T_.tri[next(e)]] = 1;
      e = T_.opp[prev(e)];
    } while (e != e0);
  }
}

// Polled once per removal or merge attempt: whether a budget has run out or the run was
// cancelled. Now and then it reports progress (phase "improve", the vertices in the mesh).
bool Refiner::improvementShouldStop() {
  if ((++attempts_ & 63) != 0) return false;
  if (reportProgress_ && options_.progress && (attempts_ & 4095) == 0)
    options_.progress({"improve", -1, uint32_t(input_.vertexCount() + liveSteiner())});
  return budget_.stop();
}

// Steiner points in the mesh (vertexCount() also counts those removed).
size_t Refiner::liveSteiner() const {
  size_t n = 0;
  for (uint32_t v = uint32_t(input_.vertexCount()); v < T_.vertexCount(); ++v)
    n += T_.vertexEdge[v] != kNone;
  return n;
}

// Moves every free vertex to the middle of where its star meets the target (relocate()), and
// every segment vertex along its segment likewise: points with room to spare let more of their
// neighbours go in the next removal pass.
void Refiner::smooth() {
  for (uint32_t v = uint32_t(input_.vertexCount()); v < T_.vertexCount(); ++v) {
    if (T_.vertexEdge[v] == kNone || (role_[v] != kFree && role_[v] != kOnSegment) || !owned(v))
      continue;
    if (relocate(v) || (!strictMax_ && slide(v))) {
      settleMove(v);
      if (log_) log_->push_back({Step::Move, v, kNone, kNone, P(v)[0], P(v)[1]});
    }
  }
}

// The improvement pass (once the target is met: runSteps and polish make sure of that, a scan
// of every triangle here took 1% of all the time): every Steiner point whose removal keeps
// every triangle on target goes, oldest first, until a pass removes none.
void Refiner::removeSteinerPoints(const std::vector<uint8_t>* due, int passes) {
  // The first pass tries every Steiner point; later ones only those whose surroundings a
  // removal has changed since their last try (the rest would fail the same way again).
  markDue(due);
  for (int pass = 0; pass < passes; ++pass) {
    uint32_t removed = 0;
    // Oldest first: the early, coarse points are the likeliest to have become redundant
    // (fewer points than newest first: A 92 vs 97, Superior 299 vs 311).
    for (uint32_t v = 0, count = T_.vertexCount(); v < count; ++v) {
      if (!dirty_[v] || T_.vertexEdge[v] == kNone || !owned(v)) continue;
      dirty_[v] = 0;
      if (improvementShouldStop()) return;
      if (!removePoint(v)) continue;
      ++removed;
      if (log_) log_->push_back({Step::Remove, v, kNone, kNone, 0, 0});
    }
    if (removed == 0) break;
  }
}

// The first pass's vertices: those `due` marks, and any made after it (all without it).
void Refiner::markDue(const std::vector<uint8_t>* due) {
  dirty_.assign(T_.vertexCount(), 1);
  if (due) std::copy(due->begin(), due->end(), dirty_.begin());
}

// Pairs of neighbouring Steiner points that one point can stand in for (on a mesh that meets
// the target, as removeSteinerPoints).
void Refiner::mergeSteinerPoints(const std::vector<uint8_t>* due, int passes) {
  markDue(due);
  for (int pass = 0; pass < passes; ++pass)
    if (mergePass() == 0 || budget_.stop()) break;
}

// Tries each due Steiner vertex (of mine_) with its partners, the same pair once.
uint32_t Refiner::mergePass() {
  uint32_t merged = 0;
  std::vector<uint8_t> pending = dirty_;  // a pair is tried once a pass: at the turn of the
                                          // higher index, if due
  for (uint32_t u = T_.vertexCount(); u-- > 0;) {
    bool onSegment = role_[u] == kOnSegment;
    if (u >= dirty_.size() || !dirty_[u] || (role_[u] != kFree && !onSegment) ||
        T_.vertexEdge[u] == kNone || !owned(u))
      continue;
    dirty_[u] = 0;
    if (improvementShouldStop()) break;
    // The partners first (free neighbours of a free vertex, the neighbours along its segment
    // of a segment vertex): a failed merge re-inserts u, which renumbers its edges.
    std::vector<uint32_t>& partners = ring_;
    partners.clear();
    uint32_t e0 = T_.vertexEdge[u], e = e0;
    do {
      uint32_t w = T_.tri[next(e)];
      bool triedAtItsTurn = w > u && w < pending.size() && pending[w];
      bool partner = w != kGhost && owned(w) &&
                     (onSegment ? role_[w] == kOnSegment && T_.isFixed(e) : role_[w] == kFree);
      if (partner && !triedAtItsTurn) partners.push_back(w);
      e = T_.opp[prev(e)];
    } while (e != e0);
    std::vector<uint32_t> list = partners;  // ring_ is reused by the repairs
    for (uint32_t w : list) {
      if (mergePair(u, w)) {
        ++merged;
        if (log_) log_->push_back({Step::Merge, u, w, T_.vertexCount() - 1, 0, 0});
        break;
      }
    }
  }
  return merged;
}

// Steiner vertex v taken out if tryRemove (or, on a segment, tryRemoveFromSegment) can, the
// stars that changed marked (markChanged).
bool Refiner::removePoint(uint32_t v) {
  const bool gone =
      role_[v] == kFree ? tryRemove(v) : role_[v] == kOnSegment && tryRemoveFromSegment(v);
  if (gone) markChanged();
  return gone;
}

// Neighbours u and w (both free, or both on one segment) made one point if tryMerge (or
// tryMergeOnSegment) can, the stars that changed marked (markChanged); the point is the last
// vertex then. False, changing nothing, where either is gone or they are no longer neighbours.
bool Refiner::mergePair(uint32_t u, uint32_t w) {
  if (T_.vertexEdge[u] == kNone || T_.vertexEdge[w] == kNone || T_.findEdge(u, w) == kNone)
    return false;
  if (!(role_[u] == kOnSegment ? tryMergeOnSegment(u, w) : tryMerge(u, w))) return false;
  markChanged();
  return true;
}

// An improvement round in two halves at once (polish, on a mesh of kSmallPolish Steiner points
// or more): the Steiner vertices on either side of their median x (y in odd rounds),
// those with a neighbour across it excepted, are smoothed, removed and merged as in a round of
// their own, one half here and the other on a copy of the triangulation, on a second thread
// where there is one (the same steps either way, so every build and thread count makes the
// same mesh). The copy's steps are then made again here in order (replay), each checked anew,
// and the vertices along the middle, with the points the merges made, get one removal and one
// merge pass. On 2 threads the 25 slowest CG:SHOP acute instances take 12% less wall time (the
// halves take about half a round each; the replay and the middle a tenth to a fifth of it);
// CG:SHOP acute 47,429 -> 47,393 Steiner points, non-obtuse unchanged (from 500 points: 47,365,
// but non-obtuse 13,235 -> 13,268). Tried: only the first merge pass of each round in halves
// (from 1,000 points, before this): half the gain; without the middle's passes 47,759; the
// middle's passes in full (removals until none, two merge passes) 47,420, but they took as
// long as the halves in the first round.
void Refiner::roundInHalves(int round) {
  const int axis = round % 2;
  const uint32_t n = T_.vertexCount();
  std::vector<double> at;
  for (uint32_t v = uint32_t(input_.vertexCount()); v < n; ++v)
    if (T_.vertexEdge[v] != kNone && (role_[v] == kFree || role_[v] == kOnSegment))
      at.push_back(P(v)[axis]);
  if (at.empty()) return;
  std::nth_element(at.begin(), at.begin() + at.size() / 2, at.end());
  const double middle = at[at.size() / 2];
  std::vector<uint8_t> mine[2] = {std::vector<uint8_t>(n, 0), std::vector<uint8_t>(n, 0)};
  std::vector<uint8_t> along(n, 0);  // the vertices with a neighbour across the middle
  for (uint32_t v = 0; v < n; ++v) {
    if (T_.vertexEdge[v] == kNone) continue;
    const bool second = P(v)[axis] >= middle;
    bool across = false;
    uint32_t e0 = T_.vertexEdge[v], e = e0;
    do {
      uint32_t w = T_.tri[next(e)];
      across |= w != kGhost && (P(w)[axis] >= middle) != second;
      e = T_.opp[prev(e)];
    } while (e != e0);
    mine[second][v] = !across;
    along[v] = across;
  }
  Triangulation copy = T_;
  Refiner other(copy, input_, options_, budget_, strategy_, 0);
  other.role_ = role_;
  other.fanCenter_ = fanCenter_;
  other.footOf_ = footOf_;
  other.fanRadius_ = fanRadius_;
  other.reportProgress_ = false;
  std::vector<Step> log;
  other.mine_ = &mine[1];
  other.log_ = &log;
  mine_ = &mine[0];
  auto secondHalf = [&] { other.polishRound(true); };
#ifdef ACUTEMESH_STRATEGY_THREADS
  if (threadsFor(options_) > 1) {
    std::thread helper(secondHalf);
    polishRound(true);
    helper.join();
  } else {
    polishRound(true);
    secondHalf();
  }
#else
  polishRound(true);
  secondHalf();
#endif
  mine_ = nullptr;
  replay(log, n, other.T_.vertexCount());
  along.resize(T_.vertexCount(), 1);  // and the points the merges made
  removeSteinerPoints(&along, 1);
  mergeSteinerPoints(&along);
}

// The copy's steps (roundInHalves) made again here, in order: a move if the vertex's star
// still meets the target there (replayMove), a removal or merge if tryRemove or tryMerge (or
// their segment forms) decide so now. The copy's points from firstNew on (up to made) map to
// those made here. (A step near the middle may fail where the other half changed things.)
void Refiner::replay(const std::vector<Step>& log, uint32_t firstNew, uint32_t made) {
  std::vector<uint32_t> here(made, kNone);
  for (uint32_t v = 0; v < firstNew; ++v) here[v] = v;
  for (const Step& step : log) {
    const uint32_t a = here[step.u];
    if (a == kNone || T_.vertexEdge[a] == kNone) continue;
    if (step.kind == Step::Move) {
      const double to[2] = {step.x, step.y};
      replayMove(a, to);
    } else if (step.kind == Step::Remove) {
      removePoint(a);
    } else {
      const uint32_t b = here[step.w];
      if (b != kNone && role_[a] == role_[b] && mergePair(a, b))
        here[step.made] = T_.vertexCount() - 1;
    }
  }
}

// After an improvement round moved Steiner vertex v (smooth, replayMove): its star legalized,
// unless v is free and no foot stands for an exact right angle (feet_), where nothing would
// flip. The rounds work on a mesh that meets the target (each step keeps it so; v's new star
// does), and each link edge of a free vertex is fixed or lies between two triangles of the
// domain, neither obtuse across it: locally Delaunay (see legalizeStar). (A vertex put back
// after a failed removal may get another star among cocircular points, and a triangle miss the
// target until the round's repair pass, which legalizes first.) Legalized anyway, the 666,000
// moves of free vertices in the acute and non-obtuse runs on CG:SHOP, A and Superior flipped
// nothing; skipped, the 25 slowest acute instances take 2% fewer instructions.
void Refiner::settleMove(uint32_t v) {
  if (role_[v] == kFree && !feet_) return;
  legalizeStar(v);
}

// Moves Steiner vertex v to `to` (where smoothing moved it on the copy: on its segment's line
// for a segment vertex) and settles it there (settleMove) if its star then meets the target,
// with the checks relocate() and slide() make; else v stays.
bool Refiner::replayMove(uint32_t v, const double* to) {
  const bool onSegment = role_[v] == kOnSegment;
  uint32_t spokes[2];
  if (onSegment ? !segmentStar(v, spokes) : !freeStar(v)) return false;
  const double old[2] = {P(v)[0], P(v)[1]};
  if (moveTo(v, to[0], to[1]) && !(onSegment && nearFixedLinkEdge(v, to))) {
    settleMove(v);
    return true;
  }
  moveTo(v, old[0], old[1]);
  return false;
}

// The ends of the input segment through segment vertex f, whose fixed edge `spoke` leaves f;
// on a point set's hull (no input segment) the input vertices the hull edge runs between,
// found by following the fixed edges from f both ways.
void Refiner::segmentEnds(uint32_t f, uint32_t spoke, const double*& a, const double*& b) const {
  const uint32_t seg = T_.segment.empty() ? kNone : T_.segment[spoke];
  if (seg != kNone) {
    const SegmentLine line = segmentLine(seg, P(f), P(f));
    a = line.start, b = line.end;
    return;
  }
  // The next vertex along the fixed edges from `from`, coming from `before`.
  auto along = [&](uint32_t from, uint32_t before) {
    uint32_t e0 = T_.vertexEdge[from], e = e0;
    do {
      uint32_t to = T_.tri[next(e)];
      if (T_.isFixed(e) && to != kGhost && to != before) return to;
      e = T_.opp[prev(e)];
    } while (e != e0);
    return kNone;
  };
  const double* ends[2] = {nullptr, nullptr};
  uint32_t first = T_.tri[next(spoke)];
  for (int side = 0; side < 2; ++side) {
    uint32_t before = f, at = side == 0 ? first : along(f, first);
    for (uint32_t steps = 0; at != kNone && role_[at] != kInput && steps < T_.vertexCount(); ++steps) {
      uint32_t after = along(at, before);
      before = at, at = after;
    }
    ends[side] = at == kNone || role_[at] != kInput ? P(f) : P(at);
  }
  a = ends[0], b = ends[1];
}

// Every triangle of T's domain around the vertices in `exact` is counter-clockwise and has
// no obtuse corner with those at their exact positions.
bool feetKeepTarget(const Triangulation& T, const std::vector<ExactVertex>& exact) {
  std::vector<const RationalPoint*> at(T.vertexCount(), nullptr);
  for (const ExactVertex& x : exact) at[x.vertex] = &x.at;
  for (uint32_t t = 0; t < T.triangleSlots(); ++t) {
    if (!T.inDomain(t)) continue;
    const uint32_t* v = &T.tri[3 * t];
    if (!at[v[0]] && !at[v[1]] && !at[v[2]]) continue;
    const double* p[3] = {T.point(v[0]), T.point(v[1]), T.point(v[2])};
    const RationalPoint* exactAt[3] = {at[v[0]], at[v[1]], at[v[2]]};
    int dots[3];
    if (triangleSigns(p, exactAt, dots) <= 0 || std::min({dots[0], dots[1], dots[2]}) < 0)
      return false;
  }
  return true;
}

// Options::exactFeet, once refinement is over: each foot vertex (footOf_) with a corner that
// counts as right (footCorners: within kFootSlack of it, either way) goes to the exact foot
// of the altitude (into `exact`). True if every triangle around them is then right or
// sharper.
bool Refiner::exactFeet(std::vector<ExactVertex>& exact) const {
  exact.clear();
  if (!feet_) return true;
  std::vector<uint32_t> spokeOf(T_.vertexCount(), kNone);  // a piece of its segment
  for (uint32_t t = 0; t < T_.triangleSlots(); ++t) {
    if (!T_.inDomain(t)) continue;
    const int mask = footCorners(t);
    const uint32_t* v = &T_.tri[3 * t];
    for (uint32_t k = 0; k < 3; ++k) {
      const double *a = P(v[k]), *b = P(v[(k + 1) % 3]), *c = P(v[(k + 2) % 3]);
      if ((mask >> k & 1) && std::fabs(dot2d(a, b, c)) <= footSlack(a, b, c))
        spokeOf[v[k]] = footEdge(3 * t + k) ? 3 * t + k : 3 * t + (k + 2) % 3;
    }
  }
  // A foot's vertex may be a foot itself: its exact place first (around a cycle, the place
  // it has).
  std::vector<uint8_t> state(T_.vertexCount(), 0);  // 1: being placed, 2: placed
  std::vector<RationalPoint> at(T_.vertexCount());
  std::vector<uint32_t> stack;
  for (uint32_t f = 0; f < T_.vertexCount(); ++f) {
    if (spokeOf[f] == kNone || state[f]) continue;
    stack.assign(1, f);
    while (!stack.empty()) {
      const uint32_t g = stack.back(), partner = footOf_[g];
      if (state[g] == 0 && spokeOf[partner] != kNone && state[partner] == 0) {
        state[g] = 1;
        stack.push_back(partner);
        continue;
      }
      const double *a, *b;
      segmentEnds(g, spokeOf[g], a, b);
      at[g] = exactFoot(state[partner] == 2 ? at[partner] : exactPoint(P(partner)), a, b);
      state[g] = 2;
      stack.pop_back();
    }
  }
  for (uint32_t f = 0; f < T_.vertexCount(); ++f)
    if (spokeOf[f] != kNone) exact.push_back({f, at[f]});
  return feetKeepTarget(T_, exact);
}

// One strategy's run on its own copy of the triangulation.
struct StrategyRun {
  StrategyRun() = default;
  StrategyRun(const Triangulation& start, const Pslg& input, const Options& options,
              const Budget& budget, const Strategy& strategy, uint32_t steinerCap)
      : T(std::make_unique<Triangulation>(start)),
        refiner(std::make_unique<Refiner>(*T, input, options, budget, strategy, steinerCap)) {}
  void go() {
    result = refiner->run();
    met = result.ok() && !refiner->anyBad();
  }
  std::unique_ptr<Triangulation> T;
  std::unique_ptr<Refiner> refiner;
  StepResult result;
  bool met = false;
};

// Which run refineWithStrategies keeps, the runs considered one after another: the first,
// unless a later one meets the target with fewer Steiner points than the best so far. A later
// run stops once it has made as many points as the best so far (cap()); none runs once that
// leaves it no room, or the budget is out (done()).
struct StrategyChoice {
  StrategyChoice(const Triangulation& start, const Budget& budget, uint32_t steinerCap)
      : startVertices(start.vertexCount()), budget(budget), steinerCap(steinerCap) {}
  uint32_t cap() const {
    if (!best.met) return steinerCap;
    return uint32_t(best.T->vertexCount() - startVertices) - 1;
  }
  bool done() const {
    if (best.T && (best.result.status == Status::Cancelled || budget.stop())) return true;
    return best.met && best.T->vertexCount() - startVertices <= 1;
  }
  void consider(StrategyRun&& run) {
    if (!best.T || (run.met && (!best.met || run.refiner->liveSteiner() < best.refiner->liveSteiner())))
      best = std::move(run);
  }
  const size_t startVertices;
  const Budget& budget;
  const uint32_t steinerCap;
  StrategyRun best;
};

#ifdef ACUTEMESH_STRATEGY_THREADS
// Runs strategies [0, count) on threads, the calling one among them, and hands them to the
// choice in order: with the same result as running them one after another (so every build,
// threads or not, makes the same mesh). A run starts before those ahead of it are done, with
// only the budget's cap; once they are, it gets the cap it would have had (StrategyChoice::cap)
// through its SteinerGate. Had it already checked a vertex count at or over that cap, it would
// have stopped there: it is stopped now and does not count. (The new limit is stored before
// the last count checked is read: a check at or over it either shows in that count or sees
// the new limit and stops the run.) Otherwise it has gone just as it
// would have, and goes on under the cap. (Its vertex count only grows until run() returns.)
// Only the calling thread's runs report progress.
class ConcurrentStrategies {
 public:
  ConcurrentStrategies(const Triangulation& T, const Pslg& input, const Options& options,
                       const Budget& budget, const std::vector<Strategy>& strategies,
                       size_t count, StrategyChoice& choice)
      : T_(T), input_(input), options_(options), budget_(budget), strategies_(strategies),
        choice_(choice), slots_(count), end_(count) {
    slots_[0].cap = choice.cap();
  }

  // The calling thread takes the first run before any helper starts: it reports progress, and
  // a cancel on its word ("improve") then finds the first run past its refinement, as one
  // after another would.
  void run(size_t threads) {
    const size_t first = claim(true);
    std::vector<std::thread> helpers;
    for (size_t i = 1; i < threads; ++i) helpers.emplace_back([this] { work(false, claim(false)); });
    work(true, first);
    for (std::thread& helper : helpers) helper.join();
  }

 private:
  // Slots [0, next_) are started, [0, handed_) handed over; slot handed_ knows its cap.
  struct Slot {
    StrategyRun run;
    SteinerGate gate;
    bool finished = false, stopped = false;
    uint32_t cap = 0;  // the cap it would have had (from when it is slot handed_)
  };

  // Sets up the next run for this thread: its slot, or kNoRun if none is left.
  static constexpr size_t kNoRun = SIZE_MAX;
  size_t claim(bool caller) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (next_ >= end_) return kNoRun;
    const size_t i = next_++;
    Slot& slot = slots_[i];
    const uint32_t cap = i == handed_ ? slot.cap : choice_.steinerCap;
    slot.run = StrategyRun(T_, input_, options_, budget_, strategies_[i], cap);
    slot.gate.limit = slot.run.refiner->steinerLimitWith(cap);
    slot.run.refiner->useGate(&slot.gate);
    slot.run.refiner->reportProgress(caller);
    return i;
  }

  void work(bool caller, size_t i) {
    for (; i != kNoRun; i = claim(caller)) {
      slots_[i].run.go();
      std::lock_guard<std::mutex> lock(mutex_);
      slots_[i].finished = true;
      handOver();
    }
  }

  // (Under the lock.) Hands the finished runs at the front to the choice, in order, and gives
  // the next one its cap.
  void handOver() {
    while (handed_ < end_ && slots_[handed_].finished) {
      Slot& slot = slots_[handed_++];
      if (slot.stopped) slot.run.met = false;
      slot.run.refiner->leaveGate(slot.cap);
      slot.run.refiner->reportProgress(true);
      choice_.consider(std::move(slot.run));
      slot.run = StrategyRun{};
      if (choice_.done()) {  // none after it would have run: stop them
        end_ = handed_;
        for (size_t k = handed_; k < slots_.size(); ++k) slots_[k].gate.limit = 0;
        return;
      }
      if (handed_ == end_) return;
      Slot& nextSlot = slots_[handed_];
      nextSlot.cap = choice_.cap();
      if (handed_ < next_) {  // started: the limit goes in before `checked` is read (see above)
        const uint32_t limit = nextSlot.run.refiner->steinerLimitWith(nextSlot.cap);
        nextSlot.gate.limit = limit;
        if (nextSlot.gate.checked >= limit) nextSlot.stopped = true, nextSlot.gate.limit = 0;
      }
    }
  }

  const Triangulation& T_;
  const Pslg& input_;
  const Options& options_;
  const Budget& budget_;
  const std::vector<Strategy>& strategies_;
  StrategyChoice& choice_;
  std::vector<Slot> slots_;
  std::mutex mutex_;
  size_t end_;  // the runs from here on are not started (and stopped if they were)
  size_t next_ = 0, handed_ = 0;
};
#endif

// The strategies of refine() in turn, then polish() on the one that met the target with the
// fewest Steiner points; true if one met the target. steinerCap (0: none) bounds each run's
// Steiner points.
// With exactFeet (see Refiner::exactFeet) the exact feet go into `exact`, and feetHeld says
// whether every triangle around them is right or sharper there.
bool refineWithStrategies(Triangulation& T, const Pslg& input, const Options& options,
                          const Budget& budget, uint32_t steinerCap,
                          std::vector<uint8_t>& freeVertex, StepResult& bestResult,
                          std::vector<ExactVertex>& exact, bool& feetHeld) {
  std::vector<Strategy> strategies = {Strategy{}};
  if (options.mode == Mode::NonObtuse) {
    // Each with exact slides, then with sampled ones: CG:SHOP 49,678 -> 40,851 Steiner points
    // (exact slides alone: 41,745, but more on text outlines, A and Superior, where sampling
    // wins). The exact ones usually win, and run first their point count caps the rest early
    // (half the time of the other order on the slowest instances).
    const Strategy boundary[] = {{false, true, false}, {true, true, true}, {}};
    strategies.clear();
    for (bool exact : {true, false})
      for (Strategy s : boundary) {
        s.exactSlide = exact;
        strategies.push_back(s);
      }
  } else if (options.mode == Mode::Acute) {
    strategies.push_back({false, false, true});
    // Both again with the farthest point of the slice whatever it encroaches, as fallbacks:
    // sparing the segments can grade into a narrow wedge and end a sliver short (it did on one
    // CG:SHOP instance). Run every time, they saved 29 of CG:SHOP's 54,398 Steiner points, for
    // about a tenth of the time.
    for (size_t i = 0; i < 2; ++i) {
      strategies.push_back(strategies[i]);
      strategies.back().weighPoints = false;
      strategies.back().fallback = true;
    }
  }
  if (options.mode == Mode::NonObtuse || options.mode == Mode::Acute) {
    // First of all the first strategy in the fewest-bad-first order: it wins on about half
    // the CG:SHOP instances, and its count caps the others early (CG:SHOP non-obtuse 35,770
    // -> 34,596 Steiner points, acute 62,336 -> 61,129, in less time; alone it does worse on
    // letters: A.poly acute 97 instead of 76).
    Strategy first = strategies.front();
    first.fewestBadFirst = true;
    strategies.insert(strategies.begin(), first);
  }
  if (options.mode == Mode::Acute) {
    // Wide fans in every strategy, and should none of them meet the target (one CG:SHOP
    // instance: two triangles left where wide fans crowd a 6-degree corner), all of them again
    // with the usual fans as fallbacks. Not below 90 degrees, where a bound no strategy
    // reaches is best effort anyway (refine() meshes to 90 then), and each fallback would run
    // until half the Steiner budget is spent (A.poly at 70 degrees: 1.4 s instead of 0.46).
    const size_t count = strategies.size();
    for (size_t i = 0; i < count; ++i) {
      if (options.maxAngle >= 90) {
        strategies.push_back(strategies[i]);
        strategies.back().fallback = true;
      }
      strategies[i].wideFans = true;
    }
  }
  StrategyChoice choice(T, budget, steinerCap);
  size_t next = 0;
#ifdef ACUTEMESH_STRATEGY_THREADS
  // The strategies before the fallbacks concurrently, where there are threads to spare.
  size_t leading = 0;
  while (leading < strategies.size() && !strategies[leading].fallback) ++leading;
  const unsigned threads = threadsFor(options);
  if (threads > 1 && leading > 1) {
    ConcurrentStrategies(T, input, options, budget, strategies, leading, choice)
        .run(std::min<size_t>(threads, leading));
    next = leading;
  }
#endif
  for (; next < strategies.size() && !choice.done(); ++next) {
    const Strategy& strategy = strategies[next];
    if (strategy.fallback && choice.best.met) continue;
    StrategyRun run(T, input, options, budget, strategy, choice.cap());
    run.go();
    choice.consider(std::move(run));
  }
  StrategyRun& best = choice.best;
  if (best.met) best.refiner->polish();
  // Cancelled while improving: the mesh meets the target, but the caller asked to stop.
  if (budget.cancelled() && best.result.ok())
    best.result = {Status::Cancelled, "cancelled while removing Steiner points; the mesh meets "
                                      "the target"};
  best.refiner->markFree(freeVertex);
  feetHeld = best.refiner->exactFeet(exact);
  bestResult = best.result;
  T = std::move(*best.T);
  return best.met;
}

}  // namespace

// Acute and non-obtuse runs try a few boundary strategies on copies of the triangulation and
// keep the result that meets the target with the fewest Steiner points: the corner fans
// everywhere are the safe way (they settle every small angle), fans built lazily and altitude
// feet (non-obtuse) often need far fewer points but now and then do not finish. A later
// strategy stops as soon as it has used as many points as the best so far, so the extra runs
// cost little where the first is already good.
// A bound below 90 degrees is best effort: if no strategy reaches it with half the Steiner
// budget, the input is meshed acute from the start again, so a run that falls short still ends
// acute and certified (exit 1) rather than half refined. So is a minimum angle above
// kSureMinAngle: beyond it Delaunay refinement need not terminate (the seed's refinement
// "generally" does up to 42 degrees; ours wanders on the plate and the airfoil at 42, its
// smallest angle sinking to 12-17 degrees as the points run out), so a run that uses half the
// budget is made again to kSureMinAngle.
//
// Exact feet (non-obtuse, Options::exactFeet): should some triangle around them not be right
// at their exact positions after all (or a vertex stand for two feet), the run is made again
// without them; not when a budget stopped it (the certificate counts what is left).
namespace {
// The largest minimum angle quality refinement reaches on every input we have (whose input
// angles allow it; Refine.QualityReachesItsMinimumAngle).
constexpr double kSureMinAngle = 40;
}  // namespace

StepResult refine(Triangulation& T, const Pslg& input, const Options& options,
                  const Budget& budget, std::vector<uint8_t>& freeVertex,
                  std::vector<ExactVertex>& exact) {
  StepResult result;
  bool feetHeld = true;
  exact.clear();
  if (options.exactFeet && options.mode == Mode::NonObtuse) {
    const Triangulation start = T;
    bool met = refineWithStrategies(T, input, options, budget, 0, freeVertex, result, exact, feetHeld);
    if (feetHeld || !met || !result.ok() || budget.stop()) return result;
    Options plain = options;
    plain.exactFeet = false;
    T = start;
    refineWithStrategies(T, input, plain, budget, 0, freeVertex, result, exact, feetHeld);
    return result;
  }
  const bool acuteBelow90 = options.mode == Mode::Acute && options.maxAngle < 90;
  const bool qualityBeyondSure = options.mode == Mode::Quality && options.minAngle > kSureMinAngle;
  if (!acuteBelow90 && !qualityBeyondSure) {
    refineWithStrategies(T, input, options, budget, 0, freeVertex, result, exact, feetHeld);
    return result;
  }
  const Triangulation start = T;
  const uint32_t half = uint32_t(std::clamp(steinerBudget(input, options, domainArea(T, options)) / 2,
                                            1.0, double(kMaxVertices)));
  bool met = refineWithStrategies(T, input, options, budget, half, freeVertex, result, exact, feetHeld);
  if (result.status == Status::Cancelled || budget.stop()) return result;
  Options sure = options;
  if (acuteBelow90) {
    if (met) return result;
    sure.maxAngle = 90;
    T = start;
    if (!refineWithStrategies(T, input, sure, budget, 0, freeVertex, result, exact, feetHeld))
      return result;
    return {Status::TargetNotMet,
            "the bound of " + degreesText(options.maxAngle) + " was not reached; the mesh is acute"};
  }
  // Quality: a run that ended short of the target for lack of points (not for input angles
  // below it, which no point mends) has been wandering.
  if (T.vertexCount() < start.vertexCount() + half) return result;
  sure.minAngle = kSureMinAngle;
  T = start;
  refineWithStrategies(T, input, sure, budget, 0, freeVertex, result, exact, feetHeld);
  if (result.status == Status::Cancelled) return result;
  return {Status::TargetNotMet, "a minimum angle of " + degreesText(options.minAngle) +
                                    " was not reached with half the Steiner budget; the mesh is "
                                    "refined to " + degreesText(kSureMinAngle) +
                                    (result.ok() ? "" : " (" + result.message + ")")};
}

}  // namespace acutemesh::detail
