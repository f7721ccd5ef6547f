// Which triangles form the domain. Regions are the pieces of the plane separated by fixed
// edges; they are found by flooding across non-fixed edges, never by geometry, so the result
// is exactly as robust as the triangulation itself.
#include <deque>

#include "build.h"

namespace acutemesh::detail {
namespace {

// Clears `inside` for every triangle reachable from `seeds` without crossing a fixed edge.
void floodOutside(const Triangulation& T, std::vector<uint32_t>& stack,
                  std::vector<uint8_t>& inside) {
  while (!stack.empty()) {
    uint32_t t = stack.back();
    stack.pop_back();
    for (uint32_t k = 0; k < 3; ++k) {
      uint32_t e = 3 * t + k;
      if (T.isFixed(e)) continue;
      uint32_t n = T.opp[e] / 3;
      if (inside[n]) {
        inside[n] = 0;
        stack.push_back(n);
      }
    }
  }
}

// Net winding carried by each half-edge, with open chains removed: a segment end that no
// other segment continues (in net winding) bounds no region, so the chain ending there is
// peeled off edge by edge. What remains forms closed cycles, where the winding number of a
// region does not depend on the path it is reached by.
std::vector<int32_t> closedWinding(const Triangulation& T) {
  std::vector<int32_t> wind = T.wind;
  wind.resize(3 * size_t(T.triangleSlots()));
  std::vector<uint32_t> degree(T.vertexCount(), 0), stack;
  for (uint32_t e = 0; e < wind.size(); ++e)
    if (wind[e] != 0 && T.tri[e] != kGhost) ++degree[T.tri[e]];
  for (uint32_t v = 0; v < degree.size(); ++v)
    if (degree[v] == 1) stack.push_back(v);
  while (!stack.empty()) {
    uint32_t v = stack.back();
    stack.pop_back();
    if (degree[v] != 1) continue;
    uint32_t e0 = T.vertexEdge[v], e = e0;
    do {
      if (wind[e] != 0) break;
      e = T.opp[prev(e)];
    } while (e != e0);
    uint32_t w = T.tri[next(e)];
    wind[e] = wind[T.opp[e]] = 0;
    degree[v] = 0;
    if (--degree[w] == 1) stack.push_back(w);
  }
  return wind;
}

// Winding number of every triangle: 0 on the ghosts (the far outside), changing by the net
// winding of the segments on each edge crossed. A 0-1 breadth-first search floods each region
// (triangles joined by unfixed edges) completely before leaving it, so a region gets one
// winding number even where the segments do not close up and paths would disagree.
void applyFillRule(const Triangulation& T, FillRule rule, std::vector<uint8_t>& inside,
                   std::vector<std::string>& warnings) {
  uint32_t slots = T.triangleSlots();
  std::vector<int32_t> wind = closedWinding(T);
  std::vector<int32_t> winding(slots, 0);
  std::vector<uint8_t> done(slots, 0);
  std::deque<std::pair<uint32_t, int32_t>> queue;
  for (uint32_t t = 0; t < slots; ++t)
    if (!T.isFree(t) && T.isGhost(t)) queue.push_back({t, 0});
  bool consistent = true;
  while (!queue.empty()) {
    auto [t, w] = queue.front();
    queue.pop_front();
    if (done[t]) {
      consistent &= winding[t] == w;
      continue;
    }
    done[t] = 1;
    winding[t] = w;
    for (uint32_t e = 3 * t; e < 3 * t + 3; ++e) {
      uint32_t n = T.opp[e] / 3;
      if (done[n] && !T.isFixed(e)) continue;
      // The triangle left of e sees the segments a->b on e as +1 relative to its right side.
      if (T.isFixed(e))
        queue.push_back({n, w - wind[e]});
      else
        queue.push_front({n, w});
    }
  }
  if (!consistent)
    warnings.push_back("the segments do not close up into rings (an open path joins two "
                       "of them); each region took the winding number of the first way in");
  for (uint32_t t = 0; t < slots; ++t) {
    if (!inside[t]) continue;
    inside[t] = rule == FillRule::EvenOdd ? (winding[t] & 1) != 0 : winding[t] != 0;
  }
}

}  // namespace

std::vector<uint8_t> classifyDomain(const Triangulation& T, const Pslg& input,
                                    const Options& options, bool keepHull,
                                    std::vector<std::string>& warnings) {
  uint32_t slots = T.triangleSlots();
  std::vector<uint8_t> inside(slots, 0);
  for (uint32_t t = 0; t < slots; ++t) inside[t] = !T.isFree(t) && !T.isGhost(t);

  if (options.fill != FillRule::Triangle) {
    applyFillRule(T, options.fill, inside, warnings);
    return inside;  // nesting decides the holes; hole points belong to Triangle's rule
  }
  std::vector<uint32_t> stack;
  if (!keepHull) {
    for (uint32_t t = 0; t < slots; ++t)
      if (!T.isFree(t) && T.isGhost(t)) stack.push_back(t);
    floodOutside(T, stack, inside);
  }
  uint32_t hint = 0;
  for (size_t h = 0; h < input.holes.size() / 2; ++h) {
    Location loc = T.locate(&input.holes[2 * h], hint);
    if (loc.where == Where::Failed || !inside[loc.tri]) continue;
    hint = loc.tri;
    inside[loc.tri] = 0;
    stack.push_back(loc.tri);
    floodOutside(T, stack, inside);
  }
  return inside;
}

}  // namespace acutemesh::detail
