// One walk of an input segment along mesh edges (see segment_walker.h for its rules).
// Fixtures named below are in tests/data/bad/.
#include <algorithm>
#include <limits>

#include "segment_walker.h"

namespace acutemesh::validation {

using detail::nearLine;
using detail::nearSegment;

void SegmentWalker::walkAll() {
  chains_.assign(c_.in.segmentCount(), {});
  for (uint32_t s = 0; s < c_.in.segmentCount(); ++s) walkSegment(s);
}

// Walks that may also leave the domain where an edge goes on are tried only when no stricter
// walk gets through; the segment is reported along the strict walk of first choices.
void SegmentWalker::walkSegment(uint32_t s) {
  uint32_t a = c_.in.segments[2 * s], b = c_.in.segments[2 * s + 1];
  const double *A = c_.inP(a), *B = c_.inP(b);
  if (A[0] == B[0] && A[1] == B[1]) return;
  SegmentWalk walk{s, a, b, A, B};
  walk.leaveAnywhere = false;
  if (walkDepthFirst(walk, true)) return;
  walk.leaveAnywhere = true;
  if (walkDepthFirst(walk, true)) return;
  walk.leaveAnywhere = false;
  walkDepthFirst(walk, false);
}

// The boundary vertices on the segment (within rounding reach) past position k, in order:
// the index of the first in w.entries.
size_t SegmentWalker::entriesAfter(SegmentWalk& w, double k) {
  if (!w.haveEntries) {
    w.haveEntries = true;
    const double *A = w.A, *B = w.B;
    double r = w.reach;
    double box[8][2] = {{A[0] - r, A[1] - r}, {A[0] + r, A[1] - r}, {A[0] + r, A[1] + r},
                        {A[0] - r, A[1] + r}, {B[0] - r, B[1] - r}, {B[0] + r, B[1] - r},
                        {B[0] + r, B[1] + r}, {B[0] - r, B[1] + r}};
    const double* around[8];
    for (int i = 0; i < 8; ++i) around[i] = box[i];
    // From a rounding before a: where a is no mesh vertex, a rounded crossing may stand in
    // for it an ulp behind it (overlap-reaches-through-triangle.poly).
    boundaryGrid().forEachNear(around, 8, [&](const Query& q) {
      if (w.key(q.xy) >= w.key(A) - r && w.key(q.xy) <= w.key(B) && nearLine(A, B, q.xy))
        w.entries.push_back(q.id);
    });
    std::sort(w.entries.begin(), w.entries.end(),
              [&](uint32_t u, uint32_t v) { return w.key(P(u)) < w.key(P(v)); });
  }
  size_t i = 0;
  while (i < w.entries.size() && w.key(P(w.entries[i])) <= k) ++i;
  return i;
}

// The steps from cur, best first: edges to a vertex exactly on the segment and closer to
// b, then listed edges to vertices within rounding reach, the most advanced first; with no
// such edge, the jump to the next boundary vertex if the segment leaves the domain at cur.
// The walk of first choices (backtrack false) logs why it is stuck at cur, if it is.
void SegmentWalker::walkSteps(SegmentWalk& w, uint32_t cur, bool backtrack,
                              std::vector<WalkStep>& out) {
  out.clear();
  const double *A = w.A, *B = w.B;
  auto key = [&](const double* p) { return w.key(p); };
  auto name = reporter(w, !backtrack);
  uint32_t past = kNone;
  // An edge runs past b only from a vertex exactly on the segment: from a rounded one it
  // does not lie along the segment to begin with (boundary-edge-along-segment-past-its-end).
  bool curOn = orient2d(A, B, P(cur)) == 0;
  size_t exactCount = 0;
  const uint32_t end = vertices_.rep[w.b];
  topo_.forEachEdge(cur, [&](uint32_t c, uint32_t h) {
    bool on = orient2d(A, B, P(c)) == 0;
    if (c == end && listed_[canon(h)]) {
      // A listed edge to b ends the walk, even from a rounding past b or beside it
      // (chain-overshoots-its-end, end-an-ulp-above-the-chain).
      out.insert(out.begin() + long(exactCount++), {c, h});
    } else if (on && key(P(c)) > key(P(cur)) && onSegment_[c] != w.s) {
      // Never back to a vertex of this walk (overlap-back-step).
      if (key(P(c)) > key(B)) {
        if (curOn) past = c;
      } else {
        out.insert(out.begin() + long(exactCount++), {c, h});
      }
    } else if (listed_[canon(h)] && onSegment_[c] != w.s && key(P(c)) <= key(B) + w.reach &&
               (on || nearLine(A, B, P(c)))) {
      // Up to a rounding past b: a chain may reach b from a rounded crossing an ulp beyond it.
      out.push_back({c, h});
    }
  });
  // The most advanced near step first.
  std::sort(out.begin() + long(exactCount), out.end(),
            [&](const WalkStep& x, const WalkStep& y) { return key(P(x.to)) > key(P(y.to)); });
  // A near step that does not advance (roundings out of order) is for a chain that would
  // otherwise be stuck inside the mesh: where the segment leaves the mesh at cur, it leaves
  // (overlap-sideways-step: a listed edge an ulp long beside the start).
  uint32_t toward = topo_.triangleToward(cur, B);
  if (toward == kNone)
    out.erase(std::remove_if(out.begin() + long(exactCount), out.end(),
                             [&](const WalkStep& x) { return key(P(x.to)) <= key(P(cur)); }),
              out.end());
  if (w.preferListed) {  // listed edges no walk took, then the other listed ones; no others
    // Two passes rather than std::stable_sort: libstdc++ 12's temporary buffer trips ASan's
    // alloc-dealloc check.
    preferred_.clear();
    for (bool walked : {false, true})
      for (const WalkStep& z : out)
        if (listed_[canon(z.he)] && (marked_[canon(z.he)] > 0) == walked) preferred_.push_back(z);
    out.swap(preferred_);
  }
  if (!out.empty()) {
    if (!backtrack || !w.leaveAnywhere || toward != kNone) return;
  } else if (past != kNone) {
    return name("is not a chain of mesh edges: mesh edge ", cur, "-", past, " runs past ", w.b);
  } else if (toward != kNone) {
    return name("is not a chain of mesh edges: stops at vertex ", cur, " and enters ",
                topo_.tri(toward));
  }
  // The segment leaves the domain at cur (with w.leaveAnywhere also where an edge goes on).
  entrySteps(w, key(P(cur)), backtrack, out);
}

// The jumps to where the segment re-enters the domain after position k: the next boundary
// vertex on it, and with w.leaveAnywhere the few after it too, since one within rounding
// reach of the segment need not be on it (overlap-back-step under EvenOdd); {kNone} if none
// is left (the segment ends outside). A vertex the segment would reach through one of its
// triangles is no entry (the reporting walk says so).
void SegmentWalker::entrySteps(SegmentWalk& w, double k, bool backtrack,
                               std::vector<WalkStep>& out) {
  constexpr size_t kEntriesTried = 4;
  size_t i = entriesAfter(w, k);
  if (i == w.entries.size()) return out.push_back({kNone, kNone});
  size_t last = std::min(w.entries.size(), i + (w.leaveAnywhere ? kEntriesTried : 1));
  for (size_t j = i; j < last; ++j) {
    uint32_t next = w.entries[j];
    bool through =
        backtrack ? enteringTriangle(next, w.A) != kNone : enteredThroughTriangle(next, w);
    if (!through) out.push_back({next, kNone});
  }
  // With b outside the mesh, a segment that left the domain may also end outside if every
  // boundary vertex still ahead is only a rounding off it (crossing-rounded-onto-the-top-vertex).
  if (backtrack && w.leaveAnywhere && vertices_.rep[w.b] == kNone) {
    bool exactAhead = false;
    for (size_t j = i; j < w.entries.size() && !exactAhead; ++j)
      exactAhead = orient2d(w.A, w.B, P(w.entries[j])) == 0;
    if (!exactAhead) out.push_back({kNone, kNone});
  }
}

// The walk of segment w, depth first over the steps from each vertex (backtrack) or along
// the first step from each (reporting why it is stuck where it is). True, with the chain's
// edges marked, if it reaches b (or, b being no mesh vertex, ends outside the domain).
bool SegmentWalker::walkDepthFirst(SegmentWalk& w, bool backtrack) {
  uint32_t start = vertices_.rep[w.a];
  if (start != kNone) return walkFrom(w, backtrack, start);
  // a is no mesh vertex: the segment starts outside the domain and enters it where
  // entrySteps() says.
  std::vector<WalkStep> firsts;
  entrySteps(w, -std::numeric_limits<double>::infinity(), backtrack, firsts);
  for (const WalkStep& first : firsts)
    if (walkFrom(w, backtrack, first.to)) return true;
  return false;
}

// The walk of walkDepthFirst from vertex cur (kNone: the segment lies outside the domain).
bool SegmentWalker::walkFrom(SegmentWalk& w, bool backtrack, uint32_t cur) {
  const uint32_t end = vertices_.rep[w.b];
  auto name = reporter(w, !backtrack);
  std::vector<WalkFrame>& stack = walkStack_;
  stack.clear();
  // Vertices past which every walk got stuck are not tried again in this walk; with that,
  // and a bound on the steps, a walk takes time linear in what it looks at.
  if (deadEnd_.size() != topo_.n) deadEnd_.assign(topo_.n, 0);
  const uint32_t id = ++walkId_;
  size_t budget = 1024 + 16 * size_t(topo_.n);
  uint32_t via = kNone;  // the half-edge of the last step (kNone: a jump, or the start)
  bool reached = false;
  for (;;) {
    if (cur == end || cur == kNone) {
      reached = cur == end || end == kNone;
      if (reached && w.mustTakeLeftOver) {
        bool takes = stillLeftOver(via);
        for (size_t i = 1; i < stack.size() && !takes; ++i) takes = stillLeftOver(stack[i].he);
        reached = takes;
      }
      if (reached) break;
      if (!backtrack) {
        name("is not a chain of mesh edges: never reaches vertex ", end, ", which is in the mesh");
        break;
      }
    } else {
      stack.push_back({cur, via, onSegment_[cur], {}, 0});
      onSegment_[cur] = w.s;
      walkSteps(w, cur, backtrack, stack.back().steps);
    }
    // The next step: the first untried one from the deepest vertex that has one left.
    bool stepped = false;
    while (!stack.empty() && !stepped) {
      WalkFrame& f = stack.back();
      if (backtrack)
        while (f.nextStep < f.steps.size() && f.steps[f.nextStep].to != kNone &&
               deadEnd_[f.steps[f.nextStep].to] == id)
          ++f.nextStep;
      if (f.nextStep < f.steps.size() && (backtrack || f.nextStep == 0)) {
        const WalkStep& step = f.steps[f.nextStep++];
        cur = step.to, via = step.he, stepped = true;
      } else if (!backtrack) {
        break;  // stuck, and walkSteps has said why
      } else {
        deadEnd_[f.vertex] = id;
        onSegment_[f.vertex] = f.previousOnSegment;
        stack.pop_back();
      }
    }
    if (!stepped || (backtrack && budget-- == 0)) break;
  }
  if (backtrack && !reached) {
    for (size_t i = stack.size(); i-- > 0;)
      onSegment_[stack[i].vertex] = stack[i].previousOnSegment;
    return false;
  }
  keepChain(w, stack, via, reached);
  return reached;
}

// The chain walked (in full, or as far as the reporting walk got) lies on the segment.
void SegmentWalker::keepChain(const SegmentWalk& w, const std::vector<WalkFrame>& stack,
                              uint32_t via, bool reached) {
  const uint32_t end = vertices_.rep[w.b];
  Chain& chain = chains_[w.s];
  chain.steps.clear();
  chain.vertices.clear();
  for (size_t i = 0; i < stack.size(); ++i) {
    chain.vertices.push_back(stack[i].vertex);
    if (i > 0 && stack[i].he != kNone) chain.steps.push_back({stack[i].he, stack[i - 1].vertex});
  }
  if (reached && end != kNone) {
    if (via != kNone && !stack.empty()) chain.steps.push_back({via, stack.back().vertex});
    chain.vertices.push_back(end);
    onSegment_[end] = w.s;
  }
  for (const auto& step : chain.steps) markWalked(step[0], step[1]);
}

// Half-edge h, taken from vertex from, lies on the segment walked (w: +1), or no longer
// does (w: -1).
void SegmentWalker::markWalked(uint32_t h, uint32_t from, int w) {
  if (h == kNone) return;
  uint32_t e = canon(h);
  marked_[e] += uint32_t(w);
  segCount_[e] += topo_.org(e) == from ? w : -w;
}

const QueryGrid& SegmentWalker::boundaryGrid() {
  if (!boundaryGrid_) {
    std::vector<Query> q;
    for (uint32_t v = 0; v < topo_.n; ++v)
      if (topo_.boundaryVertex[v]) q.push_back({Query::Boundary, v, {P(v)[0], P(v)[1]}});
    boundaryGrid_ = std::make_unique<QueryGrid>(std::move(q));
  }
  return *boundaryGrid_;
}

// The segment reaches boundary vertex v from outside the mesh: it must not arrive through
// one of v's triangles (logged).
bool SegmentWalker::enteredThroughTriangle(uint32_t v, const SegmentWalk& w) {
  uint32_t t = enteringTriangle(v, w.A);
  if (t != kNone)
    reporter(w, true)("is not a chain of mesh edges: reaches vertex ", v, " through ",
                      topo_.tri(t));
  return t != kNone;
}

// The triangle of v that the direction from v toward A enters, unless its side opposite v
// passes within rounding reach of v: a corner that thin a segment may graze by rounding
// (grazes-a-corner).
uint32_t SegmentWalker::enteringTriangle(uint32_t v, const double* A) const {
  uint32_t t = topo_.triangleToward(v, A);
  if (t == kNone) return kNone;
  const uint32_t* c = topo_.corners(t);
  int k = c[0] == v ? 0 : c[1] == v ? 1 : 2;
  return nearSegment(P(c[(k + 1) % 3]), P(c[(k + 2) % 3]), P(v)) ? kNone : t;
}

}  // namespace acutemesh::validation
