#include "descent.h"

#include <algorithm>
#include <cmath>

#include "joint_smooth.h"
#include "params.h"

namespace acutemesh::detail {
namespace {

// The eight directions of the pattern search (unit length).
constexpr double kDiag = 0.70710678118654752;
constexpr double kDirections[8][2] = {{1, 0},           {0, 1},         {-1, 0},
                                      {0, -1},          {kDiag, kDiag}, {-kDiag, kDiag},
                                      {-kDiag, -kDiag}, {kDiag, -kDiag}};

// The cosine of the angle between sides of squared lengths p and q, opposite the side of
// squared length o (law of cosines).
double cosineOpposite(double o, double p, double q) { return (p + q - o) / (2 * std::sqrt(p * q)); }

// Triangle a, b, c's squared side lengths: o the longest, p and q the others.
struct Sides {
  double o, p, q;
};
Sides byLongest(const double* a, const double* b, const double* c) {
  const double la = dist2(b, c), lb = dist2(a, c), lc = dist2(a, b);
  if (la >= lb && la >= lc) return {la, lb, lc};
  if (lb >= lc) return {lb, la, lc};
  return {lc, la, lb};
}

// The cosine of the largest angle of triangle a, b, c (opposite its longest side).
double largestCosine(const double* a, const double* b, const double* c) {
  const Sides s = byLongest(a, b, c);
  return cosineOpposite(s.o, s.p, s.q);
}

// The cosine of the smallest angle of triangle a, b, c (opposite its shortest side).
double smallestCosine(const double* a, const double* b, const double* c) {
  const double la = dist2(b, c), lb = dist2(a, c), lc = dist2(a, b);
  if (la <= lb && la <= lc) return cosineOpposite(la, lb, lc);
  if (lb <= lc) return cosineOpposite(lb, la, lc);
  return cosineOpposite(lc, la, lb);
}

// Triangle a, b, c's margin to the target: the cosine of its largest angle less the bound's
// (and with a minimum angle, the cosine of that less that of its smallest angle, if smaller).
// Negative: it misses the target by that much.
double triangleMargin(const Target& target, const double* a, const double* b, const double* c) {
  const double m = largestCosine(a, b, c) - target.cosMax;
  return target.minAngle > 0 ? std::min(m, target.cosMin - smallestCosine(a, b, c)) : m;
}

// Whether triangle a, b, c's largest angle surely has a cosine below w, without the root and
// the division of largestCosine: (p + q - o) / (2 sqrt(pq)) < w, squared, by a margin far
// above their rounding (so it never says yes where largestCosine would not).
bool largestCosineBelow(const double* a, const double* b, const double* c, double w) {
  const Sides s = byLongest(a, b, c);
  const double n = s.p + s.q - s.o, pq = s.p * s.q;
  w -= 1e-9;
  if (w > 0) return n < 0 || n * n < 4 * w * w * pq;
  return n < 0 && n * n > 4 * w * w * pq;
}

}  // namespace

// The star of v in star_ (its triangles but ghosts), and for a point on a segment its
// neighbours there in seg_; false for a vertex that does not move (RefineState::slideOf).
bool AngleDescent::gather(uint32_t v) {
  const Triangulation& T = s_.T;
  if (!s_.slideOf(v, seg_, segment_)) return false;
  star_.clear();
  starInside_.clear();
  uint32_t e0 = T.vertexEdge[v], e = e0;
  do {
    if (!T.isGhost(e / 3)) {
      star_.push_back(e / 3);
      starInside_.push_back(T.inDomain(e / 3));
    }
    e = T.opp[prev(e)];
  } while (e != e0);
  return true;
}

// The margins (triangleMargin) of the star's domain triangles, smallest first, into `out`.
// Empty (and false) if a triangle of the star is not
// counter-clockwise (in floating point: a move is confirmed with exact predicates). Stars are
// compared by these lists (leximin): the worst triangle first, then the next, so that a move
// that helps the worst does not spoil the others.
bool AngleDescent::margins(std::vector<double>& out) const {
  const Target& target = job_.target;
  const Triangulation& T = s_.T;
  out.clear();
  for (size_t i = 0; i < star_.size(); ++i) {
    const uint32_t* v = &T.tri[3 * star_[i]];
    const double *a = T.point(v[0]), *b = T.point(v[1]), *c = T.point(v[2]);
    const double abx = b[0] - a[0], aby = b[1] - a[1], acx = c[0] - a[0], acy = c[1] - a[1];
    if (abx * acy - aby * acx <= 0) {
      out.clear();
      return false;
    }
    if (starInside_[i]) out.push_back(triangleMargin(target, a, b, c));
  }
  std::sort(out.begin(), out.end());
  return true;
}

void AngleDescent::putAt(uint32_t v, const double* p) {
  double* at = &s_.T.pts[2 * size_t(v)];
  at[0] = p[0], at[1] = p[1];
}

// Whether margins a are better than b (leximin, ignoring differences under kEven).
bool AngleDescent::better(const std::vector<double>& a, bool aValid, const std::vector<double>& b,
                          bool bValid) {
  if (!aValid || !bValid) return aValid && !bValid;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i) {
    if (a[i] > b[i] + kEven) return true;
    if (a[i] < b[i] - kEven) return false;
  }
  return false;
}

// Puts v at p (for now) and whether its star is better there than best_ (margins() into try_):
// the same as better() on the two lists, but a star with a triangle turned over or worse than
// the best's worst is turned down at that triangle (most tries of a search end there).
bool AngleDescent::improvesAt(uint32_t v, const double* p, bool bestValid) {
  const Target& target = job_.target;
  Triangulation& T = s_.T;
  putAt(v, p);
  const double worst = bestValid && !best_.empty() ? best_.front() - kEven : -INFINITY;
  // First the cheap tests that turn most tries down: a triangle turned over, or one whose
  // largest angle alone is worse than the best's worst.
  for (size_t i = 0; i < star_.size(); ++i) {
    const uint32_t* c = &T.tri[3 * star_[i]];
    const double *a = T.point(c[0]), *b = T.point(c[1]), *d = T.point(c[2]);
    if ((b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]) <= 0) return false;
    if (starInside_[i] && largestCosineBelow(a, b, d, worst + target.cosMax)) return false;
  }
  try_.clear();
  for (size_t i = 0; i < star_.size(); ++i) {
    if (!starInside_[i]) continue;
    const uint32_t* c = &T.tri[3 * star_[i]];
    const double m = triangleMargin(target, T.point(c[0]), T.point(c[1]), T.point(c[2]));
    if (m < worst) return false;
    try_.push_back(m);
  }
  std::sort(try_.begin(), try_.end());
  return better(try_, true, best_, bestValid);
}

// Puts v at p if its star stays a valid triangulation there (exact) with no edge shorter than
// refinement's smallest; else v stays. (No Delaunay flips: flipIfBetter decides the edges.)
bool AngleDescent::settleAt(uint32_t v, const double* p) {
  Triangulation& T = s_.T;
  T.notePoint(v);
  double* at = &T.pts[2 * size_t(v)];
  const double old[2] = {at[0], at[1]};
  at[0] = p[0], at[1] = p[1];
  bool valid = true;
  for (size_t i = 0; i < star_.size() && valid; ++i) {
    const uint32_t* t = &T.tri[3 * star_[i]];
    valid = orient2d(T.point(t[0]), T.point(t[1]), T.point(t[2])) > 0;
    for (int k = 0; k < 3 && valid; ++k)
      valid = t[k] == v || dist2(p, T.point(t[k])) >= job_.minEdge2;
  }
  if (!valid) {
    at[0] = old[0], at[1] = old[1];
    return false;
  }
  if (recording_) changed_.push_back(v);
  return true;
}

// Flips the edge of e if it lies between two triangles of the domain and the flip lowers the
// larger of their largest angles (the quadrilateral strictly convex: exact).
bool AngleDescent::flipIfBetter(uint32_t e) {
  Triangulation& T = s_.T;
  const uint32_t f = T.opp[e];
  if (T.isFree(e / 3) || f == kNone || T.isFixed(e)) return false;
  if (!T.inDomain(e / 3) || !T.inDomain(f / 3)) return false;
  const uint32_t x = T.tri[e], y = T.tri[next(e)], z = T.tri[prev(e)], w = T.tri[prev(f)];
  const double *px = T.point(x), *py = T.point(y), *pz = T.point(z), *pw = T.point(w);
  const double now = std::min(largestCosine(px, py, pz), largestCosine(py, px, pw));
  const double after = std::min(largestCosine(pz, px, pw), largestCosine(pw, py, pz));
  if (!(after > now + 1e-12)) return false;
  if (orient2d(pz, px, pw) <= 0 || orient2d(pw, py, pz) <= 0) return false;
  T.flip(e);
  if (recording_) changed_.insert(changed_.end(), {x, y, z, w});
  return true;
}

// flipIfBetter on every edge once; the number flipped.
size_t AngleDescent::flipPass() {
  size_t flipped = 0;
  for (uint32_t e = 0; e < 3 * s_.T.triangleSlots(); ++e)
    if (e < s_.T.opp[e] || s_.T.opp[e] == kNone) flipped += flipIfBetter(e);
  return flipped;
}

// A pattern search from the best of the current place, the middle of the link and the
// optimal Delaunay triangulation's place (the star's circumcentres weighed by area, which
// evens out the triangles).
bool AngleDescent::optimiseFree(uint32_t v) {
  const Triangulation& T = s_.T;
  const double start[2] = {T.point(v)[0], T.point(v)[1]};
  double best[2] = {start[0], start[1]};
  bool bestValid = margins(best_);
  double mean[2] = {0, 0}, odt[2] = {0, 0}, area = 0, nearest2 = INFINITY;
  for (uint32_t t : star_) {
    const uint32_t* c = &T.tri[3 * t];
    const double *a = T.point(c[0]), *b = T.point(c[1]), *d = T.point(c[2]);
    double cc[2];
    circumcenter(a, b, d, cc);
    const double w = 0.5 * std::fabs((b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]));
    odt[0] += w * cc[0], odt[1] += w * cc[1], area += w;
    for (int k = 0; k < 3; ++k)
      if (c[k] != v && c[(k + 1) % 3] == v) {  // each link vertex once: the one before v
        mean[0] += T.point(c[k])[0] / double(star_.size());
        mean[1] += T.point(c[k])[1] / double(star_.size());
        nearest2 = std::min(nearest2, dist2(start, T.point(c[k])));
      }
  }
  odt[0] /= area, odt[1] /= area;
  auto tryAt = [&](const double* q) {
    if (!std::isfinite(q[0]) || !std::isfinite(q[1]) || !improvesAt(v, q, bestValid)) return false;
    best_.swap(try_);
    bestValid = true;
    best[0] = q[0], best[1] = q[1];
    return true;
  };
  tryAt(mean);
  tryAt(odt);
  const double r = std::sqrt(nearest2);
  if (!(r > 0 && r < INFINITY)) return false;
  int steps = 0;
  for (double h = kDescentStep * r; h > kDescentFinestStep * r && ++steps < kDescentSearchSteps;) {
    const double from[2] = {best[0], best[1]};
    bool moved = false;
    for (const auto& d : kDirections) {
      const double q[2] = {from[0] + h * d[0], from[1] + h * d[1]};
      moved |= tryAt(q);
    }
    if (!moved) h *= 0.5;
  }
  putAt(v, start);
  return (best[0] != start[0] || best[1] != start[1]) && settleAt(v, best);
}

// The same along the segment, between v's neighbours on it.
bool AngleDescent::optimiseOnSegment(uint32_t v) {
  const Triangulation& T = s_.T;
  const double start[2] = {T.point(v)[0], T.point(v)[1]};
  const double *a = T.point(seg_[0]), *b = T.point(seg_[1]);
  const SegmentLine line = job_.line(segment_, a, b);
  const double ta = line.param(a), tb = line.param(b);
  const double lo = std::min(ta, tb), hi = std::max(ta, tb), room = kDescentSegmentRoom * (hi - lo);
  bool bestValid = margins(best_);
  double best = line.param(start);
  bool movedAtAll = false;
  if (!(hi - lo > 0 && hi - lo < INFINITY)) return false;
  int steps = 0;
  for (double h = kDescentStep * (hi - lo);
       h > kDescentFinestStep * (hi - lo) && ++steps < kDescentSearchSteps;) {
    const double from = best;
    bool moved = false;
    for (double t : {from - h, from + h}) {
      if (!(t > lo + room && t < hi - room)) continue;
      double q[2];
      line.at(t, q);
      if (!improvesAt(v, q, bestValid)) continue;
      best_.swap(try_);
      bestValid = true, best = t, moved = true;
    }
    movedAtAll |= moved;
    if (!moved) h *= 0.5;
  }
  putAt(v, start);
  if (!movedAtAll) return false;
  double q[2];
  line.at(best, q);
  return settleAt(v, q);
}

// Moves Steiner vertex v where its star is best, if some triangle of the star is within
// kDescentSlack of the bound or past it (elsewhere a move would only cost time).
bool AngleDescent::optimise(uint32_t v) {
  if (!gather(v) || (margins(best_) && best_.front() > kDescentSlack)) return false;
  return s_.role[v] == kFree ? optimiseFree(v) : optimiseOnSegment(v);
}

size_t AngleDescent::smooth() {
  size_t moved = 0;
  for (uint32_t v = uint32_t(job_.input.vertexCount()); v < s_.T.vertexCount(); ++v) {
    if ((v & 1023) == 0 && job_.budget.stop()) break;
    moved += optimise(v);
  }
  return moved;
}

// How far triangle slot t of s is from the target: its negative margin (triangleMargin), at
// least 1e-9 where the exact check says it misses; 0 when it meets it or is not in the domain.
double AngleDescent::violationOf(const RefineState& s, uint32_t t) const {
  const Triangulation& T = s.T;
  if (!T.inDomain(t)) return 0;
  const uint32_t* v = &T.tri[3 * t];
  const double* p[3] = {T.point(v[0]), T.point(v[1]), T.point(v[2])};
  // (Non-obtuse targets, which only thinning serves: the target's own test, whose corners at
  // exact feet may stay right within their slack.)
  if (job_.target.nonObtuse)
    return job_.target.worstCorner(s, t).k < 0
               ? 0
               : std::max(-triangleMargin(job_.target, p[0], p[1], p[2]), 1e-9);
  return violationAt(p);
}

// violationOf's for the domain triangle with corners p, for acute targets (no exact feet, so
// the corners say it all).
double AngleDescent::violationAt(const double* const p[3]) const {
  const double m = triangleMargin(job_.target, p[0], p[1], p[2]);
  return m < 0 || job_.target.worstCorner(p, 0).k >= 0 ? std::max(-m, 1e-9) : 0;
}

// The total violation: violationOf summed over the domain, 0 when every triangle meets it.
double AngleDescent::violation() const {
  double sum = 0;
  for (uint32_t t = 0; t < s_.T.triangleSlots(); ++t) sum += violationOf(s_, t);
  return sum;
}

// violationOf summed over the triangles of s with a vertex in changed_ (each once). A move
// changes only such triangles (changed_ holds every vertex whose star it changed), so this
// before and after the move gives the change of the total, without a pass over the mesh.
double AngleDescent::violationNearChanges(const RefineState& s) {
  const Triangulation& T = s.T;
  slots_.clear();
  for (uint32_t v : changed_) {
    if (v >= T.vertexCount() || T.vertexEdge[v] == kNone) continue;
    uint32_t e0 = T.vertexEdge[v], e = e0;
    do {
      slots_.push_back(e / 3);
      e = T.opp[prev(e)];
    } while (e != e0);
  }
  std::sort(slots_.begin(), slots_.end());
  slots_.erase(std::unique(slots_.begin(), slots_.end()), slots_.end());
  double sum = 0;
  for (uint32_t t : slots_) sum += violationOf(s, t);
  return sum;
}

// violationNearChanges of the state as it was at mark m, read through the journal: each slot,
// vertex edge and point as its first note since m has it, else as it is now (what no write
// noted is unchanged). Vertices made since m were not there.
double AngleDescent::violationNearChangesAt(const Journal::Mark& m) {
  const Triangulation& T = s_.T;
  const Journal& j = journal_;
  if (oldSlot_.size() < T.triangleSlots()) oldSlot_.resize(T.triangleSlots(), 0);
  if (oldEdge_.size() < T.vertexCount()) oldEdge_.resize(T.vertexCount(), 0);
  if (oldPoint_.size() < T.vertexCount()) oldPoint_.resize(T.vertexCount(), 0);
  for (size_t i = m.slots; i < j.slots.size(); ++i)
    if (!oldSlot_[j.slots[i].t]) oldSlot_[j.slots[i].t] = uint32_t(i + 1);
  // (A vertex made and dropped since the mark may be noted: it is past the count.)
  for (size_t i = m.edges; i < j.edges.size(); ++i)
    if (j.edges[i].first < T.vertexCount() && !oldEdge_[j.edges[i].first])
      oldEdge_[j.edges[i].first] = uint32_t(i + 1);
  for (size_t i = m.points; i < j.points.size(); ++i)
    if (j.points[i].v < T.vertexCount() && !oldPoint_[j.points[i].v])
      oldPoint_[j.points[i].v] = uint32_t(i + 1);
  auto record = [&](uint32_t t) -> const Journal::Slot* {
    return oldSlot_[t] ? &j.slots[oldSlot_[t] - 1] : nullptr;
  };
  auto cornerOf = [&](uint32_t e) {
    const Journal::Slot* r = record(e / 3);
    return r ? r->tri[e % 3] : T.tri[e];
  };
  auto twinOf = [&](uint32_t e) {
    const Journal::Slot* r = record(e / 3);
    return r ? r->opp[e % 3] : T.opp[e];
  };
  auto pointOf = [&](uint32_t v, double* out) {
    const double* p = oldPoint_[v] ? j.points[oldPoint_[v] - 1].xy : T.point(v);
    out[0] = p[0], out[1] = p[1];
  };
  slots_.clear();
  for (uint32_t v : changed_) {
    if (v >= m.vertices) continue;
    const uint32_t e0 = oldEdge_[v] ? j.edges[oldEdge_[v] - 1].second : T.vertexEdge[v];
    if (e0 == kNone) continue;
    uint32_t e = e0;
    do {
      slots_.push_back(e / 3);
      e = twinOf(prev(e));
    } while (e != e0);
  }
  std::sort(slots_.begin(), slots_.end());
  slots_.erase(std::unique(slots_.begin(), slots_.end()), slots_.end());
  double sum = 0;
  for (uint32_t t : slots_) {
    const Journal::Slot* r = record(t);
    const bool inside = r ? r->inside != 0 : T.inside[t] != 0;
    uint32_t c[3];
    for (uint32_t k = 0; k < 3; ++k) c[k] = cornerOf(3 * t + k);
    if (!inside || c[0] == kNone || c[0] == kGhost || c[1] == kGhost || c[2] == kGhost) continue;
    double x[3][2];
    for (int k = 0; k < 3; ++k) pointOf(c[k], x[k]);
    const double* p[3] = {x[0], x[1], x[2]};
    sum += violationAt(p);
  }
  for (size_t i = m.slots; i < j.slots.size(); ++i) oldSlot_[j.slots[i].t] = 0;
  for (size_t i = m.edges; i < j.edges.size(); ++i)
    if (j.edges[i].first < T.vertexCount()) oldEdge_[j.edges[i].first] = 0;
  for (size_t i = m.points; i < j.points.size(); ++i)
    if (j.points[i].v < T.vertexCount()) oldPoint_[j.points[i].v] = 0;
  return sum;
}

// Smoothing sweeps over the vertices of the triangles `touched` lists and their neighbours.
void AngleDescent::smoothAround(const std::vector<uint32_t>& touched) {
  const Triangulation& T = s_.T;
  near_.clear();
  for (uint32_t t : touched) {
    if (T.isFree(t)) continue;
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = T.tri[3 * t + k];
      if (v == kGhost || T.vertexEdge[v] == kNone) continue;
      near_.push_back(v);
      uint32_t e0 = T.vertexEdge[v], e = e0;
      do {
        near_.push_back(T.tri[next(e)]);
        e = T.opp[prev(e)];
      } while (e != e0);
    }
  }
  std::sort(near_.begin(), near_.end());
  near_.erase(std::unique(near_.begin(), near_.end()), near_.end());
  for (int sweep = 0; sweep < kDescentLocalSweeps; ++sweep) {
    size_t moved = 0;
    for (uint32_t v : near_)
      if (v != kGhost && v >= job_.input.vertexCount()) moved += optimise(v);
    for (uint32_t v : near_)
      if (v != kGhost && T.vertexEdge[v] != kNone) moved += flipAround(v);
    if (moved == 0) break;
  }
}

// flipIfBetter on the edges of v's link until none flips (a flip changes the link: it is
// walked anew each time, at most kFlipWalks times); the number flipped.
size_t AngleDescent::flipAround(uint32_t v) {
  constexpr int kFlipWalks = 8;
  const Triangulation& T = s_.T;
  size_t flipped = 0;
  for (int walk = 0; walk < kFlipWalks; ++walk) {
    uint32_t e0 = T.vertexEdge[v], e = e0;
    bool any = false;
    do {
      any = flipIfBetter(next(e));
      e = T.opp[prev(e)];
    } while (!any && e != e0);
    if (!any) break;
    ++flipped;
  }
  return flipped;
}

// The edge opposite the largest angle of t.
uint32_t AngleDescent::longestEdge(uint32_t t) const {
  const Triangulation& T = s_.T;
  const uint32_t* c = &T.tri[3 * t];
  int k = 0;
  double longest = -1;
  for (int i = 0; i < 3; ++i) {
    const double len = dist2(T.point(c[(i + 1) % 3]), T.point(c[(i + 2) % 3]));
    if (len > longest) longest = len, k = i;
  }
  return 3 * t + uint32_t(k + 1) % 3;
}

// The moves tried for triangle t, which misses the target, best first: where the angle
// over the bound is at a vertex that does not move (an input corner, a point on a segment),
// an edge from it, to the apex of the equilateral triangle on either of its edges or to a
// point on its bisector; the edge opposite that angle split in the middle (a subsegment by
// the boundary rule's split); a point at the circumcentre; one of t's Steiner points removed.
void AngleDescent::movesFor(uint32_t t, std::vector<Move>& out) const {
  const Triangulation& T = s_.T;
  const uint32_t* c = &T.tri[3 * t];
  const uint32_t e = longestEdge(t), apex = T.tri[prev(e)];
  out.clear();
  if (s_.role[apex] != kFree) {
    const double *o = T.point(apex), *p = T.point(T.tri[e]), *q = T.point(T.tri[next(e)]);
    const double h = 0.8660254037844386;  // sin 60
    out.push_back({Move::Insert, t, kNone, o[0] + 0.5 * (p[0] - o[0]) - h * (p[1] - o[1]),
                   o[1] + 0.5 * (p[1] - o[1]) + h * (p[0] - o[0])});
    out.push_back({Move::Insert, t, kNone, o[0] + 0.5 * (q[0] - o[0]) + h * (q[1] - o[1]),
                   o[1] + 0.5 * (q[1] - o[1]) - h * (q[0] - o[0])});
    const double lp = std::sqrt(dist2(o, p)), lq = std::sqrt(dist2(o, q));
    const double ux = (p[0] - o[0]) / lp + (q[0] - o[0]) / lq,
                 uy = (p[1] - o[1]) / lp + (q[1] - o[1]) / lq;
    const double un = std::sqrt(ux * ux + uy * uy);
    for (double f : {0.5, 0.75, 1.0}) {
      const double scale = f * std::min(lp, lq) / un;
      out.push_back({Move::Insert, t, kNone, o[0] + ux * scale, o[1] + uy * scale});
    }
  }
  out.push_back({Move::Split, t, e, 0, 0});
  double cc[2];
  circumcenter(T.point(c[0]), T.point(c[1]), T.point(c[2]), cc);
  out.push_back({Move::Insert, t, kNone, cc[0], cc[1]});
  for (int k = 0; k < 3; ++k)
    if (c[k] >= job_.input.vertexCount()) out.push_back({Move::Remove, t, c[k], 0, 0});
}

// Puts a free point at x, reached from triangle `from` without crossing a segment, whatever
// it encroaches (smoothing is what settles the points around it); false if x is not in the
// domain, on an edge or too near a vertex.
bool AngleDescent::insertFree(uint32_t from, const double* x) {
  Triangulation& T = s_.T;
  if (!std::isfinite(x[0]) || !std::isfinite(x[1])) return false;
  uint32_t reached = kNone;
  if (firstFixedCrossed(T, from, x, reached) != kNone || reached == kNone || !T.inDomain(reached))
    return false;
  const Location loc = T.locate(x, reached);
  if (loc.where != Where::InTriangle || !T.inDomain(loc.tri)) return false;
  for (uint32_t k = 0; k < 3; ++k)
    if (dist2(x, T.point(T.tri[3 * loc.tri + k])) < job_.minEdge2) return false;
  const uint32_t v = s_.addVertex(x, kFree);
  if (T.insertAt(v, loc) == v) return true;
  s_.dropLastVertex();
  return false;
}

bool AngleDescent::apply(const Move& m) {
  Triangulation& T = s_.T;
  switch (m.kind) {
    case Move::Insert: {
      const double x[2] = {m.x, m.y};
      return insertFree(m.t, x);
    }
    case Move::Split: {
      if (T.isFixed(m.what)) return boundary_.splitSubsegment(m.what, 0.5);
      const double *p = T.point(T.tri[m.what]), *q = T.point(T.tri[next(m.what)]);
      const double x[2] = {0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1])};
      return insertFree(m.t, x) || insertion_.insertSteiner(m.t, x);
    }
    case Move::Remove: {
      if (s_.role[m.what] == kFree) return T.removeVertex(m.what);
      uint32_t ends[2];
      return (s_.role[m.what] == kOnSegment || s_.role[m.what] == kOnHull) &&
             T.removeFromSegment(m.what, ends);
    }
  }
  return false;
}

// Of the triangles around the vertices smoothAround() last worked on, the one that misses the
// target by most; kNone if none does.
uint32_t AngleDescent::worstNear() {
  const Triangulation& T = s_.T;
  uint32_t worst = kNone;
  double lowest = INFINITY;
  for (uint32_t v : near_) {
    if (v == kGhost || T.vertexEdge[v] == kNone) continue;
    uint32_t e0 = T.vertexEdge[v], e = e0;
    do {
      const uint32_t t = e / 3;
      if (job_.target.misses(s_, t)) {
        const uint32_t* c = &T.tri[3 * t];
        const double m = largestCosine(T.point(c[0]), T.point(c[1]), T.point(c[2]));
        if (m < lowest) lowest = m, worst = t;
      }
      e = T.opp[prev(e)];
    } while (e != e0);
  }
  return worst;
}

bool AngleDescent::applySmoothed(const Move& m) {
  touched_.clear();
  changed_.clear();
  s_.T.touched = &touched_;
  const bool changed = apply(m);
  s_.T.touched = nullptr;
  if (!changed) return false;
  if (m.kind == Move::Remove) changed_.push_back(m.what);
  for (uint32_t x : touched_)
    for (int k = 0; k < 3; ++k)
      if (!s_.T.isFree(x) && s_.T.tri[3 * x + k] != kGhost) changed_.push_back(s_.T.tri[3 * x + k]);
  recording_ = true;
  smoothAround(touched_);
  recording_ = false;
  // (A vertex moved in several sweeps is listed once: its star is summed once anyway.)
  std::sort(changed_.begin(), changed_.end());
  changed_.erase(std::unique(changed_.begin(), changed_.end()), changed_.end());
  return true;
}

// Tries the moves for t in turn, each followed by smoothing around what it changed; keeps the
// first that lowers the violation below `now`. With depth > 1 a move that does not is given
// a second move at the worst triangle near it (a look-ahead: a corner often needs two points
// before either helps). What is not kept is put back as it was.
bool AngleDescent::fix(uint32_t t, int depth, double& now, double current) {
  std::vector<Move> moves;
  movesFor(t, moves);
  const bool outermost = s_.T.journal == nullptr;
  if (outermost) s_.T.journal = &journal_;
  bool kept = false;
  for (const Move& m : moves) {
    if (job_.budget.stop() || movesLeft_ == 0) break;
    --movesLeft_;
    const Journal::Mark mark = s_.mark();
    if (applySmoothed(m)) {
      const double after = current + violationNearChanges(s_) - violationNearChangesAt(mark);
      if (after < now - 1e-12) {
        now = after;
        kept = true;
        break;
      }
      const uint32_t u = depth > 1 ? worstNear() : kNone;
      if (u != kNone && fix(u, depth - 1, now, after)) {
        kept = true;
        break;
      }
    }
    s_.undoTo(mark);
  }
  if (outermost) {
    s_.T.journal = nullptr;
    clearJournal();
  }
  return kept;
}

// fix() for each triangle that misses the target (while it is still there and still misses
// it); the number of fixes kept.
size_t AngleDescent::repair(int depth) {
  struct Bad {
    uint32_t t, a, b, c;
  };
  std::vector<Bad> bad;
  const Triangulation& T = s_.T;
  for (uint32_t t = 0; t < T.triangleSlots(); ++t)
    if (job_.target.misses(s_, t))
      bad.push_back({t, T.tri[3 * t], T.tri[3 * t + 1], T.tri[3 * t + 2]});
  double now = violation();
  size_t kept = 0;
  for (size_t i = 0; i < bad.size(); ++i) {
    const Bad& x = bad[i];
    if (job_.limits->reached(T.vertexCount()) || job_.budget.stop() || movesLeft_ == 0) break;
    (*onProgress_)((double(round_) + double(i) / double(bad.size())) / kDescentRounds);
    const uint32_t* c = &T.tri[3 * x.t];
    if (c[0] != x.a || c[1] != x.b || c[2] != x.c || !job_.target.misses(s_, x.t)) continue;
    kept += fix(x.t, depth, now, now);
  }
  return kept;
}

// Smoothing and flip passes over the mesh, up to kDescentSweeps, until one changes nothing.
void AngleDescent::sweeps() {
  for (int sweep = 0; sweep < kDescentSweeps && !job_.budget.stop(); ++sweep)
    if (smooth() + flipPass() == 0) break;
}

// Where the moves stop paying: every point moved at once (joint_smooth.h), then the sweeps;
// kept if the violation drops by kDescentGain below `least` (which it lowers), else undone.
bool AngleDescent::unstick(double& least) {
  RefineState before = s_;
  smoothJointly(s_, job_, job_.options.maxAngle - kJointRoom, kJointSteps);
  sweeps();
  const double now = violation();
  if (now < least * (1 - kDescentGain)) {
    least = now;
    return true;
  }
  s_ = std::move(before);
  return false;
}

size_t AngleDescent::splitMissed() {
  const Triangulation& T = s_.T;
  std::vector<std::pair<uint32_t, uint32_t>> edges;
  for (uint32_t t = 0; t < T.triangleSlots(); ++t)
    if (job_.target.misses(s_, t))
      for (int k = 0; k < 3; ++k) {
        const uint32_t a = T.tri[3 * t + k], b = T.tri[3 * t + (k + 1) % 3];
        edges.push_back({std::min(a, b), std::max(a, b)});
      }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  size_t split = 0;
  for (const auto& [a, b] : edges) {
    if (job_.limits->reached(T.vertexCount()) || job_.budget.stop()) break;
    uint32_t found = T.findEdge(a, b);
    if (found != kNone && !T.inDomain(found / 3)) found = T.opp[found];  // (its domain side)
    if (found == kNone || !T.inDomain(found / 3)) continue;
    split += apply({Move::Split, found / 3, found, 0, 0});
  }
  return split;
}

bool AngleDescent::run(const std::function<void(double)>& onProgress) {
  onProgress_ = &onProgress;
  round_ = 0;
  double least = INFINITY;
  int depth = 1;
  for (int stale = 0; round_ < kDescentRounds; ++round_) {
    onProgress(double(round_) / kDescentRounds);
    sweeps();
    const double now = violation();
    if (now == 0) return true;
    if (job_.budget.stop() || job_.limits->reached(s_.T.vertexCount())) return false;
    // Look-ahead only once single moves stop gaining, deeper while it finds nothing.
    if (now < least * (1 - kDescentGain)) {
      least = now, stale = 0;
    } else if (++stale >= kDescentStaleRounds) {
      if (!unstick(least)) return false;
      if (least == 0) return true;
      stale = 0;
    } else {
      depth = std::max(depth, 2);
    }
    while (repair(depth) == 0) {
      if (depth < kDescentDepth) {
        ++depth;
      } else {
        if (!unstick(least)) return false;
        if (least == 0) return true;
        break;
      }
    }
  }
  return false;
}

size_t AngleDescent::thin() {
  Triangulation& T = s_.T;
  T.journal = &journal_;
  size_t removed = 0;
  for (uint32_t v = T.vertexCount(); v-- > uint32_t(job_.input.vertexCount());) {
    if (job_.improvementOver() || movesLeft_ == 0) break;
    if (T.vertexEdge[v] == kNone ||
        !(s_.role[v] == kFree || s_.role[v] == kOnSegment || s_.role[v] == kOnHull))
      continue;
    --movesLeft_;
    const Journal::Mark mark = s_.mark();
    if (applySmoothed({Move::Remove, kNone, v, 0, 0}) && violationNearChanges(s_) == 0)
      ++removed;
    else
      s_.undoTo(mark);
    clearJournal();
  }
  T.journal = nullptr;
  return removed;
}

void thinOut(RefineState& s, const Job& job, Insertion& insertion, Boundary& boundary,
             int passes) {
  uint64_t moves = uint64_t(passes) * s.T.vertexCount();  // (one per point a pass: never short)
  AngleDescent descent(s, job, insertion, boundary, moves);
  for (int pass = 0; pass < passes && !job.improvementOver(); ++pass) {
    const size_t steiner = s.liveSteiner(job.input.vertexCount());
    if (double(descent.thin()) < kThinGain * double(steiner)) break;
  }
}

}  // namespace acutemesh::detail
