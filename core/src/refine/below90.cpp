#include "below90.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "../angle_bound.h"
#include "../domain_angles.h"
#include "descent.h"
#include "fans.h"
#include "geometry.h"
#include "refiner.h"
#include "strategies.h"
#include "threads.h"

namespace acutemesh::detail {
namespace {

// The cosine of the largest angle of the domain's triangles (the smaller, the larger the
// angle; only exact operations, so that every build compares meshes alike).
double largestAngleCosine(const RefineState& s) {
  double smallest = 1;
  for (uint32_t t = 0; t < s.T.triangleSlots(); ++t) {
    if (!s.T.inDomain(t)) continue;
    const uint32_t* v = &s.T.tri[3 * t];
    for (int k = 0; k < 3; ++k) {
      const double *x = s.P(v[k]), *y = s.P(v[(k + 1) % 3]), *z = s.P(v[(k + 2) % 3]);
      smallest =
          std::min(smallest, ((y[0] - x[0]) * (z[0] - x[0]) + (y[1] - x[1]) * (z[1] - x[1])) /
                                 std::sqrt(dist2(x, y) * dist2(x, z)));
    }
  }
  return smallest;
}

// A candidate mesh and what it reached.
struct Candidate {
  RefineState state;
  bool acute = false;  // every angle below 90 (the first certificate)
  bool met = false;    // the bound (and a minimum angle) met
  double cosLargest = -1;
  size_t steiner = 0;
  bool overBudget = false;  // more Steiner points than Options::maxSteiner
  // Better: meets the bound with fewer points, or (neither meets it) a smaller largest angle,
  // by kCandidateEven degrees or more, else fewer points.
  bool betterThan(const Candidate& o) const {
    if (!acute || overBudget) return false;
    if (!o.acute || o.overBudget) return true;
    if (met != o.met) return met;
    if (met) return steiner < o.steiner;
    const double largest = std::acos(cosLargest) / kDegree,
                 other = std::acos(o.cosLargest) / kDegree;
    if (std::fabs(largest - other) >= kCandidateEven) return largest < other;
    return steiner < o.steiner;
  }
};

Candidate judge(RefineState&& s, const Pslg& input, const Options& options) {
  Candidate c;
  Options at90 = options;
  at90.maxAngle = 90, at90.minAngle = 0;
  c.acute = !Target(at90).anyMissed(s);
  c.met = c.acute && !Target(options).anyMissed(s);
  c.cosLargest = largestAngleCosine(s);
  c.steiner = s.liveSteiner(input.vertexCount());
  c.overBudget = options.maxSteiner && c.steiner > options.maxSteiner;
  c.state = std::move(s);
  return c;
}

// The bounds the descent goes down through to reach `lowest`: a step of two degrees down to
// 80, then one, then half a degree; the last is `lowest` itself.
std::vector<double> levelsDownTo(double lowest) {
  std::vector<double> levels;
  for (double level = 88; level > lowest; level -= level > 80 ? 2 : level > 76 ? 1 : 0.5)
    levels.push_back(level);
  levels.push_back(lowest);
  return levels;
}

// Where a descent starts. No one start wins everywhere (docs/TUNING.md): the acute mesh has
// the fewest points but its skinny triangles must go below 80 degrees; a quality mesh has none
// but more points; fans at every corner settle corners the others leave stuck.
enum class Start { Direct, Acute, AcuteGraded, Quality, QualityFans };
constexpr Start kStarts[] = {Start::Direct, Start::Acute, Start::AcuteGraded, Start::Quality,
                             Start::QualityFans};

// The quality mesh of `from` with minimum angle `minAngle` (with fans at every corner first:
// the quality refinement keeps them, their points free afterwards).
RefineState qualityMesh(const RefineState& from, const Pslg& input, const Options& options,
                        const Budget& budget, uint32_t steinerCap, double minAngle, bool fans) {
  Options quality = options;
  quality.mode = Mode::Quality;
  quality.minAngle = std::max(options.minAngle, minAngle);
  RefineState start = from, s;
  if (fans) {
    Strategy everywhere;
    everywhere.fansEverywhere = true;
    const Target target(quality);
    RunLimits limits;
    const Job job{input, quality, target, everywhere, budget, &limits, smallestEdge2(input)};
    CornerFans(start, job).buildAll();
  }
  std::vector<ExactVertex> none;
  refineWithStrategies(start, input, quality, budget, steinerCap, s, none, nullptr,
                       QualityRun::Start);
  for (size_t v = 0; v < s.role.size(); ++v) {
    if (s.role[v] == kArc) s.role[v] = kFree;
    s.fanCenter[v] = kNone;
  }
  return s;
}

// The descent (descent.h) from `s` down through the levels to `lowest`: the mesh of the
// lowest level met, polished at that level, unless where the descent stopped is better.
// With `graded`, the triangles too skinny for a level (an angle under 180 - 2 level) are
// refined away before it (quality refinement, which ends for such angles). The first level
// must be met within the moves `reference` vertices give (the acute mesh's): a quality start
// of a thin domain can have several times its points, and as many more moves, each dearer,
// spent on a level it never meets.
// The limits of work on `s` that may add steinerCap points, within Options::maxSteiner.
RunLimits cappedLimits(const RefineState& s, const Pslg& input, const Options& options,
                       uint32_t steinerCap) {
  RunLimits limits;
  const double budgetLimit = options.maxSteiner
                                 ? double(input.vertexCount()) + double(options.maxSteiner)
                                 : double(kMaxVertices);
  limits.steinerLimit = uint32_t(
      std::min({s.T.vertexCount() + double(steinerCap), budgetLimit, double(kMaxVertices)}));
  return limits;
}

Candidate descend(RefineState s, const Pslg& input, const Options& options, const Budget& budget,
                  uint32_t reference, uint32_t steinerCap, double lowest, bool graded,
                  double done, double share) {
  RunLimits limits = cappedLimits(s, input, options, steinerCap);
  const Strategy strategy;
  const double minEdge2 = smallestEdge2(input);
  RefineState met;
  double reached = 0;
  uint64_t moves = uint64_t(kDescentMoves + kDescentMovesPerVertex * s.T.vertexCount());
  const uint64_t firstMoves =
      uint64_t(kDescentFirstMoves + kDescentFirstMovesPerVertex * double(reference));
  const std::vector<double> levels = levelsDownTo(lowest);
  for (size_t i = 0; i < levels.size(); ++i) {
    const double level = levels[i];
    if (budget.stop()) break;
    // (Progress: the starts in turn, each its bounds in turn.)
    if (options.progress)
      options.progress(
          {"improve", done + share * double(i) / double(levels.size()), s.T.vertexCount()});
    if (graded)
      s = qualityMesh(s, input, options, budget, steinerCap,
                      std::min(180 - 2 * level + kGradedRoom, kDescentMinAngle), false);
    Options at = options;
    at.maxAngle = level;
    const Target target(at);
    const Job job{input, at, target, strategy, budget, &limits, minEdge2};
    Refiner refiner(s, job);
    const uint64_t allowed = i == 0 ? std::min(moves, firstMoves) : moves;
    uint64_t left = allowed;
    AngleDescent descent(s, job, refiner.insertion(), refiner.boundary(), left);
    // (Progress within the bound: the part of its rounds done, noted for the relay to send;
    // where splits may follow, the first run is its first half and each run after the splits
    // an equal share of the rest.)
    double runFrom = 0, runWidth = i > 0 ? 0.5 : 1;
    auto within = [&](double part) {
      if (ProgressRelay* relay = budget.progress())
        relay->note("improve",
                    done + share * (double(i) + runFrom + runWidth * part) / double(levels.size()),
                    s.T.vertexCount());
    };
    bool levelMet = descent.run(within);
    // Where it stalls past its first bound (a start must meet that one as it is), more points
    // where the bound is missed: the edges of those triangles split, and the descent again.
    for (int retry = 0; i > 0 && !levelMet && retry < kDescentSplitRetries && !budget.stop() &&
                        !limits.reached(s.T.vertexCount());
         ++retry) {
      const uint32_t before = s.T.vertexCount();
      if (descent.splitMissed() == 0) break;
      const uint64_t credit = uint64_t(kDescentMovesPerSplit * double(s.T.vertexCount() - before));
      left += credit;
      runFrom = 0.5 + 0.5 * double(retry) / kDescentSplitRetries;
      runWidth = 0.5 / kDescentSplitRetries;
      levelMet = descent.run(within);
    }
    moves = moves - allowed + left;  // (what this bound used, less what its splits granted)
    if (!levelMet) break;
    met = s;
    reached = level;
  }
  Candidate stopped = judge(std::move(s), input, options);
  if (reached == 0) return stopped;
  Options at = options;
  at.maxAngle = reached;
  const Target target(at);
  const Job job{input, at, target, strategy, budget, &limits, minEdge2};
  Refiner refiner(met, job);
  if (!budget.stop()) {
    const ProgressRelay::Scope quiet(budget.progress());  // (the polish's own fractions: not ours)
    // The points the bound reached does not need out first (the newest first: the descent's
    // and its splits'), then the polish.
    thinOut(met, job, refiner.insertion(), refiner.boundary(), kThinPasses);
    refiner.polish();
  }
  Candidate polished = judge(std::move(met), input, options);
  return stopped.betterThan(polished) ? std::move(stopped) : std::move(polished);
}

// Options::optimize's search on the best mesh, which meets the bound `asked` gives, at that
// bound (and its minimum angle); its progress spans what is left of the run's.
void searchAtTheBound(Candidate& best, const Pslg& input, const Options& asked,
                      const Budget& budget, uint32_t steinerCap) {
  RunLimits limits = cappedLimits(best.state, input, asked, steinerCap);
  const Strategy strategy;
  const Target target(asked);
  const Job job{input, asked, target, strategy, budget, &limits, smallestEdge2(input)};
  Refiner refiner(best.state, job);
  if (ProgressRelay* relay = budget.progress()) relay->span(relay->done(), 1);
  searchFewerPoints(best.state, refiner, job, asked);
  best = judge(std::move(best.state), input, asked);
}

}  // namespace

StepResult refineBelow90(const RefineState& start, const Pslg& input, const Options& asked,
                         const Budget& budget, RefineState& out, std::vector<ExactVertex>& exact) {
  // (The refinements here are starts and steps of the descent: no search of their own.)
  Options options = asked;
  options.optimize = 0, options.optimizeTries = 0;
  const bool automatic = options.maxAngle == kAutoMaxAngle;
  Options at90 = options;
  at90.maxAngle = 90;
  RefineState first;
  RefineOutcome o = refineWithStrategies(start, input, at90, budget, 0, first, exact);
  Candidate best = judge(std::move(first), input, options);
  uint32_t cap = 0;  // (set below: the Steiner points each try may add)
  auto finish = [&](StepResult result) {
    if (searchAsked(asked) && !budget.stop()) {
      if (best.met && !automatic) {
        searchAtTheBound(best, input, asked, budget, cap);
      } else if (automatic && best.acute) {
        // (Auto: at the bound reached, as the stats will say it.)
        Options reached = asked;
        const double largest = std::acos(std::max(-1.0, std::min(1.0, best.cosLargest))) / kDegree;
        reached.maxAngle = tenthBound(largest, [&](double bound) {
          Options at = asked;
          at.maxAngle = bound;
          return !Target(at).anyMissed(best.state);
        });
        searchAtTheBound(best, input, reached, budget, cap);
      }
    }
    out = std::move(best.state);
    return result;
  };
  if (!best.acute || budget.stop()) return finish(o.result);
  exact.clear();  // (non-obtuse only)
  // Each later try may use a few times the points of the acute mesh.
  cap = uint32_t(std::min<double>(kBelow90Points * double(best.steiner) + 200, double(kMaxVertices)));
  const double domainFloor = angleFloor(smallestDomainAngle(start.T));
  const double lowest = automatic ? domainFloor + kAutoMargin : options.maxAngle;
  // (A domain whose floor is within a hair of 90 degrees leaves auto nothing to gain.)
  if (portableCos(lowest * kDegree) <= best.cosLargest) return finish({});
  const RefineState acute = best.state;
  // One start's descent; false if it could not start (the direct refinement missed).
  auto run = [&](Start from, const Options& opts, Candidate& out) {
    RefineState s;
    if (from == Start::Direct) {
      // Acute refinement to the bound itself, or to kDirectFrom where the bound is lower
      // (below it the repairs do not end); the descent goes on from there.
      Options direct = opts;
      direct.maxAngle = std::max(lowest, kDirectFrom);
      std::vector<ExactVertex> none;
      refineWithStrategies(start, input, direct, budget, cap, s, none);
      if (Target(direct).anyMissed(s)) return false;
    } else if (from == Start::Quality || from == Start::QualityFans) {
      s = qualityMesh(start, input, opts, budget, cap, kDescentMinAngle,
                      from == Start::QualityFans);
    } else {
      s = acute;
    }
    const double share = 1.0 / double(std::size(kStarts));
    out = descend(std::move(s), input, opts, budget, acute.T.vertexCount(), cap, lowest,
                  from == Start::AcuteGraded, share * double(int(from)), share);
    return true;
  };
  // The starts two at a time, the better of each pair kept (the direct refinement meets 85
  // degrees, but often with more points than the acute mesh's descent), until a pair meets the
  // bound; on a large mesh the direct start alone first (kDirectAloneFrom). Where there are
  // threads the pair runs at once (the second's progress unreported): the same mesh either way.
  constexpr size_t count = std::size(kStarts), batch = 2;
  const bool directAlone = acute.T.vertexCount() >= kDirectAloneFrom;
  // (Auto: no further start once one is within kAutoEnough of the floor, or of a floor near
  // 90, a quarter of the way from it to 90.)
  const double enough =
      portableCos((domainFloor + std::min(kAutoEnough, (90 - domainFloor) / 4)) * kDegree);
  auto done = [&] { return best.met || (automatic && best.acute && best.cosLargest >= enough); };
  for (size_t i = 0, n = 0; i < count && !done() && !budget.stop(); i += n) {
    n = std::min(i == 0 && directAlone ? 1 : batch, count - i);
    std::vector<Candidate> results(n);
    std::vector<char> ran(n, 0);
    bool together = false;
#ifdef ACUTEMESH_THREADS
    together = threadsFor(options) > 1;
    if (together) {
      Options quiet = options;
      quiet.progress = nullptr;
      std::vector<std::thread> helpers;
      for (size_t k = 1; k < n; ++k)
        helpers.emplace_back([&, k] { ran[k] = run(kStarts[i + k], quiet, results[k]); });
      ran[0] = run(kStarts[i], options, results[0]);
      for (std::thread& helper : helpers) helper.join();
    }
#endif
    for (size_t k = 0; k < n && !together; ++k) ran[k] = run(kStarts[i + k], options, results[k]);
    for (size_t k = 0; k < n; ++k)
      if (ran[k] && results[k].betterThan(best)) best = std::move(results[k]);
  }
  // Auto has no bound to miss, but a run cut short says so, as any other does. (For a bound,
  // mesh() adds what every angle is certified below.)
  if (best.met || (automatic && !budget.stop())) return finish({});
  const double largest = std::acos(std::max(-1.0, std::min(1.0, best.cosLargest))) * 180 / M_PI;
  const std::string aim =
      automatic ? "the lowest bound was found (the largest angle is " + degreesText(largest) + ")"
                : "the bound of " + degreesText(options.maxAngle) + " was reached";
  if (budget.cancelled()) return finish({Status::Cancelled, "cancelled before " + aim});
  if (budget.stop()) return finish({Status::TargetNotMet, "the time limit came before " + aim});
  return finish(
      {Status::TargetNotMet, "the bound of " + degreesText(options.maxAngle) + " was not reached"});
}

}  // namespace acutemesh::detail
