#include "insertion.h"

#include <algorithm>

namespace acutemesh::detail {

bool Insertion::insertSteiner(uint32_t from, const double* x) {
  if (!std::isfinite(x[0]) || !std::isfinite(x[1])) return false;
  return insertSteiner(from, x, cavity_.examine(from, x));
}

bool Insertion::insertSteiner(uint32_t from, const double* x, Cavity::Rim rim) {
  Triangulation& T = s_.T;
  auto [encroached, beyond] = rim;
  if (encroached != kNone) return boundary_.splitSubsegment(encroached);
  Location loc = T.locate(x, from);
  if (loc.where == Where::Failed || loc.where == Where::OnVertex) return false;
  const std::vector<uint32_t>& cavity = cavity_.triangles();
  bool reachable = std::find(cavity.begin(), cavity.end(), loc.tri) != cavity.end();
  if (!reachable || !T.inDomain(loc.tri)) {
    if (beyond != kNone) return boundary_.splitSubsegment(beyond);
    // Relocation leaves the triangulation not quite Delaunay in places, and the cavity can
    // then miss x: the straight walk from `from` to x decides instead.
    uint32_t reached = kNone, crossed = firstFixedCrossed(T, from, x, reached);
    if (crossed != kNone) return boundary_.splitSubsegment(crossed);
    if (reached == kNone || !T.inDomain(reached)) return false;
  }
  if (loc.where == Where::OnEdge && T.isFixed(loc.edge)) return boundary_.splitSubsegment(loc.edge);
  for (uint32_t k = 0; k < 3; ++k)
    if (dist2(x, s_.P(T.tri[3 * loc.tri + k])) < job_.minEdge2) return false;
  uint32_t v = s_.addVertex(x, kFree);
  if (T.insertAt(v, loc) != v) {
    s_.dropLastVertex();
    return false;
  }
  return true;
}

// (Quality refinement keeps the first that spares the segments: counting bad triangles there
// made more points.)
bool Insertion::insertSparingSegments(uint32_t t, const Candidates& points, bool fewestBad) {
  const bool weighPoints = job_.strategy.weighPoints;
  if (fewestBad && weighPoints) {
    int fewest = 0;
    return insertWeighed(t, points, weigh(t, points, fewest));
  } else {
    for (size_t i = 0; weighPoints && i < points.size() && i < kSliceTries; ++i) {
      const double* x = points[i].data();
      if (!std::isfinite(x[0]) || !std::isfinite(x[1])) continue;
      Cavity::Rim rim = cavity_.examine(t, x);
      if (rim.encroached == kNone && insertSteiner(t, x, rim)) return true;
    }
  }
  return insertSteiner(t, points[0].data());
}

bool Insertion::insertWeighed(uint32_t t, const Candidates& points, size_t chosen) {
  if (chosen < points.size() && insertSteiner(t, points[chosen].data())) return true;
  return insertSteiner(t, points[0].data());
}

size_t Insertion::weigh(uint32_t t, const Candidates& points, int& fewest) {
  size_t chosen = points.size();
  fewest = 0;
  for (size_t i = 0; i < points.size() && i < kSliceTries; ++i) {
    const double* x = points[i].data();
    if (!std::isfinite(x[0]) || !std::isfinite(x[1])) continue;
    Cavity::Rim rim = cavity_.examine(t, x);
    if (rim.encroached != kNone || rim.beyond != kNone || cavity_.tooLarge()) continue;
    int change = cavity_.badChange(x);
    if (chosen == points.size() || change < fewest) chosen = i, fewest = change;
  }
  return chosen;
}

}  // namespace acutemesh::detail
