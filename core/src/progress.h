// Options::progress as mesh() runs it: reports reach the caller at least every
// kProgressInterval of work (a cancel asked for from the callback then lands that soon), with
// one fraction for the whole refinement that only grows.
//
// The steps note where they are (note: cheap, no call); every poll of the budget
// (Budget::stop) sends the last note once the interval has passed. Only the thread that
// called mesh() reports: calls from other threads are ignored.
//
// Refinement nests (acute below 90 degrees runs whole refinements inside its own), so only the
// outermost level's fractions count: Scope marks a level, and a report from a deeper one keeps
// the fraction where it was. Within the outermost level, span() says which part of the whole
// the fractions noted next stand for.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <functional>
#include <thread>

#include "acutemesh/acutemesh.h"

namespace acutemesh::detail {

constexpr double kProgressInterval = 0.04;  // seconds

class ProgressRelay {
 public:
  explicit ProgressRelay(std::function<void(const Progress&)> user)
      : user_(std::move(user)), owner_(std::this_thread::get_id()), sent_(Clock::now()) {}

  // A report (Options::progress as the steps get it): noted and sent now.
  void report(const Progress& p) {
    if (!mine()) return;
    note(p.phase, p.fraction, p.vertices);
    send();
  }
  // Where the work is: `fraction` of the current span (-1: unknown, keep the last).
  void note(const char* phase, double fraction, uint32_t vertices) {
    if (!mine()) return;
    const bool refining = isRefinement(phase);
    if (refining && !isRefinement(phase_)) floor_ = 0;  // refinement starts
    phase_ = phase;
    if (vertices) vertices_ = vertices;
    if (!refining) {
      fraction_ = fraction;
      return;
    }
    if (fraction >= 0 && depth_ <= 1)
      floor_ = std::max(floor_, std::min(1.0, from_ + (to_ - from_) * fraction));
    fraction_ = floor_;
  }
  // Sends the last note if kProgressInterval has passed since the last call.
  void poll() {
    if (!mine()) return;
    if (std::chrono::duration<double>(Clock::now() - sent_).count() >= kProgressInterval) send();
  }
  // The share of the whole refinement done so far (as last noted).
  double done() const { return floor_; }
  // The part [from, to] of the whole refinement that the fractions noted next stand for
  // (outermost level only).
  void span(double from, double to) {
    if (!mine() || depth_ > 1) return;
    from_ = from, to_ = to;
  }
  // The part [from, to] of the current span (fractions of it) while it lives.
  class Part {
   public:
    Part(ProgressRelay* r, double from, double to)
        : relay_(r && r->mine() && r->depth_ <= 1 ? r : nullptr) {
      if (!relay_) return;
      saved_[0] = relay_->from_, saved_[1] = relay_->to_;
      const double width = saved_[1] - saved_[0];
      relay_->from_ = saved_[0] + from * width, relay_->to_ = saved_[0] + to * width;
    }
    ~Part() {
      if (relay_) relay_->from_ = saved_[0], relay_->to_ = saved_[1];
    }
    Part(const Part&) = delete;
    Part& operator=(const Part&) = delete;

   private:
    ProgressRelay* relay_;
    double saved_[2] = {0, 1};
  };
  // One level of refinement while it lives (outermost first).
  class Scope {
   public:
    explicit Scope(ProgressRelay* r) : relay_(r && r->mine() ? r : nullptr) {
      if (relay_) ++relay_->depth_;
    }
    ~Scope() {
      if (relay_ && --relay_->depth_ == 0) relay_->from_ = 0, relay_->to_ = 1;
    }
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;
    // Whether this is the outermost level, whose fractions count.
    bool outermost() const { return relay_ && relay_->depth_ == 1; }

   private:
    ProgressRelay* relay_;
  };

 private:
  using Clock = std::chrono::steady_clock;
  static bool isRefinement(const char* phase) {
    return phase && (std::strcmp(phase, "refine") == 0 || std::strcmp(phase, "improve") == 0);
  }
  bool mine() const { return std::this_thread::get_id() == owner_; }
  void send() {
    sent_ = Clock::now();
    if (phase_) user_({phase_, fraction_, vertices_});
  }

  std::function<void(const Progress&)> user_;
  std::thread::id owner_;
  Clock::time_point sent_;
  const char* phase_ = nullptr;
  double fraction_ = -1, floor_ = 0, from_ = 0, to_ = 1;
  uint32_t vertices_ = 0;
  int depth_ = 0;
};

}  // namespace acutemesh::detail
