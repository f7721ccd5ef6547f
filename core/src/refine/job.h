// What one refinement run is asked to do, read by every step: the input, the options and the
// target they set, the strategy, the budget; and the run's Steiner limit.
#pragma once

#include <atomic>
#include <cstdint>

#include "../build.h"
#include "geometry.h"
#include "strategy.h"
#include "target.h"

namespace acutemesh::detail {

// A run's Steiner limit where strategies run concurrently (strategies.cpp): it may tighten
// while the run goes on, so the run reads it at every check, and publishes the vertex count
// it checked.
struct SteinerGate {
  std::atomic<uint32_t> limit{0};
  std::atomic<uint32_t> checked{0};
};

// The vertex count at which a run stops (its own, or a gate's), and whether it reports
// progress (only the thread that called mesh() does: see Options::progress).
struct RunLimits {
  uint32_t steinerLimit = 0;
  SteinerGate* gate = nullptr;
  bool reportProgress = true;
  // The polish stops here (Budget::elapsed seconds; 0: it runs its rounds out): a sized
  // quality mesh's polish counts within --optimize's seconds (refineWithStrategies), and the
  // search's tries end with its seconds (Polish::search).
  double polishUntil = 0;
  bool reached(uint32_t vertexCount) {
    if (!gate) return vertexCount >= steinerLimit;
    gate->checked.store(vertexCount);
    return vertexCount >= gate->limit.load();
  }
};

// A run's progress (Refiner::run's parts of its span): its repairs up to this fraction, then
// the removal of the points not needed.
constexpr double kRepairShare = 0.7;
// A repair's progress: its first queue's share when each entry is weighed (the fewest-bad-first
// order), measured on generated coastlines.
constexpr double kWeighedQueueShare = 0.15;

struct Job {
  const Pslg& input;
  const Options& options;
  const Target& target;
  const Strategy& strategy;
  const Budget& budget;
  RunLimits* limits;
  // No edge shorter than this (squared) is made (smallestEdge2, geometry.h).
  double minEdge2;

  SegmentLine line(uint32_t seg, const double* p, const double* q) const {
    return segmentLine(input, options.exactSegments, seg, p, q);
  }
  // Options::progress is called on the reporting thread only.
  bool reportsProgress() const { return limits->reportProgress && bool(options.progress); }
  // Whether the polish and the removals must stop: the budget is spent, or the polish's time.
  bool improvementOver() const {
    return budget.stop() || (limits && limits->polishUntil > 0 && budget.elapsed() > limits->polishUntil);
  }
  // Lets the progress relay report, from long loops that do not poll the budget.
  void pollProgress() const {
    if (reportsProgress() && budget.progress()) budget.progress()->poll();
  }
  // The relay this run's steps note progress to (nullptr when it does not report).
  ProgressRelay* progressRelay() const { return reportsProgress() ? budget.progress() : nullptr; }
};

}  // namespace acutemesh::detail
