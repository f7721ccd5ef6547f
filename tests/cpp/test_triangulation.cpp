// The half-edge store and the Delaunay builder, checked directly: twin consistency,
// orientation, the empty-circle property (brute force, exact), vertex removal.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>

#include "acutemesh/predicates.h"
#include "build.h"
#include "curve_order.h"
#include "refine/params.h"
#include "refine/state.h"
#include "triangulation.h"

using namespace acutemesh;
using namespace acutemesh::detail;

namespace {

// Every structural invariant of the store; returns the first violation found.
std::string checkStore(const Triangulation& T) {
  uint32_t ghosts = 0, reals = 0;
  for (uint32_t t = 0; t < T.triangleSlots(); ++t) {
    if (T.isFree(t)) continue;
    int ghostCorners = 0;
    for (uint32_t k = 0; k < 3; ++k) {
      uint32_t e = 3 * t + k, f = T.opp[e];
      if (f == kNone || T.isFree(f / 3)) return "half-edge " + std::to_string(e) + " has no twin";
      if (T.opp[f] != e) return "twins of " + std::to_string(e) + " disagree";
      if (T.tri[f] != T.tri[next(e)] || T.tri[next(f)] != T.tri[e])
        return "twin of " + std::to_string(e) + " has other endpoints";
      if (T.fixed[e] != T.fixed[f]) return "fixed flag differs across " + std::to_string(e);
      if (T.trackWinding && T.wind[e] != -T.wind[f]) return "winding not antisymmetric";
      if (T.trackSegments && T.segment[e] != T.segment[f]) return "segment differs between twins";
      ghostCorners += T.tri[e] == kGhost;
      if (T.tri[e] != kGhost && T.tri[e] >= T.vertexCount()) return "bad vertex index";
    }
    if (ghostCorners > 1) return "triangle " + std::to_string(t) + " has two ghost corners";
    if (ghostCorners == 1) {
      ++ghosts;
      continue;
    }
    ++reals;
    if (orient2d(T.point(T.tri[3 * t]), T.point(T.tri[3 * t + 1]), T.point(T.tri[3 * t + 2])) <= 0)
      return "triangle " + std::to_string(t) + " is not counter-clockwise";
  }
  for (uint32_t v = 0; v < T.vertexCount(); ++v) {
    uint32_t e = T.vertexEdge[v];
    if (e != kNone && (T.isFree(e / 3) || T.tri[e] != v))
      return "vertexEdge of " + std::to_string(v) + " is stale";
  }
  (void)reals;
  return {};
}

// Brute force: no vertex strictly inside any real triangle's circumcircle (edges not fixed).
size_t delaunayViolations(const Triangulation& T) {
  size_t bad = 0;
  for (uint32_t t = 0; t < T.triangleSlots(); ++t) {
    if (T.isFree(t) || T.isGhost(t)) continue;
    const double *a = T.point(T.tri[3 * t]), *b = T.point(T.tri[3 * t + 1]),
                 *c = T.point(T.tri[3 * t + 2]);
    for (uint32_t v = 0; v < T.vertexCount(); ++v)
      if (T.vertexEdge[v] != kNone && incircle(a, b, c, T.point(v)) > 0) ++bad;
  }
  return bad;
}

size_t realTriangles(const Triangulation& T) {
  size_t n = 0;
  for (uint32_t t = 0; t < T.triangleSlots(); ++t) n += !T.isFree(t) && !T.isGhost(t);
  return n;
}

// Builds the Delaunay triangulation of pts; canonical[i] is input vertex i's vertex in T.
Triangulation build(const std::vector<double>& pts, std::vector<uint32_t>* canonical = nullptr,
                    StepResult* result = nullptr) {
  Triangulation T;
  std::vector<uint32_t> local, inputOf;
  Options options;
  Budget budget(options);
  StepResult r = buildDelaunay(T, pts, canonical ? *canonical : local, inputOf, budget);
  if (result) *result = r;
  return T;
}

std::vector<double> randomPoints(size_t n, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<double> pts(2 * n);
  for (double& x : pts) x = u(rng);
  return pts;
}

}  // namespace

TEST(Triangulation, RandomPointsAreDelaunay) {
  for (uint64_t seed = 1; seed <= 5; ++seed) {
    Triangulation T = build(randomPoints(400, seed));
    EXPECT_EQ(checkStore(T), "");
    EXPECT_EQ(delaunayViolations(T), 0u);
  }
}

TEST(Triangulation, CocircularGridIsValidAndDelaunay) {
  std::vector<double> pts;
  for (int i = 0; i < 25; ++i)
    for (int j = 0; j < 25; ++j) pts.push_back(i), pts.push_back(j);
  Triangulation T = build(pts);
  EXPECT_EQ(checkStore(T), "");
  EXPECT_EQ(delaunayViolations(T), 0u);
  // A grid of n x n points has 2 (n-1)^2 triangles whatever the diagonals.
  EXPECT_EQ(realTriangles(T), 2u * 24 * 24);
}

TEST(Triangulation, CollinearRunsAndHullGrowth) {
  // Points inserted along a line first, then on both sides: exercises hull edges that are
  // collinear and insertion on ghost edges.
  std::vector<double> pts;
  for (int i = 0; i < 50; ++i) pts.push_back(i * 0.5), pts.push_back(0);
  for (int i = 0; i < 50; ++i) pts.push_back(i * 0.37), pts.push_back(i % 2 ? 3.0 : -2.0);
  Triangulation T = build(pts);
  EXPECT_EQ(checkStore(T), "");
  EXPECT_EQ(delaunayViolations(T), 0u);
}

TEST(Triangulation, DuplicatesMapToTheFirstEqualVertex) {
  std::vector<double> pts = {0, 0, 1, 0, 0, 1, 1, 0, 0.25, 0.25, 0, 0, 0.25, 0.25};
  std::vector<uint32_t> canonical;
  Triangulation T = build(pts, &canonical);
  EXPECT_EQ(checkStore(T), "");
  ASSERT_EQ(canonical.size(), 7u);
  // Whichever of two equal vertices was inserted first represents both.
  EXPECT_EQ(canonical[1], canonical[3]);
  EXPECT_EQ(canonical[0], canonical[5]);
  EXPECT_EQ(canonical[4], canonical[6]);
  EXPECT_EQ(realTriangles(T), 3u);
  size_t connected = 0;
  for (uint32_t v = 0; v < 7; ++v) connected += T.vertexEdge[v] != kNone;
  EXPECT_EQ(connected, 4u);
}

TEST(Triangulation, DegenerateInputsAreErrors) {
  StepResult r;
  build({0, 0, 1, 1, 2, 2, 3, 3}, nullptr, &r);
  EXPECT_EQ(r.status, Status::BadInput);
  EXPECT_NE(r.message.find("collinear"), std::string::npos) << r.message;
  build({1, 1, 1, 1, 1, 1}, nullptr, &r);
  EXPECT_EQ(r.status, Status::BadInput);
  EXPECT_NE(r.message.find("coincide"), std::string::npos) << r.message;
  build({1, 1, 2, 2}, nullptr, &r);
  EXPECT_EQ(r.status, Status::BadInput);
}

TEST(Triangulation, LocateReportsVertexEdgeAndTriangle) {
  std::vector<uint32_t> canonical;
  Triangulation T = build({0, 0, 4, 0, 0, 4, 4, 4}, &canonical);
  double onVertex[2] = {4, 0}, onEdge[2] = {2, 0}, inside[2] = {1, 2}, outside[2] = {9, 1};
  Location l = T.locate(onVertex, 0);
  EXPECT_EQ(l.where, Where::OnVertex);
  EXPECT_EQ(l.vertex, canonical[1]);
  l = T.locate(onEdge, 0);
  ASSERT_EQ(l.where, Where::OnEdge);
  EXPECT_EQ(orient2d(T.point(T.tri[l.edge]), T.point(T.tri[next(l.edge)]), onEdge), 0);
  EXPECT_EQ(T.locate(inside, 0).where, Where::InTriangle);
  l = T.locate(outside, 0);
  ASSERT_EQ(l.where, Where::InTriangle);
  EXPECT_TRUE(T.isGhost(l.tri));
}

TEST(Triangulation, RemoveVertexKeepsDelaunay) {
  Triangulation T = build(randomPoints(300, 7));
  std::mt19937 rng(3);
  size_t removed = 0;
  for (int attempt = 0; attempt < 200; ++attempt) {
    uint32_t v = rng() % 300;
    if (!T.removeVertex(v)) continue;  // hull vertices are not removable
    ++removed;
    ASSERT_EQ(checkStore(T), "") << "after removing " << v;
    ASSERT_EQ(T.vertexEdge[v], kNone);
  }
  EXPECT_GT(removed, 100u);
  EXPECT_EQ(delaunayViolations(T), 0u);
  // Every removed vertex can go back in.
  for (uint32_t v = 0; v < 300; ++v)
    if (T.vertexEdge[v] == kNone) {
      EXPECT_EQ(T.insert(v, 0), v);
    }
  EXPECT_EQ(checkStore(T), "");
  EXPECT_EQ(delaunayViolations(T), 0u);
}

TEST(Triangulation, RemoveVertexRefusesFixedAndHullVertices) {
  std::vector<uint32_t> v;
  Triangulation T = build({0, 0, 4, 0, 4, 4, 0, 4, 2, 2, 1, 2}, &v);
  EXPECT_FALSE(T.removeVertex(v[0]));  // on the hull
  uint32_t e = T.findEdge(v[4], v[5]);
  ASSERT_NE(e, kNone);
  T.fixEdge(e, 1);
  EXPECT_FALSE(T.removeVertex(v[4]));
  T.unfixEdge(e);
  EXPECT_TRUE(T.removeVertex(v[4]));
  EXPECT_EQ(checkStore(T), "");
}

// The journal (Triangulation::journal) takes back every change since a mark: insertions,
// removals, fixed edges and moved points, nested marks each to their own state, and the store
// then goes on as a copy from before would (its random walk's state included).
TEST(Triangulation, JournalTakesEveryChangeBack) {
  Triangulation T = build(randomPoints(300, 11));
  T.inside.assign(T.triangleSlots(), 0);
  for (uint32_t t = 0; t < T.triangleSlots(); ++t) T.inside[t] = !T.isFree(t) && !T.isGhost(t);
  auto same = [](const Triangulation& a, const Triangulation& b) -> std::string {
    if (a.triangleSlots() != b.triangleSlots()) return "slot count";
    if (a.liveTriangleCount() != b.liveTriangleCount()) return "free slots";
    if (a.pts != b.pts) return "points";
    if (a.vertexEdge != b.vertexEdge) return "vertex edges";
    for (size_t e = 0; e < 3 * size_t(a.triangleSlots()); ++e)
      if (a.tri[e] != b.tri[e] || a.opp[e] != b.opp[e] || a.fixed[e] != b.fixed[e])
        return "half-edge " + std::to_string(e);
    for (uint32_t t = 0; t < a.triangleSlots(); ++t)
      if (a.inside[t] != b.inside[t]) return "inside " + std::to_string(t);
    return "";
  };
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-0.9, 0.9);
  auto change = [&](Triangulation& S) {
    for (int i = 0; i < 20; ++i) {
      const uint32_t v = S.addVertex(u(rng), u(rng));
      S.insert(v, 0);
    }
    for (int i = 0; i < 20; ++i) S.removeVertex(uint32_t(rng() % 300));
    for (int i = 0; i < 5; ++i) {
      const uint32_t t = uint32_t(rng() % S.triangleSlots());
      if (!S.isFree(t) && !S.isGhost(t) && !S.isFixed(3 * t)) S.fixEdge(3 * t, 1);
    }
    for (int i = 0; i < 10; ++i) {  // (a point moved: the caller notes it)
      const uint32_t v = uint32_t(rng() % 300);
      S.notePoint(v);
      S.pts[2 * size_t(v)] += 1e-9;
    }
  };
  Journal journal;
  const Triangulation before = T;
  T.journal = &journal;
  const Journal::Mark outer = T.mark();
  change(T);
  const Triangulation between = [&] {
    Triangulation copy = T;
    copy.journal = nullptr;
    return copy;
  }();
  const Journal::Mark inner = T.mark();
  change(T);
  ASSERT_NE(same(T, between), "") << "the changes changed nothing";
  T.undoTo(inner);
  EXPECT_EQ(same(T, between), "") << "back to the inner mark";
  EXPECT_EQ(checkStore(T), "");
  T.undoTo(outer);
  EXPECT_EQ(same(T, before), "") << "back to the outer mark";
  EXPECT_EQ(checkStore(T), "");
  EXPECT_TRUE(journal.slots.empty() && journal.edges.empty() && journal.points.empty());
  T.journal = nullptr;
  Triangulation copy = before;
  for (int i = 0; i < 50; ++i) {
    const double x = u(rng), y = u(rng);
    T.insert(T.addVertex(x, y), 0);
    copy.insert(copy.addVertex(x, y), 0);
  }
  EXPECT_EQ(same(T, copy), "") << "the store went on otherwise than a copy";
}

// The improvement passes visit every live vertex of the range once: by index on small meshes
// (their point counts depend on it), and on large ones along a Hilbert curve, each vertex near
// the one before (the cache holds its neighbourhood), where refinement's numbering jumps about.
TEST(RefineState, VisitOrderIsEveryLiveVertexOnceAndLocalWhenLarge) {
  auto stepLength = [](const RefineState& s, const std::vector<uint32_t>& order) {
    double sum = 0;
    for (size_t i = 1; i < order.size(); ++i)
      sum += std::hypot(s.P(order[i])[0] - s.P(order[i - 1])[0],
                        s.P(order[i])[1] - s.P(order[i - 1])[1]);
    return sum / double(order.size() - 1);
  };
  for (size_t n : {size_t(500), kSpatialOrderFrom + 6000}) {
    // (Vertices numbered in the order they go in, as refinement numbers its points: random
    // here, where the Delaunay build would number them along its own curve.)
    const std::vector<double> pts = randomPoints(n, 5);
    RefineState s;
    s.T = build({pts.begin(), pts.begin() + 6});
    uint32_t hint = 0;
    for (size_t i = 6; i < pts.size(); i += 2)
      hint = s.T.vertexEdge[s.T.insert(s.T.addVertex(pts[i], pts[i + 1]), hint)] / 3;
    size_t removed = 0;
    for (uint32_t v = 7; v < n; v += 13) removed += s.T.removeVertex(v);
    ASSERT_GT(removed, n / 20);
    const uint32_t from = 100;
    std::vector<uint32_t> order, expected;
    s.visitOrder(from, uint32_t(n), order);
    for (uint32_t v = from; v < n; ++v)
      if (s.T.vertexEdge[v] != kNone) expected.push_back(v);
    if (n < kSpatialOrderFrom) {
      EXPECT_EQ(order, expected);
      continue;
    }
    EXPECT_GE(order.size(), kSpatialOrderFrom);
    std::vector<uint32_t> sorted = order;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(sorted, expected) << "not every live vertex once";
    EXPECT_LT(stepLength(s, order), 0.05 * stepLength(s, expected));
  }
}

// The curve order (curve_order.h) puts every item once, each near the one before, and items at
// one place in their given order (the Delaunay build keeps the first of equal vertices), both
// by comparisons (small sets) and by radix passes.
// The Hilbert index, table-driven, against the curve's definition one level at a time (the
// rotate-and-flip recursion): every cell of a 256 x 256 corner, the grid's edges, and random
// cells.
TEST(CurveOrder, HilbertIndexFollowsTheCurveLevelByLevel) {
  auto byLevels = [](uint32_t x, uint32_t y) {
    uint32_t d = 0;
    for (uint32_t s = 1u << 15; s > 0; s >>= 1) {
      const uint32_t rx = (x & s) ? 1 : 0, ry = (y & s) ? 1 : 0;
      d += s * s * ((3 * rx) ^ ry);
      if (ry == 0) {
        if (rx == 1) x = s - 1 - x, y = s - 1 - y;
        std::swap(x, y);
      }
      x &= s - 1, y &= s - 1;
    }
    return d;
  };
  size_t wrong = 0;
  for (uint32_t x = 0; x < 256; ++x)
    for (uint32_t y = 0; y < 256; ++y) wrong += hilbertIndex(x, y) != byLevels(x, y);
  for (uint32_t k = 0; k < 65536; ++k)
    wrong += (hilbertIndex(k, 65535) != byLevels(k, 65535)) +
             (hilbertIndex(65535, k) != byLevels(65535, k));
  std::mt19937 rng(4);
  for (int i = 0; i < 1000000; ++i) {
    const uint32_t x = rng() & 0xFFFF, y = rng() & 0xFFFF;
    wrong += hilbertIndex(x, y) != byLevels(x, y);
  }
  EXPECT_EQ(wrong, 0u);
  // (A curve: consecutive indices are neighbouring cells.)
  std::vector<uint32_t> at(256 * 256);
  for (uint32_t x = 0; x < 256; ++x)
    for (uint32_t y = 0; y < 256; ++y) at[hilbertIndex(x << 8, y << 8) >> 16] = (x << 8) | y;
  size_t jumps = 0;
  for (size_t k = 1; k < at.size(); ++k) {
    const int dx = int(at[k] >> 8) - int(at[k - 1] >> 8),
              dy = int(at[k] & 255) - int(at[k - 1] & 255);
    jumps += std::abs(dx) + std::abs(dy) != 1;
  }
  EXPECT_EQ(jumps, 0u);
}

TEST(CurveOrder, EveryItemOnceLocalAndTiesInOrder) {
  for (size_t n : {size_t(3000), kRadixFrom + 5000}) {
    const std::vector<double> pts = randomPoints(n, 6);
    std::vector<uint32_t> items(2 * n);  // item i and item n + i at the same place
    for (uint32_t i = 0; i < 2 * n; ++i) items[i] = i;
    auto place = [&](uint32_t i, double* p) {
      p[0] = pts[2 * (i % n)], p[1] = pts[2 * (i % n) + 1];
    };
    sortAlongCurve(items, place);
    std::vector<uint32_t> seen(2 * n, 0), at(2 * n);
    for (size_t k = 0; k < items.size(); ++k) ++seen[items[k]], at[items[k]] = uint32_t(k);
    EXPECT_EQ(std::count(seen.begin(), seen.end(), 1u), long(2 * n));
    size_t inOrder = 0;
    for (uint32_t i = 0; i < n; ++i) inOrder += at[i] < at[n + i];
    EXPECT_EQ(inOrder, n) << "items at one place not in their given order";
    auto stepLength = [&](const std::vector<uint32_t>& order) {
      double sum = 0, a[2], b[2];
      for (size_t k = 1; k < order.size(); ++k) {
        place(order[k - 1], a), place(order[k], b);
        sum += std::hypot(a[0] - b[0], a[1] - b[1]);
      }
      return sum;
    };
    std::vector<uint32_t> shuffled = items;
    std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(2));
    EXPECT_LT(stepLength(items), 0.05 * stepLength(shuffled));
  }
}

// A polish round's way back (Triangulation::Compact) makes the very store again: the same
// slots, twins, flags, segments and vertex edges, and (free list, walk) the same store after
// more work.
TEST(Triangulation, CompactRestoresTheVeryStore) {
  Triangulation T = build(randomPoints(3000, 17));
  T.trackSegments = true;
  T.segment.assign(T.tri.size(), kNone);
  T.inside.assign(T.tri.size() / 3, 1);
  for (uint32_t v = 5; v < 3000; v += 11) T.removeVertex(v);  // free slots
  uint32_t marked = 0;
  for (uint32_t e = 0; e < 3 * T.triangleSlots() && marked < 40; e += 97)
    if (!T.isFree(e / 3) && !T.isGhost(e / 3) && !T.isFixed(e)) T.fixEdge(e, 0, marked++);
  T.trimToSlots();
  const Triangulation original = T;
  Triangulation::Compact c = T.compact();
  EXPECT_EQ(c.marked.size(), 2 * size_t(marked));  // (both halves of each fixed edge)
  Triangulation restored = build(randomPoints(100, 18));  // something else entirely first
  restored.restore(std::move(c));
  auto same = [](const Triangulation& a, const Triangulation& b) {
    EXPECT_EQ(a.triangleSlots(), b.triangleSlots());
    EXPECT_EQ(a.tri, b.tri);
    EXPECT_EQ(a.opp, b.opp);
    EXPECT_EQ(a.fixed, b.fixed);
    EXPECT_EQ(a.segment, b.segment);
    EXPECT_EQ(a.vertexEdge, b.vertexEdge);
    EXPECT_EQ(a.pts, b.pts);
    EXPECT_EQ(a.inside, b.inside);
  };
  same(restored, original);
  EXPECT_EQ(checkStore(restored), "");
  Triangulation again = original;
  const std::vector<double> more = randomPoints(500, 19);
  for (Triangulation* t : {&restored, &again})
    for (size_t i = 0; i < more.size(); i += 2) t->insert(t->addVertex(more[i], more[i + 1]), 0);
  same(restored, again);
}

namespace {
// Every live triangle as its corners, rotated to start at the smallest, sorted.
std::vector<std::array<uint32_t, 3>> triangleSet(const Triangulation& T) {
  std::vector<std::array<uint32_t, 3>> set;
  for (uint32_t t = 0; t < T.triangleSlots(); ++t) {
    if (T.isFree(t)) continue;
    std::array<uint32_t, 3> c = {T.tri[3 * t], T.tri[3 * t + 1], T.tri[3 * t + 2]};
    std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
    set.push_back(c);
  }
  std::sort(set.begin(), set.end());
  return set;
}
}  // namespace

// Renumbering the triangles (RefineState::compactTriangles along the curve, or any order)
// keeps the triangulation as it was, with twins, vertex edges, fixed edges and segments moved
// along, and the free slots gone.
TEST(Triangulation, PermuteSlotsKeepsTheTriangulation) {
  Triangulation T = build(randomPoints(2000, 9));
  T.trackSegments = true;
  T.segment.assign(T.tri.size(), kNone);
  size_t fixedEdges = 0;
  for (uint32_t e = 0; e < 3 * T.triangleSlots() && fixedEdges < 40; e += 97)
    if (!T.isFree(e / 3) && !T.isFixed(e)) T.fixEdge(e, 0, uint32_t(e)), ++fixedEdges;
  for (uint32_t v = 5; v < 2000; v += 11) T.removeVertex(v);  // (fixed ends refuse: fine)
  const auto before = triangleSet(T);
  std::vector<std::pair<uint32_t, uint32_t>> fixedBefore;
  for (uint32_t e = 0; e < 3 * T.triangleSlots(); ++e)
    if (!T.isFree(e / 3) && T.isFixed(e)) fixedBefore.push_back({T.tri[e], T.segment[e]});
  std::sort(fixedBefore.begin(), fixedBefore.end());
  std::vector<uint32_t> order;
  for (uint32_t t = 0; t < T.triangleSlots(); ++t)
    if (!T.isFree(t)) order.push_back(t);
  ASSERT_LT(order.size(), T.triangleSlots()) << "no free slot to drop";
  std::shuffle(order.begin(), order.end(), std::mt19937(4));
  T.permuteSlots(order);
  EXPECT_EQ(T.triangleSlots(), order.size());
  EXPECT_EQ(checkStore(T), "");
  EXPECT_EQ(triangleSet(T), before);
  std::vector<std::pair<uint32_t, uint32_t>> fixedAfter;
  for (uint32_t e = 0; e < 3 * T.triangleSlots(); ++e)
    if (T.isFixed(e)) fixedAfter.push_back({T.tri[e], T.segment[e]});
  std::sort(fixedAfter.begin(), fixedAfter.end());
  EXPECT_EQ(fixedAfter, fixedBefore);
  // Still a working store: points go in and out.
  for (uint32_t v = 5; v < 200; v += 11) EXPECT_EQ(T.insert(v, 0), v);
  EXPECT_EQ(checkStore(T), "");
  EXPECT_EQ(delaunayViolations(T), 0u);

  RefineState s;
  s.T = build(randomPoints(kSpatialOrderFrom + 1000, 3));
  const auto all = triangleSet(s.T);
  s.compactTriangles(0);
  EXPECT_EQ(checkStore(s.T), "");
  EXPECT_EQ(triangleSet(s.T), all);
}

// Trimmed to its slots (the polish does it before copying the state), the store gives back its
// spare tail, keeps its free slots, and grows again as points go in.
TEST(Triangulation, TrimToSlotsKeepsTheStoreWorking) {
  Triangulation T = build(randomPoints(1000, 12));
  T.reserveTriangles(4 * size_t(T.triangleSlots()));
  for (uint32_t v = 3; v < 1000; v += 7) T.removeVertex(v);
  const auto before = triangleSet(T);
  T.trimToSlots();
  EXPECT_EQ(T.tri.size(), 3 * size_t(T.triangleSlots()));
  EXPECT_EQ(T.opp.capacity(), 3 * size_t(T.triangleSlots()));
  EXPECT_EQ(checkStore(T), "");
  EXPECT_EQ(triangleSet(T), before);
  std::vector<double> more = randomPoints(3000, 13);
  for (size_t i = 0; i < more.size(); i += 2) T.insert(T.addVertex(more[i], more[i + 1]), 0);
  EXPECT_EQ(checkStore(T), "");
  EXPECT_EQ(delaunayViolations(T), 0u);
}

// The slots' arrays are filled (so resident) only a little past the slots in use as they grow,
// whatever room was set aside: a map with as many duplicate vertices as distinct ones (room
// for two triangles per vertex) and a store that grows from nothing both stay within an
// eighth.
TEST(Triangulation, FilledArraysStayNearTheSlotsInUse) {
  const std::vector<double> distinct = randomPoints(20000, 14);
  std::vector<double> twice = distinct;
  twice.insert(twice.end(), distinct.begin(), distinct.end());
  Triangulation T;
  T.reserveCapacity(twice.size() / 2, twice.size() + 16);
  std::vector<uint32_t> canonical, inputOf;
  Options options;
  Budget budget(options);
  ASSERT_TRUE(buildDelaunay(T, twice, canonical, inputOf, budget).ok());
  auto filled = [&] { return T.tri.size() / 3; };
  EXPECT_LE(filled(), T.triangleSlots() + T.triangleSlots() / 8 + 1024);
  EXPECT_GE(T.tri.capacity() / 3, twice.size());  // (the room stays: no copy was made)
  EXPECT_EQ(checkStore(T), "");

  Triangulation grown = build(randomPoints(1000, 15));
  const std::vector<double> more = randomPoints(20000, 16);
  uint32_t hint = 0;
  for (size_t i = 0; i < more.size(); i += 2)
    hint = grown.vertexEdge[grown.insert(grown.addVertex(more[i], more[i + 1]), hint)] / 3;
  EXPECT_LE(grown.tri.size() / 3, grown.triangleSlots() + grown.triangleSlots() / 8 + 1024);
  EXPECT_EQ(grown.opp.size(), grown.tri.size());
  EXPECT_EQ(checkStore(grown), "");
}
