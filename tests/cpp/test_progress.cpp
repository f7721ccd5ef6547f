// Options::progress: a fraction that moves, reports often enough to draw a bar and to cancel
// from. Timings are asserted loosely (a loaded 2-core machine stretches every gap).
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "acutemesh/acutemesh.h"
#include "acutemesh/vocabulary.h"
#include "fixtures.h"

using namespace acutemesh;

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

Pslg randomPoints(int n) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(0, 1);
  Pslg in;
  for (int i = 0; i < 2 * n; ++i) in.points.push_back(u(rng));
  return in;
}

// A gear: 40 teeth around a round hole. Below 90 degrees its descent runs for seconds.
Pslg gear() {
  Pslg in;
  const int teeth = 40, hole = 30;
  for (int i = 0; i < teeth; ++i)
    for (const auto& [f, r] : {std::pair{0.0, 9.0}, {0.2, 10.0}, {0.5, 10.0}, {0.7, 9.0}}) {
      const double a = 2 * M_PI * (i + f) / teeth;
      in.points.insert(in.points.end(), {r * std::cos(a), r * std::sin(a)});
    }
  for (int k = 0; k < hole; ++k)
    in.points.insert(in.points.end(),
                     {3 * std::cos(2 * M_PI * k / hole), 3 * std::sin(2 * M_PI * k / hole)});
  const uint32_t outer = 4 * teeth;
  for (uint32_t k = 0; k < outer; ++k) in.segments.insert(in.segments.end(), {k, (k + 1) % outer});
  for (uint32_t k = 0; k < uint32_t(hole); ++k)
    in.segments.insert(in.segments.end(), {outer + k, outer + (k + 1) % hole});
  in.holes = {0, 0};
  return in;
}

// A coastline: a 16-gon whose edges are split again and again at points pushed off their
// middles (a fixed seed), 8,192 vertices, with two lakes; even-odd fill.
Pslg coastline() {
  std::mt19937_64 rng(25);
  Pslg in;
  fixtures::addRing(in, fixtures::coastline(rng, 0, 0, 100, 16, 9));
  fixtures::addRing(in, fixtures::coastline(rng, -30, 10, 12, 8, 5));
  fixtures::addRing(in, fixtures::coastline(rng, 35, -20, 8, 8, 5));
  return in;
}

bool refining(const char* phase) {
  return std::strcmp(phase, "refine") == 0 || std::strcmp(phase, "improve") == 0;
}

struct Report {
  double at;
  std::string phase;
  double fraction;
};

// The refinement's fraction is in [0, 1], never goes down, takes many values, and the reports
// come often: in a run of about a second, the longest gap between two is well under its length.
TEST(Progress, FractionMovesAndReportsCome) {
  const Pslg in = randomPoints(10000);
  Options o;
  o.mode = Mode::Acute;
  o.threads = 1;
  std::vector<Report> reports;
  const Clock::time_point start = Clock::now();
  o.progress = [&](const Progress& p) { reports.push_back({since(start), p.phase, p.fraction}); };
  const Result r = mesh(in, o);
  const double seconds = since(start);
  ASSERT_EQ(r.status, Status::Ok) << r.message;

  std::set<double> values;
  double last = 0, gap = 0, previous = 0;
  size_t during = 0;
  for (const Report& p : reports) {
    gap = std::max(gap, p.at - previous);
    previous = p.at;
    if (!refining(p.phase.c_str())) continue;
    ++during;
    EXPECT_GE(p.fraction, 0) << p.phase << " at " << p.at;
    EXPECT_LE(p.fraction, 1);
    EXPECT_GE(p.fraction, last) << p.phase << " at " << p.at;
    last = p.fraction;
    values.insert(p.fraction);
  }
  // One report per 40 ms of work; a busy machine may stretch that, so ask for a fifth of it.
  EXPECT_GE(double(during), 0.2 * seconds / 0.04) << seconds << " s";
  EXPECT_GE(values.size(), 5u);
  EXPECT_LT(gap, std::max(0.5, seconds / 3)) << "of " << seconds << " s";
}

// A cancel asked for from the callback (as the JavaScript package does: it has no other way in)
// lands soon, also in the descent below 90 degrees, whose levels take seconds each.
TEST(Progress, CancelFromTheCallbackLandsSoon) {
  for (double maxAngle : {90.0, 80.0}) {
    const Pslg in = maxAngle < 90 ? gear() : randomPoints(20000);
    std::atomic<bool> cancel{false};
    Options o;
    o.mode = Mode::Acute;
    o.maxAngle = maxAngle;
    o.threads = 1;
    o.cancel = &cancel;
    const Clock::time_point start = Clock::now();
    double asked = -1;
    // The user decides to stop 0.3 s into the refinement; the callback is where it can say so.
    o.progress = [&](const Progress& p) {
      if (asked < 0 && refining(p.phase) && since(start) > 0.3) {
        asked = since(start);
        cancel = true;
      }
    };
    const Result r = mesh(in, o);
    const double ended = since(start);
    ASSERT_GE(asked, 0) << maxAngle << ": the run ended after " << ended << " s, before the cancel";
    EXPECT_EQ(r.status, Status::Cancelled) << maxAngle << ": " << r.message;
    // Reports every 40 ms, and the core stops at the next poll: 0.5 s leaves room for a busy
    // machine (before the relay, below 90 degrees it took seconds).
    EXPECT_LT(ended - 0.3, 0.5) << maxAngle << ": asked at " << asked << " s, ended at " << ended;
  }
}

}  // namespace

// Below 90 degrees the fraction moves within each bound of the descent too (its rounds), not
// only from one bound to the next: the longest time it stands still is a small part of the run.
TEST(Progress, FractionMovesBelow90) {
  const Pslg in = gear();
  Options o;
  o.mode = Mode::Acute;
  o.maxAngle = 75;
  o.threads = 1;
  std::vector<Report> reports;
  const Clock::time_point start = Clock::now();
  o.progress = [&](const Progress& p) { reports.push_back({since(start), p.phase, p.fraction}); };
  mesh(in, o);
  const double seconds = since(start);
  double stillSince = 0, still = 0, last = -1;
  for (const Report& p : reports) {
    if (!refining(p.phase.c_str())) continue;
    EXPECT_GE(p.fraction, last) << p.phase << " at " << p.at;
    if (p.fraction > last) stillSince = p.at, last = p.fraction;
    still = std::max(still, p.at - stillSince);
  }
  still = std::max(still, seconds - stillSince);
  RecordProperty("seconds", std::to_string(seconds));
  EXPECT_LT(still, std::max(0.5, seconds / 4)) << "the fraction stood still for " << still
                                               << " s of " << seconds << " s";
}

// A large input (a generated coastline, the kind of outline maps bring) in both certified
// modes: every mesh valid and certified; the fraction moves steadily enough to tell what is
// left: it never stands still for long (the first queue's weighing, the strategies' runs, the
// polish's rounds and their halves all move it) and is neither near 0 nor near 1 halfway
// through; a cancel from the callback midway lands soon with a valid mesh.
TEST(Progress, LargeCoastlineMovesSteadilyAndCancels) {
  const Pslg in = coastline();
  for (Mode mode : {Mode::Acute, Mode::NonObtuse}) {
    Options o;
    o.mode = mode;
    o.fill = FillRule::EvenOdd;
    std::vector<Report> reports;
    const Clock::time_point start = Clock::now();
    o.progress = [&](const Progress& p) { reports.push_back({since(start), p.phase, p.fraction}); };
    const Result r = mesh(in, o);
    const double seconds = since(start);
    ASSERT_EQ(r.status, Status::Ok) << r.message;
    EXPECT_TRUE(r.stats.certified);
    EXPECT_EQ(fixtures::validationErrors(in, o, r.mesh), "");
    EXPECT_GT(r.mesh.triangleCount(), 8192u);
    double stillSince = 0, still = 0, last = -1, refineFrom = -1;
    std::string stillAt;  // the phase and fraction of the longest stand
    for (const Report& p : reports) {
      if (!refining(p.phase.c_str())) continue;
      if (refineFrom < 0) refineFrom = stillSince = p.at;
      EXPECT_GE(p.fraction, last) << p.phase << " at " << p.at;
      if (p.fraction > last) stillSince = p.at, last = p.fraction;
      if (p.at - stillSince > still)
        still = p.at - stillSince, stillAt = p.phase + " at " + std::to_string(p.fraction);
    }
    ASSERT_GE(refineFrom, 0) << "no refinement report";
    const double span = seconds - refineFrom;
    double halfway = 0;  // the fraction halfway through the refinement
    for (const Report& p : reports)
      if (refining(p.phase.c_str()) && p.at <= refineFrom + span / 2) halfway = p.fraction;
    RecordProperty(std::string(nameOf(mode)) + "_seconds", std::to_string(seconds));
    EXPECT_LT(still, std::max(0.3, span / 10))
        << nameOf(mode) << ": the fraction stood still for " << still << " s of " << span
        << " (" << stillAt << ")";
    EXPECT_GT(halfway, 0.15) << nameOf(mode) << " (" << span << " s)";
    EXPECT_LT(halfway, 0.85) << nameOf(mode) << " (" << span << " s)";

    // The same run cancelled from the callback once the refinement is half done (by its own
    // fraction, not the clock: a loaded machine slows one run and not the other).
    double asked = -1;
    Options c = o;
    std::atomic<bool> cancel{false};
    c.cancel = &cancel;
    const Clock::time_point again = Clock::now();
    c.progress = [&](const Progress& p) {
      if (asked < 0 && refining(p.phase) && p.fraction >= 0.5) asked = since(again), cancel = true;
    };
    const Result cut = mesh(in, c);
    const double ended = since(again);
    ASSERT_GE(asked, 0) << nameOf(mode) << ": ended after " << ended << " s, before the cancel";
    EXPECT_EQ(cut.status, Status::Cancelled) << cut.message;
    EXPECT_LT(ended - asked, 0.5) << nameOf(mode) << ": asked at " << asked << " s";
    Options plain = o;
    plain.mode = Mode::Cdt;  // (a cancelled mesh meets no angle target: check it as a CDT's)
    EXPECT_EQ(fixtures::validationErrors(in, plain, cut.mesh), "") << nameOf(mode);
  }
}

// A cancel asked for as the Delaunay phase ends stops the segments' insertion, not the phase
// after it (the United States' segments take 0.2 s), in both ways of inserting them: after
// the Delaunay triangulation (a coastline) and along with their ends (a large star polygon).
TEST(Progress, CancelLandsInTheSegmentsPhase) {
  const Pslg star = fixtures::starPolygon(20000, 3);
  for (const Pslg& in : {coastline(), star}) {
    std::atomic<bool> cancel{false};
    Options o;
    o.mode = Mode::Acute;
    o.fill = FillRule::EvenOdd;
    o.cancel = &cancel;
    o.progress = [&](const Progress& p) {
      if (std::string(p.phase) == "delaunay" && p.fraction == 1) cancel = true;
    };
    const Result r = mesh(in, o);
    EXPECT_EQ(r.status, Status::Cancelled) << r.message;
    EXPECT_EQ(r.message, "stopped while inserting the segments");
  }
}
