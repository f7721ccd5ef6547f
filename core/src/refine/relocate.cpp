#include "relocate.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "../rounding.h"

namespace acutemesh::detail {

// The link of free vertex a in ring_, every triangle of its star counted in the domain; false
// if a is no free vertex, or its star has a fixed edge or leaves the domain (relocate() keeps
// such a star's shape).
bool Relocation::freeStar(uint32_t a) {
  const Triangulation& T = s_.T;
  if (s_.role[a] != kFree) return false;
  uint32_t e0 = T.vertexEdge[a], e = e0;
  ring_.clear();
  do {
    if (T.isFixed(e) || !T.inDomain(e / 3)) return false;
    ring_.push_back(T.tri[next(e)]);
    e = T.opp[prev(e)];
  } while (e != e0);
  ringInside_.assign(ring_.size(), 1);
  return true;
}

// The link of vertex a on a segment (or on a point set's hull) in ring_, which of its star's
// triangles are in the domain, and its two fixed edges, the pieces of one segment (spokes);
// false if a is no such vertex, its star holds a ghost, or it has other fixed edges.
bool Relocation::segmentStar(uint32_t a, uint32_t spokes[2]) {
  const Triangulation& T = s_.T;
  if (s_.role[a] != kOnSegment && s_.role[a] != kOnHull) return false;
  uint32_t count = 0, e0 = T.vertexEdge[a], e = e0;
  ring_.clear();
  ringInside_.clear();
  do {
    if (T.isGhost(e / 3)) return false;
    if (T.isFixed(e)) {
      if (count == 2) return false;
      spokes[count++] = e;
    }
    ring_.push_back(T.tri[next(e)]);
    ringInside_.push_back(T.inside[e / 3]);
    e = T.opp[prev(e)];
  } while (e != e0);
  return count == 2 && T.segment[spokes[0]] == T.segment[spokes[1]];
}

// Puts vertex a at (x, y); true if its star (link in ring_) stays a valid triangulation
// (exact) and meets the target there.
bool Relocation::place(uint32_t a, double x, double y) {
  const Target& target = job_.target;
  s_.T.notePoint(a);
  double* where = &s_.T.pts[2 * size_t(a)];
  where[0] = x, where[1] = y;
  // The right angle at a is what most samples fail: tested first (the answer is the same).
  if (target.boundsLargest())
    for (size_t i = 0, n = ring_.size(); i < n; ++i) {
      if (!ringInside_[i]) continue;
      double d = dot2d(where, s_.P(ring_[i]), s_.P(ring_[i + 1 < n ? i + 1 : 0]));
      if (target.tooLarge(d)) return false;
    }
  // No edge shorter than the refinement's smallest (a slide into a stretch a few ulps long
  // left two segment vertices too close for their subsegment to have a direction).
  for (uint32_t w : ring_)
    if (dist2(where, s_.P(w)) < job_.minEdge2) return false;
  for (size_t i = 0, n = ring_.size(); i < n; ++i)
    if (orient2d(s_.P(ring_[i]), s_.P(ring_[i + 1 < n ? i + 1 : 0]), where) <= 0) return false;
  return target.starMeets(s_, a);
}

// The point must lie in the region its link leaves; its centroid and points between it and
// the corners are tried, and the first whose star passes the exact test is kept.
bool Relocation::relocate(uint32_t a) {
  if (!freeStar(a)) return false;
  const Target& target = job_.target;
  region_.edges.clear();
  for (size_t i = 0; i < ring_.size(); ++i)
    region_.edges.push_back({ring_[i], ring_[(i + 1) % ring_.size()]});
  if (!region_.leavesRoom()) return false;
  double old[2] = {s_.P(a)[0], s_.P(a)[1]};
  // Below 90 degrees the bound's wedges first, then the plain slabs: the angle at a is no
  // half-plane, and the wider region's samples find places the narrower one's miss.
  for (bool wedges : {target.strictMax, false}) {
    region_.clip(wedges);
    const std::vector<std::array<double, 2>>& poly = region_.corners();
    double centroid[2];
    if (region_.centroid(centroid) && !(target.boundsLargest() && insideOneDiametralDisk(poly))) {
      if (place(a, centroid[0], centroid[1])) return true;
      for (double w : {0.5, 0.25})
        for (const auto& p : poly)
          if (place(a, centroid[0] + w * (p[0] - centroid[0]),
                    centroid[1] + w * (p[1] - centroid[1])))
            return true;
    }
    if (!wedges) break;
  }
  if (target.nonObtuse && ontoPerpendicular(a, old)) return true;
  place(a, old[0], old[1]);
  return false;
}

// Whether every corner of convex polygon `poly` lies inside the diametral disk of one edge of
// the link in ring_, with a margin: then so does every point relocate() samples in it (convex
// combinations of the corners), and a would make an obtuse angle there, which place() refuses.
// (The test only gives up moves, so whatever rounding does it cannot let a bad one through.)
bool Relocation::insideOneDiametralDisk(const std::vector<std::array<double, 2>>& poly) const {
  const size_t n = ring_.size();
  for (size_t i = 0; i < n; ++i) {
    const double *u = s_.P(ring_[i]), *v = s_.P(ring_[i + 1 < n ? i + 1 : 0]);
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
// degrees, so a must stand exactly on the perpendicular at m: the region's open slabs leave
// no room for that. Tries points of that perpendicular near a's projection on it, whose
// offsets have few bits (so that the point, and the right angles, can come out exact).
bool Relocation::ontoPerpendicular(uint32_t a, const double* old) {
  const size_t n = ring_.size();
  for (size_t i = 0; i < n; ++i) {
    const double *m = s_.P(ring_[i]), *before = s_.P(ring_[(i + n - 1) % n]),
                 *after = s_.P(ring_[(i + 1) % n]);
    if (orient2d(before, m, after) != 0) continue;
    double nx = -(after[1] - m[1]), ny = after[0] - m[0];  // to the left of m->after: a's side
    double s = ((old[0] - m[0]) * nx + (old[1] - m[1]) * ny) / (nx * nx + ny * ny);
    if (!(s > 0)) continue;
    for (int bits : {8, 12, 16, 24}) {
      int e = 0;
      std::frexp(s, &e);
      double t = std::ldexp(std::nearbyint(std::ldexp(s, bits - e)), e - bits);
      if (place(a, m[0] + t * nx, m[1] + t * ny)) return true;
    }
  }
  return false;
}

// Whether x lies within rounding reach of a fixed edge of a's link (as Triangulation::
// splitFixedEdge refuses for a new segment vertex).
bool Relocation::nearFixedLinkEdge(uint32_t a, const double* x) const {
  const Triangulation& T = s_.T;
  uint32_t e0 = T.vertexEdge[a], e = e0;
  do {
    uint32_t link = next(e);
    if (T.isFixed(link) && nearSegment(s_.P(T.tri[link]), s_.P(T.tri[next(link)]), x)) return true;
    e = T.opp[prev(e)];
  } while (e != e0);
  return false;
}

// Positions are taken on the original input segment.
bool Relocation::slide(uint32_t a) {
  uint32_t spokes[2];
  if (!segmentStar(a, spokes)) return false;
  const Triangulation& T = s_.T;
  const double *p = s_.P(T.tri[next(spokes[0])]), *q = s_.P(T.tri[next(spokes[1])]);
  SegmentLine line = job_.line(T.segment[spokes[0]], p, q);
  double tp = line.param(p), tq = line.param(q);
  const double old[2] = {s_.P(a)[0], s_.P(a)[1]};
  auto tryAt = [&](double t) {
    double x[2];
    line.at(t, x);
    return place(a, x[0], x[1]) && !nearFixedLinkEdge(a, x);
  };
  // With Strategy::exactSlide the middle of the longest stretch: it finds narrow ones the
  // samples below miss. (place() before nearFixedLinkEdge: it rejects most positions, and
  // more cheaply.)
  if (job_.strategy.exactSlide && slideStretches(tp, tq, line, 0)) {
    const std::array<double, 2>* longest = &stretches_[0];
    for (const auto& st : stretches_)
      if (st[1] - st[0] > (*longest)[1] - (*longest)[0]) longest = &st;
    if (tryAt(0.5 * ((*longest)[0] + (*longest)[1]))) return true;
  }
  // Only samples within the stretches (widened by a margin for rounding, also the rounding of
  // the point itself) can pass place()'s exact test; the others are not tried (with exact
  // segments each costs exact predicates to put it on the line).
  const double reach =
      std::fabs(line.start[0]) + std::fabs(line.start[1]) + std::fabs(line.ux) + std::fabs(line.uy);
  const double margin = 1e-9 * std::fabs(tq - tp) +
                        8 * std::numeric_limits<double>::epsilon() * reach / std::sqrt(line.u2);
  if (!slideStretches(tp, tq, line, margin)) return false;
  for (int k : {8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14}) {
    double t = tp + (tq - tp) * k / 16.0;
    bool within = false;
    for (const auto& st : stretches_) within |= st[0] < t && t < st[1];
    if (within && tryAt(t)) return true;
  }
  place(a, old[0], old[1]);
  return false;
}

// Where along the segment line (parameter t strictly between tp and tq) a vertex with link
// ring_ keeps every star triangle counter-clockwise, and (acute, non-obtuse) those in the
// domain with right or sharper angles: each triangle (X(t), x, y) asks t to be on one side of
// three values (orientation, the angles at x and y: linear in t) and outside the interval
// where the line crosses the diametral disk of x-y (the angle at X). Leaves the stretches of t
// that are left in stretches_ (open intervals, in increasing order), each bound relaxed by
// margin; false if there are none. (In floating point: place() checks a point exactly.)
bool Relocation::slideStretches(double tp, double tq, const SegmentLine& line, double margin) {
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
      const double bound = -f0 / f1,
                   slack = margin + (e0 + std::fabs(bound) * e1) / (std::fabs(f1) - e1);
      if (f1 > 0)
        lo = std::max(lo, bound - slack);
      else
        hi = std::min(hi, bound + slack);
    } else if (margin > 0 ? f0 < -e0 : !(f0 > 0)) {  // (margin: 0 may be a right angle all along)
      hi = -INFINITY;
    }
  };
  auto dot = [](const double* u, const double* v) { return u[0] * v[0] + u[1] * v[1]; };
  auto mag = [](const double* u, const double* v) {
    return std::fabs(u[0] * v[0]) + std::fabs(u[1] * v[1]);
  };
  std::vector<std::array<double, 2>>& cut = cut_;
  cut.clear();
  for (size_t i = 0; i < ring_.size() && lo < hi; ++i) {
    const double *x = s_.P(ring_[i]), *y = s_.P(ring_[(i + 1) % ring_.size()]);
    double yx[2] = {y[0] - x[0], y[1] - x[1]}, sx[2] = {s[0] - x[0], s[1] - x[1]};
    double sy[2] = {s[0] - y[0], s[1] - y[1]}, xy[2] = {-yx[0], -yx[1]};
    const double yxPerp[2] = {yx[1], -yx[0]};  // X left of x->y: (X - x) . yxPerp < 0
    keep(yx[0] * sx[1] - yx[1] * sx[0], yx[0] * d[1] - yx[1] * d[0], mag(sx, yxPerp),
         mag(d, yxPerp));
    // Outside the domain only the orientation counts; so it does for a minimum angle alone
    // (quality), whose bounds are not taken here.
    if (!ringInside_[i] || !job_.target.boundsLargest()) continue;
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
  std::vector<std::array<double, 2>>& stretches = stretches_;
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

// Otherwise a triangle whose circumcircle now holds a keeps standing, and later insertions
// (whose cavities assume Delaunay) can miss it. Flips only touch edges next to triangles that
// miss the target: two acute triangles always meet at a locally Delaunay edge. Each star
// triangle gives its spoke from a and its link edge (the other spoke is the next triangle's).
void Relocation::legalizeStar(uint32_t a) {
  Triangulation& T = s_.T;
  std::vector<uint32_t>& stack = flips_;
  stack.clear();
  uint32_t e0 = T.vertexEdge[a], e = e0;
  do {
    stack.push_back(e);
    stack.push_back(next(e));
    e = T.opp[prev(e)];
  } while (e != e0);
  T.legalize(stack);
}

// Only where v is on a segment or a foot stands for an exact right angle: the rounds work on
// a mesh that meets the target (each step keeps it so), and each link edge of a free vertex
// is fixed or lies between two triangles of the domain, neither obtuse across it, so locally
// Delaunay already. (A vertex put back after a failed removal may get another star among
// cocircular points and a triangle miss the target until the round's repair pass, which
// legalizes first.)
void Relocation::settle(uint32_t v) {
  if (s_.role[v] == kFree && !job_.target.feet) return;
  legalizeStar(v);
}

bool Relocation::tryMoveTo(uint32_t v, const double* to) {
  const bool onSegment = s_.role[v] == kOnSegment;
  uint32_t spokes[2];
  if (onSegment ? !segmentStar(v, spokes) : !freeStar(v)) return false;
  const double old[2] = {s_.P(v)[0], s_.P(v)[1]};
  if (place(v, to[0], to[1]) && !(onSegment && nearFixedLinkEdge(v, to))) {
    settle(v);
    return true;
  }
  place(v, old[0], old[1]);
  return false;
}

}  // namespace acutemesh::detail
