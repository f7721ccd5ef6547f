#include "strategies.h"

#include <algorithm>
#include <memory>
#include <mutex>

#include "../size_field.h"
#include "descent.h"
#include "exact_feet.h"
#include "geometry.h"
#include "refiner.h"
#include "threads.h"

namespace acutemesh::detail {

double steinerBudget(const Pslg& input, const Options& options, double demand) {
  if (options.maxSteiner) return options.maxSteiner;
  double cap = std::max(kSteinerAtLeast, kSteinerPerInputVertex * double(input.vertexCount()));
  return cap + 4 * demand;
}

namespace {

constexpr size_t kPolishRun = SIZE_MAX;  // (progressSpan)
constexpr double kSizedAlone = 16;  // triangles the sizes ask for per input vertex

// The strategies for a mode, in the order they run (see docs/TUNING.md for what each saves).
std::vector<Strategy> strategiesFor(const Options& options, double demand, uint32_t vertices) {
  std::vector<Strategy> strategies = {Strategy{}};
  if (options.mode == Mode::NonObtuse) {
    // Feet on segments; feet first with lazy fans; plain fans. Each with exact slides, then
    // with sampled ones: the exact ones usually win, and run first their count caps the rest.
    Strategy feet, cutFirst, plain;
    feet.footOnSegments = true;
    cutFirst.cutAtFeetFirst = cutFirst.footOnSegments = cutFirst.lazyFans = true;
    strategies.clear();
    for (bool exact : {true, false})
      for (Strategy s : {feet, cutFirst, plain}) {
        s.exactSlide = exact;
        strategies.push_back(s);
      }
  } else if (options.mode == Mode::Acute) {
    Strategy lazy;
    lazy.lazyFans = true;
    strategies.push_back(lazy);
    // Both again with the farthest point of the slice whatever it encroaches, as fallbacks:
    // sparing the segments can grade into a narrow wedge and end a sliver short.
    for (size_t i = 0; i < 2; ++i) {
      strategies.push_back(strategies[i]);
      strategies.back().weighPoints = false;
      strategies.back().fallback = true;
    }
  }
  if (options.mode == Mode::NonObtuse || options.mode == Mode::Acute) {
    // First of all the first strategy in the fewest-bad-first order: it often wins, and its
    // count caps the others early.
    Strategy first = strategies.front();
    first.fewestBadFirst = true;
    strategies.insert(strategies.begin(), first);
  }
  // Sizes that ask for many more triangles than the input has vertices set the count
  // themselves: the strategies would differ by little, so only the first runs.
  if (demand > kSizedAlone * vertices) strategies.resize(1);
  // A large domain (a country's mainland): the first strategy wins there (docs/TUNING.md), and
  // each other one costs the time and memory of a whole run: they run only should it miss.
  if (vertices >= kFirstStrategyAloneFrom)
    for (size_t i = 1; i < strategies.size(); ++i) strategies[i].fallback = true;
  if (options.mode == Mode::Acute) {
    // Wide fans in every strategy, and should none of them meet the target (wide fans can
    // crowd a tiny corner), all of them again with the usual fans as fallbacks. Not below 90
    // degrees, where a bound no strategy reaches is best effort anyway (refine() meshes to 90
    // then), and each fallback would run until half the Steiner budget is spent.
    const size_t count = strategies.size();
    for (size_t i = 0; i < count; ++i) {
      if (options.maxAngle >= 90) {
        strategies.push_back(strategies[i]);
        strategies.back().fallback = true;
      }
      strategies[i].wideFans = true;
    }
  }
  return strategies;
}

// The vertex count at which a run stops, for a Steiner cap (0: none) and the budget; and the
// triangles the area and size bounds ask for (sizeDemand's, for the runs' reservations).
struct SteinerLimit {
  uint32_t startVertices;
  double demand;
  double budget;  // steinerBudget's
  uint32_t with(uint32_t steinerCap) const {
    double cap = steinerCap ? std::min(budget, double(steinerCap)) : budget;
    return uint32_t(std::min(double(startVertices) + cap, double(kMaxVertices)));
  }
};

// One strategy's run on its own copy of the start state.
class StrategyRun {
 public:
  StrategyRun() = default;
  StrategyRun(const RefineState& start, const Job& job, const SteinerLimit& limit,
              uint32_t steinerCap)
      : box_(std::make_unique<Box>(start, job)) {
    const uint32_t steinerLimit = limit.with(steinerCap);
    box_->limits.steinerLimit = steinerLimit;
    if (limit.demand > 0) {
      // About one vertex per two triangles of a third of the bounds' area, within the limit,
      // and no more than kReservedVerticesAtMost more: a bound far too small for the time
      // limit must not reserve gigabytes up front.
      const double n = start.T.vertexCount();
      box_->state.reserve(
          size_t(std::min({double(steinerLimit), n + 1.6 * limit.demand,
                           n + double(kReservedVerticesAtMost)})));
    }
  }
  void go() {
    result = box_->refiner.run();
    met = result.ok() && !box_->job.target.anyMissed(box_->state);
  }
  bool exists() const { return box_ != nullptr; }
  RefineState& state() { return box_->state; }
  const RefineState& state() const { return box_->state; }
  RunLimits& limits() { return box_->limits; }
  const Job& job() const { return box_->job; }
  Refiner& refiner() { return box_->refiner; }
  size_t liveSteiner() const { return box_->state.liveSteiner(box_->job.input.vertexCount()); }

  StepResult result;
  bool met = false;

 private:
  // The state, the run's limits and its job, where the refiner can keep referring to them.
  struct Box {
    Box(const RefineState& start, const Job& j)
        : state(start), job(j), refiner(state, withLimits()) {}
    const Job& withLimits() {
      job.limits = &limits;
      return job;
    }
    RefineState state;
    RunLimits limits;
    Job job;
    Refiner refiner;
  };
  std::unique_ptr<Box> box_;
};

// Which run refineWithStrategies keeps, the runs considered one after another: the first,
// unless a later one meets the target with fewer Steiner points than the best so far. A later
// run stops once it has made as many points as the best so far (cap()); none runs once that
// leaves it no room, or the budget is out (done()).
struct StrategyChoice {
  StrategyChoice(const RefineState& start, const Budget& budget, uint32_t steinerCap)
      : startVertices(start.T.vertexCount()), budget(budget), steinerCap(steinerCap) {}
  uint32_t cap() const {
    if (!best.met) return steinerCap;
    return uint32_t(best.state().T.vertexCount() - startVertices) - 1;
  }
  bool done() const {
    if (best.exists() && (best.result.status == Status::Cancelled || budget.stop())) return true;
    return best.met && best.state().T.vertexCount() - startVertices <= 1;
  }
  void consider(StrategyRun&& run) {
    if (!best.exists() || (run.met && (!best.met || run.liveSteiner() < best.liveSteiner())))
      best = std::move(run);
  }
  const size_t startVertices;
  const Budget& budget;
  const uint32_t steinerCap;
  StrategyRun best;
};

// The job of strategy i: the same input, options, target and budget for every run.
struct Jobs {
  const Pslg& input;
  const Options& options;
  const Target& target;
  const Budget& budget;
  const std::vector<Strategy>& strategies;
  double minEdge2;
  Job operator()(size_t i) const {
    return {input, options, target, strategies[i], budget, nullptr, minEdge2};
  }
};

// Progress: the runs of the strategies before the fallbacks, `leading` of them, then the
// polish (Target::countsPoints). On large inputs, where progress matters, the polish takes about
// 70% of the time and the first run nearly all of the runs' (the later ones stop once they
// have made as many points; the helper threads' do not report). Fallbacks run only when no
// run met the target, each to its end: they share what is left of the runs' part, `total`
// runs in all.
constexpr double kRunsShare = 0.3, kFirstRunShare = 0.8;
// With Options::optimize, the polish's share of what is left; the search has the rest.
constexpr double kPolishBeforeSearch = 0.3;
void progressSpan(const Budget& budget, const Target& target, size_t run, size_t leading,
                  size_t total) {
  ProgressRelay* relay = budget.progress();
  if (!relay) return;
  const double runs = target.countsPoints() ? kRunsShare : 1;
  if (run == kPolishRun) return relay->span(runs, 1);
  if (run >= leading) {
    const double from = std::min(relay->done(), runs);
    return relay->span(from, from + (runs - from) / double(total - run));
  }
  const double first = leading == 1 ? runs : runs * kFirstRunShare;
  if (run == 0) return relay->span(0, first);
  const double share = (runs - first) / double(leading - 1);
  relay->span(first + double(run - 1) * share, first + double(run) * share);
}

#ifdef ACUTEMESH_THREADS
// Runs strategies [0, count) on threads, the calling one among them, and hands them to the
// choice in order: with the same result as running them one after another (so every build,
// threads or not, makes the same mesh). A run starts before those ahead of it are done, with
// only the budget's cap; once they are, it gets the cap it would have had (StrategyChoice::cap)
// through its SteinerGate. Had it already checked a vertex count at or over that cap, it would
// have stopped there: it is stopped now and does not count. (The new limit is stored before
// the last count checked is read: a check at or over it either shows in that count or sees
// the new limit and stops the run.) Otherwise it has gone just as it would have, and goes on
// under the cap. (Its vertex count only grows until run() returns.) Only the calling thread's
// runs report progress.
class ConcurrentStrategies {
 public:
  ConcurrentStrategies(const RefineState& start, const Jobs& jobs, const SteinerLimit& limit,
                       size_t count, StrategyChoice& choice)
      : start_(start), jobs_(jobs), limit_(limit), choice_(choice), slots_(count), end_(count) {
    slots_[0].cap = choice.cap();
  }

  // The calling thread takes the first run before any helper starts: it reports progress, and
  // a cancel on its word ("improve") then finds the first run past its refinement, as one
  // after another would.
  void run(size_t threads) {
    const size_t first = claim(true);
    std::vector<std::thread> helpers;
    for (size_t i = 1; i < threads; ++i)
      helpers.emplace_back([this] { work(false, claim(false)); });
    work(true, first);
    for (std::thread& helper : helpers) helper.join();
  }

 private:
  // Slots [0, next_) are started, [0, handed_) handed over; slot handed_ knows its cap.
  struct Slot {
    StrategyRun run;
    SteinerGate gate;
    bool finished = false, stopped = false;
    uint32_t cap = 0;  // the cap it would have had (from when it is slot handed_)
  };

  // Sets up the next run for this thread: its slot, or kNoRun if none is left.
  static constexpr size_t kNoRun = SIZE_MAX;
  size_t claim(bool caller) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (next_ >= end_) return kNoRun;
    const size_t i = next_++;
    Slot& slot = slots_[i];
    const uint32_t cap = i == handed_ ? slot.cap : choice_.steinerCap;
    slot.run = StrategyRun(start_, jobs_(i), limit_, cap);
    slot.gate.limit = limit_.with(cap);
    slot.run.limits().gate = &slot.gate;
    slot.run.limits().reportProgress = caller;
    return i;
  }

  void work(bool caller, size_t i) {
    for (; i != kNoRun; i = claim(caller)) {
      if (caller) progressSpan(jobs_.budget, jobs_.target, i, slots_.size(), slots_.size());
      slots_[i].run.go();
      std::lock_guard<std::mutex> lock(mutex_);
      slots_[i].finished = true;
      handOver();
    }
  }

  // (Under the lock.) Hands the finished runs at the front to the choice, in order, and gives
  // the next one its cap.
  void handOver() {
    while (handed_ < end_ && slots_[handed_].finished) {
      Slot& slot = slots_[handed_++];
      if (slot.stopped) slot.run.met = false;
      slot.run.limits() = {limit_.with(slot.cap), nullptr, true};
      choice_.consider(std::move(slot.run));
      slot.run = StrategyRun{};
      if (choice_.done()) {  // none after it would have run: stop them
        end_ = handed_;
        for (size_t k = handed_; k < slots_.size(); ++k) slots_[k].gate.limit = 0;
        return;
      }
      if (handed_ == end_) return;
      Slot& nextSlot = slots_[handed_];
      nextSlot.cap = choice_.cap();
      if (handed_ < next_) {  // started: the limit goes in before `checked` is read (see above)
        const uint32_t limit = limit_.with(nextSlot.cap);
        nextSlot.gate.limit = limit;
        if (nextSlot.gate.checked >= limit) nextSlot.stopped = true, nextSlot.gate.limit = 0;
      }
    }
  }

  const RefineState& start_;
  const Jobs& jobs_;
  const SteinerLimit& limit_;
  StrategyChoice& choice_;
  std::vector<Slot> slots_;
  std::mutex mutex_;
  size_t end_;  // the runs from here on are not started (and stopped if they were)
  size_t next_ = 0, handed_ = 0;
};
#endif

}  // namespace

void searchFewerPoints(RefineState& s, Refiner& refiner, const Job& job, const Options& search) {
  // Acute and non-obtuse targets: the points the target does not need out first, and again
  // after each try (AngleDescent::thin: where smoothing lets a point go, which the polish's
  // removals do not try).
  const bool thins = job.target.boundsLargest();
  Options rest = search;  // (what the thinning leaves of the seconds)
  if (thins) {
    const double start = job.budget.elapsed(), until = job.limits->polishUntil;
    if (search.optimize > 0) job.limits->polishUntil = start + search.optimize;
    thinOut(s, job, refiner.insertion(), refiner.boundary(), kThinPasses);
    job.limits->polishUntil = until;
    if (search.optimize > 0) {
      rest.optimize = search.optimize - (job.budget.elapsed() - start);
      if (rest.optimize <= 0 && search.optimizeTries == 0) return;
      rest.optimize = std::max(rest.optimize, 0.0);
    }
  }
  size_t chains = 1;
#ifdef ACUTEMESH_THREADS
  chains = std::max(1u, threadsFor(rest));
#endif
  std::vector<RefineState> copies(chains - 1, s);
  std::vector<RunLimits> limits(chains - 1, *job.limits);
  std::vector<Job> copyJobs(chains - 1, job);
  std::vector<std::unique_ptr<Refiner>> refiners;
  for (size_t i = 1; i < chains; ++i) {
    limits[i - 1].reportProgress = false;
    copyJobs[i - 1].limits = &limits[i - 1];
    refiners.push_back(std::make_unique<Refiner>(copies[i - 1], copyJobs[i - 1]));
  }
  auto chain = [&](size_t i) {
    Refiner& r = i == 0 ? refiner : *refiners[i - 1];
    RefineState& state = i == 0 ? s : copies[i - 1];
    const Job& j = i == 0 ? job : copyJobs[i - 1];
    std::function<void()> thin;
    if (thins) thin = [&] { thinOut(state, j, r.insertion(), r.boundary(), 1); };
    r.polisher().search(rest.optimize, rest.optimizeTries, rest.seed + i, thin);
  };
#ifdef ACUTEMESH_THREADS
  std::vector<std::thread> helpers;
  for (size_t i = 1; i < chains; ++i) helpers.emplace_back(chain, i);
  chain(0);
  for (std::thread& helper : helpers) helper.join();
#else
  chain(0);
#endif
  const size_t inputVertices = job.input.vertexCount();
  for (RefineState& copy : copies)
    if (copy.liveSteiner(inputVertices) < s.liveSteiner(inputVertices)) s = std::move(copy);
}

RefineOutcome refineWithStrategies(const RefineState& start, const Pslg& input,
                                   const Options& options, const Budget& budget,
                                   uint32_t steinerCap, RefineState& out,
                                   std::vector<ExactVertex>& exact, RefineState* releaseStart,
                                   QualityRun quality) {
  const ProgressRelay::Scope level(budget.progress());  // (nested: reports no fraction)
  const double demand = sizeDemand(start.T, options);
  const std::vector<Strategy> strategies = strategiesFor(options, demand, start.T.vertexCount());
  const Target target = [&] {
    Target t(options);
    t.qualityCounts = quality == QualityRun::Mesh;
    return t;
  }();
  const Jobs jobs{input, options, target, budget, strategies, smallestEdge2(input)};
  const SteinerLimit limit{start.T.vertexCount(), demand, steinerBudget(input, options, demand)};
  StrategyChoice choice(start, budget, steinerCap);
  size_t next = 0;
  size_t leading = 0;
  while (leading < strategies.size() && !strategies[leading].fallback) ++leading;
#ifdef ACUTEMESH_THREADS
  // The strategies before the fallbacks concurrently, where there are threads to spare.
  const unsigned threads = threadsFor(options);
  if (threads > 1 && leading > 1) {
    ConcurrentStrategies(start, jobs, limit, leading, choice)
        .run(std::min<size_t>(threads, leading));
    next = leading;
  }
#endif
  for (; next < strategies.size() && !choice.done(); ++next) {
    if (strategies[next].fallback && choice.best.met) continue;
    StrategyRun run(start, jobs(next), limit, choice.cap());
    progressSpan(budget, target, next, leading, strategies.size());
    run.go();
    choice.consider(std::move(run));
  }
  if (releaseStart) *releaseStart = RefineState{};
  StrategyRun& best = choice.best;
  progressSpan(budget, target, kPolishRun, leading, strategies.size());
  // (Quality: also where all that misses the target are the triangles left at small input
  // angles.)
  const bool settled =
      best.met || (best.result.ok() && !best.refiner().repairs().missesBeyondLeft());
  const bool search = settled && searchAsked(options) && quality == QualityRun::Mesh &&
                      target.countsPoints() && !target.strictMax;
  Options searchFor = options;
  {
    const ProgressRelay::Part part(budget.progress(), 0, search ? kPolishBeforeSearch : 1);
    const double before = budget.elapsed();
    // A sized quality mesh is polished only for the search (Target::countsPoints): its polish
    // counts within the seconds asked, and may take them all (it stops there).
    const bool polishCounts =
        search && !target.boundsLargest() && target.sized() && options.optimize > 0;
    if (polishCounts) best.limits().polishUntil = before + options.optimize;
    if (settled) best.refiner().polish();
    if (polishCounts) {
      best.limits().polishUntil = 0;
      searchFor.optimize = options.optimize - (budget.elapsed() - before);
      if (searchFor.optimize <= 0) searchFor.optimize = 0, searchFor.optimizeTries = 0;
    }
  }
  if (search && searchAsked(searchFor)) {
    const ProgressRelay::Part part(budget.progress(), kPolishBeforeSearch, 1);
    searchFewerPoints(best.state(), best.refiner(), best.job(), searchFor);
  }
  RefineOutcome outcome;
  outcome.met = best.met;
  outcome.result = best.result;
  // Cancelled while improving: the mesh meets the target, but the caller asked to stop.
  if (budget.cancelled() && outcome.result.ok())
    outcome.result = {Status::Cancelled,
                      "cancelled while removing Steiner points; the mesh meets "
                      "the target"};
  outcome.feetHeld = placeExactFeet(best.state(), jobs(0), exact);
  out = std::move(best.state());
  return outcome;
}

}  // namespace acutemesh::detail
