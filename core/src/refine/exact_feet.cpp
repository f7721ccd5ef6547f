#include "exact_feet.h"

#include <algorithm>

#include "../exact.h"

namespace acutemesh::detail {
namespace {

// The ends of the input segment through segment vertex f, whose fixed edge `spoke` leaves f;
// on a point set's hull (no input segment) the input vertices the hull edge runs between,
// found by following the fixed edges from f both ways.
void segmentEnds(const RefineState& s, const Job& job, uint32_t f, uint32_t spoke, const double*& a,
                 const double*& b) {
  const Triangulation& T = s.T;
  const uint32_t seg = T.segment.empty() ? kNone : T.segment[spoke];
  if (seg != kNone) {
    const SegmentLine line = job.line(seg, s.P(f), s.P(f));
    a = line.start, b = line.end;
    return;
  }
  // The next vertex along the fixed edges from `from`, coming from `before`.
  auto along = [&](uint32_t from, uint32_t before) {
    uint32_t e0 = T.vertexEdge[from], e = e0;
    do {
      uint32_t to = T.tri[next(e)];
      if (T.isFixed(e) && to != kGhost && to != before) return to;
      e = T.opp[prev(e)];
    } while (e != e0);
    return kNone;
  };
  const double* ends[2] = {nullptr, nullptr};
  uint32_t first = T.tri[next(spoke)];
  for (int side = 0; side < 2; ++side) {
    uint32_t before = f, at = side == 0 ? first : along(f, first);
    for (uint32_t steps = 0; at != kNone && s.role[at] != kInput && steps < T.vertexCount();
         ++steps) {
      uint32_t after = along(at, before);
      before = at, at = after;
    }
    ends[side] = at == kNone || s.role[at] != kInput ? s.P(f) : s.P(at);
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

}  // namespace

bool placeExactFeet(const RefineState& s, const Job& job, std::vector<ExactVertex>& exact) {
  exact.clear();
  if (!job.target.feet) return true;
  const Triangulation& T = s.T;
  std::vector<uint32_t> spokeOf(T.vertexCount(), kNone);  // a piece of its segment
  for (uint32_t t = 0; t < T.triangleSlots(); ++t) {
    if (!T.inDomain(t)) continue;
    const int mask = job.target.footCorners(s, t);
    const uint32_t* v = &T.tri[3 * t];
    for (uint32_t k = 0; k < 3; ++k) {
      const double *a = s.P(v[k]), *b = s.P(v[(k + 1) % 3]), *c = s.P(v[(k + 2) % 3]);
      if ((mask >> k & 1) && std::fabs(dot2d(a, b, c)) <= footSlack(a, b, c))
        spokeOf[v[k]] = s.isSubsegment(3 * t + k) ? 3 * t + k : 3 * t + (k + 2) % 3;
    }
  }
  // A foot's vertex may be a foot itself: its exact place first (around a cycle, the place
  // it has).
  std::vector<uint8_t> state(T.vertexCount(), 0);  // 1: being placed, 2: placed
  std::vector<RationalPoint> at(T.vertexCount());
  std::vector<uint32_t> stack;
  for (uint32_t f = 0; f < T.vertexCount(); ++f) {
    if (spokeOf[f] == kNone || state[f]) continue;
    stack.assign(1, f);
    while (!stack.empty()) {
      const uint32_t g = stack.back(), partner = s.footOf[g];
      if (state[g] == 0 && spokeOf[partner] != kNone && state[partner] == 0) {
        state[g] = 1;
        stack.push_back(partner);
        continue;
      }
      const double *a, *b;
      segmentEnds(s, job, g, spokeOf[g], a, b);
      at[g] = exactFoot(state[partner] == 2 ? at[partner] : exactPoint(s.P(partner)), a, b);
      state[g] = 2;
      stack.pop_back();
    }
  }
  for (uint32_t f = 0; f < T.vertexCount(); ++f)
    if (spokeOf[f] != kNone) exact.push_back({f, at[f]});
  return feetKeepTarget(T, exact);
}

}  // namespace acutemesh::detail
