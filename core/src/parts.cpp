#include "parts.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <memory>
#include <string>

#include "refine/params.h"
#include "refine/threads.h"

namespace acutemesh::detail {

namespace {

// A part, as a problem of its own: its vertices (input vertex i of `pslg` is T's vertex
// vertices[i], then kFrame more) and the fixed edges around and inside it as segments, each
// with the input segment it lies on (`origin`, to map the part mesh's Mesh::segmentInput back;
// an edge inside the part goes in both ways, one after the other); and its triangles of T by
// their corners in that numbering, 3 each (kept should its run stop before it has a mesh).
struct Part {
  std::vector<uint32_t> corners;
  size_t triangleCount() const { return corners.size() / 3; }
  std::vector<uint32_t> vertices;
  Pslg pslg;
  std::vector<uint32_t> origin;
  Result result;
  std::exception_ptr failure;
  Result acute;  // below 90 degrees: the first round's mesh (runParts)
  bool outOfTime = false;  // its run stopped at its share of the time limit
};

// Per triangle slot of the domain its part, kNone outside; parts numbered by their first slot.
uint32_t labelParts(const Triangulation& T, const std::vector<uint8_t>& inside,
                    std::vector<uint32_t>& partOf) {
  const uint32_t slots = T.triangleSlots();
  partOf.assign(slots, kNone);
  uint32_t parts = 0;
  std::vector<uint32_t> stack;
  for (uint32_t t = 0; t < slots; ++t) {
    if (!inside[t] || partOf[t] != kNone) continue;
    partOf[t] = parts;
    stack.push_back(t);
    while (!stack.empty()) {
      const uint32_t u = stack.back();
      stack.pop_back();
      for (uint32_t e = 3 * u; e < 3 * u + 3; ++e) {
        const uint32_t w = T.opp[e] / 3;
        if (inside[w] && partOf[w] == kNone) partOf[w] = parts, stack.push_back(w);
      }
    }
    ++parts;
  }
  return parts;
}

// Four vertices around a part, as far from it as it is wide: outside its domain, they keep
// its boundary off the convex hull, as the rest of the input did, so that a sliver outside
// a boundary edge always has an edge to flip away (Boundary::openOuterSliver).
constexpr uint32_t kFrame = 4;
void addFrame(Pslg& pslg) {
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (size_t i = 0; i < pslg.points.size(); ++i)
    lo[i % 2] = std::min(lo[i % 2], pslg.points[i]), hi[i % 2] = std::max(hi[i % 2], pslg.points[i]);
  const double d = std::max(hi[0] - lo[0], hi[1] - lo[1]);
  pslg.points.insert(pslg.points.end(), {lo[0] - d, lo[1] - d, hi[0] + d, lo[1] - d,
                                         hi[0] + d, hi[1] + d, lo[0] - d, hi[1] + d});
}

// The parts' problems. Their segments run with the part on their left (a triangle's corners
// are counter-clockwise), so fill NonZero keeps exactly the part: winding 1 inside it, 0 in
// its lakes and outside. A fixed edge inside a part goes in both ways: a constraint that
// winds nothing. False if a part's boundary has an edge no segment lies on (a kept hull).
bool buildParts(const Triangulation& T, const std::vector<uint32_t>& partOf, uint32_t count,
                std::vector<Part>& parts) {
  parts.assign(count, Part{});
  std::vector<std::vector<uint32_t>> slots(count);
  for (uint32_t t = 0; t < partOf.size(); ++t)
    if (partOf[t] != kNone) slots[partOf[t]].push_back(t);
  std::vector<uint32_t> local(T.vertexCount(), kNone), stamp(T.vertexCount(), kNone);
  for (uint32_t p = 0; p < count; ++p) {
    Part& part = parts[p];
    std::vector<uint32_t> triangles;
    triangles.swap(slots[p]);
    auto at = [&](uint32_t v) {
      if (stamp[v] != p) {
        stamp[v] = p, local[v] = uint32_t(part.vertices.size());
        part.vertices.push_back(v);
        part.pslg.points.insert(part.pslg.points.end(), {T.point(v)[0], T.point(v)[1]});
      }
      return local[v];
    };
    for (uint32_t t : triangles)
      for (uint32_t e = 3 * t; e < 3 * t + 3; ++e) {
        const bool boundary = partOf[T.opp[e] / 3] != p;
        if (!T.fixed[e]) {
          if (boundary) return false;
          continue;
        }
        if (boundary && (T.segment.empty() || T.segment[e] == kNone)) return false;
        if (!boundary && e > T.opp[e]) continue;
        const uint32_t a = at(T.tri[e]), b = at(T.tri[next(e)]);
        const uint32_t input = T.segment.empty() ? 0 : T.segment[e];
        part.pslg.segments.insert(part.pslg.segments.end(), {a, b});
        part.origin.push_back(input);
        if (!boundary) {
          part.pslg.segments.insert(part.pslg.segments.end(), {b, a});
          part.origin.push_back(input);
        }
      }
    part.corners.reserve(3 * triangles.size());
    for (uint32_t t : triangles)  // (every corner, should one touch no fixed edge)
      for (uint32_t e = 3 * t; e < 3 * t + 3; ++e) part.corners.push_back(at(T.tri[e]));
    addFrame(part.pslg);
  }
  return true;
}

// How far each part's run has come (0..1), written by the thread running it, read by the
// one that reports; and the share of the whole each part stands for (its triangles).
class PartProgress {
 public:
  explicit PartProgress(const std::vector<Part>& parts)
      : done_(new std::atomic<double>[parts.size()]), weight_(parts.size()) {
    double total = 0;
    for (const Part& part : parts) total += double(part.triangleCount());
    for (size_t p = 0; p < parts.size(); ++p) {
      done_[p] = 0;
      weight_[p] = double(parts[p].triangleCount()) / total;
    }
  }
  // The round of runs now going on spans [from, to] of each part's fraction.
  void span(double from, double to) { from_ = from, to_ = to; }
  // Options::progress for part p's run: refinement's fraction, the round's end once done.
  void noteFrom(size_t p, const Progress& report) {
    const std::string phase = report.phase;
    if ((phase == "refine" || phase == "improve") && report.fraction >= 0)
      done_[p] = std::max(done_[p].load(), from_ + (to_ - from_) * report.fraction);
    else if (phase == "output")
      finish(p);
  }
  void finish(size_t p) { done_[p] = to_; }
  double share(size_t p) const { return weight_[p]; }
  double fraction() const {
    double sum = 0;
    for (size_t p = 0; p < weight_.size(); ++p) sum += weight_[p] * done_[p].load();
    return sum;
  }

 private:
  std::unique_ptr<std::atomic<double>[]> done_;
  std::vector<double> weight_;
  double from_ = 0, to_ = 1;
};

// A part's run. Memory running out on a worker thread goes to the calling thread, where
// mesh() says so, instead of ending the process.
void runPart(Part& part, const Options& options) {
#if defined(__cpp_exceptions) || defined(__EXCEPTIONS)
  try {
    part.result = meshInRange(part.pslg, options, 0, false);
  } catch (...) {
    part.failure = std::current_exception();
  }
#else
  part.result = meshInRange(part.pslg, options, 0, false);
#endif
}

// Whether a part's run ended with an acute mesh (the first certificate of a bound below 90).
bool isAcute(const Result& r) {
  return !r.mesh.triangles.empty() && r.stats.certified && r.stats.nonAcute == 0;
}

// Which round of runs (runParts): the only one; below 90 degrees the acute meshes (the parts'
// inputs kept for the next), then the descents.
enum class Round { Only, Acute, Descents };

// Runs every part's problem toward `target` on `threads` threads (the calling one alone for
// 1), the largest first so that the last to end are small; reports the whole's fraction from
// the calling thread, which alone may call Options::progress. No part starts once the time
// limit is reached (in the descents' round, nor once cancelled). In the descents' round each
// part's run may use its share (by weight) of the time left to the parts not yet started, and
// a part's acute mesh goes once its own run has one.
void runRound(std::vector<Part>& parts, const Options& target, const Budget& budget,
              unsigned threads, PartProgress& progress, Round round) {
  const bool shareTime = round == Round::Descents;
  std::vector<size_t> order(parts.size());
  for (size_t p = 0; p < parts.size(); ++p) order[p] = p;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return parts[a].triangleCount() > parts[b].triangleCount();
  });
  std::vector<double> weightFrom(order.size() + 1, 0);  // the weight of order[k..]
  for (size_t k = order.size(); k-- > 0;) weightFrom[k] = weightFrom[k + 1] + progress.share(order[k]);
  ProgressRelay* relay = budget.progress();
  auto report = [&] {
    if (!relay) return;
    relay->note("refine", progress.fraction(), 0);
    relay->poll();
  };
  std::atomic<size_t> next{0};
  auto work = [&](bool reporting) {
    for (size_t k; (k = next++) < order.size();) {
      const size_t p = order[k];
      // (Each would make its CDT before it heard that the time is up; a cancel is heard at a
      // run's first poll.)
      if (shareTime ? budget.stop() : budget.outOfTime()) {
        progress.finish(p);
        continue;
      }
      Options options = target;
      options.fill = FillRule::NonZero;
      options.convexHull = false;
      // The parts are the threads' work; but a part of more than a thread's share of the whole
      // would end last, alone: it gets them all, as the others are done.
      options.threads = progress.share(p) * threads > 1 ? threads : 1;
      // The search's seconds (Options::optimize) are the threads' seconds shared out by the
      // parts' weights, each part's over the threads it has, so that the parts' searches end
      // at about the time asked; its tries (optimizeTries) are per part and thread.
      options.optimize = target.optimize * progress.share(p) * threads / options.threads;
      if (target.timeLimit > 0) {  // (what is left of it; 0 would mean none)
        const double left = std::max(target.timeLimit - budget.elapsed(), 1e-9);
        options.timeLimit = shareTime ? left * progress.share(p) / weightFrom[k] : left;
      }
      options.progress = [&, p, reporting](const Progress& r) {
        progress.noteFrom(p, r);
        if (reporting) report();
      };
      runPart(parts[p], options);
      parts[p].outOfTime = options.timeLimit > 0 && parts[p].result.status != Status::Ok &&
                           parts[p].result.stats.seconds >= options.timeLimit;
      // (No longer needed, unless the run stopped before it had a mesh: the assembly takes the
      // part's CDT triangles (Part::corners) then, with its segments from here.)
      if (round != Round::Acute && !parts[p].result.mesh.triangles.empty()) parts[p].pslg = Pslg{};
      if (shareTime && isAcute(parts[p].result)) parts[p].acute = Result{};
      progress.finish(p);
      if (reporting) report();
    }
  };
#ifdef ACUTEMESH_THREADS
  if (threads > 1 && parts.size() > 1) {
    std::vector<std::thread> workers;
    std::atomic<size_t> running{0};
    for (unsigned i = 0; i < std::min<size_t>(threads, parts.size()); ++i) {
      ++running;
      workers.emplace_back([&] {
        work(false);
        --running;
      });
    }
    // (This thread reports, and hears a cancel from the callback, while they work; the runs
    // poll the cancel flag themselves.)
    while (running > 0) {
      report();
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    for (std::thread& worker : workers) worker.join();
    return;
  }
#endif
  (void)threads;
  work(true);
}

// Runs every part's problem (runRound). A bound below 90 degrees (or auto) goes in two rounds:
// every part's acute mesh first (quick), then each part's descent toward the bound in its
// share of the time left; a part whose descent a time limit or a cancel cut short before it
// had an acute mesh keeps the first round's. (In one round, the first parts' descents could
// spend the time and leave the last ones their CDT.)
void runParts(std::vector<Part>& parts, const Options& target, const Budget& budget,
              unsigned threads) {
  PartProgress progress(parts);
  if (target.mode != Mode::Acute || target.maxAngle >= 90) {
    runRound(parts, target, budget, threads, progress, Round::Only);
    return;
  }
  Options acute = target;
  acute.maxAngle = 90;
  acute.optimize = 0, acute.optimizeTries = 0;
  progress.span(0, kPartsAcuteShare);
  runRound(parts, acute, budget, threads, progress, Round::Acute);
  for (Part& part : parts) part.acute = std::move(part.result), part.result = Result{};
  progress.span(kPartsAcuteShare, 1);
  runRound(parts, target, budget, threads, progress, Round::Descents);
  for (Part& part : parts) {
    if (isAcute(part.result) || part.acute.mesh.triangles.empty()) continue;
    part.result = std::move(part.acute);
    part.result.stats.targetMet = false;  // (its target was 90 degrees)
  }
}

}  // namespace

bool meshByParts(Triangulation& T, const std::vector<uint8_t>& inside, const Pslg& input,
                 const std::vector<uint32_t>& inputOf, const Options& target, const Budget& budget,
                 Result& result) {
  if ((target.mode != Mode::Acute && target.mode != Mode::NonObtuse) || target.exactFeet ||
      target.maxSteiner)
    return false;
  std::vector<uint32_t> partOf;
  const uint32_t count = labelParts(T, inside, partOf);
  if (count < 2) return false;
  if (std::count_if(partOf.begin(), partOf.end(), [](uint32_t p) { return p != kNone; }) <
      long(kPartsFrom))
    return false;
  std::vector<Part> parts;
  if (!buildParts(T, partOf, count, parts)) return false;
  // The whole's store goes while the parts run (the United States: 190 MB): each part holds
  // its problem and its triangles, the assembly needs only the store's crossing points.
  const uint32_t storeVertices = T.vertexCount(), inputStored = uint32_t(inputOf.size());
  const std::vector<double> crossingPoints(T.pts.begin() + 2 * size_t(inputStored), T.pts.end());
  T = Triangulation{};
  std::vector<uint32_t>().swap(partOf);
#ifdef ACUTEMESH_THREADS
  const unsigned threads = threadsFor(target);
#else
  const unsigned threads = 1;
#endif
  runParts(parts, target, budget, threads);
#if defined(__cpp_exceptions) || defined(__EXCEPTIONS)
  for (const Part& part : parts)
    if (part.failure) std::rethrow_exception(part.failure);
#endif

  // A part's run refusing its input would be a fault here: the caller meshes the domain whole.
  for (const Part& part : parts)
    if (part.result.status == Status::BadInput && !budget.stop()) return false;

  // The mesh: input vertices at their indices, then T's other vertices and each part's
  // Steiner points as they come, part by part. A part whose run was stopped before it had a
  // mesh (a cancel, the time limit) keeps its triangles of T.
  Mesh& mesh = result.mesh;
  mesh = Mesh{};
  const uint32_t inputCount = uint32_t(input.vertexCount());
  mesh.points = input.points;
  mesh.vertexKind.assign(inputCount, kUnusedVertex);
  std::vector<uint32_t> index(storeVertices, kNone);
  std::copy(inputOf.begin(), inputOf.end(), index.begin());
  auto output = [&](uint32_t v) {  // T's vertex v in the mesh
    if (index[v] == kNone) {
      index[v] = uint32_t(mesh.vertexKind.size());
      const double* p = &crossingPoints[2 * size_t(v - inputStored)];
      mesh.points.insert(mesh.points.end(), {p[0], p[1]});
      mesh.vertexKind.push_back(kSegmentVertex);  // (a crossing point)
    } else if (v < inputOf.size()) {
      mesh.vertexKind[index[v]] = kInputVertex;
    }
    return index[v];
  };
  bool missed = false, cancelled = false, partCut = false;
  // The whole's twins from the parts' (each part's run leaves its store's in
  // Mesh::adjacency.halfedges; no edge joins two parts).
  std::vector<int32_t>& twin = mesh.adjacency.halfedges;
  bool twinsKnown = true;
  for (uint32_t p = 0; p < count; ++p) {
    Part& part = parts[p];
    const Mesh& m = part.result.mesh;
    missed |= !part.result.stats.targetMet || m.triangles.empty();
    cancelled |= part.result.status == Status::Cancelled;
    partCut |= part.outOfTime;
    twinsKnown &= !m.triangles.empty() && m.adjacency.halfedges.size() == m.triangles.size();
    if (twinsKnown) {
      const int32_t offset = int32_t(mesh.triangles.size());
      for (int32_t t : m.adjacency.halfedges) twin.push_back(t < 0 ? -1 : t + offset);
    }
    if (m.triangles.empty()) {  // (its triangles of T; the output labels find the twins)
      std::vector<uint32_t> to(part.vertices.size());
      for (uint32_t i = 0; i < to.size(); ++i) to[i] = output(part.vertices[i]);
      for (uint32_t v : part.corners) mesh.triangles.push_back(to[v]);
      const std::vector<uint32_t>& ends = part.pslg.segments;
      for (size_t i = 0; i < part.origin.size(); ++i) {
        if (i > 0 && ends[2 * i] == ends[2 * i - 1] && ends[2 * i + 1] == ends[2 * i - 2])
          continue;  // (an edge inside the part, its second way)
        mesh.segments.insert(mesh.segments.end(), {to[ends[2 * i]], to[ends[2 * i + 1]]});
        mesh.segmentInput.push_back(part.origin[i]);
      }
      continue;
    }
    std::vector<uint32_t> to(m.vertexCount());
    const uint32_t own = uint32_t(part.vertices.size());
    for (uint32_t i = 0; i < own; ++i) to[i] = output(part.vertices[i]);
    for (uint32_t i = own + kFrame; i < m.vertexCount(); ++i) {
      to[i] = uint32_t(mesh.vertexKind.size());
      mesh.points.insert(mesh.points.end(), {m.points[2 * size_t(i)], m.points[2 * size_t(i) + 1]});
      mesh.vertexKind.push_back(m.vertexKind[i]);
    }
    for (uint32_t v : m.triangles) mesh.triangles.push_back(to[v]);
    for (uint32_t v : m.segments) mesh.segments.push_back(to[v]);
    for (uint32_t s : m.segmentInput) mesh.segmentInput.push_back(part.origin[s]);
    part.result = Result{};
  }
  if (!twinsKnown) twin.clear();
  // A part short of its target is counted by the caller's certificate, which names the places
  // in the whole's numbering; only why it stopped is said here (a cancel that came while the
  // parts left were only improving leaves a mesh that meets the target).
  if (cancelled) {
    result.status = Status::Cancelled;
    result.message = missed ? "cancelled before every part met the target"
                            : "cancelled while removing Steiner points; the mesh meets the target";
  } else if (target.maxAngle == kAutoMaxAngle && target.mode == Mode::Acute && partCut) {
    // (Auto has no bound to miss; a part's descent cut short is said, as a whole run's is.)
    result.status = Status::TargetNotMet;
    result.message = "the time limit came before the lowest bound was found";
  } else if (missed && (partCut || budget.outOfTime())) {
    result.status = Status::TargetNotMet;
    result.message = "time limit reached before every triangle met the target";
  }
  return true;
}

}  // namespace acutemesh::detail
