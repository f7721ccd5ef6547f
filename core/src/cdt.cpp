// Segment insertion for the constrained Delaunay triangulation.
//
// Each input segment is inserted as a chain of fixed edges. Walking from one end toward the
// other, every decision is an exact orientation test: a vertex exactly on the segment splits
// it there (so does an input point that ends no segment within rounding reach of it, and in
// refinement a segment end that near: NearEnds), an
// already fixed edge crossed by it yields a new vertex at the crossing (both segments then
// pass through that vertex), and otherwise the triangles it crosses give way to
// the constrained Delaunay triangulations of its two sides (Triangulation::
// insertEdgeThroughCavity), or, where a side is not a simple chain, the crossed edges are
// flipped away (Sloan's method) and Delaunay is restored with Lawson flips. Long chained
// segments may instead go in one pass with their ends (triangulateAlongSegments, build.h).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <deque>
#include <initializer_list>

#include "acutemesh/predicates.h"
#include "build.h"
#include "curve_order.h"
#include "rounding.h"

namespace acutemesh::detail {
namespace {

struct Piece {
  uint32_t from, to;
  int dir;       // winding contribution along from->to
  uint32_t seg;  // the input segment this piece lies on
};

class SegmentInserter {
 public:
  SegmentInserter(Triangulation& T, const Pslg& input, const std::vector<uint32_t>& canonical,
                  const Budget& budget, NearEnds& nearEnds)
      : T_(T), input_(input), canonical_(canonical), budget_(budget),
        inputCount_(uint32_t(input.vertexCount())), nearEnds_(nearEnds) {}

  StepResult insert(uint32_t seg, uint64_t crossingBudget);
  uint64_t crossings() const { return crossings_; }

 private:
  // representative_[s]: the first segment with the same two (merged) ends as s; made at the
  // first crossing (most inputs have none).
  uint32_t representative(uint32_t seg) {
    if (representative_.empty()) findRepresentatives();
    return representative_[seg];
  }
  void findRepresentatives() {
    const size_t n = input_.segmentCount();
    if (endsBelow_ == kNone) {
      groupByEnds(n, [&](size_t i) {
        const uint32_t a = canonical_[input_.segments[2 * i]];
        const uint32_t b = canonical_[input_.segments[2 * i + 1]];
        return (uint64_t(std::min(a, b)) << 32) | std::max(a, b);
      });
      return;
    }
    // Along the segments, the ends of segments not yet inserted have no canonical vertex yet:
    // the same grouping by their coordinates (canonical vertices are equal points).
    groupByEnds(n, [&](size_t i) {
      const double* a = &input_.points[2 * size_t(input_.segments[2 * i])];
      const double* b = &input_.points[2 * size_t(input_.segments[2 * i + 1])];
      const std::array<double, 2> p{a[0], a[1]}, q{b[0], b[1]};
      const std::array<double, 2> lo = std::min(p, q), hi = std::max(p, q);
      return std::array<double, 4>{lo[0], lo[1], hi[0], hi[1]};
    });
  }
  // representative_[s]: the first of the segments whose keyOf (their ends) is s's.
  template <class KeyOf>
  void groupByEnds(size_t n, KeyOf keyOf) {
    std::vector<std::pair<decltype(keyOf(0)), uint32_t>> keyed(n);
    for (size_t i = 0; i < n; ++i) keyed[i] = {keyOf(i), uint32_t(i)};
    std::sort(keyed.begin(), keyed.end());
    representative_.resize(n);
    for (size_t i = 0; i < n; ++i)
      representative_[keyed[i].second] = i > 0 && keyed[i].first == keyed[i - 1].first
                                             ? representative_[keyed[i - 1].second]
                                             : keyed[i].second;
  }
  const double* P(uint32_t v) const { return T_.point(v); }
  const double* segmentEnd(uint32_t seg, int k) const {
    return P(canonical_[input_.segments[2 * size_t(seg) + k]]);
  }
  // Whether vertex y lies exactly on input segment seg, strictly between its ends.
  bool onSegment(uint32_t seg, uint32_t y) const {
    const double *a = segmentEnd(seg, 0), *b = segmentEnd(seg, 1);
    return orient2d(a, b, P(y)) == 0 && dot2d(P(y), a, b) < 0;
  }
  // Whether input vertex y lies within rounding reach of the piece's segment, strictly
  // between the piece's ends, and splits the segment as one exactly on it would:
  // - a point that ends no segment: a turned or otherwise rounded copy of a point on the
  //   segment (a CG:SHOP point set's points on its hull); passed by, it would stand a rounding
  //   off a segment that refinement could then never split beside it;
  // - a segment end, with NearEnds::snap (refinement): mostly the tip of a spike or sliver
  //   thinner than the reach validate() grants (a digitising artefact: Canada's outline has
  //   one 4.5e-11 wide, at 2e-6 degrees), whose wedge no refinement resolves. Snapped, the
  //   sliver's sides coincide and it is gone, a change of the domain within the reach. A CDT
  //   keeps the input as given.
  bool nearlyOnPiece(const Piece& piece, uint32_t y) {
    if (y >= inputCount_) return false;
    const double *a = segmentEnd(piece.seg, 0), *b = segmentEnd(piece.seg, 1);
    const bool end = isSegmentEnd(y);
    if (!(nearLine(a, b, P(y), end ? kSliverUlps : kRoundingUlps) && dot2d(P(y), a, b) < 0 &&
          dot2d(P(y), P(piece.from), P(piece.to)) < 0))
      return false;
    if (!end) return true;
    const bool within = nearLine(a, b, P(y));
    auto& list = within ? nearEnds_.found : nearEnds_.close;
    if (list.empty() || list.back() != std::make_pair(y, piece.seg))
      list.push_back({y, piece.seg});  // (a walk may pass it more than once)
    return within && nearEnds_.snap;
  }
  // Whether input vertex y (in T) ends a segment. Along the segments (endsBelow_), the ends
  // are T's first vertices; otherwise a flag per vertex, made when first asked.
  bool isSegmentEnd(uint32_t y) {
    if (endsBelow_ != kNone) return y < endsBelow_;
    if (segmentEnds_.empty()) {
      segmentEnds_.assign(inputCount_, 0);
      for (uint32_t end : input_.segments) segmentEnds_[canonical_[end]] = 1;
    }
    return segmentEnds_[y];
  }
  std::vector<uint8_t> segmentEnds_;

 public:
  // Along the segments: T's vertices below `endsBelow` are the segment ends, and a piece that
  // crosses a fixed edge on the hull so far is not resolved but declined (declined() says
  // so): its rounded crossing point could bend the hull inward by an ulp, which the vertices
  // inserted after it outside that edge must be free to cover (Triangulation::
  // hullFollowsSegments).
  void insertAlongSegments(uint32_t endsBelow) { endsBelow_ = endsBelow; }
  bool declined() const { return declined_; }
  // Whether vertex y, just inserted, lies within rounding reach of a fixed edge opposite it
  // (not on it: that split it): insertSegments would have run the segment through it.
  bool nearFixedEdge(uint32_t y) {
    const uint32_t e0 = T_.vertexEdge[y];
    uint32_t e = e0;
    do {
      const uint32_t f = next(e);  // w->x, opposite y in (y, w, x)
      if (T_.isFixed(f) && T_.tri[f] != kGhost && T_.tri[next(f)] != kGhost) {
        const uint32_t seg = T_.segment[f];
        const double *a = segmentEnd(seg, 0), *b = segmentEnd(seg, 1);
        if (nearLine(a, b, P(y), isSegmentEnd(y) ? kSliverUlps : kRoundingUlps) &&
            dot2d(P(y), a, b) < 0)
          return true;
      }
      e = T_.opp[prev(e)];
    } while (e != e0);
    return false;
  }

 private:
  uint32_t endsBelow_ = kNone;
  bool declined_ = false;
  // The piece is to run through vertex y: its two halves, the first on top.
  void splitAt(const Piece& piece, uint32_t y) {
    todo_.push_back({y, piece.to, piece.dir, piece.seg});
    todo_.push_back({piece.from, y, piece.dir, piece.seg});
  }
  // Returns the half-edge leaving u toward the segment's interior: an edge u->w with w on the
  // segment (*collinear set), or the edge w->x of the triangle (u, w, x) that the segment
  // crosses first.
  uint32_t firstStep(uint32_t u, uint32_t v, bool* collinear) const;
  bool splitAtCrossing(const Piece& piece, uint32_t crossed);
  uint32_t nearbyCrossing(const double* p, double scale, uint32_t t,
                          std::initializer_list<uint32_t> ends) const;
  bool joinAcross(uint32_t u, uint32_t end, const Piece& piece, std::vector<uint32_t>& crossedEdges);

  Triangulation& T_;
  const Pslg& input_;
  const std::vector<uint32_t>& canonical_;
  const Budget& budget_;
  uint32_t inputCount_;  // store vertices below this are input vertices, exact
  NearEnds& nearEnds_;
  std::vector<uint32_t> representative_;
  std::vector<Piece> todo_;
  // joinAcross's queue: crossed edges by their ends, with the half-edge last seen for them.
  struct Crossed {
    uint32_t w, x, e;
  };
  std::deque<Crossed> queue_;
  std::vector<std::pair<uint32_t, uint32_t>> created_;
  uint64_t crossings_ = 0;
};

uint32_t SegmentInserter::firstStep(uint32_t u, uint32_t v, bool* collinear) const {
  // Most segments of real inputs are already edges: look for that before any geometry.
  uint32_t existing = T_.findEdge(u, v);
  if (existing != kNone) {
    *collinear = true;
    return existing;
  }
  uint32_t e0 = T_.vertexEdge[u], e = e0;
  do {
    uint32_t w = T_.tri[next(e)], x = T_.tri[prev(e)];
    if (w != kGhost) {
      double ow = orient2d(P(u), P(w), P(v));
      if (ow == 0 && dot2d(P(u), P(w), P(v)) > 0) {  // w on the segment (a hull edge, maybe)
        *collinear = true;
        return e;
      }
      if (x != kGhost && ow > 0 && orient2d(P(u), P(x), P(v)) < 0) {
        *collinear = false;
        return next(e);
      }
    }
    e = T_.opp[prev(e)];
  } while (e != e0);
  return kNone;
}

// Three or more segments through one point meet pairwise at roundings of it a few ulps
// apart: a crossing point that close to an earlier one (a corner of the triangle it falls
// in) is taken to be that one, so the segments share a single vertex there. The same goes
// for any vertex an ulp off a segment, whether a corner of that triangle (fuzz finding
// overlap-one-ulp-off.poly) or an end of one of the two crossing pieces (`ends`): the
// crossing there is that vertex (fuzz finding crossing-one-ulp-from-vertex.poly, where a
// rounded crossing one ulp from an input vertex left two vertices no segment walk could tell
// apart). The rounding is relative to the segments' coordinates (`scale`), not to the
// point's: near the origin a tolerance relative to the point itself is next to zero, and 12
// diameters of a circle centred there cascaded into tens of thousands of crossings
// (star-burst-crossings.poly). Two pieces that nearly overlap cross at a point their
// rounding leaves far off (the error grows as the angle between them shrinks): a crossing
// within the rounding reach validate() grants a chain (kRoundingUlps) of a piece end is that
// end (fuzz finding overlap-twenty-ulps-off.poly, a crossing 20 ulps from an end); of several,
// the first in `ends`: the crossed edge's ends before the new piece's, so the piece bends
// through the edge's end rather than the edge detouring through the piece's end
// (the other way round, or the nearest, broke tests/fuzz/findings' overlap neighbours).
uint32_t SegmentInserter::nearbyCrossing(const double* p, double scale, uint32_t t,
                                         std::initializer_list<uint32_t> ends) const {
  double unit = std::numeric_limits<double>::epsilon() *
                std::max({scale, std::fabs(p[0]), std::fabs(p[1])});
  auto distance = [&](uint32_t c) {
    return c == kGhost ? INFINITY : std::max(std::fabs(P(c)[0] - p[0]), std::fabs(P(c)[1] - p[1]));
  };
  for (uint32_t k = 0; k < 3; ++k)
    if (distance(T_.tri[3 * t + k]) <= 16 * unit) return T_.tri[3 * t + k];
  for (uint32_t c : ends)
    if (distance(c) <= kRoundingUlps * unit) return c;
  return kNone;
}

// The segment piece crosses the fixed edge `crossed`: add a vertex at the crossing and route
// both the piece and the fixed edge through it. Returns false if no vertex could be placed.
bool SegmentInserter::splitAtCrossing(const Piece& piece, uint32_t crossed) {
  uint32_t w = T_.tri[crossed], x = T_.tri[next(crossed)];
  // Intersect the two original input segments, not the pieces (whose ends may be earlier
  // rounded crossing points): the same pair then always yields the same point.
  // Repeated segments (same ends, either direction) share one representative, and the
  // lower-numbered representative is always the one parametrised: a pair of segments always
  // yields the very same point, however often the input repeats them.
  uint32_t other = T_.segment[crossed];
  const double *u, *v, *pw = P(w), *px = P(x);
  if (other == kNone) {
    u = segmentEnd(piece.seg, 0), v = segmentEnd(piece.seg, 1);
  } else {
    uint32_t first = std::min(representative(piece.seg), representative(other));
    uint32_t second = std::max(representative(piece.seg), representative(other));
    u = segmentEnd(first, 0), v = segmentEnd(first, 1);
    pw = segmentEnd(second, 0), px = segmentEnd(second, 1);
  }
  double ou = orient2d(pw, px, u), ov = orient2d(pw, px, v);
  double p[2], scale = 0;
  for (const double* q : {u, v, pw, px, P(piece.from), P(piece.to)})
    scale = std::max({scale, std::fabs(q[0]), std::fabs(q[1])});
  if ((ou > 0 && ov < 0) || (ou < 0 && ov > 0)) {
    double s = ou / (ou - ov);
    p[0] = u[0] + s * (v[0] - u[0]), p[1] = u[1] + s * (v[1] - u[1]);
  } else {
    // The originals do not cross (only the rounded pieces do): meet at the pieces' crossing.
    const double *a = P(piece.from), *b = P(piece.to);
    double oa = orient2d(P(w), P(x), a), ob = orient2d(P(w), P(x), b);
    double s = oa / (oa - ob);
    p[0] = a[0] + s * (b[0] - a[0]), p[1] = a[1] + s * (b[1] - a[1]);
  }
  int windOfCrossed = T_.wind[crossed];
  Location loc = T_.locate(p, crossed / 3);
  if (loc.where == Where::Failed) return false;
  bool onCrossed = loc.where == Where::OnEdge &&
                   (loc.edge == crossed || loc.edge == T_.opp[crossed]);
  uint32_t r = loc.where == Where::OnVertex
                   ? loc.vertex
                   : nearbyCrossing(p, scale, loc.tri, {w, x, piece.from, piece.to});
  if (r == kNone) r = T_.insertAt(T_.addVertex(p[0], p[1]), loc);
  if (!onCrossed && r != w && r != x) {
    // The rounded crossing point is off the fixed edge: re-route that edge through it.
    uint32_t old = T_.findEdge(w, x);
    if (old != kNone) {
      T_.unfixEdge(old);
      todo_.push_back({w, r, windOfCrossed, other});
      todo_.push_back({r, x, windOfCrossed, other});
      std::vector<uint32_t> stack{old};
      T_.legalize(stack);
    }
  }
  if (r != piece.to) todo_.push_back({r, piece.to, piece.dir, piece.seg});
  if (r != piece.from) todo_.push_back({piece.from, r, piece.dir, piece.seg});
  return true;
}

// Makes u-end a fixed edge: the crossed triangles replaced by the triangulations of its two
// sides, or where the cavity cannot take it, the edges crossed flipped until none is left
// (Sloan 1993: a crossed edge whose quadrilateral is convex can always be flipped, and one
// always is), then the Delaunay property restored around the new edges.
bool SegmentInserter::joinAcross(uint32_t u, uint32_t end, const Piece& piece,
                                 std::vector<uint32_t>& crossedEdges) {
  const uint32_t edge = T_.insertEdgeThroughCavity(u, end, crossedEdges);
  if (edge != kNone) {
    T_.fixEdge(edge, piece.dir, piece.seg);
    return true;
  }
  // Queue entries remember their half-edge; flips elsewhere usually leave it valid, so the
  // search around w runs only when it went stale.
  std::deque<Crossed>& queue = queue_;
  queue.clear();
  for (uint32_t e : crossedEdges) queue.push_back({T_.tri[e], T_.tri[next(e)], e});
  std::vector<std::pair<uint32_t, uint32_t>>& created = created_;
  created.clear();
  while (!queue.empty()) {
    auto [w, x, e] = queue.front();
    queue.pop_front();
    if (T_.isFree(e / 3) || T_.tri[e] != w || T_.tri[next(e)] != x) e = T_.findEdge(w, x);
    uint32_t c = T_.tri[prev(e)], d = T_.tri[prev(T_.opp[e])];
    if (orient2d(P(c), P(w), P(d)) <= 0 || orient2d(P(d), P(x), P(c)) <= 0) {
      queue.push_back({w, x, e});
      continue;
    }
    uint32_t t1 = T_.opp[e] / 3;
    T_.flip(e);
    double oc = orient2d(P(u), P(end), P(c)), od = orient2d(P(u), P(end), P(d));
    if ((oc > 0 && od < 0) || (oc < 0 && od > 0))
      queue.push_back({c, d, 3 * t1 + 2});  // the new diagonal c->d
    else
      created.emplace_back(c, d);
  }
  uint32_t fixedEdge = T_.findEdge(u, end);
  if (fixedEdge == kNone) return false;
  T_.fixEdge(fixedEdge, piece.dir, piece.seg);
  std::vector<uint32_t>& stack = T_.scratch();
  stack.clear();
  for (auto [c, d] : created) {
    uint32_t e = T_.findEdge(c, d);
    if (e != kNone) stack.push_back(e);
  }
  T_.legalize(stack);
  return true;
}

StepResult SegmentInserter::insert(uint32_t seg, uint64_t crossingBudget) {
  uint32_t a = canonical_[input_.segments[2 * size_t(seg)]];
  uint32_t b = canonical_[input_.segments[2 * size_t(seg) + 1]];
  todo_.assign(1, {a, b, 1, seg});
  std::vector<uint32_t> crossedEdges;
  while (!todo_.empty()) {
    Piece piece = todo_.back();
    todo_.pop_back();
    uint32_t u = piece.from, v = piece.to;
    if (u == v) continue;
    bool collinear = false;
    uint32_t h = firstStep(u, v, &collinear);
    if (h == kNone) return {Status::BadInput, "internal: no way from vertex " +
                                                  std::to_string(u) + " toward " +
                                                  std::to_string(v)};
    if (collinear) {
      // (An edge already: a vertex a rounding off it, either side, still splits it.)
      uint32_t near = kNone;
      if (T_.tri[next(h)] == v)
        for (uint32_t y : {T_.tri[prev(h)], T_.tri[prev(T_.opp[h])]})
          if (near == kNone && nearlyOnPiece(piece, y)) near = y;  // (kGhost: no input vertex)
      if (near != kNone) {
        splitAt(piece, near);
        continue;
      }
      T_.fixEdge(h, piece.dir, piece.seg);
      todo_.push_back({T_.tri[next(h)], v, piece.dir, piece.seg});
      continue;
    }
    // Walk across the triangles the piece passes through. Crossed edges run from the
    // vertex right of u->v to the one left of it. A piece that starts or ends at a rounded
    // crossing point is off its segment's exact line: a vertex exactly on the segment can then
    // lie beside the piece, and it must still split the segment.
    bool rounded = u >= inputCount_ || v >= inputCount_;
    crossedEdges.clear();
    uint32_t end = kNone;
    bool split = false;
    for (uint32_t y : {T_.tri[h], T_.tri[next(h)]})
      if (!split && ((rounded && onSegment(piece.seg, y)) || nearlyOnPiece(piece, y))) {
        splitAt(piece, y);
        split = true;
      }
    while (!split) {
      if (T_.isFixed(h)) {
        if (endsBelow_ != kNone && (T_.isGhost(h / 3) || T_.isGhost(T_.opp[h] / 3))) {
          declined_ = true;
          return {Status::BadInput, "a crossing (declined along the segments)"};
        }
        if (++crossings_ > crossingBudget || budget_.stop())
          return {budget_.cancelled() ? Status::Cancelled : Status::BadInput,
                  "too many segment crossings to resolve (" + std::to_string(crossings_) + ")"};
        if (!splitAtCrossing(piece, h))
          return {Status::BadInput, "could not place the crossing point of two segments"};
        split = true;
        break;
      }
      crossedEdges.push_back(h);
      uint32_t g = T_.opp[h], y = T_.tri[prev(g)];
      if (y == v) {
        end = v;
        break;
      }
      double o = orient2d(P(u), P(v), P(y));
      if (o == 0) {
        end = y;
        break;
      }
      if ((rounded && onSegment(piece.seg, y)) || nearlyOnPiece(piece, y)) {
        splitAt(piece, y);
        split = true;
        break;
      }
      h = o > 0 ? next(g) : prev(g);
    }
    if (split) continue;
    if (!joinAcross(u, end, piece, crossedEdges))
      return {Status::BadInput, "internal: segment piece " + std::to_string(u) + "-" +
                                    std::to_string(end) + " missing after flips"};
    if (end != v) todo_.push_back({end, v, piece.dir, piece.seg});
  }
  return {};
}

// Inserts the segments in input order, each after before(s) (which readies its ends), with
// the warnings for zero-length segments and crossings.
template <class Before>
StepResult insertInOrder(SegmentInserter& inserter, const Pslg& input,
                         const std::vector<uint32_t>& canonical, Stats& stats, const Budget& budget,
                         Before before) {
  size_t n = input.segmentCount();
  // Rounded crossing points can create a few more crossings; a budget far above any real
  // input's crossing count turns a pathological cascade into an error instead of a hang.
  uint64_t crossingBudget = 64ull * n * n + 4096;
  uint32_t zeroLength = 0;
  for (size_t s = 0; s < n; ++s) {
    // (Not before the 4,096th: a small input's CDT is always made, for a stopped run to return.)
    if (s > 0 && (s & 0xFFF) == 0 && budget.stop())
      return {budget.cancelled() ? Status::Cancelled : Status::TargetNotMet,
              "stopped while inserting the segments"};
    StepResult r = before(s);
    if (!r.ok()) return r;
    uint32_t a = canonical[input.segments[2 * s]], b = canonical[input.segments[2 * s + 1]];
    if (a == b) {
      if (++zeroLength <= 5)
        stats.warnings.push_back("segment " + std::to_string(s) + " has zero length; dropped");
      continue;
    }
    r = inserter.insert(uint32_t(s), crossingBudget);
    if (!r.ok()) {
      r.message = "segment " + std::to_string(s) + ": " + r.message;
      return r;
    }
  }
  if (zeroLength > 5)
    stats.warnings.push_back(std::to_string(zeroLength) + " zero-length segments dropped");
  if (inserter.crossings() > 0)
    stats.warnings.push_back(std::to_string(inserter.crossings()) +
                             " segment crossings split at new vertices");
  return {};
}

}  // namespace

StepResult insertSegments(Triangulation& T, const Pslg& input,
                          const std::vector<uint32_t>& canonical, Stats& stats,
                          const Budget& budget, NearEnds& nearEnds) {
  nearEnds.found.clear();
  nearEnds.close.clear();
  SegmentInserter inserter(T, input, canonical, budget, nearEnds);
  return insertInOrder(inserter, input, canonical, stats, budget,
                       [](size_t) { return StepResult{}; });
}

bool alongSegmentsPays(const Pslg& input) {
  const size_t n = input.segmentCount(), count = input.vertexCount();
  if (n < kAlongSegmentsFrom || count < 3) return false;
  size_t chained = 0;
  double length = 0, lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (size_t s = 0; s < n; ++s) {
    const uint32_t *a = &input.segments[2 * s], *b = a - 2;
    if (s > 0) chained += a[0] == b[1] || a[0] == b[0] || a[1] == b[0] || a[1] == b[1];
    const double *p = &input.points[2 * size_t(a[0])], *q = &input.points[2 * size_t(a[1])];
    length += std::hypot(q[0] - p[0], q[1] - p[1]);
  }
  for (size_t i = 0; i < 2 * count; ++i) {
    lo[i % 2] = std::min(lo[i % 2], input.points[i]);
    hi[i % 2] = std::max(hi[i % 2], input.points[i]);
  }
  const double spacing = std::sqrt((hi[0] - lo[0]) * (hi[1] - lo[1]) / double(count));
  return chained >= n - n / 8 && length / double(n) >= spacing;
}

StepResult triangulateAlongSegments(Triangulation& T, const Pslg& input,
                                    std::vector<uint32_t>& canonical,
                                    std::vector<uint32_t>& inputOf, Stats& stats,
                                    const Budget& budget, NearEnds& nearEnds, bool& declined) {
  declined = false;
  nearEnds.found.clear();
  nearEnds.close.clear();
  const uint32_t count = uint32_t(input.vertexCount());
  // T's vertices: the segment ends in the order the segments first name them, then the
  // other vertices along the curve. Until vertex k is inserted, canonical[inputOf[k]] is k;
  // after, the vertex it ended up as (k, or an earlier one at the same place): never above k.
  canonical.assign(count, kNone);
  inputOf.clear();
  inputOf.reserve(count);
  for (uint32_t end : input.segments)
    if (canonical[end] == kNone) {
      canonical[end] = uint32_t(inputOf.size());
      inputOf.push_back(end);
    }
  const uint32_t ends = uint32_t(inputOf.size());
  std::vector<uint32_t> rest;
  for (uint32_t i = 0; i < count; ++i)
    if (canonical[i] == kNone) rest.push_back(i);
  sortAlongCurve(rest, [&](uint32_t i, double* p) {
    p[0] = input.points[2 * size_t(i)], p[1] = input.points[2 * size_t(i) + 1];
  });
  for (uint32_t i : rest) {
    canonical[i] = uint32_t(inputOf.size());
    inputOf.push_back(i);
  }
  std::vector<uint32_t>().swap(rest);
  placeVertices(T, input.points, inputOf);
  // The first triangle, from segment ends (all of them on a line: the general way).
  uint32_t b, c;
  firstTriangle(T, ends, b, c);
  if (c == kNone) {
    declined = true;
    return {};
  }
  T.init(0, b, c);
  // Segments on the hull so far must let later vertices outside them in.
  T.hullFollowsSegments = false;

  SegmentInserter inserter(T, input, canonical, budget, nearEnds);
  inserter.insertAlongSegments(ends);
  uint32_t inserted = 1, hint = T.vertexEdge[0] / 3;
  // Inserts T's vertices up to `last`, each from where the one before went in.
  auto insertUpTo = [&](uint32_t last) -> StepResult {
    for (; inserted <= last; ++inserted) {
      const uint32_t k = inserted;
      if ((k & 0xFFFF) == 0 && budget.stop())
        return {budget.cancelled() ? Status::Cancelled : Status::TargetNotMet,
                "stopped while triangulating the input vertices"};
      uint32_t r = k;
      if (k != b && k != c) {
        r = T.insert(k, hint);
        if (r == kNone)
          return {Status::BadInput, "could not locate vertex " + std::to_string(inputOf[k])};
        // (At a crossing point made before it: two steps would have made that crossing there.)
        if (r >= count || (r == k && inserter.nearFixedEdge(k))) {
          declined = true;
          return {Status::BadInput,
                  "a vertex at or beside a segment (declined along the segments)"};
        }
      }
      canonical[inputOf[k]] = r;
      hint = T.vertexEdge[r] / 3;
    }
    return {};
  };
  StepResult step = insertInOrder(inserter, input, canonical, stats, budget, [&](size_t s) {
    return insertUpTo(
        std::max(canonical[input.segments[2 * s]], canonical[input.segments[2 * s + 1]]));
  });
  if (step.ok()) step = insertUpTo(count - 1);
  T.hullFollowsSegments = true;
  // (And anything else this way could not do: the general way says what is wrong, if anything.)
  declined = declined || inserter.declined() || step.status == Status::BadInput;
  return declined ? StepResult{} : step;
}

}  // namespace acutemesh::detail
