#include "repair.h"

#include <algorithm>

#include "slice.h"

namespace acutemesh::detail {

bool Repair::repair(uint32_t t, Corner c, size_t weighed) {
  Triangulation& T = s_.T;
  const Target& target = job_.target;
  const Strategy& strategy = job_.strategy;
  // Moving vertices (relocation, the removal pass) can leave edges that are not locally
  // Delaunay; a triangle standing on one is flipped away first, since the search for a new
  // point below assumes empty circumcircles.
  flips_.assign({3 * t, 3 * t + 1, 3 * t + 2});
  size_t before = touched_.size();
  T.legalize(flips_);
  if (touched_.size() > before) return true;
  if (strategy.lazyFans && target.boundsLargest()) {
    for (int k = 0; k < 3; ++k) {
      uint32_t v = T.tri[3 * t + k];
      if (v >= s_.fanRadius.size()) continue;
      if (double r = fans_.radiusFor(v, true)) {
        fans_.build(v, r);
        return true;
      }
    }
  }
  if (!c.area) {
    for (int k = 0; k < 3; ++k) {
      uint32_t a = T.tri[3 * t + k];
      if (relocation_.move(a)) {
        uint32_t e0 = T.vertexEdge[a], e = e0;
        do {
          touched_.push_back(e / 3);
          for (uint32_t f = 3 * (e / 3); f < 3 * (e / 3) + 3; ++f) touched_.push_back(T.opp[f] / 3);
          e = T.opp[prev(e)];
        } while (e != e0);
        relocation_.legalizeStar(a);
        return true;
      }
    }
  }
  if (c.large) {
    // The edge opposite the large angle: if it is a subsegment, the apex encroaches it.
    uint32_t opposite = 3 * t + uint32_t((c.k + 1) % 3);
    if (strategy.weighPoints && T.isFixed(opposite) && !s_.isChord(opposite))
      return boundary_.splitWeighed(opposite, T.tri[3 * t + c.k]);
    if (target.nonObtuse && strategy.footOnSegments && T.isFixed(opposite))
      return boundary_.splitAtFoot(t, c.k);
    if (T.isFixed(opposite)) return boundary_.splitSubsegment(opposite);
    // The farthest point of the slice; but one that encroaches a subsegment would split it,
    // and next to a sliver each split starts a chain of feet across it: a point of the slice
    // that encroaches nothing goes first, if there is one, and of those the one that leaves
    // the fewest bad triangles. (Unless repairAll has just weighed t's candidates for its
    // gain, and nothing above has changed the mesh: the same candidates, the same choice.)
    if (weighed != kNotWeighed && strategy.weighPoints)
      return insertion_.insertWeighed(t, candidates_, weighed);
    slicePoints(s_, t, strategy.weighPoints, candidates_);
    return insertion_.insertSparingSegments(t, candidates_, true);
  }
  if (!c.area) {
    // (Left for the stats to count, unless it is too big as well: sizes have a floor, so their
    // splits end. Not in below90's quality starts, tuned without it.)
    if (target.qualityCounts && acrossSmallInputAngle(t)) {
      if (!target.tooBig(s_, t)) return false;
    } else {
      qualityPoints(s_, t, target.cosQuality, candidates_);
      return insertion_.insertSparingSegments(t, candidates_, false);
    }
  }
  const uint32_t* v = &T.tri[3 * t];
  double x[2];
  circumcenter(s_.P(v[0]), s_.P(v[1]), s_.P(v[2]), x);
  return insertion_.insertSteiner(t, x);
}

namespace {
// The input segment a Steiner vertex on a segment lies on, else kNone.
uint32_t segmentOf(const RefineState& s, uint32_t v) {
  if (s.role[v] != kOnSegment || !s.T.trackSegments) return kNone;
  const Triangulation& T = s.T;
  uint32_t e0 = T.vertexEdge[v], e = e0;
  do {
    if (T.isFixed(e)) return T.segment[e];
    e = T.opp[prev(e)];
  } while (e != e0);
  return kNone;
}
}  // namespace

// Small input angles (Shewchuk's rule for them): a skinny triangle whose shortest edge joins
// two segments that meet at an input vertex at less than the minimum angle is left as it is.
// Splitting it puts points between the two segments, whose splits then call for more points
// closer to the corner, without end; no mesh has every angle there at the minimum anyway.
bool Repair::acrossSmallInputAngle(uint32_t t) const {
  const Triangulation& T = s_.T;
  int shortest = 0;
  double least = INFINITY;
  for (int k = 0; k < 3; ++k) {
    const double d = dist2(s_.P(T.tri[3 * t + k]), s_.P(T.tri[3 * t + (k + 1) % 3]));
    if (d < least) least = d, shortest = k;
  }
  const uint32_t p = T.tri[3 * t + shortest], q = T.tri[3 * t + (shortest + 1) % 3];
  const uint32_t sp = segmentOf(s_, p), sq = segmentOf(s_, q);
  if (sp == kNone || sq == kNone || sp == sq) return false;
  const Pslg& in = job_.input;
  const uint32_t a0 = in.segments[2 * size_t(sp)], a1 = in.segments[2 * size_t(sp) + 1];
  const uint32_t b0 = in.segments[2 * size_t(sq)], b1 = in.segments[2 * size_t(sq) + 1];
  // (Ends compared by place: a duplicate input vertex, merged in the mesh, is another index.)
  auto same = [&](uint32_t i, uint32_t j) {
    return in.points[2 * size_t(i)] == in.points[2 * size_t(j)] &&
           in.points[2 * size_t(i) + 1] == in.points[2 * size_t(j) + 1];
  };
  const uint32_t apex = same(a0, b0) || same(a0, b1) ? a0 : same(a1, b0) || same(a1, b1) ? a1 : kNone;
  if (apex == kNone) return false;
  const double* a = &in.points[2 * size_t(apex)];
  const double* u = &in.points[2 * size_t(apex == a0 ? a1 : a0)];
  const double* w = &in.points[2 * size_t(same(apex, b0) ? b1 : b0)];
  const double ux = u[0] - a[0], uy = u[1] - a[1], wx = w[0] - a[0], wy = w[1] - a[1];
  const double lengths = std::sqrt((ux * ux + uy * uy) * (wx * wx + wy * wy));
  if (!(ux * wx + uy * wy > job_.target.cosMin * lengths)) return false;
  // And t lies in that narrow wedge (not around the corner, where the angle is wide).
  const uint32_t* v = &T.tri[3 * t];
  const double c[2] = {(s_.P(v[0])[0] + s_.P(v[1])[0] + s_.P(v[2])[0]) / 3 - a[0],
                       (s_.P(v[0])[1] + s_.P(v[1])[1] + s_.P(v[2])[1]) / 3 - a[1]};
  const double turn = ux * wy - uy * wx;
  return (ux * c[1] - uy * c[0]) * turn > 0 && (c[0] * wy - c[1] * wx) * turn > 0;
}

bool Repair::missesBeyondLeft() const {
  const Target& target = job_.target;
  for (uint32_t t = 0; t < s_.T.triangleSlots(); ++t) {
    if (!s_.T.inDomain(t)) continue;
    const Corner c = target.worstCorner(s_, t);
    if (c.k < 0) continue;
    if (c.large || c.area || !target.qualityCounts || !acrossSmallInputAngle(t) ||
        target.tooBig(s_, t))
      return true;
  }
  return false;
}

// The gain of repairing t (whose worst corner is c) for the FewestBadFirst order: the bad
// triangles the best of its slice's points that spares the segments would take away, less
// those it would make, at least -1 (also where no point counts); 1 for a subsegment split and
// for a small angle (boundary and quality repairs settle their triangle). `weighed`, if
// given, gets the candidate chosen.
int Repair::repairGain(uint32_t t, Corner c, size_t* weighed) {
  if (!c.large || s_.T.isFixed(3 * t + uint32_t((c.k + 1) % 3))) return 1;
  slicePoints(s_, t, job_.strategy.weighPoints, candidates_);
  int fewest = 0;
  const size_t chosen = insertion_.weigh(t, candidates_, fewest);
  if (weighed) *weighed = chosen;
  if (chosen == candidates_.size()) return -1;
  return -std::min(fewest, 1);
}

// Entries are re-checked when popped (a triangle may have changed); in the fewest-bad-first
// order an entry whose gain has dropped since (its neighbours changed) goes back with its new
// gain.
StepResult Repair::repairAll() {
  Triangulation& T = s_.T;
  const Target& target = job_.target;
  RepairQueue& queue = queue_;
  using Order = RepairQueue::Order;
  const bool byGain = job_.strategy.fewestBadFirst && target.boundsLargest() && !target.sized();
  const bool skinniest = target.countsPoints() && !target.boundsLargest();
  queue.reset(target.sized() ? Order::FactorsOfTwo
              : byGain       ? Order::FewestBadFirst
              : skinniest    ? Order::SkinniestFirst
                             : Order::Largest);
  auto key = [&](uint32_t t) { return skinniest ? smallestAngleCos(T, t) : shortestEdge2(T, t); };
  auto push = [&](uint32_t t) {
    if (!T.inDomain(t)) return;
    Corner c = target.worstCorner(s_, t);
    if (c.k >= 0) queue.push({byGain ? repairGain(t, c) : 0, key(t), t});
  };
  const auto stopped = [&]() -> StepResult {
    const bool cancelled = job_.budget.cancelled();
    return {cancelled ? Status::Cancelled : Status::TargetNotMet,
            std::string(cancelled ? "cancelled" : "time limit reached") +
                " before every triangle met the target"};
  };
  // Progress: the first queue's share (weighing every bad triangle's repair takes a while),
  // then the share of the entries popped among those popped and still queued.
  ProgressRelay* relay = job_.progressRelay();
  const double pushed = byGain ? kWeighedQueueShare : 0;
  for (uint32_t t = 0, slots = T.triangleSlots(); t < slots; ++t) {
    if ((t & 255) == 0) {
      if (relay) relay->note("refine", pushed * t / slots, T.vertexCount());
      if (job_.budget.stop()) return stopped();
    }
    push(t);
  }
  uint32_t steps = 0;
  RepairQueue::Entry entry;
  while (queue.pop(entry)) {
    if ((++steps & 255) == 0) {
      if (relay)
        relay->note("refine", pushed + (1 - pushed) * steps / double(steps + queue.size()),
                    T.vertexCount());
      if (job_.budget.stop()) return stopped();
    }
    if (job_.limits->reached(T.vertexCount()))
      return {Status::TargetNotMet,
              "Steiner point budget used up before every triangle met "
              "the target"};
    const uint32_t t = entry.t;
    if (!T.inDomain(t) || key(t) != entry.size) continue;
    Corner c = target.worstCorner(s_, t);
    if (c.k < 0) continue;
    size_t weighed = kNotWeighed;
    if (byGain) {
      int gain = repairGain(t, c, &weighed);
      if (gain < entry.gain) {
        queue.push({gain, entry.size, t});
        continue;
      }
    }
    touched_.clear();
    T.touched = &touched_;
    bool changed = repair(t, c, weighed);
    T.touched = nullptr;
    if (!changed) continue;  // left for the certificate to count
    std::sort(touched_.begin(), touched_.end());
    touched_.erase(std::unique(touched_.begin(), touched_.end()), touched_.end());
    for (uint32_t u : touched_) push(u);
    push(t);
  }
  return {};
}

}  // namespace acutemesh::detail
