// The construction steps of mesh(), in the order it runs them. Each reports failure as a
// Status plus a one-line message and never throws.
#pragma once

#include <atomic>
#include <chrono>
#include <string>
#include <vector>

#include "acutemesh/acutemesh.h"
#include "triangulation.h"

namespace acutemesh::detail {

// Time limit and cancel flag of one mesh() call, polled by long loops.
class Budget {
 public:
  explicit Budget(const Options& o)
      : cancel_(o.cancel), start_(std::chrono::steady_clock::now()), limit_(o.timeLimit) {}
  double elapsed() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }
  bool cancelled() const { return cancel_ && cancel_->load(std::memory_order_relaxed); }
  bool outOfTime() const { return limit_ > 0 && elapsed() > limit_; }
  bool stop() const { return cancelled() || outOfTime(); }

 private:
  const std::atomic<bool>* cancel_;
  std::chrono::steady_clock::time_point start_;
  double limit_;
};

struct StepResult {
  Status status = Status::Ok;
  std::string message;
  bool ok() const { return status == Status::Ok; }
};

// Delaunay triangulation of the first `count` vertices of T.pts, inserted in Hilbert-curve
// order. canonical[i] becomes the vertex that input vertex i ended up as (itself, or the
// earlier vertex with identical coordinates).
StepResult buildDelaunay(Triangulation& T, uint32_t count, std::vector<uint32_t>& canonical,
                         const Budget& budget);

// Inserts every input segment as a chain of fixed edges, splitting it at vertices that lie
// on it and at crossings with other segments (adding the crossing points as vertices).
StepResult insertSegments(Triangulation& T, const Pslg& input,
                          const std::vector<uint32_t>& canonical, Stats& stats,
                          const Budget& budget);

// Marks which triangles belong to the domain (per triangle slot: 1 inside, 0 outside or
// ghost or free), following options.fill / convexHull and the input's hole points.
std::vector<uint8_t> classifyDomain(const Triangulation& T, const Pslg& input,
                                    const Options& options, bool keepHull);

}  // namespace acutemesh::detail
