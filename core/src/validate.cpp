// validate(): invariant checks of an output mesh against its input (see acutemesh.h).
//
// Every decision is an exact predicate sign or an exact comparison of doubles. The one
// allowance: a segment's chain may pass through a vertex a few hundred ulps off the segment
// when a listed segment edge leads there, since crossing and split points are rounded
// constructions (see walkSegment). The work is O(n log n): per-vertex sorted half-edge lists
// give twins and stars, a hash table matches coordinates, uniform grids over the few points
// that need locating (unused vertices and hole points; boundary vertices where a segment
// leaves the domain) replace all-pairs tests, and winding numbers are propagated across
// edges, with one ray cast per connected piece of the mesh.
#include <acutemesh/acutemesh.h>
#include <acutemesh/predicates.h>

#include "build.h"
#include "rounding.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <type_traits>

namespace acutemesh {
namespace {

constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();
constexpr size_t kMaxErrors = 20;
using detail::nearLine;
using detail::nearSegment;
using detail::roundingReach;

// Message parts, formatted as an ostream would (numbers in decimal, floating point as %g), but
// without iostreams: those pull the whole locale machinery into the WebAssembly build (about
// a sixth of the .wasm).
[[maybe_unused]] void append(std::string& s, const std::string& x) { s += x; }
void append(std::string& s, const char* x) { s += x; }
void append(std::string& s, char c) { s += c; }
template <class T>
std::enable_if_t<std::is_integral_v<T> && !std::is_same_v<T, char> && !std::is_same_v<T, bool>>
append(std::string& s, T v) {
  s += std::to_string(v);
}
template <class T>
std::enable_if_t<std::is_floating_point_v<T>> append(std::string& s, T v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", double(v));
  s += buf;
}
struct Xy;
struct Tri;
void append(std::string& s, Xy q);
void append(std::string& s, Tri t);

// Collects the first kMaxErrors messages; formats nothing once full, so a badly broken mesh
// costs no more than a good one.
class ErrorLog {
 public:
  explicit ErrorLog(Validation& out) : out_(out) {}
  template <class... Parts>
  void add(const Parts&... parts) {
    out_.ok = false;
    if (out_.errors.size() >= kMaxErrors) {
      ++dropped_;
      return;
    }
    std::string s;
    (append(s, parts), ...);
    out_.errors.push_back(std::move(s));
  }
  void finish() {
    if (dropped_ > 0) out_.errors.push_back("... and " + std::to_string(dropped_) + " more");
  }

 private:
  Validation& out_;
  size_t dropped_ = 0;
};

// The shortest decimal that reads back as exactly x.
std::string exact(double x) {
  char buf[32];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, x);
    if (std::strtod(buf, nullptr) == x) break;
  }
  return buf;
}

// "(x, y)", exactly.
struct Xy {
  const double* p;
};
void append(std::string& s, Xy q) { s += '(' + exact(q.p[0]) + ", " + exact(q.p[1]) + ')'; }

// "triangle 17 (4,9,12)"
struct Tri {
  size_t t;
  const uint32_t* v;
};
void append(std::string& s, Tri t) {
  s += "triangle " + std::to_string(t.t) + " (" + std::to_string(t.v[0]) + ',' +
       std::to_string(t.v[1]) + ',' + std::to_string(t.v[2]) + ')';
}

bool finite(const double* p) { return std::isfinite(p[0]) && std::isfinite(p[1]); }

// Open-addressing table from exact coordinates to the first vertex stored with them. Each
// slot keeps 32 bits of the hash beside the vertex, so probing rarely touches coordinates.
class CoordTable {
 public:
  CoordTable(const double* xy, size_t count) : xy_(xy) {
    size_t size = 16;
    while (size < 2 * count) size <<= 1;
    slots_.assign(size, kEmpty);
  }
  // The vertex already stored with v's coordinates, or v after storing it.
  uint32_t insert(uint32_t v) {
    const double* p = xy_ + 2 * size_t(v);
    uint64_t h = hash(p);
    size_t i = probe(h, p);
    if (slots_[i] == kEmpty) slots_[i] = (h & ~uint64_t(kNone)) | v;
    return uint32_t(slots_[i]);
  }
  uint32_t find(const double* p) const { return uint32_t(slots_[probe(hash(p), p)]); }

 private:
  static constexpr uint64_t kEmpty = ~uint64_t(0);
  // The slot holding p's coordinates, or the empty slot where they would go.
  size_t probe(uint64_t h, const double* p) const {
    size_t mask = slots_.size() - 1;
    for (size_t i = size_t(h) & mask;; i = (i + 1) & mask) {
      uint64_t s = slots_[i];
      if (s == kEmpty) return i;
      const double* q = xy_ + 2 * size_t(uint32_t(s));
      if ((s >> 32) == (h >> 32) && q[0] == p[0] && q[1] == p[1]) return i;
    }
  }
  static uint64_t mix(uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  static uint64_t hash(const double* p) {
    double x = p[0] + 0.0, y = p[1] + 0.0;  // -0.0 + 0.0 == +0.0: equal values, equal bits
    uint64_t a, b;
    std::memcpy(&a, &x, 8);
    std::memcpy(&b, &y, 8);
    return mix(a ^ mix(b));
  }
  const double* xy_;
  std::vector<uint64_t> slots_;
};

// A point to locate among the triangles.
struct Query {
  enum Kind : uint8_t { Unused, Boundary, Hole } kind;
  uint32_t id;  // vertex index, or hole index
  double xy[2];
};

// Uniform grid over the query points. forEachNear() visits a superset of the points in the
// closed convex hull of a few given points (a triangle, or a box around a segment), touching
// only the grid cells the shape can reach (row by row for a big shape).
class QueryGrid {
 public:
  explicit QueryGrid(std::vector<Query> queries) : q_(std::move(queries)) {
    if (q_.empty()) return;
    lo_[0] = hi_[0] = q_[0].xy[0];
    lo_[1] = hi_[1] = q_[0].xy[1];
    for (const Query& q : q_)
      for (int k = 0; k < 2; ++k)
        lo_[k] = std::min(lo_[k], q.xy[k]), hi_[k] = std::max(hi_[k], q.xy[k]);
    double w = hi_[0] - lo_[0], h = hi_[1] - lo_[1], cells = double(q_.size());
    if (w > 0 && h > 0) {
      nx_ = int(std::clamp(std::sqrt(cells * w / h), 1.0, cells));
      ny_ = int(std::clamp(cells / nx_, 1.0, cells));
    } else {
      nx_ = w > 0 ? int(cells) : 1;
      ny_ = h > 0 ? int(cells) : 1;
    }
    step_[0] = w > 0 ? w / nx_ : 0;
    step_[1] = h > 0 ? h / ny_ : 0;
    scale_[0] = w > 0 ? nx_ / w : 0;
    scale_[1] = h > 0 ? ny_ / h : 0;
    start_.assign(size_t(nx_) * ny_ + 1, 0);
    for (const Query& q : q_) ++start_[cellOf(q) + 1];
    for (size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
    order_.resize(q_.size());
    std::vector<uint32_t> fill(start_.begin(), start_.end() - 1);
    for (uint32_t i = 0; i < q_.size(); ++i) order_[fill[cellOf(q_[i])]++] = i;
  }

  const std::vector<Query>& queries() const { return q_; }

  template <class F>
  void forEachNear(const double* const* pts, int count, F&& visit) const {
    if (q_.empty()) return;
    double box[2][2];  // [axis][min, max]
    for (int k = 0; k < 2; ++k) {
      box[k][0] = box[k][1] = pts[0][k];
      for (int i = 1; i < count; ++i)
        box[k][0] = std::min(box[k][0], pts[i][k]), box[k][1] = std::max(box[k][1], pts[i][k]);
      if (box[k][1] < lo_[k] || box[k][0] > hi_[k]) return;
    }
    int i0 = cell(0, box[0][0]), i1 = cell(0, box[0][1]);
    int j0 = cell(1, box[1][0]), j1 = cell(1, box[1][1]);
    if (j0 == j1 || (i1 - i0 + 1) * (j1 - j0 + 1) <= 16) {
      for (int j = j0; j <= j1; ++j) visitRow(j, i0, i1, box, visit);
      return;
    }
    // Big shape: per row, only the cells under the shape's x-extent within that row (widened
    // by half a row and a cell each way, which covers any rounding of these float bounds).
    double slack = 1e-9 * (std::fabs(box[0][0]) + std::fabs(box[0][1]) + std::fabs(box[1][0]) +
                           std::fabs(box[1][1]));
    for (int j = j0; j <= j1; ++j) {
      double ya = lo_[1] + (j - 0.5) * step_[1] - slack, yb = lo_[1] + (j + 1.5) * step_[1] + slack;
      double xa, xb;
      if (!xExtentInStrip(pts, count, ya, yb, xa, xb)) continue;
      int ia = std::max(i0, cell(0, xa - slack) - 1), ib = std::min(i1, cell(0, xb + slack) + 1);
      visitRow(j, ia, ib, box, visit);
    }
  }

 private:
  // Monotone in x, so a point inside [a, b] lands in a cell between a's and b's.
  int cell(int axis, double x) const {
    double f = (x - lo_[axis]) * scale_[axis];
    int n = axis == 0 ? nx_ : ny_;
    if (!(f > 0)) return 0;
    if (f >= n) return n - 1;
    return int(f);
  }
  size_t cellOf(const Query& q) const { return size_t(cell(1, q.xy[1])) * nx_ + cell(0, q.xy[0]); }

  template <class F>
  void visitRow(int j, int i0, int i1, const double box[2][2], F& visit) const {
    for (int i = i0; i <= i1; ++i) {
      size_t c = size_t(j) * nx_ + i;
      for (uint32_t k = start_[c]; k < start_[c + 1]; ++k) {
        const Query& q = q_[order_[k]];
        if (q.xy[0] >= box[0][0] && q.xy[0] <= box[0][1] && q.xy[1] >= box[1][0] &&
            q.xy[1] <= box[1][1])
          visit(q);
      }
    }
  }

  // x-extent of the convex hull of pts within ya <= y <= yb (approximate: callers widen it).
  // Any order of the points will do.
  static bool xExtentInStrip(const double* const* pts, int count, double ya, double yb, double& xa,
                             double& xb) {
    xa = std::numeric_limits<double>::infinity();
    xb = -xa;
    auto take = [&](double x) { xa = std::min(xa, x), xb = std::max(xb, x); };
    for (int i = 0; i < count; ++i) {
      const double* p = pts[i];
      if (p[1] >= ya && p[1] <= yb) take(p[0]);
      for (int j = i + 1; j < count; ++j) {  // every pair: the hull's edges are among them
        const double* q = pts[j];
        for (double y : {ya, yb})
          if ((p[1] < y && y < q[1]) || (q[1] < y && y < p[1]))
            take(p[0] + (y - p[1]) * (q[0] - p[0]) / (q[1] - p[1]));
      }
    }
    return xa <= xb;
  }

  std::vector<Query> q_;
  std::vector<uint32_t> start_, order_;
  double lo_[2] = {0, 0}, hi_[2] = {0, 0}, step_[2] = {0, 0}, scale_[2] = {0, 0};
  int nx_ = 1, ny_ = 1;
};

// Winding numbers of points about the input segments (directed a->b): crossings of the +x ray,
// decided by exact orientation with the half-open rule (a segment counts when
// min y <= py < max y), found by a sweep in y over the segments spanning each point's y.
std::vector<int64_t> windingNumbers(const Pslg& in, const std::vector<std::array<double, 2>>& pts) {
  auto P = [&](uint32_t v) { return &in.points[2 * size_t(v)]; };
  std::vector<uint32_t> segs, byY(pts.size());
  for (uint32_t s = 0; s < in.segmentCount(); ++s)
    if (P(in.segments[2 * s])[1] != P(in.segments[2 * s + 1])[1]) segs.push_back(s);
  auto ymin = [&](uint32_t s) {
    return std::min(P(in.segments[2 * s])[1], P(in.segments[2 * s + 1])[1]);
  };
  auto ymax = [&](uint32_t s) {
    return std::max(P(in.segments[2 * s])[1], P(in.segments[2 * s + 1])[1]);
  };
  std::sort(segs.begin(), segs.end(), [&](uint32_t a, uint32_t b) { return ymin(a) < ymin(b); });
  for (uint32_t i = 0; i < pts.size(); ++i) byY[i] = i;
  std::sort(byY.begin(), byY.end(), [&](uint32_t a, uint32_t b) { return pts[a][1] < pts[b][1]; });

  std::vector<int64_t> winding(pts.size(), 0);
  std::vector<uint32_t> active;
  size_t next = 0;
  for (uint32_t i : byY) {
    const double* p = pts[i].data();
    while (next < segs.size() && ymin(segs[next]) <= p[1]) active.push_back(segs[next++]);
    size_t kept = 0;
    for (uint32_t s : active) {
      if (ymax(s) <= p[1]) continue;
      active[kept++] = s;
      const double *a = P(in.segments[2 * s]), *b = P(in.segments[2 * s + 1]);
      double o = orient2d(a, b, p);
      if (a[1] < b[1] && o > 0) ++winding[i];
      if (a[1] > b[1] && o < 0) --winding[i];
    }
    active.resize(kept);
  }
  return winding;
}

// The winding number inside triangle (v, c1, c2) where no double lies strictly inside it (a
// sliver an ulp high): at v + e (c1 - v) + e^2 (c2 - v) for an infinitesimal e > 0, a point
// strictly inside. Every test on it is decided by exact tests on v, c1 and c2 in turn (the
// first that is not zero), so no coordinate of it is ever formed.
int64_t windingNumberInside(const Pslg& in, const double* v, const double* c1, const double* c2) {
  auto P = [&](uint32_t i) { return &in.points[2 * size_t(i)]; };
  auto sign = [](double x) { return (x > 0) - (x < 0); };
  auto aboveY = [&](double y) {  // sign of p.y - y
    if (int s = sign(v[1] - y)) return s;
    if (int s = sign(c1[1] - v[1])) return s;
    return sign(c2[1] - v[1]);
  };
  auto orient = [&](const double* a, const double* b) {  // sign of orient2d(a, b, p)
    if (int s = sign(orient2d(a, b, v))) return s;
    if (int s = sign(orient2d(a, b, c1))) return s;
    return sign(orient2d(a, b, c2));
  };
  int64_t winding = 0;
  for (uint32_t s = 0; s < in.segmentCount(); ++s) {
    const double *a = P(in.segments[2 * s]), *b = P(in.segments[2 * s + 1]);
    if (a[1] < b[1] && aboveY(a[1]) >= 0 && aboveY(b[1]) < 0 && orient(a, b) > 0) ++winding;
    if (a[1] > b[1] && aboveY(b[1]) >= 0 && aboveY(a[1]) < 0 && orient(a, b) < 0) --winding;
  }
  return winding;
}

// Vertices on the boundary of the convex hull of the distinct points, counter-clockwise,
// including those in the middle of a hull edge. Among equal points the used one is taken.
std::vector<uint32_t> convexHull(const std::vector<double>& xy, const std::vector<uint8_t>& used) {
  struct Point {
    double xy[2];
    bool unused;
    uint32_t v;
    bool operator<(const Point& o) const {
      if (xy[0] != o.xy[0]) return xy[0] < o.xy[0];
      if (xy[1] != o.xy[1]) return xy[1] < o.xy[1];
      return unused != o.unused ? o.unused : v < o.v;  // the used copy of a point first
    }
  };
  size_t n = xy.size() / 2;
  if (n == 0) return {};
  // Akl-Toussaint: drop the points strictly left of every edge of a closed polygon of input
  // points (here: the extremes in 8 directions, counter-clockwise). Such a point has
  // positive winding number, so it lies strictly inside the hull, whatever the rounding of
  // the scores that picked the polygon.
  auto at = [&](uint32_t v) { return &xy[2 * size_t(v)]; };
  const double dir[8][2] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};
  uint32_t ext[8] = {};
  for (uint32_t v = 1; v < n; ++v)
    for (int k = 0; k < 8; ++k)
      if (dir[k][0] * at(v)[0] + dir[k][1] * at(v)[1] >
          dir[k][0] * at(ext[k])[0] + dir[k][1] * at(ext[k])[1])
        ext[k] = v;
  std::vector<uint32_t> poly;
  for (uint32_t v : ext)
    if (poly.empty() || (v != poly.back() && v != poly.front())) poly.push_back(v);
  std::vector<Point> pts;
  for (uint32_t v = 0; v < n; ++v) {
    bool inside = poly.size() >= 3;
    for (size_t k = 0; k < poly.size() && inside; ++k)
      inside = orient2d(at(poly[k]), at(poly[(k + 1) % poly.size()]), at(v)) > 0;
    if (!inside) pts.push_back({{at(v)[0], at(v)[1]}, !used[v], v});
  }
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end(),
                        [](const Point& a, const Point& b) {
                          return a.xy[0] == b.xy[0] && a.xy[1] == b.xy[1];
                        }),
            pts.end());
  std::vector<uint32_t> hull;
  if (pts.size() < 3) {
    for (const Point& p : pts) hull.push_back(p.v);
    return hull;
  }
  // Monotone chain that pops only on a right turn, so collinear boundary points stay.
  std::vector<const Point*> chainPts;
  auto chain = [&](auto first, auto last) {
    size_t base = chainPts.size();
    for (auto it = first; it != last; ++it) {
      while (chainPts.size() >= base + 2 &&
             orient2d(chainPts[chainPts.size() - 2]->xy, chainPts.back()->xy, it->xy) < 0)
        chainPts.pop_back();
      chainPts.push_back(&*it);
    }
    chainPts.pop_back();
  };
  chain(pts.begin(), pts.end());
  chain(pts.rbegin(), pts.rend());
  for (const Point* p : chainPts) hull.push_back(p->v);
  return hull;
}

class Validator {
 public:
  Validator(const Pslg& in, const Mesh& m, const Options& opt, Validation& out)
      : in_(in), m_(m), opt_(opt), log_(out) {}

  void run() {
    if (!checkSizes()) return log_.finish();
    buildHalfEdges();
    checkStars();
    checkVertices();
    grid_ = QueryGrid(makeQueries());
    marked_.assign(3 * size_t(T_), 0);
    segCount_.assign(3 * size_t(T_), 0);
    onSegment_.assign(n_, kNone);
    listed_.assign(3 * size_t(T_), 0);
    if (opt_.mode != Mode::Delaunay) {
      readMeshSegments();
      chains_.assign(in_.segmentCount(), {});
      for (uint32_t s = 0; s < in_.segmentCount(); ++s) walkSegment(s);
      rerouteToListedEdges();
      checkMeshSegments();
    }
    checkKinds();
    checkBoundaryEdges();
    bool rule = opt_.mode != Mode::Delaunay && opt_.fill != FillRule::Triangle;
    if (rule && windingIsDefined()) checkWindings();
    locateQueries();
    log_.finish();
  }

 private:
  // ---- helpers ----------------------------------------------------------------------------
  const double* P(uint32_t v) const { return &m_.points[2 * size_t(v)]; }
  const double* inP(uint32_t v) const { return &in_.points[2 * size_t(v)]; }
  const uint32_t* corners(uint32_t t) const { return &m_.triangles[3 * size_t(t)]; }
  Tri tri(uint32_t t) const { return {t, corners(t)}; }
  static uint32_t nextHe(uint32_t h) { return h % 3 == 2 ? h - 2 : h + 1; }
  static uint32_t prevHe(uint32_t h) { return h % 3 == 0 ? h + 2 : h - 1; }
  uint32_t org(uint32_t h) const { return m_.triangles[h]; }
  uint32_t dst(uint32_t h) const { return m_.triangles[nextHe(h)]; }
  // One half-edge stands for each undirected edge: the smaller of a twin pair.
  uint32_t canon(uint32_t h) const { return twin_[h] == kNone ? h : std::min(h, twin_[h]); }
  // Input segments along h minus those against it (NonZero/EvenOdd bookkeeping).
  int64_t along(uint32_t h) const { return canon(h) == h ? segCount_[h] : -segCount_[canon(h)]; }
  // Calls f(h) for every half-edge h leaving v, turning counter-clockwise around v fan by
  // fan: each open fan from its first (boundary) edge, else the one closed fan through any
  // half-edge leaving v. (A second closed fan at v is a fold, reported by checkStars.)
  template <class F>
  void forEachOut(uint32_t v, F&& f) const {
    auto fan = [&](uint32_t first) {
      uint32_t h = first;
      do {
        f(h);
        h = twin_[prevHe(h)];
      } while (h != kNone && h != first);
    };
    if (fanOff_[v] == fanOff_[v + 1]) {
      if (anyOut_[v] != kNone) fan(anyOut_[v]);
    } else {
      for (uint32_t k = fanOff_[v]; k < fanOff_[v + 1]; ++k) fan(fanStart_[k]);
    }
  }
  // Calls f(neighbour, half-edge) for every mesh edge at v: the half-edges leaving v, and the
  // boundary half-edges ending each open fan (their reverse is no half-edge).
  template <class F>
  void forEachEdge(uint32_t v, F&& f) const {
    forEachOut(v, [&](uint32_t h) {
      f(dst(h), h);
      if (twin_[prevHe(h)] == kNone) f(org(prevHe(h)), prevHe(h));
    });
  }
  // The mesh edge u-v (either direction), or kNone.
  uint32_t meshEdge(uint32_t u, uint32_t v) const {
    uint32_t found = kNone;
    forEachEdge(u, [&](uint32_t w, uint32_t h) {
      if (w == v) found = h;
    });
    return found;
  }
  // A triangle of v's star that the direction from v toward point d points into, or kNone.
  // Each triangle (v, p, q) owns the half-open wedge of directions [p - v, q - v), so a
  // direction along an edge belongs to exactly one triangle (when the star is valid).
  uint32_t triangleToward(uint32_t v, const double* d) const {
    uint32_t found = kNone;
    forEachOut(v, [&](uint32_t h) {
      if (found == kNone && orient2d(P(v), P(dst(h)), d) >= 0 &&
          orient2d(P(v), d, P(org(prevHe(h)))) > 0)
        found = h / 3;
    });
    return found;
  }

  // ---- 1. sizes, indices, finite coordinates, input vertices copied exactly ---------------
  bool checkSizes() {
    bool fatal = false;
    auto bad = [&](auto&&... parts) {
      log_.add(parts...);
      fatal = true;
    };
    if (in_.points.size() % 2) bad("input points has odd length ", in_.points.size());
    if (in_.segments.size() % 2) bad("input segments has odd length ", in_.segments.size());
    if (in_.holes.size() % 2) bad("input holes has odd length ", in_.holes.size());
    if (m_.points.size() % 2) bad("mesh points has odd length ", m_.points.size());
    if (m_.triangles.size() % 3)
      bad("mesh triangles has length ", m_.triangles.size(), ", not a multiple of 3");
    if (m_.segments.size() % 2) bad("mesh segments has odd length ", m_.segments.size());
    if (m_.points.size() / 2 >= kNone || m_.triangles.size() >= (size_t(1) << 31))
      bad("mesh too large for 32-bit indices");
    if (fatal) return false;
    nIn_ = uint32_t(in_.vertexCount());
    n_ = uint32_t(m_.vertexCount());
    T_ = uint32_t(m_.triangleCount());
    if (n_ < nIn_) bad("mesh has ", n_, " vertices, fewer than the ", nIn_, " input vertices");
    if (!m_.vertexKind.empty() && m_.vertexKind.size() != n_)
      bad("vertexKind has ", m_.vertexKind.size(), " entries for ", n_, " vertices");
    for (uint32_t v = 0; v < nIn_; ++v)
      if (!finite(inP(v))) bad("input vertex ", v, ' ', Xy{inP(v)}, " is not finite");
    for (uint32_t v = 0; v < n_; ++v)
      if (!finite(P(v))) bad("vertex ", v, ' ', Xy{P(v)}, " is not finite");
    for (uint32_t s = 0; s < in_.segmentCount(); ++s)
      for (int k = 0; k < 2; ++k)
        if (in_.segments[2 * s + k] >= nIn_)
          bad("input segment ", s, " (", in_.segments[2 * s], "->", in_.segments[2 * s + 1],
              ") refers to vertex ", in_.segments[2 * s + k], ", but there are ", nIn_,
              " input vertices");
    for (uint32_t t = 0; t < T_; ++t)
      for (int k = 0; k < 3; ++k)
        if (corners(t)[k] >= n_)
          bad(tri(t), " has index ", corners(t)[k], " out of range (", n_, " vertices)");
    for (size_t s = 0; s < m_.segments.size(); ++s)
      if (m_.segments[s] >= n_)
        bad("mesh segment ", s / 2, " has index ", m_.segments[s], " out of range (", n_,
            " vertices)");
    if (fatal) return false;
    for (uint32_t v = 0; v < nIn_; ++v)
      if (!(P(v)[0] == inP(v)[0] && P(v)[1] == inP(v)[1]))
        log_.add("mesh vertex ", v, ' ', Xy{P(v)}, " differs from input vertex ", v, ' ',
                 Xy{inP(v)});
    return true;
  }

  // ---- 2. orientation, half-edge structure, each directed edge at most once ----------------
  // Also counts, per vertex, the triangles (v, p, q) whose wedge [p - v, q - v) holds the +x
  // direction: with the triangle strictly CCW, that is exactly p.y <= v.y < q.y.
  void buildHalfEdges() {
    good_.assign(T_, 0);
    cover_.assign(n_, 0);
    anyOut_.assign(n_, kNone);
    for (uint32_t t = 0; t < T_; ++t) {
      const uint32_t* c = corners(t);
      const double *a = P(c[0]), *b = P(c[1]), *d = P(c[2]);
      if (!(orient2d(a, b, d) > 0)) {
        log_.add(tri(t), " is not counter-clockwise");
        continue;
      }
      good_[t] = 1;
      double y[3] = {a[1], b[1], d[1]};
      for (int k = 0; k < 3; ++k) {
        cover_[c[k]] += y[(k + 1) % 3] <= y[k] && y[(k + 2) % 3] > y[k];
        anyOut_[c[k]] = 3 * t + k;
      }
    }
    findTwins();
    // Open fans start at the boundary half-edges, grouped here by origin.
    boundaryVertex_.assign(n_, 0);
    fanOff_.assign(n_ + 1, 0);
    for (uint32_t h : boundary_) {
      boundaryVertex_[org(h)] = boundaryVertex_[dst(h)] = 1;
      ++fanOff_[org(h) + 1];
    }
    for (uint32_t v = 0; v < n_; ++v) fanOff_[v + 1] += fanOff_[v];
    fanStart_.resize(boundary_.size());
    std::vector<uint32_t> fill(fanOff_.begin(), fanOff_.end() - 1);
    for (uint32_t h : boundary_) fanStart_[fill[org(h)]++] = h;
  }

  // Twins, and each directed edge at most once. Half-edges are grouped by the smaller end of
  // their edge, so a twin pair lands side by side once each (small) group is sorted: a count,
  // a scatter and a scan, with no search.
  void findTwins() {
    std::vector<uint32_t> off(n_ + 1, 0);
    for (uint32_t h = 0; h < 3 * T_; ++h)
      if (good_[h / 3]) ++off[std::min(org(h), dst(h)) + 1];
    for (uint32_t v = 0; v < n_; ++v) off[v + 1] += off[v];
    // Entry: larger end << 32 | half-edge << 1 | whether the half-edge runs from the larger end.
    std::vector<uint64_t> edges(off[n_]);
    std::vector<uint32_t> fill(off.begin(), off.end() - 1);
    for (uint32_t h = 0; h < 3 * T_; ++h) {
      if (!good_[h / 3]) continue;
      uint32_t u = org(h), v = dst(h);
      edges[fill[std::min(u, v)]++] = uint64_t(std::max(u, v)) << 32 | uint64_t(h) << 1 | (u > v);
    }
    twin_.assign(3 * size_t(T_), kNone);
    auto half = [](uint64_t e) { return uint32_t(e) >> 1; };
    for (uint32_t v = 0; v < n_; ++v) {
      auto first = edges.begin() + off[v], last = edges.begin() + off[v + 1];
      std::sort(first, last);
      for (auto run = first, end = first; run != last; run = end) {
        while (end != last && *end >> 32 == *run >> 32) ++end;
        if (end - run == 2 && (run[0] & 1) != (run[1] & 1)) {
          twin_[half(run[0])] = half(run[1]);
          twin_[half(run[1])] = half(run[0]);
          continue;
        }
        for (auto e = run; e != end; ++e) boundary_.push_back(half(*e));
        for (auto e = run + 1; e != end; ++e) {
          auto same = std::find_if(run, e, [&](uint64_t x) { return (x & 1) == (*e & 1); });
          if (same == e) continue;
          log_.add("directed edge ", org(half(*e)), "->", dst(half(*e)), " is used twice: by ",
                   tri(half(*same) / 3), " and ", tri(half(*e) / 3));
          break;
        }
      }
    }
  }

  // ---- 3. no vertex star wraps around more than once ---------------------------------------
  void checkStars() {
    for (uint32_t v = 0; v < n_; ++v) {
      if (anyOut_[v] == kNone) continue;
      if (cover_[v] > 1)
        log_.add("vertex ", v, ' ', Xy{P(v)}, ": its triangles wrap around it ", cover_[v],
                 " times (folded or overlapping triangles)");
      else if (cover_[v] == 0 && !boundaryVertex_[v])
        log_.add("vertex ", v, ' ', Xy{P(v)},
                 " has no boundary edge, but its triangles do not close around it");
    }
    // Each fan at a boundary vertex starts at an outgoing boundary edge; the fan must not
    // wrap past its own start, nor may another fan cover that direction.
    for (uint32_t h : boundary_) {
      uint32_t v = org(h), covering = 0;
      forEachOut(v, [&](uint32_t g) {
        covering += orient2d(P(v), P(dst(g)), P(dst(h))) >= 0 &&
                    orient2d(P(v), P(dst(h)), P(org(prevHe(g)))) > 0;
      });
      if (covering > 1)
        log_.add("vertex ", v, ' ', Xy{P(v)}, ": ", covering,
                 " of its triangles overlap along boundary edge ", v, "->", dst(h));
    }
  }

  // ---- 4. used vertices, duplicates, the input-to-mesh vertex map --------------------------
  void checkVertices() {
    used_.assign(n_, 0);
    for (uint32_t v = 0; v < n_; ++v) used_[v] = anyOut_[v] != kNone;
    CoordTable table(m_.points.data(), n_);
    for (uint32_t v = 0; v < n_; ++v) {
      if (!used_[v]) continue;
      uint32_t first = table.insert(v);
      if (first != v)
        log_.add("vertices ", first, " and ", v, " are both used and both at ", Xy{P(v)});
    }
    // Segment endpoints go by coordinates: a duplicate input vertex stands for its used twin.
    rep_.assign(nIn_, kNone);
    for (uint32_t v = 0; v < nIn_; ++v)
      rep_[v] = used_[v] && P(v)[0] == inP(v)[0] && P(v)[1] == inP(v)[1] ? v : table.find(inP(v));
    twinOfUnused_.assign(n_, kNone);
    int flat = -1;  // whether all vertices are collinear; worked out when first needed
    for (uint32_t v = 0; v < n_; ++v) {
      if (used_[v]) continue;
      uint32_t u = table.find(P(v));
      twinOfUnused_[v] = u;
      if (u == kNone && hullDomain() && (opt_.mode == Mode::Delaunay || in_.holes.empty())) {
        if (flat < 0) flat = allCollinear();
        if (!flat)
          log_.add("vertex ", v, ' ', Xy{P(v)},
                   " is used by no triangle, but the whole convex hull is meshed");
      }
      if (u == kNone || v >= nIn_) continue;
      if (u >= nIn_)
        log_.add("input vertex ", v, ' ', Xy{P(v)}, " is unused, but Steiner vertex ", u,
                 " is at the same point");
      else if (u > v)
        log_.add("input vertex ", v, ' ', Xy{P(v)}, " is unused, but its later duplicate ", u,
                 " is used (the first copy should be kept)");
    }
  }

  // Whether the domain is the convex hull (less hole regions): Delaunay mode, and Triangle
  // fill with convexHull set or without any segment. The fill rules ignore convexHull.
  bool hullDomain() const {
    return opt_.mode == Mode::Delaunay ||
           (opt_.fill == FillRule::Triangle && (opt_.convexHull || in_.segments.empty()));
  }

  bool allCollinear() const {
    uint32_t a = 0, b = 1;
    while (b < n_ && P(b)[0] == P(a)[0] && P(b)[1] == P(a)[1]) ++b;
    for (uint32_t v = b + 1; v < n_; ++v)
      if (orient2d(P(a), P(b), P(v)) != 0) return false;
    return true;
  }

  void checkKinds() {
    if (m_.vertexKind.empty()) return;
    static const char* names[] = {"input", "unused", "segment", "free"};
    for (uint32_t v = 0; v < n_; ++v) {
      uint8_t kind = m_.vertexKind[v];
      if (kind > kFreeVertex) {
        log_.add("vertex ", v, " has unknown kind ", int(kind));
        continue;
      }
      uint8_t want = kind;
      if (v < nIn_)
        want = used_[v] ? kInputVertex : kUnusedVertex;
      else if (kind < kSegmentVertex)
        want = kFreeVertex;
      else if (opt_.mode != Mode::Delaunay && used_[v])
        want = onSegment_[v] != kNone ? kSegmentVertex : kFreeVertex;
      if (want == kind) continue;
      if (v >= nIn_ && want == kSegmentVertex)
        log_.add("vertex ", v, ' ', Xy{P(v)}, " has kind free, but lies on input segment ",
                 onSegment_[v]);
      else if (v >= nIn_ && kind == kSegmentVertex)
        log_.add("vertex ", v, ' ', Xy{P(v)}, " has kind segment, but lies on no input segment");
      else
        log_.add("vertex ", v, ' ', Xy{P(v)}, " has kind ", names[kind], ", expected ",
                 names[want]);
    }
  }

  // The points to locate among the triangles: unused vertices without a used twin, and
  // (Triangle fill) the hole points.
  std::vector<Query> makeQueries() {
    std::vector<Query> q;
    for (uint32_t v = 0; v < n_; ++v)
      if (!used_[v] && twinOfUnused_[v] == kNone)
        q.push_back({Query::Unused, v, {P(v)[0], P(v)[1]}});
    if (opt_.mode != Mode::Delaunay && opt_.fill == FillRule::Triangle)
      for (uint32_t i = 0; i < in_.holes.size() / 2; ++i) {
        const double* h = &in_.holes[2 * size_t(i)];
        if (finite(h))
          q.push_back({Query::Hole, i, {h[0], h[1]}});
        else
          log_.add("hole ", i, ' ', Xy{h}, " is not finite");
      }
    return q;
  }

  // ---- 5. every input segment is a chain of mesh edges ----------------------------------
  // Walks from a toward b. A step goes along a mesh edge to a vertex exactly on the segment
  // and strictly closer to b, or else along a listed segment edge (Mesh::segments) to a
  // vertex within rounding reach of the segment (a rounded crossing or split point: two
  // roundings of nearly the same point may even be out of order) not visited before. Where
  // no step continues, the segment must leave the meshed domain there (no
  // triangle of the vertex covers the direction toward b) and may re-enter only at a boundary
  // vertex on it (within rounding reach).
  // Segments a rounding apart can make two chains side by side, and the first step that
  // looks best may lead into the wrong one (fuzz finding parallel-chains-one-ulp-apart): the
  // walk is depth first, trying the other steps from a vertex when one leads to a dead end;
  // failing that, walks that may also leave the domain where an edge goes on and skip
  // boundary vertices beside the segment (SegmentWalk::leaveAnywhere). Only if no walk gets
  // through is the segment reported, along the walk of first choices. rerouteToListedEdges()
  // then matches the walks against the mesh's segment list.
  void walkSegment(uint32_t s) {
    uint32_t a = in_.segments[2 * s], b = in_.segments[2 * s + 1];
    const double *A = inP(a), *B = inP(b);
    if (A[0] == B[0] && A[1] == B[1]) return;
    SegmentWalk walk{s, a, b, A, B};
    walk.leaveAnywhere = false;
    if (walkDepthFirst(walk, true)) return;
    walk.leaveAnywhere = true;
    if (walkDepthFirst(walk, true)) return;
    walk.leaveAnywhere = false;
    walkDepthFirst(walk, false);
  }

  // A walk along input segment s (a->b): see walkSegment.
  struct SegmentWalk {
    uint32_t s, a, b;
    const double *A, *B;
    int axis = 0;
    double dir = 1;
    std::vector<uint32_t> entries;  // boundary vertices on the segment, in order; built lazily
    bool haveEntries = false;
    // Whether a depth-first walk may also leave the domain where an edge goes on, and skip
    // boundary vertices; tried only when no walk gets through without (see walkSteps).
    bool leaveAnywhere = false;
    // rerouteToListedEdges: listed edges only, those no walk has taken first; with
    // mustTakeLeftOver only a walk that takes one of those (leftOver_) gets through.
    bool preferListed = false, mustTakeLeftOver = false;
    SegmentWalk(uint32_t s_, uint32_t a_, uint32_t b_, const double* A_, const double* B_)
        : s(s_), a(a_), b(b_), A(A_), B(B_) {
      reach = roundingReach(A, B, A);
      // Position along the segment: the coordinate on its dominant axis, signed to grow toward b.
      axis = std::fabs(B[0] - A[0]) >= std::fabs(B[1] - A[1]) ? 0 : 1;
      dir = B[axis] > A[axis] ? 1 : -1;
    }
    double key(const double* p) const { return dir * p[axis]; }
    double reach = 0;  // roundingReach() about the segment (it takes both ends into account)
  };

  // The boundary vertices on the segment (within rounding reach) past position k, in order:
  // the index of the first in w.entries.
  size_t entriesAfter(SegmentWalk& w, double k) {
    if (!w.haveEntries) {
      w.haveEntries = true;
      const double *A = w.A, *B = w.B;
      double r = w.reach;
      double box[8][2] = {{A[0] - r, A[1] - r}, {A[0] + r, A[1] - r}, {A[0] + r, A[1] + r},
                          {A[0] - r, A[1] + r}, {B[0] - r, B[1] - r}, {B[0] + r, B[1] - r},
                          {B[0] + r, B[1] + r}, {B[0] - r, B[1] + r}};
      const double* around[8];
      for (int i = 0; i < 8; ++i) around[i] = box[i];
      // From a rounding before a: where a is no mesh vertex, a rounded crossing may stand in
      // for it an ulp behind it (fuzz finding overlap-reaches-through-triangle).
      boundaryGrid().forEachNear(around, 8, [&](const Query& q) {
        if (w.key(q.xy) >= w.key(A) - r && w.key(q.xy) <= w.key(B) && nearLine(A, B, q.xy))
          w.entries.push_back(q.id);
      });
      std::sort(w.entries.begin(), w.entries.end(),
                [&](uint32_t u, uint32_t v) { return w.key(P(u)) < w.key(P(v)); });
    }
    size_t i = 0;
    while (i < w.entries.size() && w.key(P(w.entries[i])) <= k) ++i;
    return i;
  }

  // One step of a walk: to vertex `to` along mesh half-edge `he`, or (he == kNone) past a
  // stretch outside the domain to boundary vertex `to` (kNone: the segment ends outside).
  struct WalkStep {
    uint32_t to, he;
  };
  struct WalkFrame {
    uint32_t vertex, he;             // the vertex, and the half-edge that led to it (or kNone)
    uint32_t previousOnSegment;      // onSegment_[vertex] before the walk came
    std::vector<WalkStep> steps;     // the steps from it, best first
    size_t nextStep = 0;
  };

  // What logs why segment w is not a chain of mesh edges (report), or nothing (a depth-first
  // walk trying its ways).
  auto reporter(const SegmentWalk& w, bool report) {
    return [this, &w, report](auto&&... parts) {
      if (report) log_.add("input segment ", w.s, " (", w.a, "->", w.b, ") ", parts...);
    };
  }

  // The steps from cur, best first: edges to a vertex exactly on the segment and closer to
  // b, then listed edges to vertices within rounding reach, the most advanced first; with no
  // such edge, the jump to the next boundary vertex if the segment leaves the domain at cur.
  // The walk of first choices (backtrack false) logs why it is stuck at cur, if it is.
  void walkSteps(SegmentWalk& w, uint32_t cur, bool backtrack, std::vector<WalkStep>& out) {
    out.clear();
    const double *A = w.A, *B = w.B;
    auto key = [&](const double* p) { return w.key(p); };
    auto name = reporter(w, !backtrack);
    uint32_t past = kNone;
    // An edge runs past b only from a vertex exactly on the segment: from a rounded one
    // (entered a rounding off the line) it does not lie along the segment to begin with
    // (fuzz finding boundary-edge-along-segment-past-its-end.poly).
    bool curOn = orient2d(A, B, P(cur)) == 0;
    size_t exactCount = 0;
    const uint32_t end = rep_[w.b];
    forEachEdge(cur, [&](uint32_t c, uint32_t h) {
      bool on = orient2d(A, B, P(c)) == 0;
      if (c == end && listed_[canon(h)]) {
        // A listed edge to b ends the walk, even from a rounding past b or beside it
        // (chain-overshoots-its-end, end-an-ulp-above-the-chain).
        out.insert(out.begin() + long(exactCount++), {c, h});
      } else if (on && key(P(c)) > key(P(cur)) && onSegment_[c] != w.s) {  // never back: overlap-back-step.poly
        if (key(P(c)) > key(B)) {
          if (curOn) past = c;
        } else {
          out.insert(out.begin() + long(exactCount++), {c, h});
        }
      } else if (listed_[canon(h)] && onSegment_[c] != w.s && key(P(c)) <= key(B) + w.reach &&
                 (on || nearLine(A, B, P(c)))) {
        // (up to a rounding past b: a chain may reach b from a rounded crossing an ulp
        // beyond it, fuzz finding chain-overshoots-its-end.poly)
        out.push_back({c, h});
      }
    });
    // The most advanced near step first.
    std::sort(out.begin() + long(exactCount), out.end(), [&](const WalkStep& x, const WalkStep& y) {
      return key(P(x.to)) > key(P(y.to));
    });
    // A near step that does not advance (roundings out of order) is for a chain that would
    // otherwise be stuck inside the mesh: where the segment leaves the mesh at cur, it leaves
    // (fuzz finding overlap-sideways-step.poly: a listed edge an ulp long beside the start).
    uint32_t toward = triangleToward(cur, B);
    if (toward == kNone)
      out.erase(std::remove_if(out.begin() + long(exactCount), out.end(),
                               [&](const WalkStep& x) { return key(P(x.to)) <= key(P(cur)); }),
                out.end());
    if (w.preferListed) {  // listed edges no walk took, then the other listed ones; no others
      // (Two passes rather than std::stable_sort: libstdc++ 12's temporary buffer trips
      // ASan's alloc-dealloc check.)
      preferred_.clear();
      for (bool walked : {false, true})
        for (const WalkStep& z : out)
          if (listed_[canon(z.he)] && (marked_[canon(z.he)] > 0) == walked) preferred_.push_back(z);
      out.swap(preferred_);
    }
    if (!out.empty()) {
      if (!backtrack || !w.leaveAnywhere || toward != kNone) return;
    } else if (past != kNone) {
      return name("is not a chain of mesh edges: mesh edge ", cur, "-", past, " runs past ", w.b);
    } else if (toward != kNone) {
      return name("is not a chain of mesh edges: stops at vertex ", cur, " and enters ",
                  tri(toward));
    }
    // The segment leaves the domain at cur (with w.leaveAnywhere also where an edge goes on).
    entrySteps(w, key(P(cur)), backtrack, out);
  }

  // The jumps to where the segment re-enters the domain after position k: the next boundary
  // vertex on it, and with w.leaveAnywhere the few after it too, since one within rounding
  // reach of the segment need not be on it (overlap-back-step.poly under EvenOdd: the segment
  // leaves at its start and passes an ulp beside a boundary vertex whose triangle it never
  // enters); {kNone} if none is left (the segment ends outside). A vertex the segment would
  // reach through one of its triangles is no entry (the reporting walk says so).
  void entrySteps(SegmentWalk& w, double k, bool backtrack, std::vector<WalkStep>& out) {
    constexpr size_t kEntriesTried = 4;
    auto name = reporter(w, !backtrack);
    size_t i = entriesAfter(w, k);
    if (i == w.entries.size()) return out.push_back({kNone, kNone});
    size_t last = std::min(w.entries.size(), i + (w.leaveAnywhere ? kEntriesTried : 1));
    for (size_t j = i; j < last; ++j) {
      uint32_t next = w.entries[j];
      bool through = backtrack ? enteringTriangle(next, w.A) != kNone
                               : enteredThroughTriangle(next, w.A, name);
      if (!through) out.push_back({next, kNone});
    }
    // With b outside the mesh, a segment that left the domain may also end outside if every
    // boundary vertex still ahead is only a rounding off it (crossing-rounded-onto-the-top-
    // vertex: the segment touches the domain only at a, and the vertex an ulp below a, whose
    // obtuse corner covers the direction to b, is no way back in).
    if (backtrack && w.leaveAnywhere && rep_[w.b] == kNone) {
      bool exactAhead = false;
      for (size_t j = i; j < w.entries.size() && !exactAhead; ++j)
        exactAhead = orient2d(w.A, w.B, P(w.entries[j])) == 0;
      if (!exactAhead) out.push_back({kNone, kNone});
    }
  }

  // The walk of segment w, depth first over the steps from each vertex (backtrack) or along
  // the first step from each (reporting why it is stuck where it is). True, with the chain's
  // edges marked, if it reaches b (or, b being no mesh vertex, ends outside the domain).
  bool walkDepthFirst(SegmentWalk& w, bool backtrack) {
    uint32_t start = rep_[w.a];
    if (start != kNone) return walkFrom(w, backtrack, start);
    // a is no mesh vertex: the segment starts outside the domain and enters it where
    // entrySteps() says.
    std::vector<WalkStep> firsts;
    entrySteps(w, -std::numeric_limits<double>::infinity(), backtrack, firsts);
    for (const WalkStep& first : firsts)
      if (walkFrom(w, backtrack, first.to)) return true;
    return false;
  }

  // The walk of walkDepthFirst from vertex cur (kNone: the segment lies outside the domain).
  bool walkFrom(SegmentWalk& w, bool backtrack, uint32_t cur) {
    const uint32_t end = rep_[w.b];
    auto name = reporter(w, !backtrack);
    std::vector<WalkFrame>& stack = walkStack_;
    stack.clear();
    // Vertices past which every walk got stuck are not tried again in this walk (its rules:
    // a later walk of the same segment may have other steps); with that, and a bound on the
    // steps, a walk takes time linear in what it looks at.
    if (deadEnd_.size() != n_) deadEnd_.assign(n_, 0);
    const uint32_t id = ++walkId_;
    size_t budget = 1024 + 16 * size_t(n_);
    uint32_t via = kNone;  // the half-edge of the last step (kNone: a jump, or the start)
    bool reached = false;
    for (;;) {
      if (cur == end || cur == kNone) {
        reached = cur == end || end == kNone;
        if (reached && w.mustTakeLeftOver) {
          bool takes = stillLeftOver(via);
          for (size_t i = 1; i < stack.size() && !takes; ++i) takes = stillLeftOver(stack[i].he);
          reached = takes;
        }
        if (reached) break;
        if (!backtrack) {
          name("is not a chain of mesh edges: never reaches vertex ", end,
               ", which is in the mesh");
          break;
        }
      } else {
        stack.push_back({cur, via, onSegment_[cur], {}, 0});
        onSegment_[cur] = w.s;
        walkSteps(w, cur, backtrack, stack.back().steps);
      }
      // The next step: the first untried one from the deepest vertex that has one left.
      bool stepped = false;
      while (!stack.empty() && !stepped) {
        WalkFrame& f = stack.back();
        if (backtrack)
          while (f.nextStep < f.steps.size() && f.steps[f.nextStep].to != kNone &&
                 deadEnd_[f.steps[f.nextStep].to] == id)
            ++f.nextStep;
        if (f.nextStep < f.steps.size() && (backtrack || f.nextStep == 0)) {
          const WalkStep& step = f.steps[f.nextStep++];
          cur = step.to, via = step.he, stepped = true;
        } else if (!backtrack) {
          break;  // stuck, and walkSteps has said why
        } else {
          deadEnd_[f.vertex] = id;
          onSegment_[f.vertex] = f.previousOnSegment;
          stack.pop_back();
        }
      }
      if (!stepped || (backtrack && budget-- == 0)) break;
    }
    if (backtrack && !reached) {
      for (size_t i = stack.size(); i-- > 0;)
        onSegment_[stack[i].vertex] = stack[i].previousOnSegment;
      return false;
    }
    // The chain walked (in full, or as far as the reporting walk got) lies on the segment.
    Chain& chain = chains_[w.s];
    chain.steps.clear();
    chain.vertices.clear();
    for (size_t i = 0; i < stack.size(); ++i) {
      chain.vertices.push_back(stack[i].vertex);
      if (i > 0 && stack[i].he != kNone) chain.steps.push_back({stack[i].he, stack[i - 1].vertex});
    }
    if (reached && end != kNone) {
      if (via != kNone && !stack.empty()) chain.steps.push_back({via, stack.back().vertex});
      chain.vertices.push_back(end);
      onSegment_[end] = w.s;
    }
    for (const auto& step : chain.steps) markWalked(step[0], step[1]);
    return reached;
  }

  // Whether half-edge h (kNone: no) was left over by the first walks and no walk has taken it
  // since (rerouteToListedEdges).
  bool stillLeftOver(uint32_t h) const {
    return h != kNone && leftOver_[canon(h)] && !marked_[canon(h)];
  }

  // Half-edge h, taken from vertex from, lies on the segment walked (w: +1), or no longer
  // does (w: -1).
  void markWalked(uint32_t h, uint32_t from, int w = 1) {
    if (h == kNone) return;
    uint32_t e = canon(h);
    marked_[e] += uint32_t(w);
    segCount_[e] += org(e) == from ? w : -w;
  }

  // A segment's walk as found: its steps along mesh edges, and the vertices it went through.
  struct Chain {
    std::vector<std::array<uint32_t, 2>> steps;  // half-edge, and the vertex it was taken from
    std::vector<uint32_t> vertices;
  };

  // Where segments lie a rounding apart, the mesh can hold two chains side by side and a
  // walk may take the other segment's (fuzz finding parallel-chains-one-ulp-apart: the walk of
  // 3->1 took 2-0-1, the mesh's chain for it is 2-4-1, and then edges 2-4 and 4-1, listed as
  // segment edges, lay on no walk), or an unlisted edge exactly on a segment the mesh follows
  // by a chain through a rounded crossing beside it (parallel-chains-leftover-edge). Where
  // either is left, the walks of the segments concerned (through an end of a left-over listed
  // edge, or along an unlisted edge) are tried again along listed edges only, those no walk
  // took first, and a new walk is kept if it leaves fewer edges either listed and on no walk,
  // or on a walk and unlisted (or as many, having freed an unlisted edge of its own).
  void rerouteToListedEdges() {
    auto wrong = [&](uint32_t e) { return listed_[e] ? marked_[e] == 0 : marked_[e] > 0; };
    auto touchesLeftOver = [&](uint32_t v) {
      bool any = false;
      forEachEdge(v, [&](uint32_t, uint32_t h) { any |= stillLeftOver(h); });
      return any;
    };
    auto takesUnlisted = [&](const Chain& c) {
      return std::any_of(c.steps.begin(), c.steps.end(), [&](const std::array<uint32_t, 2>& step) {
        return !listed_[canon(step[0])];
      });
    };
    auto apply = [&](const Chain& c, uint32_t s, int w) {
      for (const auto& step : c.steps) markWalked(step[0], step[1], w);
      for (uint32_t v : c.vertices)
        if (w > 0) onSegment_[v] = s;
        else if (onSegment_[v] == s) onSegment_[v] = kNone;
    };
    // The edges either chain takes, each once.
    std::vector<uint32_t> edges;
    auto wrongAmong = [&](const Chain& x, const Chain& y) {
      edges.clear();
      for (const Chain* c : {&x, &y})
        for (const auto& step : c->steps) edges.push_back(canon(step[0]));
      std::sort(edges.begin(), edges.end());
      edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
      size_t n = 0;
      for (uint32_t e : edges) n += wrong(e);
      return n;
    };
    auto anyWrong = [&] {
      for (uint32_t h = 0; h < 3 * T_; ++h)
        if (canon(h) == h && wrong(h)) return true;
      return false;
    };
    if (!anyWrong()) return;
    // A few passes: a walk moved off an edge in one leaves it over for the next.
    bool changed = true;
    for (int pass = 0; pass < 4 && changed && (pass == 0 || anyWrong()); ++pass) {
      changed = false;
      leftOver_.assign(3 * size_t(T_), 0);
      for (uint32_t h = 0; h < 3 * T_; ++h) leftOver_[h] = listed_[h] && !marked_[h];
      for (uint32_t s = 0; s < in_.segmentCount(); ++s) {
        const Chain& current = chains_[s];
        bool nearLeftOver =
            std::any_of(current.vertices.begin(), current.vertices.end(), touchesLeftOver);
        if (current.vertices.empty() || (!nearLeftOver && !takesUnlisted(current))) continue;
        Chain old = current;
        apply(old, s, -1);
        uint32_t a = in_.segments[2 * s], b = in_.segments[2 * s + 1];
        SegmentWalk walk{s, a, b, inP(a), inP(b)};
        walk.preferListed = true;
        walk.mustTakeLeftOver = nearLeftOver;
        bool found = walkDepthFirst(walk, true);
        if (!found) walk.leaveAnywhere = true, found = walkDepthFirst(walk, true);
        if (!found) {
          chains_[s] = old;
          apply(old, s, 1);
          continue;
        }
        Chain fresh = chains_[s];
        size_t after = wrongAmong(old, fresh);
        apply(fresh, s, -1);
        apply(old, s, 1);
        // Kept if it leaves fewer wrong edges, or as many but itself takes no unlisted edge
        // where the old walk did (a segment given twice: one walk alone cannot free the edge).
        size_t before = wrongAmong(old, fresh);
        if (after < before || (after == before && takesUnlisted(old))) {
          apply(old, s, -1);
          apply(fresh, s, 1);
          chains_[s] = fresh;
          changed = true;
        } else {
          chains_[s] = old;
        }
      }
    }
    // Which segment each vertex lies on, from the walks as they now are.
    std::fill(onSegment_.begin(), onSegment_.end(), kNone);
    for (uint32_t s = 0; s < in_.segmentCount(); ++s)
      for (uint32_t v : chains_[s].vertices) onSegment_[v] = s;
  }

  const QueryGrid& boundaryGrid() {
    if (!boundaryGrid_) {
      std::vector<Query> q;
      for (uint32_t v = 0; v < n_; ++v)
        if (boundaryVertex_[v]) q.push_back({Query::Boundary, v, {P(v)[0], P(v)[1]}});
      boundaryGrid_ = std::make_unique<QueryGrid>(std::move(q));
    }
    return *boundaryGrid_;
  }

  // The segment reaches boundary vertex v from outside the mesh: it must not arrive through
  // one of v's triangles.
  template <class Name>
  bool enteredThroughTriangle(uint32_t v, const double* A, Name& name) {
    uint32_t t = enteringTriangle(v, A);
    if (t != kNone) name("is not a chain of mesh edges: reaches vertex ", v, " through ", tri(t));
    return t != kNone;
  }

  // The triangle of v that the direction from v toward A enters, unless its side opposite v
  // passes within rounding reach of v: a corner that thin a segment may graze by rounding
  // (fuzz finding grazes-a-corner: two input vertices two ulps apart, a segment ending at
  // one of them passing an ulp beside the other).
  uint32_t enteringTriangle(uint32_t v, const double* A) const {
    uint32_t t = triangleToward(v, A);
    if (t == kNone) return kNone;
    const uint32_t* c = corners(t);
    int k = c[0] == v ? 0 : c[1] == v ? 1 : 2;
    return nearSegment(P(c[(k + 1) % 3]), P(c[(k + 2) % 3]), P(v)) ? kNone : t;
  }

  void readMeshSegments() {
    for (size_t i = 0; i + 1 < m_.segments.size(); i += 2) {
      uint32_t u = m_.segments[i], v = m_.segments[i + 1], h = meshEdge(u, v);
      if (h == kNone)
        log_.add("mesh segment ", i / 2, " (", u, "-", v, ") is not a mesh edge");
      else if (listed_[canon(h)])
        log_.add("mesh segment ", i / 2, " (", u, "-", v, ") is listed twice");
      else
        listed_[canon(h)] = 1;
    }
  }

  // Mesh::segments lists exactly the mesh edges that lie on input segments.
  void checkMeshSegments() {
    for (size_t i = 0; i + 1 < m_.segments.size(); i += 2) {
      uint32_t u = m_.segments[i], v = m_.segments[i + 1], h = meshEdge(u, v);
      if (h != kNone && !marked_[canon(h)])
        log_.add("mesh segment ", i / 2, " (", u, "-", v, ") lies on no input segment");
    }
    for (uint32_t h = 0; h < 3 * T_; ++h)
      if (marked_[h] && !listed_[h])
        log_.add("mesh edge ", org(h), "-", dst(h),
                 " lies on an input segment but is missing from mesh segments");
  }

  // ---- 6. domain: boundary edges, fill rule, hole points, unused vertices -----------------
  void checkBoundaryEdges() {
    bool hullOk = hullDomain();
    bool segmentOk = opt_.mode != Mode::Delaunay;
    std::vector<uint32_t> hull, hullNext;
    if (hullOk) {
      // The hull of the input vertices: refinement splits hull edges at rounded points, so
      // the mesh's own hull may differ from it by rounding.
      // Only input vertices count: a split point rounded outward would otherwise join the
      // hull and push an input vertex of a nearly straight hull stretch off it
      // (one-ulp-apart.node, nonobtuse).
      std::vector<uint8_t> usedInput(used_.begin(), used_.begin() + nIn_);
      std::vector<double> inputPoints(m_.points.begin(), m_.points.begin() + 2 * size_t(nIn_));
      hull = convexHull(inputPoints, usedInput);
      hullNext.assign(n_, kNone);
      for (size_t i = 0; i < hull.size(); ++i) hullNext[hull[i]] = hull[(i + 1) % hull.size()];
    }
    // A boundary edge with a Steiner end lies along an input hull edge A->B: each end is A, B
    // or a Steiner point within rounding reach of the line, inside the edge's extent.
    auto alongHullEdge = [&](uint32_t u, uint32_t v) {
      for (size_t i = 0; i < hull.size(); ++i) {
        uint32_t a = hull[i], b = hull[(i + 1) % hull.size()];
        auto fits = [&](uint32_t x) {
          return x == a || x == b ||
                 (x >= nIn_ && nearLine(P(a), P(b), P(x)) && dot2d(P(x), P(a), P(b)) < 0);
        };
        if (fits(u) && fits(v)) return true;
      }
      return false;
    };
    for (uint32_t h : boundary_) {
      if (segmentOk && marked_[h]) continue;
      if (hullOk && hullNext[org(h)] == dst(h)) continue;
      if (hullOk && (org(h) >= nIn_ || dst(h) >= nIn_) && alongHullEdge(org(h), dst(h))) continue;
      log_.add("boundary edge ", org(h), "->", dst(h), " of ", tri(h / 3),
               !hullOk     ? " does not lie on an input segment"
               : segmentOk ? " lies neither on an input segment nor on the convex hull"
                           : " is not a convex hull edge");
    }
  }

  // Winding numbers are defined (independent of the ray) only when the segments form closed
  // cycles: every point is the tail of as many segments as it is the head of. For EvenOdd
  // only parity matters, and an even number of segment ends at every point suffices.
  bool windingIsDefined() const {
    CoordTable table(in_.points.data(), nIn_);
    std::vector<int64_t> balance(nIn_, 0);
    bool parity = opt_.fill == FillRule::EvenOdd;
    for (uint32_t s = 0; s < in_.segmentCount(); ++s) {
      uint32_t a = table.insert(in_.segments[2 * s]), b = table.insert(in_.segments[2 * s + 1]);
      if (a != b) ++balance[a], balance[b] += parity ? 1 : -1;
    }
    return std::all_of(balance.begin(), balance.end(),
                       [&](int64_t x) { return parity ? x % 2 == 0 : x == 0; });
  }

  // EvenOdd / NonZero: winding numbers are constant inside each triangle and change across
  // an edge by the input segments along it, so one ray-cast per connected component of
  // triangles fixes every triangle's winding number and the number just beyond each
  // boundary edge. Triangles must be kept by the rule, and what lies beyond must not be.
  void checkWindings() {
    // Under EvenOdd only the parity is defined: segments need not close into cycles, only meet
    // every vertex an even number of times (windingIsDefined), so going round a vertex the
    // integer count may come back changed by an even number (fuzz finding
    // evenodd-unbalanced-duplicates, Validate.EvenOddNeedsOnlyParity).
    const bool parity = opt_.fill == FillRule::EvenOdd;
    auto keeps = [&](int64_t w) { return parity ? (w & 1) != 0 : w != 0; };
    const char* rule = parity ? "EvenOdd" : "NonZero";
    std::vector<uint32_t> comp(T_, kNone), order;
    std::vector<int64_t> rel(T_, 0), offset;
    std::vector<std::array<double, 2>> seeds;  // a point inside each component that has one
    std::vector<uint32_t> seeded;               // and which component it is in
    order.reserve(T_);
    for (uint32_t root = 0; root < T_; ++root) {
      if (!good_[root] || comp[root] != kNone) continue;
      uint32_t c = uint32_t(offset.size());
      size_t first = order.size();
      comp[root] = c;
      order.push_back(root);
      for (size_t i = first; i < order.size(); ++i) {
        uint32_t t = order[i];
        for (uint32_t h = 3 * t; h < 3 * t + 3; ++h) {
          if (twin_[h] == kNone) continue;
          uint32_t u = twin_[h] / 3;
          int64_t w = rel[t] - along(h);  // t is left of h, u right of it
          if (comp[u] == kNone) {
            comp[u] = c, rel[u] = w;
            order.push_back(u);
          } else if ((parity ? ((rel[u] - w) & 1) != 0 : rel[u] != w) && t < u) {
            log_.add("winding numbers disagree across edge ", org(h), "-", dst(h), " between ",
                     tri(t), " and ", tri(u), ": an input segment crosses the mesh");
          }
        }
      }
      std::array<double, 2> inside;
      uint32_t seed = kNone;
      if (interiorPoint(order, first, seed, inside)) {
        offset.push_back(-rel[seed]);
        seeds.push_back(inside);
        seeded.push_back(c);
      } else {
        const uint32_t* v = corners(seed);
        offset.push_back(-rel[seed] + windingNumberInside(in_, P(v[0]), P(v[1]), P(v[2])));
        // No double lies inside this component: it is all within an ulp of its edges, so of
        // the input segments its chains stand for, and its winding number is defined only up
        // to which side of them the rounding put it. One off from the exact one is taken if
        // that one is consistent (parallel-chains-leftover-edge.poly under EvenOdd: a crossing
        // rounded an ulp off a segment, and the sliver between the two).
        auto consistent = [&](int64_t o) {
          for (size_t i = first; i < order.size(); ++i) {
            int64_t w = rel[order[i]] + o;
            if (!keeps(w)) return false;
            for (uint32_t h = 3 * order[i]; h < 3 * order[i] + 3; ++h)
              if (twin_[h] == kNone && keeps(w - along(h))) return false;
          }
          return true;
        };
        for (int64_t d : {1, -1})
          if (!consistent(offset.back()) && consistent(offset.back() + d)) offset.back() += d;
      }
    }
    std::vector<int64_t> seedWinding = windingNumbers(in_, seeds);
    for (size_t i = 0; i < seeds.size(); ++i) offset[seeded[i]] += seedWinding[i];
    for (uint32_t t = 0; t < T_; ++t) {
      if (!good_[t]) continue;
      int64_t w = rel[t] + offset[comp[t]];
      if (!keeps(w))
        log_.add(tri(t), " lies where the winding number is ", w, ", which ", rule, " leaves out");
      for (uint32_t h = 3 * t; h < 3 * t + 3; ++h)
        if (twin_[h] == kNone && keeps(w - along(h)))
          log_.add("boundary edge ", org(h), "->", dst(h), " of ", tri(t),
                   ": the region beyond it has winding number ", w - along(h), ", which ", rule,
                   " keeps, but it is not meshed");
    }
  }

  std::array<double, 2> centroid(uint32_t t) const {
    const uint32_t* c = corners(t);
    std::array<double, 2> g;
    for (int k = 0; k < 2; ++k) g[k] = (P(c[0])[k] + P(c[1])[k] + P(c[2])[k]) / 3;
    return g;
  }

  // A point an exact test confirms to lie strictly inside a triangle of component
  // order[first..], for the winding number there: a rounded centroid, which in a needle may
  // round onto or past an edge, or else a double a few ulps from it (fuzz finding
  // overlap-twenty-ulps-off under EvenOdd: a component of one sliver twenty ulps high). False
  // if there is none (every triangle an ulp high: windingNumberInside then).
  bool interiorPoint(const std::vector<uint32_t>& order, size_t first, uint32_t& seed,
                     std::array<double, 2>& inside) {
    auto strictlyIn = [&](const uint32_t* c, const double* g) {
      return orient2d(P(c[0]), P(c[1]), g) > 0 && orient2d(P(c[1]), P(c[2]), g) > 0 &&
             orient2d(P(c[2]), P(c[0]), g) > 0;
    };
    for (int reach = 0; reach <= 4; reach += 4)
      for (size_t i = first; i < order.size(); ++i) {
        const uint32_t* c = corners(order[i]);
        std::array<double, 2> g = centroid(order[i]);
        for (int dx = -reach; dx <= reach; ++dx)
          for (int dy = -reach; dy <= reach; ++dy) {
            double q[2] = {g[0], g[1]};
            for (int k = 0; k < std::abs(dx); ++k) q[0] = std::nextafter(q[0], dx * INFINITY);
            for (int k = 0; k < std::abs(dy); ++k) q[1] = std::nextafter(q[1], dy * INFINITY);
            if (strictlyIn(c, q)) {
              seed = order[i];
              inside = {q[0], q[1]};
              return true;
            }
          }
      }
    seed = order[first];
    return false;
  }

  // Unused vertices must lie outside every triangle; hole points (Triangle fill) inside no
  // triangle and on no unconstrained edge between two triangles. (Boundary vertices are not
  // located: a domain's long thin triangles would make that O(T sqrt(n)); overlaps show up
  // as folded stars, reused directed edges, coincident vertices or stray boundary edges.)
  void locateQueries() {
    if (grid_.queries().empty()) return;
    for (uint32_t t = 0; t < T_; ++t) {
      if (!good_[t]) continue;
      const uint32_t* c = corners(t);
      const double* pts[3] = {P(c[0]), P(c[1]), P(c[2])};
      grid_.forEachNear(pts, 3, [&](const Query& q) {
        double o[3];
        for (int k = 0; k < 3; ++k)
          if ((o[k] = orient2d(pts[k], pts[(k + 1) % 3], q.xy)) < 0) return;
        switch (q.kind) {
          case Query::Unused:
            log_.add("vertex ", q.id, ' ', Xy{q.xy}, " is used by no triangle but lies in ",
                     tri(t));
            break;
          case Query::Boundary:
            break;
          case Query::Hole: {
            int zeros = (o[0] == 0) + (o[1] == 0) + (o[2] == 0);
            // A hole point on a segment may end up a rounding inside a triangle beside the
            // chain of split points that stands for the segment (fuzz finding
            // hole-on-a-split-segment): then which side it eats is a rounding's choice.
            bool besideChain = false;
            for (uint32_t h = 3 * t; h < 3 * t + 3 && zeros == 0; ++h)
              besideChain |= marked_[canon(h)] && nearSegment(P(org(h)), P(dst(h)), q.xy);
            if (zeros == 0 && !besideChain) {
              log_.add("hole ", q.id, ' ', Xy{q.xy}, " lies inside ", tri(t));
            } else if (zeros == 1) {
              uint32_t h = 3 * t + (o[0] == 0 ? 0 : o[1] == 0 ? 1 : 2);
              if (twin_[h] != kNone && !marked_[canon(h)] && t < twin_[h] / 3)
                log_.add("hole ", q.id, ' ', Xy{q.xy}, " lies on edge ", org(h), "-", dst(h),
                         " between ", tri(t), " and ", tri(twin_[h] / 3),
                         ", inside the meshed domain");
            }
            break;
          }
        }
      });
    }
  }

  const Pslg& in_;
  const Mesh& m_;
  const Options& opt_;
  ErrorLog log_;
  uint32_t nIn_ = 0, n_ = 0, T_ = 0;
  std::vector<uint8_t> good_, used_, boundaryVertex_;
  std::vector<uint32_t> boundary_;  // half-edges without a twin
  std::vector<uint32_t> cover_;     // per vertex: its triangles covering the +x direction
  std::vector<uint32_t> twin_, rep_, twinOfUnused_;
  std::vector<uint32_t> anyOut_;             // per vertex: a half-edge leaving it, or kNone
  std::vector<uint32_t> fanOff_, fanStart_;  // per vertex: its boundary half-edges (open fans)
  std::vector<uint32_t> marked_;  // per canonical half-edge: walks along it (0: on no segment)
  std::vector<uint8_t> listed_;              // per canonical half-edge: in Mesh::segments
  std::vector<int32_t> segCount_;    // per canonical half-edge: segments along it minus against
  std::vector<uint32_t> onSegment_;  // per vertex: an input segment through it, or kNone
  std::vector<uint32_t> deadEnd_;    // per vertex: the walk (walkId_) that got stuck past it
  uint32_t walkId_ = 0;
  std::vector<WalkFrame> walkStack_;
  std::vector<WalkStep> preferred_;  // walkSteps' scratch
  std::vector<Chain> chains_;  // per input segment: its walk (rerouteToListedEdges)
  std::vector<uint8_t> leftOver_;  // per canonical half-edge: listed, and on no first walk
  QueryGrid grid_{{}};               // unused vertices and hole points
  std::unique_ptr<QueryGrid> boundaryGrid_;  // boundary vertices, built when a walk needs it
};

}  // namespace

Validation validate(const Pslg& input, const Mesh& mesh, const Options& options) {
  Validation result;
  // Far from 1 (1e300, 1e-300), or with tiny coordinates beside large ones, the predicates
  // would overflow or underflow: check an exactly scaled copy, as mesh() meshes one (scaled
  // for the input, as there; the mesh's own points go along). Input mesh() refuses cannot be
  // checked either.
  detail::CoordinateRange range;
  range.add(input.points);
  range.add(input.holes);
  int exponent = 0;
  if (!detail::exactScale(range, exponent)) {
    result.ok = false;
    result.errors.push_back("cannot check exactly: input " + detail::rangeMessage(range));
    return result;
  }
  if (exponent != 0) {
    Pslg in = input;
    Mesh m = mesh;
    if (detail::scaleExactly(in.points, -exponent) && detail::scaleExactly(in.holes, -exponent) &&
        detail::scaleExactly(m.points, -exponent)) {
      Validator(in, m, options, result).run();
      return result;
    }
  }
  Validator(input, mesh, options, result).run();
  return result;
}

}  // namespace acutemesh
