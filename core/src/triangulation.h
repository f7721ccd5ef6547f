// The triangulation store: flat half-edge arrays over the whole plane.
//
// Triangle t has corners tri[3t], tri[3t+1], tri[3t+2] in counter-clockwise order.
// Half-edge e = 3t+k runs from tri[e] to tri[next(e)]; opp[e] is its twin in the
// neighbouring triangle. The convex hull is closed off by "ghost" triangles that share the
// vertex kGhost (a point at infinity), as in CGAL and Shewchuk's work: every half-edge then
// has a twin, point location and insertion outside the hull need no special cases, and the
// hull stays exact. Each hull edge (a->b, outside on its left) carries one ghost (a, b, kGhost).
//
// All topology decisions use the exact predicates; no coordinate is ever compared with a
// tolerance.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace acutemesh::detail {

constexpr uint32_t kNone = 0xFFFFFFFFu;
constexpr uint32_t kGhost = 0xFFFFFFFEu;
// Most vertices a triangulation may hold: about two triangles per vertex, three half-edges
// each, all numbered by uint32 (kNone and kGhost reserved).
constexpr uint32_t kMaxVertices = kNone / 6;

inline uint32_t next(uint32_t e) { return e % 3 == 2 ? e - 2 : e + 1; }
inline uint32_t prev(uint32_t e) { return e % 3 == 0 ? e + 2 : e - 1; }

enum class Where { InTriangle, OnEdge, OnVertex, Failed };

struct Location {
  Where where = Where::Failed;
  uint32_t tri = kNone;    // InTriangle: the triangle
  uint32_t edge = kNone;   // OnEdge: a half-edge the point lies on (strictly inside it)
  uint32_t vertex = kNone; // OnVertex: the vertex with exactly these coordinates
};

// What a Triangulation's writes replaced, while one is kept (Triangulation::journal): the
// old record of each triangle slot written, the old edge of each vertex, the old place of each
// point moved, and the fan radii (RefineState's) set. Marks nest; undoTo(mark) puts back what
// was there at the mark, in the reverse order of the writes (a slot noted twice ends with its
// first record), so a tried change costs what it touched, not a copy of the whole.
struct Journal {
  struct Slot {
    uint32_t t, tri[3], opp[3], segment[3];
    int32_t wind[3];
    uint8_t fixed[3], inside;
  };
  struct Mark {
    size_t slots, edges, points, radii;
    uint32_t vertices, slotCount, rng;
    std::vector<uint32_t> freeSlots;
  };
  std::vector<Slot> slots;
  std::vector<std::pair<uint32_t, uint32_t>> edges;  // vertex, old vertexEdge
  struct Point {
    uint32_t v;
    double xy[2];
  };
  std::vector<Point> points;
  std::vector<std::pair<uint32_t, double>> radii;  // input vertex, old fan radius
};

class Triangulation {
 public:
  // Vertex coordinates (x, y interleaved). Vertices are only ever appended.
  std::vector<double> pts;
  std::vector<uint32_t> tri;    // 3 per triangle; tri[3t] == kNone marks a free slot
  std::vector<uint32_t> opp;    // twin half-edge, 3 per triangle
  std::vector<uint8_t> fixed;   // per half-edge: 1 if the edge lies on an input segment
  // Per half-edge, in constrained triangulations: `wind` (while trackWinding) the net
  // winding of the input segments along it (segments a->b minus segments b->a; twins hold
  // opposite values), and `segment` (with trackSegments) the index of an input segment it lies
  // on (crossing points are computed from the original segments, so rounding errors never
  // compound).
  std::vector<int32_t> wind;
  std::vector<uint32_t> segment;
  bool trackSegments = false;
  // Only the fill rules read `wind`: once the domain is known it is dropped, a fifth of
  // every refinement state's memory.
  bool trackWinding = false;
  void dropWinding() {
    trackWinding = false;
    std::vector<int32_t>().swap(wind);  // (assigning {} would keep its capacity)
  }
  // Where a hull edge is a segment, the hull is left as the segments make it (mustFlip): a
  // rounded split point on it may bend it inward by an ulp. Off while the segments are
  // inserted along with their ends (triangulateAlongSegments): later vertices lie outside.
  bool hullFollowsSegments = true;
  std::vector<uint32_t> vertexEdge;  // per vertex: a half-edge leaving it, kNone if unused
  // Per triangle, kept when non-empty (refinement): 1 if the triangle is in the domain. Splits
  // pass it to the pieces; flips never cross a fixed edge, so both sides always agree.
  std::vector<uint8_t> inside;
  // When set, every triangle (re)written by an insertion, flip or removal is appended here.
  std::vector<uint32_t>* touched = nullptr;
  // When set, every write is noted there first (Journal); a copy of the triangulation keeps
  // none. mark() and undoTo() below.
  Journal* journal = nullptr;
  Journal::Mark mark() const {
    return {journal->slots.size(), journal->edges.size(), journal->points.size(),
            journal->radii.size(), vertexCount(), slots_, rng_, freeSlots_};
  }
  // Puts back every slot, vertex edge and point noted since `m` and drops the vertices and
  // slots added since (the caller drops its own per-vertex data past m.vertices).
  void undoTo(const Journal::Mark& m);
  // Notes point v's place before a caller moves it (the journal's writes come through here).
  void notePoint(uint32_t v) {
    if (journal) journal->points.push_back({v, {pts[2 * size_t(v)], pts[2 * size_t(v) + 1]}});
  }

  uint32_t vertexCount() const { return uint32_t(pts.size() / 2); }
  // Slots in use or on the free list; the arrays may be longer (spare capacity, kNone).
  uint32_t triangleSlots() const { return slots_; }
  // Renumbers the triangles: the live slots in `order` become slots 0, 1, ..., the free ones
  // are dropped. Nothing else may hold triangle numbers across it; no journal is kept.
  void permuteSlots(const std::vector<uint32_t>& order);
  // Gives back the arrays' spare tail past the slots in use (growth fills ahead of them, and
  // every copy of the store would carry the tail along).
  void trimToSlots();
  // The store less what its triangles' corners determine (the twins), with edge flags and
  // segments only where an edge has them: about half a copy of a refined mesh. restore() makes
  // the very store again (the same slots, twins, free list and walk); a polish round keeps its
  // way back so. Taken from a store trimmed to its slots.
  struct Compact {
    std::vector<double> pts;
    std::vector<uint32_t> tri, vertexEdge, freeSlots;
    std::vector<uint8_t> inside;
    std::vector<int32_t> wind;
    struct Marked {
      uint32_t e, segment;
      uint8_t fixed;
    };
    std::vector<Marked> marked;
    uint32_t slots = 0, rng = 0;
    bool trackSegments = false, trackWinding = false;
  };
  Compact compact() const;
  void restore(Compact&& c);
  // Sizes the arrays for `count` triangle slots up front (one allocation instead of many).
  void reserveTriangles(size_t count);
  // Room for this many vertices and triangles in all, without filling it: growth up to there
  // then copies nothing (refinement to an area bound knows roughly how big it gets).
  void reserveCapacity(size_t vertices, size_t triangles);
  const double* point(uint32_t v) const { return &pts[2 * size_t(v)]; }
  bool isGhost(uint32_t t) const {
    return tri[3 * t] == kGhost || tri[3 * t + 1] == kGhost || tri[3 * t + 2] == kGhost;
  }
  bool isFree(uint32_t t) const { return tri[3 * t] == kNone; }
  // A live, real triangle of the domain (refinement, which keeps `inside`).
  bool inDomain(uint32_t t) const { return inside[t] && !isFree(t) && !isGhost(t); }
  bool isFixed(uint32_t e) const { return fixed[e] != 0; }

  // Appends a vertex (not yet connected) and returns its index.
  uint32_t addVertex(double x, double y);

  // Builds the first real triangle from three non-collinear vertices (plus its 3 ghosts).
  void init(uint32_t a, uint32_t b, uint32_t c);

  // Exact point location by a stochastic visibility walk from the triangle `hint`.
  Location locate(const double* p, uint32_t hint) const;

  // Inserts vertex v (already in pts) at its location and restores the Delaunay property
  // around it with Lawson flips that never cross fixed edges. Returns v, or the vertex
  // already at those coordinates (v then stays unconnected).
  uint32_t insert(uint32_t v, uint32_t hint);
  uint32_t insertAt(uint32_t v, const Location& loc);

  // Inserts vertex v on the fixed edge of half-edge e, splitting it into two fixed pieces
  // that keep its winding and segment, even though v (a rounded point) need not lie exactly on
  // it; then restores Delaunay. Returns false, changing nothing, if v is not strictly inside
  // the quadrilateral of the edge's two triangles (the split would fold them).
  bool splitFixedEdge(uint32_t e, uint32_t v);

  // Flips the edge of half-edge e (which must not be fixed, and whose quadrilateral must
  // be strictly convex). Afterwards the new diagonal is half-edge 3*t0+2 / 3*t1+2.
  void flip(uint32_t e);

  // True if the apex of opp[e]'s triangle lies strictly inside the circumcircle of e's
  // triangle (ghost triangles: strictly outside their hull edge).
  bool mustFlip(uint32_t e) const;

  // Lawson flips until every non-fixed edge reachable from the stack is locally Delaunay.
  void legalize(std::vector<uint32_t>& stack);

  // Removes an interior vertex whose star has no ghost triangle and no fixed edge:
  // flips its degree down to 3, merges the last three triangles and restores Delaunay.
  // Returns false (and changes nothing) if the vertex is not removable.
  bool removeVertex(uint32_t v);

  // Removes a vertex v whose only fixed edges are the two pieces a-v, v-b of one segment (no
  // ghost triangle in its star): the pieces become one fixed edge a-b with their attributes,
  // and each side keeps its `inside` flag; `ends` gets a and b once v's star qualifies. Returns
  // false if the link does not allow it; v then stays, its star possibly re-flipped (still a
  // valid triangulation).
  bool removeFromSegment(uint32_t v, uint32_t ends[2]);

  // Makes u-w an edge by replacing the triangles it crosses with the constrained Delaunay
  // triangulations of the two pseudo-polygons either side of it (Anglada 1997), no flips.
  // crossed: the half-edges u-w crosses, in order from u, each from the vertex right of u->w
  // to the one left of it; none fixed, no vertex on u-w. Returns the half-edge u->w; kNone,
  // changing nothing, where a side passes a vertex twice or is longer than kCavityChain (the
  // caller flips the edges away instead).
  static constexpr size_t kCavityChain = 256;
  uint32_t insertEdgeThroughCavity(uint32_t u, uint32_t w, const std::vector<uint32_t>& crossed);

  // The half-edge leaving a with its other end at b, or kNone.
  uint32_t findEdge(uint32_t a, uint32_t b) const;

  // Marks the edge of half-edge e (both directions) as lying on input segment `seg`; with
  // trackWinding, adds `dir` (+1 along e, -1 against) to its net winding.
  void fixEdge(uint32_t e, int dir, uint32_t seg = kNone);
  void unfixEdge(uint32_t e);

  uint32_t liveTriangleCount() const { return triangleSlots() - uint32_t(freeSlots_.size()); }
  std::vector<uint32_t>& scratch() { return scratch_; }

 private:
  uint32_t newTriangle();
  void freeTriangle(uint32_t t);
  void setCorners(uint32_t t, uint32_t a, uint32_t b, uint32_t c);
  void link(uint32_t e, uint32_t f) {
    noteSlot(e / 3);
    noteSlot(f / 3);
    opp[e] = f;
    opp[f] = e;
  }
  void noteSlot(uint32_t t) {
    if (!journal) return;
    Journal::Slot r;
    r.t = t;
    for (int k = 0; k < 3; ++k) {
      const size_t e = 3 * size_t(t) + size_t(k);
      r.tri[k] = tri[e], r.opp[k] = opp[e], r.fixed[k] = fixed[e];
      r.wind[k] = trackWinding ? wind[e] : 0;
      r.segment[k] = trackSegments ? segment[e] : kNone;
    }
    r.inside = inside.empty() ? 0 : inside[t];
    journal->slots.push_back(r);
  }
  void noteEdge(uint32_t v) {
    if (journal && v != kGhost) journal->edges.push_back({v, vertexEdge[v]});
  }
  // What a half-edge carries besides its endpoints, moved as a unit by splits and flips.
  struct EdgeAttr {
    uint32_t twin;
    uint8_t fixed;
    int32_t wind;
    uint32_t segment;
  };
  EdgeAttr attr(uint32_t e) const {
    return {opp[e], fixed[e], trackWinding ? wind[e] : 0, trackSegments ? segment[e] : kNone};
  }
  // Sets e's flags from a (twin too, unless noTwin).
  void setAttr(uint32_t e, const EdgeAttr& a, bool withTwin = true) {
    noteSlot(e / 3);
    if (withTwin) link(e, a.twin);
    fixed[e] = a.fixed;
    if (trackWinding) wind[e] = a.wind;
    if (trackSegments) segment[e] = a.segment;
  }
  static constexpr EdgeAttr kPlain = {kNone, 0, 0, kNone};
  // Makes e and f twins of a new, plain (unfixed) edge.
  void linkPlain(uint32_t e, uint32_t f) {
    setAttr(e, kPlain, false);
    setAttr(f, kPlain, false);
    link(e, f);
  }
  // insertEdgeThroughCavity's: one side's triangles over chain[lo..hi], the side left of
  // chain[lo]->chain[hi]; sides[i] is what the old edge between chain[i] and chain[i+1] carried.
  // Returns the new half-edge chain[lo]->chain[hi].
  uint32_t fillPseudoPolygon(const uint32_t* chain, const EdgeAttr* sides, size_t lo, size_t hi);
  Location closedIn(uint32_t t, uint32_t zeros, const uint32_t zeroEdge[2]) const;
  uint32_t splitTriangle(uint32_t t, uint32_t v);
  uint32_t splitEdge(uint32_t e, uint32_t v);
  // Flips the spoke v-w of an ear of v's link (vertex removal), queueing the ear's edges: its
  // two link edges, and the new diagonal too if queueDiagonal (which stays in v's link, so a
  // removal that goes on until v is gone queues it with a later ear or the last triangle).
  void flipAwaySpoke(uint32_t v, uint32_t w, std::vector<uint32_t>& stack, bool queueDiagonal);
  void legalizeFrom(uint32_t v, std::vector<uint32_t>& stack);
  // Inside-test of point p against triangle t, honouring ghosts.
  bool inCircumcircle(uint32_t t, uint32_t p) const;

  uint32_t slots_ = 0;
  std::vector<uint32_t> freeSlots_;
  std::vector<uint32_t> scratch_;
  std::vector<uint32_t> ring_;  // removeVertex, removeFromSegment: the link of the vertex
  // insertEdgeThroughCavity's scratch: each side's chain and old edges, the cavity's triangles.
  std::vector<uint32_t> chains_[2], cavity_;
  std::vector<EdgeAttr> sides_[2];
  mutable uint32_t rng_ = 2463534242u;
};

}  // namespace acutemesh::detail
