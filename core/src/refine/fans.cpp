#include "fans.h"

#include <algorithm>

#include "params.h"

namespace acutemesh::detail {
namespace {
constexpr double kTwoPi = 2 * M_PI;
}  // namespace

// The fixed edges at v in counter-clockwise order into spokes_ (empty if v has none), and
// the distance from v to its link.
double CornerFans::readStar(uint32_t v) {
  const Triangulation& T = s_.T;
  spokes_.clear();
  double linkDistance = INFINITY;
  const double* pv = s_.P(v);
  uint32_t e0 = T.vertexEdge[v], e = e0;
  bool badBeforeFirst = false;
  do {
    uint32_t t = e / 3;
    bool inside = T.inDomain(t);
    if (T.isFixed(e)) {
      const double* pu = s_.P(T.tri[next(e)]);
      spokes_.push_back(
          {T.tri[next(e)], portableAtan2(pu[1] - pv[1], pu[0] - pv[0]), inside, false});
    }
    bool bad = inside && job_.target.worstCorner(s_, t).k >= 0;
    (spokes_.empty() ? badBeforeFirst : spokes_.back().sectorBad) |= bad;
    if (!T.isGhost(t)) {
      const double *b = s_.P(T.tri[next(e)]), *c = s_.P(T.tri[prev(e)]);
      double dx = c[0] - b[0], dy = c[1] - b[1];
      double s =
          std::clamp(((pv[0] - b[0]) * dx + (pv[1] - b[1]) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
      double q[2] = {b[0] + s * dx, b[1] + s * dy};
      linkDistance = std::min(linkDistance, std::sqrt(dist2(pv, q)));
    }
    e = T.opp[prev(e)];
  } while (e != e0);
  if (!spokes_.empty()) spokes_.back().sectorBad |= badBeforeFirst;
  return linkDistance;
}

double CornerFans::sectorAngle(size_t i) const {
  if (spokes_.size() == 1) return kTwoPi;
  double a = spokes_[(i + 1) % spokes_.size()].direction - spokes_[i].direction;
  return a <= 0 ? a + kTwoPi : a;
}

// The smallest domain sector between the spokes readStar() found.
double CornerFans::smallestSector() const {
  double smallest = kTwoPi;
  for (size_t i = 0; i < spokes_.size(); ++i)
    if (spokes_[i].sectorInside) smallest = std::min(smallest, sectorAngle(i));
  return smallest;
}

double CornerFans::radiusFor(uint32_t v, bool onlyWhereBad) {
  // Non-obtuse with exact feet builds no fans: small corners are cut at altitude feet instead,
  // right angles the feet make exact, and each fan split of a segment with a thin pocket on
  // its other side costs points there too. (Without exact feet the fans are needed.)
  if (job_.target.feet) return 0;
  if (s_.role[v] != kInput || s_.T.vertexEdge[v] == kNone || s_.fanRadius[v] > 0) return 0;
  double link = readStar(v);
  const double smallSector = job_.target.nonObtuse ? kSmallAngleNonObtuse : kSmallAngle;
  bool small = false;
  for (size_t i = 0; i < spokes_.size(); ++i)
    small |= spokes_[i].sectorInside &&
             (job_.strategy.fansEverywhere ||
              (sectorAngle(i) < smallSector && (spokes_[i].sectorBad || !onlyWhereBad)));
  return small && std::isfinite(link) && link * link > 100 * job_.minEdge2 ? kFanFactor * link : 0;
}

void CornerFans::build(uint32_t v, double r) {
  Triangulation& T = s_.T;
  readStar(v);
  s_.setFanRadius(v, r);
  const double pv[2] = {s_.P(v)[0], s_.P(v)[1]};
  const size_t n = spokes_.size();
  // Split each fixed edge at v that bounds a domain sector at distance r.
  std::vector<uint32_t> shell(n, kNone);
  for (size_t i = 0; i < n; ++i) {
    bool bounds = spokes_[i].sectorInside || spokes_[(i + n - 1) % n].sectorInside;
    uint32_t e = T.findEdge(v, spokes_[i].to);
    if (!bounds || e == kNone) continue;
    const double pu[2] = {s_.P(spokes_[i].to)[0], s_.P(spokes_[i].to)[1]};
    SegmentLine line = job_.line(T.segment.empty() ? kNone : T.segment[e], pv, pu);
    double tv = line.param(pv), tu = line.param(pu);
    double m[2];
    line.at(tv + (tu - tv) * r / std::sqrt(dist2(pv, pu)), m);
    uint32_t sv =
        s_.addVertex(m, T.segment.empty() || T.segment[e] == kNone ? kOnHull : kOnSegment, v);
    if (T.splitFixedEdge(e, sv))
      shell[i] = sv;
    else
      s_.dropLastVertex();
  }
  // Points on the arc of each domain sector, then the chords between consecutive points.
  std::vector<uint32_t>& ring = ring_;
  for (size_t i = 0; i < n; ++i) {
    size_t j = (i + 1) % n;
    if (!spokes_[i].sectorInside || shell[i] == kNone || shell[j] == kNone) continue;
    double angle = sectorAngle(i);
    int pieces = job_.strategy.fansEverywhere
                     ? std::max(1, int(std::nearbyint(angle / kEvenFanAngle)))
                     : int(std::ceil(angle / kFanAngle));
    ring.assign(1, shell[i]);
    for (int k = 1; k < pieces; ++k) {
      double a = spokes_[i].direction + angle * k / pieces;
      double sine, cosine;
      portableSinCos(a, sine, cosine);
      double x[2] = {pv[0] + r * cosine, pv[1] + r * sine};
      uint32_t w = s_.addVertex(x, kArc, v);
      Location loc = T.locate(x, T.vertexEdge[v] / 3);
      if (loc.where == Where::InTriangle && T.inside[loc.tri] && T.insertAt(w, loc) == w) {
        ring.push_back(w);
      } else {
        s_.dropLastVertex();
      }
    }
    ring.push_back(shell[j]);
    for (size_t k = 0; k + 1 < ring.size(); ++k) {
      uint32_t e = T.findEdge(ring[k], ring[k + 1]);
      if (e != kNone && !T.isFixed(e)) T.fixEdge(e, 0);
    }
  }
}

void CornerFans::buildAll() {
  std::vector<FanCentre> centres;
  for (uint32_t v = 0; v < s_.fanRadius.size(); ++v)
    if (double r = radiusFor(v, job_.strategy.lazyFans))
      centres.push_back({v, r, smallestSector(), 0});  // (the star radiusFor read)
  if (job_.strategy.wideFans) widen(centres);
  for (size_t i = 0; i < centres.size(); ++i) {
    // (A cancel or the time limit: the fans built so far stay, the repairs stop at once.)
    if ((i & 63) == 63 && job_.budget.stop()) return;
    build(centres[i].vertex, centres[i].radius);
  }
}

// Wide fans (Strategy::wideFans). Strict acute triangles in a wedge of angle a between two
// segments are at most about as long as the wedge is wide, all but the one isosceles triangle
// of the fan at its tip: past the fan, the wedge is filled with points spaced in a ratio of
// about 1 + a, in the order of ln(R / r) / a of them for a wedge R long and a fan of radius r,
// and the grading spreads into the faces beside it. So each fan grows from kFanFactor to
// kWideFan times the distance from its corner to the link, as far as the fans around it leave
// room (kFanGap), the smallest corners first; a fan at a much wider corner yields (kYield).
void CornerFans::widen(std::vector<FanCentre>& centres) const {
  std::vector<size_t> order(centres.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  // (std::sort with the index as the tie-break, not std::stable_sort, whose temporary buffer
  // trips AddressSanitizer with libstdc++ 12.)
  std::sort(order.begin(), order.end(), [&](size_t i, size_t j) {
    return centres[i].sector != centres[j].sector ? centres[i].sector < centres[j].sector : i < j;
  });
  // The centres by x, so that each looks only at those within reach of its widest fan.
  std::vector<size_t> byX(centres.size());
  for (size_t i = 0; i < byX.size(); ++i) byX[i] = i;
  auto x = [&](size_t i) { return s_.P(centres[i].vertex)[0]; };
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
          visit(centres[*it], settled[*it],
                std::sqrt(dist2(s_.P(c.vertex), s_.P(centres[*it].vertex))));
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

}  // namespace acutemesh::detail
