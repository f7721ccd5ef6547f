#include "reduce.h"

#include <algorithm>
#include <limits>

#include "exact_feet.h"
#include "slice.h"

namespace acutemesh::detail {

// Every triangle of the hole (hole_) meets the target, or is made to by moving one of its
// vertices (relocation, or sliding along a segment). Moves are logged in moved_ so that a
// failed removal can undo them.
bool Reduce::holeMeetsTarget() {
  moved_.clear();
  for (uint32_t t : hole_) {
    if (!job_.target.misses(s_, t)) continue;
    bool repaired = false;
    for (uint32_t k = 0; k < 3 && !repaired; ++k) {
      uint32_t a = s_.T.tri[3 * t + k];
      Moved old{a, s_.P(a)[0], s_.P(a)[1]};
      if (relocation_.relocate(a) || relocation_.slide(a)) moved_.push_back(old), repaired = true;
    }
    if (!repaired) return false;
  }
  return true;
}

void Reduce::undoMoves() {
  for (size_t i = moved_.size(); i-- > 0;) {
    s_.T.pts[2 * size_t(moved_[i].vertex)] = moved_[i].x;
    s_.T.pts[2 * size_t(moved_[i].vertex) + 1] = moved_[i].y;
  }
  moved_.clear();
}

// Removes free vertex v if the triangles that then fill its star meet the target. Otherwise
// everything moved goes back and v is put back (the constrained Delaunay triangulation is
// unique, so its star returns as it was up to cocircular ties, which the final repair pass
// settles).
bool Reduce::tryRemove(uint32_t v) {
  if (!recordingHole([&] { return s_.T.removeVertex(v); })) return false;
  if (holeMeetsTarget()) return true;
  undoMoves();
  s_.T.insert(v, hole_.back());  // the last triangle written is alive and next to v's place
  return false;
}

// The same for a Steiner vertex on a segment: its two pieces become one again. If that fails,
// v goes back onto the merged piece; should even that be impossible (the piece's triangles no
// longer hold v's place), v stays out and the final repair pass mends what that spoilt.
bool Reduce::tryRemoveFromSegment(uint32_t v) {
  uint32_t ends[2];
  if (!recordingHole([&] { return s_.T.removeFromSegment(v, ends); })) return false;
  if (holeMeetsTarget()) return true;
  undoMoves();
  uint32_t merged = s_.T.findEdge(ends[0], ends[1]);
  if (merged != kNone) s_.T.splitFixedEdge(merged, v);
  return false;
}

// The same for consecutive Steiner points u, w on one segment: one point in their place, halfway
// between them (on the input segment's line) or, with exact feet, at the foot of the altitude
// from the vertex opposite u-w on either side. If none will do, they go back onto their piece;
// should that be impossible, what stays out is left to the final repair pass.
bool Reduce::tryMergeOnSegment(uint32_t u, uint32_t w) {
  Triangulation& T = s_.T;
  uint32_t uw = T.findEdge(u, w);
  if (uw == kNone || !T.isFixed(uw) || T.segment.empty() || T.segment[uw] == kNone) return false;
  uint32_t seg = T.segment[uw];
  const double pu[2] = {s_.P(u)[0], s_.P(u)[1]}, pw[2] = {s_.P(w)[0], s_.P(w)[1]};
  uint32_t apexes[2] = {kNone, kNone};
  for (int side = 0; side < 2 && job_.target.feet; ++side) {
    const uint32_t e = side ? T.opp[uw] : uw;
    if (T.inDomain(e / 3)) apexes[side] = T.tri[prev(e)];
  }
  uint32_t endsU[2], endsW[2];
  touched_.clear();
  T.touched = &touched_;
  auto putBack = [&](uint32_t v, const uint32_t* ends) {
    uint32_t piece = T.findEdge(ends[0], ends[1]);
    if (piece != kNone) T.splitFixedEdge(piece, v);
  };
  if (T.removeFromSegment(u, endsU)) {
    if (T.removeFromSegment(w, endsW)) {
      SegmentLine line = job_.line(seg, pu, pw);
      int merged = 0;
      for (int c = 0; c < 3 && merged == 0; ++c) {
        const uint32_t footOf = c == 0 ? kNone : apexes[c - 1];
        if (c > 0 && footOf == kNone) continue;
        double x[2];
        line.at(c == 0 ? 0.5 * (line.param(pu) + line.param(pw)) : line.param(s_.P(footOf)), x);
        merged = tryPointOnSegment(x, footOf, endsW);
      }
      if (merged == 1) return true;
      if (merged == -1) {
        T.touched = nullptr;
        return false;
      }
      putBack(w, endsW);
    }
    putBack(u, endsU);
  }
  T.touched = nullptr;
  return false;
}

// With a merge's points out (tryMergeOnSegment): puts one at x on the piece between ends
// (standing for footOf's altitude foot, if given and the double is not exactly it), and keeps
// it if the hole then meets the target. As tryMergedPoint: 1 kept; 0 out again; -1 stuck.
int Reduce::tryPointOnSegment(const double* x, uint32_t footOf, const uint32_t* ends) {
  Triangulation& T = s_.T;
  const uint32_t m = s_.addVertex(x, kOnSegment);
  const uint32_t piece = T.findEdge(ends[0], ends[1]);
  bool removedAgain = false;
  if (piece != kNone && T.splitFixedEdge(piece, m)) {
    standForFoot(s_, job_.target, m, footOf, s_.P(ends[0]));
    hole_ = touched_;
    T.touched = nullptr;
    if (holeMeetsTarget()) return 1;
    undoMoves();
    T.touched = &touched_;
    uint32_t endsM[2];
    removedAgain = T.removeFromSegment(m, endsM);
  }
  if (!removedAgain && T.vertexEdge[m] != kNone) return -1;
  s_.dropLastVertex();
  return 0;
}

// Where one point would best stand in for free neighbours u and w: the centre of the region
// their joint link leaves (LinkRegion), else (no such region, or their stars reach outside
// the domain) their midpoint. False if the pair is not worth a try: no such region around a
// joint link of kMergeLinkEdges edges or more.
bool Reduce::mergePoint(uint32_t u, uint32_t w, double* out) {
  const Triangulation& T = s_.T;
  out[0] = 0.5 * (s_.P(u)[0] + s_.P(w)[0]), out[1] = 0.5 * (s_.P(u)[1] + s_.P(w)[1]);
  std::vector<std::array<uint32_t, 2>>& edges = region_.edges;
  edges.clear();
  for (uint32_t c : {u, w}) {
    uint32_t e0 = T.vertexEdge[c], e = e0;
    do {
      if (!T.inDomain(e / 3)) return true;
      uint32_t x = T.tri[next(e)], y = T.tri[prev(e)];
      if (x != u && x != w && y != u && y != w) edges.push_back({x, y});
      e = T.opp[prev(e)];
    } while (e != e0);
  }
  if (!region_.leavesRoom()) return edges.size() < kMergeLinkEdges;
  region_.clip(job_.target.strictMax);
  double centre[2];
  if (!region_.centroid(centre)) return edges.size() < kMergeLinkEdges;
  out[0] = centre[0], out[1] = centre[1];
  return true;
}

// With u and w out (tryMerge): puts one point at x, and keeps it if the hole then meets the
// target (holeMeetsTarget). 1: merged; 0: x is out again, the hole as it was; -1: x could not
// be taken out again and stays (the final repair pass checks).
int Reduce::tryMergedPoint(const double* x) {
  Triangulation& T = s_.T;
  Location loc = T.locate(x, touched_.back());
  if (loc.where != Where::InTriangle || !T.inside[loc.tri]) return 0;
  for (uint32_t k = 0; k < 3; ++k)  // no edge shorter than refinement's smallest
    if (dist2(x, s_.P(T.tri[3 * loc.tri + k])) < job_.minEdge2) return 0;
  uint32_t m = s_.addVertex(x, kFree);
  bool removedAgain = false;
  if (T.insertAt(m, loc) == m) {
    hole_ = touched_;
    T.touched = nullptr;
    if (holeMeetsTarget()) return 1;
    undoMoves();
    T.touched = &touched_;
    removedAgain = T.removeVertex(m);
  }
  if (!removedAgain && T.vertexEdge[m] != kNone) return -1;
  s_.dropLastVertex();
  return 0;
}

// Replaces two neighbouring free vertices u, w by one if the triangles around it meet the
// target (after moving vertices as holeMeetsTarget does): at mergePoint, else at the point
// refinement would weigh best for the first bad triangle of their hole. Otherwise the pair
// goes back. A pair mergePoint declines is not tried.
bool Reduce::tryMerge(uint32_t u, uint32_t w) {
  Triangulation& T = s_.T;
  double mid[2];
  if (!mergePoint(u, w, mid)) return false;
  touched_.clear();
  T.touched = &touched_;
  if (T.removeVertex(u)) {
    if (T.removeVertex(w)) {
      int merged = tryMergedPoint(mid);
      uint32_t bad = kNone;
      for (size_t i = 0; merged == 0 && i < touched_.size() && bad == kNone; ++i) {
        uint32_t t = touched_[i];
        if (job_.target.misses(s_, t)) bad = t;
      }
      if (bad != kNone) {
        slicePoints(s_, bad, job_.strategy.weighPoints, candidates_);
        int fewest = 0;
        size_t best = insertion_.weigh(bad, candidates_, fewest);
        if (best < candidates_.size()) {
          const double x[2] = {candidates_[best][0], candidates_[best][1]};
          merged = tryMergedPoint(x);
        }
      }
      if (merged == 1) return true;
      if (merged == -1) {
        T.touched = nullptr;
        return false;
      }
      T.insert(w, touched_.back());
    }
    T.insert(u, touched_.back());
  }
  T.touched = nullptr;
  return false;
}

// After a successful removal or merge: the vertices whose stars it changed (the hole's
// corners, and the neighbours of every vertex moved to repair it) are worth another try.
void Reduce::markChanged() {
  const Triangulation& T = s_.T;
  if (dirty_.size() < T.vertexCount()) dirty_.resize(T.vertexCount(), 1);
  for (uint32_t t : hole_) {
    if (T.isFree(t)) continue;
    for (int k = 0; k < 3; ++k)
      if (T.tri[3 * t + k] != kGhost) dirty_[T.tri[3 * t + k]] = 1;
  }
  for (const Moved& m : moved_) {
    uint32_t e0 = T.vertexEdge[m.vertex], e = e0;
    if (e0 == kNone) continue;
    do {
      if (T.tri[next(e)] != kGhost) dirty_[T.tri[next(e)]] = 1;
      e = T.opp[prev(e)];
    } while (e != e0);
  }
}

// Polled once per removal or merge attempt: whether a budget has run out or the run was
// cancelled. Now and then it reports progress (phase "improve", the vertices in the mesh).
bool Reduce::shouldStop(double done) {
  if ((++attempts_ & 63) != 0) return false;
  if (job_.reportsProgress() && job_.budget.progress())
    job_.budget.progress()->note("improve", done, s_.T.vertexCount());
  return job_.improvementOver();
}

// Oldest first (RefineState::visitOrder: on small meshes): the early, coarse points are the
// likeliest to have become redundant.
void Reduce::removeSteinerPoints(const std::vector<uint8_t>* due, int passes) {
  markDue(due);
  // (One order for all the passes: removals add no vertex.)
  s_.visitOrder(uint32_t(job_.input.vertexCount()), s_.T.vertexCount(), order_);
  for (int pass = 0; pass < passes; ++pass) {
    uint32_t removed = 0;
    for (size_t i = 0; i < order_.size(); ++i) {
      const uint32_t v = order_[i];
      if (!dirty_[v] || s_.T.vertexEdge[v] == kNone || !scope.owns(v)) continue;
      dirty_[v] = 0;
      if (shouldStop(double(i) / double(order_.size()))) return;
      if (!removePoint(v)) continue;
      ++removed;
      scope.record({Step::Remove, v, kNone, kNone, 0, 0});
    }
    if (removed == 0) break;
  }
}

// The first pass's vertices: those `due` marks, and any made after it (all without it).
void Reduce::markDue(const std::vector<uint8_t>* due) {
  dirty_.assign(s_.T.vertexCount(), 1);
  if (due) std::copy(due->begin(), due->end(), dirty_.begin());
}

void Reduce::mergeSteinerPoints(const std::vector<uint8_t>* due, int passes) {
  markDue(due);
  for (int pass = 0; pass < passes; ++pass)
    if (mergePass() == 0 || job_.improvementOver()) break;
}

// Tries each due Steiner vertex (that the scope owns) with its partners, the same pair once.
uint32_t Reduce::mergePass() {
  const Triangulation& T = s_.T;
  uint32_t merged = 0;
  std::vector<uint8_t> pending = dirty_;  // a pair is tried once a pass: at the turn of the
                                          // one visited first, if due
  // Newest first (on small meshes): the points merges make are the likeliest to merge again.
  s_.visitOrder(uint32_t(job_.input.vertexCount()), T.vertexCount(), order_);
  std::reverse(order_.begin(), order_.end());
  rank_.assign(T.vertexCount(), kNone);
  for (size_t i = 0; i < order_.size(); ++i) rank_[order_[i]] = uint32_t(i);
  for (size_t i = 0; i < order_.size(); ++i) {
    const uint32_t u = order_[i];
    bool onSegment = s_.role[u] == kOnSegment;
    if (u >= dirty_.size() || !dirty_[u] || (s_.role[u] != kFree && !onSegment) ||
        T.vertexEdge[u] == kNone || !scope.owns(u))
      continue;
    dirty_[u] = 0;
    if (shouldStop(double(i) / double(order_.size()))) break;
    // The partners first (free neighbours of a free vertex, the neighbours along its segment
    // of a segment vertex): a failed merge re-inserts u, which renumbers its edges.
    partners_.clear();
    uint32_t e0 = T.vertexEdge[u], e = e0;
    do {
      uint32_t w = T.tri[next(e)];
      bool triedAtItsTurn = w < rank_.size() && rank_[w] < i && pending[w];
      bool partner = w != kGhost && scope.owns(w) &&
                     (onSegment ? s_.role[w] == kOnSegment && T.isFixed(e) : s_.role[w] == kFree);
      if (partner && !triedAtItsTurn) partners_.push_back(w);
      e = T.opp[prev(e)];
    } while (e != e0);
    for (uint32_t w : partners_) {
      if (mergePair(u, w)) {
        ++merged;
        scope.record({Step::Merge, u, w, T.vertexCount() - 1, 0, 0});
        break;
      }
    }
  }
  return merged;
}

namespace {
constexpr double kRemovalSizeSlack = 1.25;  // how much larger the size may be a star away
}  // namespace

// With sizes: whether taking v out can leave triangles within them. The triangle that then
// covers v's place has its corners at v's neighbours, so its longest edge is at least sqrt(3)
// times v's shortest edge; with room for the size varying (grading) across it.
bool Reduce::sizesAllowRemoving(uint32_t v) const {
  const Sizes& sizes = job_.target.sizes;
  if (!sizes.maxEdge && !sizes.edge) return true;
  const Triangulation& T = s_.T;
  const double* p = T.point(v);
  double shortest2 = std::numeric_limits<double>::infinity();
  const uint32_t first = T.vertexEdge[v];
  uint32_t e = first;
  do {
    const uint32_t w = T.tri[next(e)];
    if (w != kGhost) shortest2 = std::min(shortest2, dist2(p, T.point(w)));
    e = T.opp[prev(e)];
  } while (e != first && e != kNone);
  double h = sizes.maxEdge > 0 ? sizes.maxEdge : std::numeric_limits<double>::infinity();
  if (sizes.edge) h = std::min(h, sizes.edge(p[0], p[1]));
  return !(3 * shortest2 > kRemovalSizeSlack * kRemovalSizeSlack * h * h);
}

bool Reduce::removePoint(uint32_t v) {
  if (s_.role[v] != kFree && s_.role[v] != kOnSegment) return false;
  if (!sizesAllowRemoving(v)) return false;
  const bool gone = s_.role[v] == kFree ? tryRemove(v) : tryRemoveFromSegment(v);
  if (gone) markChanged();
  return gone;
}

bool Reduce::mergePair(uint32_t u, uint32_t w) {
  const Triangulation& T = s_.T;
  if (T.vertexEdge[u] == kNone || T.vertexEdge[w] == kNone || T.findEdge(u, w) == kNone)
    return false;
  if (!(s_.role[u] == kOnSegment ? tryMergeOnSegment(u, w) : tryMerge(u, w))) return false;
  markChanged();
  return true;
}

}  // namespace acutemesh::detail
