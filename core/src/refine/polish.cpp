#include "polish.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>

#include "refiner.h"
#include "threads.h"

namespace acutemesh::detail {

namespace {
// Progress within a round: where each of its steps ends, as a share of the round's time
// (measured on country outlines of 10^4 to 10^5 vertices, where a round takes seconds).
constexpr double kRoundSteps[] = {0.05, 0.1, 0.35, 0.4, 1};            // round(false)
constexpr double kLargerRoundSteps[] = {0.07, 0.27, 0.33, 0.79, 0.84, 1};  // round(true)
constexpr double kCallersHalf = 0.75, kReplayed = 0.83, kAlongRemoved = 0.86;  // in halves
}  // namespace

void Polish::run() {
  const Target& target = job_.target;
  if (!target.countsPoints() || repair_.missesBeyondLeft()) return;
  const size_t inputVertices = job_.input.vertexCount();
  s_.compactTriangles(inputVertices);
  int idleRounds = 0;  // the last rounds in a row that took out no point
  for (int r = 0; r < kPolishRounds && !job_.improvementOver(); ++r) {
    // (Progress: each round half of what is left, as the rounds that end it are not known.)
    const ProgressRelay::Part part(job_.reportsProgress() ? job_.budget.progress() : nullptr,
                                   1 - std::ldexp(1.0, -r), 1 - std::ldexp(1.0, -r - 1));
    size_t before = s_.liveSteiner(inputVertices);
    s_.T.trimToSlots();  // (the other half's copy without the spare tail)
    RefineState::Compact saved = s_.compact();
    if (before >= kSmallPolish)
      roundInHalves(r);
    else
      round(false);
    StepResult result = repair_.repairAll();
    size_t after = s_.liveSteiner(inputVertices);
    // A round the budget cut short keeps what it took out where every triangle still meets
    // the target (the repairs it skipped were not needed): the run returns its best mesh.
    if (repair_.missesBeyondLeft() || after > before) {
      s_.restore(std::move(saved));
      return;
    }
    if (!result.ok()) return;
    idleRounds = after == before ? idleRounds + 1 : 0;
    const bool small = after < kSmallPolish;
    if (small && target.nonObtuse) continue;  // all the rounds: they are cheap there
    const double gain = before >= kLargeRoundFrom   ? kLargeGain
                        : before >= kHalvesGainFrom ? kHalvesGain
                                                    : kPolishGain;
    if (small ? idleRounds == 2 : double(before - after) < gain * double(before)) return;
  }
}

void Polish::search(double seconds, uint64_t tries, uint64_t seed,
                    const std::function<void()>& thin) {
  const Target& target = job_.target;
  if (!target.countsPoints() || repair_.missesBeyondLeft()) return;
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  ProgressRelay* relay = job_.progressRelay();
  const size_t inputVertices = job_.input.vertexCount();
  // (A try on a large mesh takes seconds: its rounds stop when the seconds end, too.)
  const double polishUntil = job_.limits->polishUntil;
  if (seconds > 0) job_.limits->polishUntil = job_.budget.elapsed() + seconds;
  RefineState best = s_;
  size_t fewest = s_.liveSteiner(inputVertices);
  uint64_t x = (seed + 1) * 0x9E3779B97F4A7C15ull;  // xorshift64: the same tries everywhere
  auto random = [&] {
    x ^= x << 13, x ^= x >> 7, x ^= x << 17;
    return double(x >> 11) * 0x1p-53;
  };
  std::vector<uint32_t> ring, steiner;
  auto ringOf = [&](uint32_t v) {
    ring.clear();
    uint32_t e0 = s_.T.vertexEdge[v], e = e0;
    do {
      ring.push_back(s_.T.tri[next(e)]);
      e = s_.T.opp[prev(e)];
    } while (e != e0);
  };
  // Kick: some free points part of the way to a neighbour, where their stars still meet the
  // target.
  auto kick = [&] {
    for (uint32_t v = uint32_t(inputVertices); v < s_.T.vertexCount(); ++v) {
      if (s_.T.vertexEdge[v] == kNone || s_.role[v] != kFree || random() >= kSearchKick) continue;
      ringOf(v);
      const uint32_t w = ring[std::min(ring.size() - 1, size_t(random() * double(ring.size())))];
      if (w == kGhost) continue;
      const double f = kSearchStep[0] + (kSearchStep[1] - kSearchStep[0]) * random();
      const double *p = s_.P(v), *q = s_.P(w);
      const double to[2] = {p[0] + f * (q[0] - p[0]), p[1] + f * (q[1] - p[1])};
      relocation_.tryMoveTo(v, to);
    }
  };
  // Ruin and recreate: some Steiner points out (free ones, and points on segments, whose
  // pieces join again) with some of their neighbours, whatever that breaks, and refinement
  // mends the holes (a temporary loss the rounds may win back).
  auto ruinable = [&](uint32_t v) {
    return v >= inputVertices && s_.T.vertexEdge[v] != kNone &&
           (s_.role[v] == kFree || s_.role[v] == kOnSegment);
  };
  auto takeOut = [&](uint32_t v) {
    uint32_t ends[2];
    if (s_.role[v] == kFree)
      s_.T.removeVertex(v);
    else
      s_.T.removeFromSegment(v, ends);
  };
  auto ruin = [&] {
    steiner.clear();
    for (uint32_t v = uint32_t(inputVertices); v < s_.T.vertexCount(); ++v)
      if (ruinable(v)) steiner.push_back(v);
    const size_t centres = std::max<size_t>(1, size_t(kRuinShare * double(steiner.size())));
    for (size_t i = 0; i < centres && !steiner.empty(); ++i) {
      const uint32_t v = steiner[std::min(steiner.size() - 1, size_t(random() * double(steiner.size())))];
      if (!ruinable(v)) continue;
      ringOf(v);
      takeOut(v);
      for (uint32_t w : ring)
        if (w != kGhost && ruinable(w) && random() < kRuinNeighbour) takeOut(w);
    }
    repair_.repairAll();
  };
  for (uint64_t done = 0; (seconds <= 0 || elapsed() < seconds) && (tries == 0 || done < tries) &&
                          !job_.budget.stop();
       ++done) {
    if (relay) {
      const double share = std::max(seconds > 0 ? elapsed() / seconds : 0,
                                    tries > 0 ? double(done) / double(tries) : 0);
      relay->note("improve", share, s_.T.vertexCount());
    }
    if (random() < kSearchRuin)
      ruin();
    else
      kick();
    bool met = true;
    for (int r = 0; r < kSearchRounds && met; ++r) {
      round(false);
      met = repair_.repairAll().ok() && !repair_.missesBeyondLeft();
    }
    if (met && thin) thin();
    const size_t count = s_.liveSteiner(inputVertices);
    if (met && count < fewest) {
      best = s_, fewest = count;
    } else if (!met || count > fewest) {
      s_ = best;
    }
  }
  s_ = std::move(best);
  job_.limits->polishUntil = polishUntil;
}

// Smoothing makes the room removals and merges need: a sweep before each removal and merge
// step. Small meshes: two sweeps before the removals (a sweep moves each vertex against its
// neighbours' old places, the second settles most of that), and two merge passes. Larger ones
// (removeAfterMerging; the rounds in halves): one merge pass, then the removals again, as a
// merge changes the stars around it and removals, several times cheaper a success than
// merges, find more there.
void Polish::round(bool removeAfterMerging) {
  size_t step = 0;
  auto part = [&](const double* ends) {
    const double from = step ? ends[step - 1] : 0, to = ends[step];
    ++step;
    return ProgressRelay::Part(job_.progressRelay(), from, to);
  };
  if (!removeAfterMerging) {
    { const auto p = part(kRoundSteps); smooth(); }
    { const auto p = part(kRoundSteps); smooth(); }
    { const auto p = part(kRoundSteps); reduce_.removeSteinerPoints(); }
    { const auto p = part(kRoundSteps); smooth(); }
    { const auto p = part(kRoundSteps); reduce_.mergeSteinerPoints(nullptr, 2); }
    return;
  }
  { const auto p = part(kLargerRoundSteps); smooth(); }
  { const auto p = part(kLargerRoundSteps); reduce_.removeSteinerPoints(); }
  { const auto p = part(kLargerRoundSteps); smooth(); }
  { const auto p = part(kLargerRoundSteps); reduce_.mergeSteinerPoints(); }
  { const auto p = part(kLargerRoundSteps); smooth(); }
  { const auto p = part(kLargerRoundSteps); reduce_.removeSteinerPoints(); }
}

// Moves every free vertex to the middle of the room its link leaves, and every segment vertex
// along its segment likewise: points with room to spare let more of their neighbours go in
// the next removal pass.
void Polish::smooth() {
  const Scope& scope = reduce_.scope;
  ProgressRelay* relay = job_.progressRelay();
  const uint32_t count = s_.T.vertexCount();
  s_.visitOrder(uint32_t(job_.input.vertexCount()), count, order_);
  for (size_t i = 0; i < order_.size(); ++i) {
    if ((i & 255) == 0 && relay) {
      relay->note("improve", double(i) / double(order_.size()), count);
      relay->poll();
    }
    const uint32_t v = order_[i];
    if (s_.T.vertexEdge[v] == kNone || (s_.role[v] != kFree && s_.role[v] != kOnSegment) ||
        !scope.owns(v))
      continue;
    if (relocation_.move(v)) {
      relocation_.settle(v);
      scope.record({Step::Move, v, kNone, kNone, s_.P(v)[0], s_.P(v)[1]});
    }
  }
}

// The Steiner vertices on either side of their median x (y in odd rounds), those with a
// neighbour across it excepted, are smoothed, removed and merged as in a round of their own,
// one half here and the other on a copy of the state, on a second thread where there is one
// (the same steps either way). The copy's steps are then made again here in order (replay),
// each checked anew, and the vertices along the middle, with the points the merges made, get
// one removal and one merge pass.
void Polish::roundInHalves(int r) {
  const int axis = r % 2;
  const Triangulation& T = s_.T;
  const uint32_t n = T.vertexCount();
  std::vector<double> at;
  for (uint32_t v = uint32_t(job_.input.vertexCount()); v < n; ++v)
    if (T.vertexEdge[v] != kNone && (s_.role[v] == kFree || s_.role[v] == kOnSegment))
      at.push_back(s_.P(v)[axis]);
  if (at.empty()) return;
  std::nth_element(at.begin(), at.begin() + at.size() / 2, at.end());
  const double middle = at[at.size() / 2];
  std::vector<uint8_t> mine[2] = {std::vector<uint8_t>(n, 0), std::vector<uint8_t>(n, 0)};
  std::vector<uint8_t> along(n, 0);  // the vertices with a neighbour across the middle
  for (uint32_t v = 0; v < n; ++v) {
    if (T.vertexEdge[v] == kNone) continue;
    const bool second = s_.P(v)[axis] >= middle;
    bool across = false;
    uint32_t e0 = T.vertexEdge[v], e = e0;
    do {
      uint32_t w = T.tri[next(e)];
      across |= w != kGhost && (s_.P(w)[axis] >= middle) != second;
      e = T.opp[prev(e)];
    } while (e != e0);
    mine[second][v] = !across;
    along[v] = across;
  }
  bool helperThread = false;
#ifdef ACUTEMESH_THREADS
  helperThread = threadsFor(job_.options) > 1;
#endif
  RefineState copy = s_;
  RunLimits quiet;  // (its limit is never asked: a round makes no repairs)
  quiet.reportProgress = false;
  quiet.polishUntil = job_.limits->polishUntil;
  Job otherJob = job_;
  if (helperThread) otherJob.limits = &quiet;  // (one after the other, both halves report)
  Refiner other(copy, otherJob);
  std::vector<Step> log;
  other.reduce().scope = {&mine[1], &log};
  reduce_.scope = {&mine[0], nullptr};
  auto secondHalf = [&] { other.polisher().round(true); };
#ifdef ACUTEMESH_THREADS
  if (helperThread) {
    const ProgressRelay::Part half(job_.progressRelay(), 0, kCallersHalf);
    std::atomic<bool> done{false};
    std::thread helper([&] {
      secondHalf();
      done = true;
    });
    round(true);
    // (Progress goes on being sent while the other half finishes: a cancel from the
    // callback lands in time; that half polls the budget itself.)
    while (!done) {
      job_.pollProgress();
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    helper.join();
  }
#endif
  if (!helperThread) {
    {
      const ProgressRelay::Part half(job_.progressRelay(), 0, kCallersHalf / 2);
      round(true);
    }
    const ProgressRelay::Part half(job_.progressRelay(), kCallersHalf / 2, kCallersHalf);
    secondHalf();
  }
  reduce_.scope = {};
  {
    const ProgressRelay::Part part(job_.progressRelay(), kCallersHalf, kReplayed);
    replay(log, n, copy.T.vertexCount());
  }
  along.resize(T.vertexCount(), 1);  // and the points the merges made
  {
    const ProgressRelay::Part part(job_.progressRelay(), kReplayed, kAlongRemoved);
    reduce_.removeSteinerPoints(&along, 1);
  }
  const ProgressRelay::Part part(job_.progressRelay(), kAlongRemoved, 1);
  reduce_.mergeSteinerPoints(&along);
}

// A move if the vertex's star still meets the target there, a removal or merge if it works
// now. The copy's points from firstNew on (up to made) map to those made here. (A step near
// the middle may fail where the other half changed things.)
void Polish::replay(const std::vector<Step>& log, uint32_t firstNew, uint32_t made) {
  std::vector<uint32_t> here(made, kNone);
  for (uint32_t v = 0; v < firstNew; ++v) here[v] = v;
  ProgressRelay* relay = job_.progressRelay();
  for (size_t i = 0; i < log.size(); ++i) {
    const Step& step = log[i];
    // (Made even after a cancel: they are the other half's work, done already.)
    if ((i & 63) == 0 && relay) {
      relay->note("improve", double(i) / double(log.size()), s_.T.vertexCount());
      relay->poll();
    }
    const uint32_t a = here[step.u];
    if (a == kNone || s_.T.vertexEdge[a] == kNone) continue;
    if (step.kind == Step::Move) {
      const double to[2] = {step.x, step.y};
      relocation_.tryMoveTo(a, to);
    } else if (step.kind == Step::Remove) {
      reduce_.removePoint(a);
    } else {
      const uint32_t b = here[step.w];
      if (b != kNone && s_.role[a] == s_.role[b] && reduce_.mergePair(a, b))
        here[step.made] = s_.T.vertexCount() - 1;
    }
  }
}

}  // namespace acutemesh::detail
