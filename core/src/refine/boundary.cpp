#include "boundary.h"

#include "exact_feet.h"

namespace acutemesh::detail {

// Next to an input vertex at a power of two from it, otherwise at the midpoint.
double Boundary::shellRatio(uint32_t e) const {
  uint32_t a = s_.T.tri[e], b = s_.T.tri[next(e)];
  if ((s_.role[a] == kInput) == (s_.role[b] == kInput)) return 0.5;
  double len = std::sqrt(dist2(s_.P(a), s_.P(b))), shell = powerOfTwoNear(len / 2);
  return s_.role[a] == kInput ? shell / len : 1 - shell / len;
}

bool Boundary::splitSubsegment(uint32_t e, double preferred, uint32_t footOf) {
  if (s_.isChord(e)) return splitChord(e);
  Triangulation& T = s_.T;
  uint32_t a = T.tri[e], b = T.tri[next(e)];
  // Copies: adding a vertex may move the coordinate array.
  const double pa[2] = {s_.P(a)[0], s_.P(a)[1]}, pb[2] = {s_.P(b)[0], s_.P(b)[1]};
  if (dist2(pa, pb) < 4 * job_.minEdge2) return false;
  double s = splitRatio(e, preferred);
  uint32_t seg = T.segment[e];
  SegmentLine line = job_.line(seg, pa, pb);
  double ta = line.param(pa), tb = line.param(pb);
  // A rounded split point may still miss the edge; next to a sliver triangle that can put it
  // outside the edge's quadrilateral. Other split ratios are tried then, and should the
  // sliver be outside the domain, again once it is flipped away.
  for (int opened = 0; opened <= kOuterSliverFlips; ++opened) {
    if (opened && !openOuterSliver(e)) return false;
    for (double ratio : {s, 0.5, 0.45, 0.55, 0.4, 0.6, 1 / 3.0, 2 / 3.0}) {
      double m[2];
      line.at(ta + ratio * (tb - ta), m);
      if ((m[0] == pa[0] && m[1] == pa[1]) || (m[0] == pb[0] && m[1] == pb[1])) continue;
      uint32_t v = s_.addVertex(m, seg != kNone ? kOnSegment : kOnHull);
      if (T.splitFixedEdge(e, v)) {
        if (ratio == preferred) standForFoot(s_, job_.target, v, footOf, pa);
        return true;
      }
      s_.dropLastVertex();
    }
  }
  return false;
}

// The triangle outside the domain across a boundary edge can be a sliver whose apex lies on
// the edge's line within rounding (a vertex between two collinear segments): a split point
// would have to fall inside it, and there may be no double there. Nothing outside is meshed,
// so the sliver's free edge is flipped instead, giving the edge another apex. False if there
// is none to flip (the hull, fixed edges, a quadrilateral that is not strictly convex).
bool Boundary::openOuterSliver(uint32_t e) {
  Triangulation& T = s_.T;
  const uint32_t f = T.opp[e];
  if (T.inside[f / 3] || T.isGhost(f / 3)) return false;
  for (uint32_t h : {next(f), prev(f)}) {
    const uint32_t g = T.opp[h];
    if (T.isFixed(h) || T.isGhost(g / 3)) continue;
    const double *x = s_.P(T.tri[h]), *y = s_.P(T.tri[next(h)]), *z = s_.P(T.tri[prev(h)]),
                 *w = s_.P(T.tri[prev(g)]);
    if (orient2d(z, x, w) <= 0 || orient2d(w, y, z) <= 0) continue;
    T.flip(h);
    return true;
  }
  return false;
}

// The fan gets one more isosceles triangle.
bool Boundary::splitChord(uint32_t e) {
  Triangulation& T = s_.T;
  uint32_t a = T.tri[e], b = T.tri[next(e)], c = s_.fanCenter[a];
  const double *pa = s_.P(a), *pb = s_.P(b), *pc = s_.P(c);
  if (dist2(pa, pb) < 4 * job_.minEdge2) return false;
  double ra = std::sqrt(dist2(pa, pc)), rb = std::sqrt(dist2(pb, pc));
  double ux = (pa[0] - pc[0]) / ra + (pb[0] - pc[0]) / rb,
         uy = (pa[1] - pc[1]) / ra + (pb[1] - pc[1]) / rb;
  double scale = s_.fanRadius[c] / std::sqrt(ux * ux + uy * uy);
  double m[2] = {pc[0] + ux * scale, pc[1] + uy * scale};
  if (!std::isfinite(m[0]) || !std::isfinite(m[1])) return false;
  uint32_t v = s_.addVertex(m, kArc, c);
  if (T.splitFixedEdge(e, v)) return true;
  // The arc point lies beyond the triangle on the chord's outer side (a thin one). Insert it
  // where it lies if no segment is in between, free the chord to flip towards it, and fix
  // the chords that are there afterwards.
  uint32_t outer = T.tri[prev(e)] == c ? T.opp[e] / 3 : e / 3, reached = kNone;
  Location loc;
  if (firstFixedCrossed(T, outer, m, reached) == kNone && reached != kNone && T.inDomain(reached))
    loc = T.locate(m, reached);
  bool placed =
      (loc.where == Where::InTriangle || (loc.where == Where::OnEdge && !T.isFixed(loc.edge))) &&
      T.insertAt(v, loc) == v;
  if (!placed) {
    s_.dropLastVertex();
    return false;
  }
  if (uint32_t ab = T.findEdge(a, b); ab != kNone) {
    T.unfixEdge(ab);
    flips_.assign({ab, T.opp[ab]});
    T.legalize(flips_);
  }
  for (auto [x, y] : {std::pair{a, v}, std::pair{v, b}, std::pair{a, b}}) {
    uint32_t f = T.findEdge(x, y);
    if (f != kNone && !T.isFixed(f)) T.fixEdge(f, 0);
  }
  return true;
}

// An obtuse corner there leaves two right triangles (non-obtuse) with one point.
bool Boundary::splitAtFoot(uint32_t t, int k) {
  const Triangulation& T = s_.T;
  uint32_t opposite = 3 * t + uint32_t((k + 1) % 3);
  const double *pc = s_.P(T.tri[3 * t + k]), *pa = s_.P(T.tri[opposite]),
               *pb = s_.P(T.tri[next(opposite)]);
  double ux = pb[0] - pa[0], uy = pb[1] - pa[1];
  double s = ((pc[0] - pa[0]) * ux + (pc[1] - pa[1]) * uy) / (ux * ux + uy * uy);
  return splitSubsegment(opposite, s, T.tri[3 * t + k]);
}

// Of the usual place (shell or midpoint; with Strategy::footOnSegments the foot of the
// altitude), the foot of the altitude from apex and the tenths of the subsegment, the one
// that leaves the fewest bad triangles (ties to the earlier).
bool Boundary::splitWeighed(uint32_t e, uint32_t apex) {
  const Triangulation& T = s_.T;
  const double *pa = s_.P(T.tri[e]), *pb = s_.P(T.tri[next(e)]), *pc = s_.P(apex);
  double ux = pb[0] - pa[0], uy = pb[1] - pa[1];
  double foot = ((pc[0] - pa[0]) * ux + (pc[1] - pa[1]) * uy) / (ux * ux + uy * uy);
  double usual = job_.target.nonObtuse && job_.strategy.footOnSegments ? foot : -1;
  SegmentLine line = job_.line(T.segment[e], pa, pb);
  double ta = line.param(pa), tb = line.param(pb);
  double best = usual;
  int fewest = INT32_MAX;
  const double ratios[] = {usual, foot, 0.5, 0.4, 0.6, 0.3, 0.7, 0.2, 0.8, 0.1, 0.9};
  for (size_t i = 0; i < std::size(ratios); ++i) {
    double r = ratios[i];
    if (i > 0 && (r == usual || !(r > 0.05 && r < 0.95))) continue;
    double m[2];
    line.at(ta + splitRatio(e, r) * (tb - ta), m);  // where splitSubsegment(e, r) splits
    int change = cavity_.splitChange(e, m, r == foot ? apex : kNone);
    if (change < fewest) fewest = change, best = r;
  }
  return splitSubsegment(e, best, best == foot ? apex : kNone);
}

// Done before the corner fans, it settles most slivers between segments with one point each,
// and the fans go only where that is not enough.
void Boundary::cutAtFeet() {
  const Triangulation& T = s_.T;
  for (int pass = 0; pass < kCutAtFeetPasses; ++pass) {
    bool changed = false;
    for (uint32_t t = 0; t < T.triangleSlots(); ++t) {
      if (!T.inDomain(t)) continue;
      Corner c = job_.target.worstCorner(s_, t);
      uint32_t opposite = 3 * t + uint32_t((c.k + 1) % 3);
      if (c.k < 0 || !c.large || !T.isFixed(opposite)) continue;
      changed |= splitAtFoot(t, c.k);
      if (job_.limits->reached(T.vertexCount())) return;
    }
    if (!changed) break;
  }
}

}  // namespace acutemesh::detail
