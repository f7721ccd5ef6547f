// Matching the segment walks against Mesh::segments, the mesh's list of segment edges.
// Fixtures named below are in tests/data/bad/.
#include <algorithm>

#include "segment_walker.h"

namespace acutemesh::validation {
namespace {

// Fills edges.listed from Mesh::segments; logs entries that are no mesh edge or repeat one.
void readMeshSegments(const Check& c, const Topology& topo, SegmentEdges& edges) {
  const std::vector<uint32_t>& list = topo.m.segments;
  for (size_t i = 0; i + 1 < list.size(); i += 2) {
    uint32_t u = list[i], v = list[i + 1], h = topo.meshEdge(u, v);
    if (h == kNone)
      c.log.add("mesh segment ", i / 2, " (", u, "-", v, ") is not a mesh edge");
    else if (edges.listed[topo.canon(h)])
      c.log.add("mesh segment ", i / 2, " (", u, "-", v, ") is listed twice");
    else
      edges.listed[topo.canon(h)] = 1;
  }
}

// Mesh::segments lists exactly the mesh edges that lie on input segments.
void checkMeshSegments(const Check& c, const Topology& topo, const SegmentEdges& edges) {
  const std::vector<uint32_t>& list = topo.m.segments;
  for (size_t i = 0; i + 1 < list.size(); i += 2) {
    uint32_t u = list[i], v = list[i + 1], h = topo.meshEdge(u, v);
    if (h != kNone && !edges.marked[topo.canon(h)])
      c.log.add("mesh segment ", i / 2, " (", u, "-", v, ") lies on no input segment");
  }
  for (uint32_t h = 0; h < 3 * topo.T; ++h)
    if (edges.marked[h] && !edges.listed[h])
      c.log.add("mesh edge ", topo.org(h), "-", topo.dst(h),
                " lies on an input segment but is missing from mesh segments");
}

}  // namespace

SegmentEdges walkSegments(const Check& c, const Topology& topo, const VertexMap& vertices) {
  SegmentEdges edges(topo);
  if (!c.segmentsKept()) return edges;
  readMeshSegments(c, topo, edges);
  SegmentWalker walker(c, topo, vertices, edges);
  walker.walkAll();
  walker.rerouteToListedEdges();
  checkMeshSegments(c, topo, edges);
  return edges;
}

// Whether half-edge h (kNone: no) was left over by the first walks and no walk has taken it
// since.
bool SegmentWalker::stillLeftOver(uint32_t h) const {
  return h != kNone && leftOver_[canon(h)] && !marked_[canon(h)];
}

bool SegmentWalker::takesUnlisted(const Chain& chain) const {
  return std::any_of(chain.steps.begin(), chain.steps.end(),
                     [&](const std::array<uint32_t, 2>& step) { return !listed_[canon(step[0])]; });
}

// Puts segment s's chain on the edges and vertices it takes (w: +1), or takes it off (-1).
void SegmentWalker::applyChain(const Chain& chain, uint32_t s, int w) {
  for (const auto& step : chain.steps) markWalked(step[0], step[1], w);
  for (uint32_t v : chain.vertices)
    if (w > 0)
      onSegment_[v] = s;
    else if (onSegment_[v] == s)
      onSegment_[v] = kNone;
}

// How many of the edges either chain takes (each once) are wrong: listed and on no walk, or
// on a walk and unlisted.
size_t SegmentWalker::wrongAmong(const Chain& x, const Chain& y) {
  edges_.clear();
  for (const Chain* c : {&x, &y})
    for (const auto& step : c->steps) edges_.push_back(canon(step[0]));
  std::sort(edges_.begin(), edges_.end());
  edges_.erase(std::unique(edges_.begin(), edges_.end()), edges_.end());
  size_t n = 0;
  for (uint32_t e : edges_) n += wrong(e);
  return n;
}

// Where segments lie a rounding apart, the mesh can hold two chains side by side and a walk
// may take the other segment's (parallel-chains-one-ulp-apart), or an unlisted edge exactly
// on a segment the mesh follows by a chain through a rounded crossing beside it
// (parallel-chains-leftover-edge). The walks concerned are tried again along listed edges.
void SegmentWalker::rerouteToListedEdges() {
  auto touchesLeftOver = [&](uint32_t v) {
    bool any = false;
    topo_.forEachEdge(v, [&](uint32_t, uint32_t h) { any |= stillLeftOver(h); });
    return any;
  };
  auto anyWrong = [&] {
    for (uint32_t h = 0; h < 3 * topo_.T; ++h)
      if (canon(h) == h && wrong(h)) return true;
    return false;
  };
  if (!anyWrong()) return;
  // A few passes: a walk moved off an edge in one leaves it over for the next.
  bool changed = true;
  for (int pass = 0; pass < 4 && changed && (pass == 0 || anyWrong()); ++pass) {
    changed = false;
    leftOver_.assign(3 * size_t(topo_.T), 0);
    for (uint32_t h = 0; h < 3 * topo_.T; ++h) leftOver_[h] = listed_[h] && !marked_[h];
    for (uint32_t s = 0; s < c_.in.segmentCount(); ++s) {
      const Chain& current = chains_[s];
      bool nearLeftOver =
          std::any_of(current.vertices.begin(), current.vertices.end(), touchesLeftOver);
      if (current.vertices.empty() || (!nearLeftOver && !takesUnlisted(current))) continue;
      if (rerouteSegment(s, nearLeftOver)) changed = true;
    }
  }
  // Which segment each vertex lies on, from the walks as they now are.
  std::fill(onSegment_.begin(), onSegment_.end(), kNone);
  for (uint32_t s = 0; s < c_.in.segmentCount(); ++s)
    for (uint32_t v : chains_[s].vertices) onSegment_[v] = s;
}

// Walks segment s again along listed edges only, those no walk took first (through an end of
// a left-over listed edge when nearLeftOver), and keeps the new walk if it leaves fewer wrong
// edges, or as many but takes no unlisted edge where the old walk did (a segment given twice:
// one walk alone cannot free the edge). True if it kept the new walk.
bool SegmentWalker::rerouteSegment(uint32_t s, bool nearLeftOver) {
  Chain old = chains_[s];
  applyChain(old, s, -1);
  uint32_t a = c_.in.segments[2 * s], b = c_.in.segments[2 * s + 1];
  SegmentWalk walk{s, a, b, c_.inP(a), c_.inP(b)};
  walk.preferListed = true;
  walk.mustTakeLeftOver = nearLeftOver;
  bool found = walkDepthFirst(walk, true);
  if (!found) walk.leaveAnywhere = true, found = walkDepthFirst(walk, true);
  if (!found) {
    chains_[s] = old;
    applyChain(old, s, 1);
    return false;
  }
  Chain fresh = chains_[s];
  size_t after = wrongAmong(old, fresh);
  applyChain(fresh, s, -1);
  applyChain(old, s, 1);
  size_t before = wrongAmong(old, fresh);
  if (after < before || (after == before && takesUnlisted(old))) {
    applyChain(old, s, -1);
    applyChain(fresh, s, 1);
    chains_[s] = fresh;
    return true;
  }
  chains_[s] = old;
  return false;
}

}  // namespace acutemesh::validation
