// Which triangles form the domain. Regions are the pieces of the plane separated by fixed
// edges; they are found by flooding across non-fixed edges, never by geometry, so the result
// is exactly as robust as the triangulation itself.
#include "acutemesh/predicates.h"
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

// Winding number of every triangle: 0 on the ghosts (the far outside), changing by the net
// winding of the segments on each edge crossed.
void applyFillRule(const Triangulation& T, FillRule rule, std::vector<uint8_t>& inside) {
  uint32_t slots = T.triangleSlots();
  std::vector<int32_t> winding(slots, 0);
  std::vector<uint8_t> seen(slots, 0);
  std::vector<uint32_t> stack;
  for (uint32_t t = 0; t < slots; ++t)
    if (!T.isFree(t) && T.isGhost(t)) seen[t] = 1, stack.push_back(t);
  while (!stack.empty()) {
    uint32_t t = stack.back();
    stack.pop_back();
    for (uint32_t k = 0; k < 3; ++k) {
      uint32_t e = 3 * t + k, n = T.opp[e] / 3;
      if (seen[n]) continue;
      seen[n] = 1;
      // The triangle left of e sees the segments a->b on e as +1 relative to its right side.
      winding[n] = winding[t] - T.wind[e];
      stack.push_back(n);
    }
  }
  for (uint32_t t = 0; t < slots; ++t) {
    if (!inside[t]) continue;
    inside[t] = rule == FillRule::EvenOdd ? (winding[t] & 1) != 0 : winding[t] != 0;
  }
}

}  // namespace

std::vector<uint8_t> classifyDomain(const Triangulation& T, const Pslg& input,
                                    const Options& options, bool keepHull) {
  uint32_t slots = T.triangleSlots();
  std::vector<uint8_t> inside(slots, 0);
  for (uint32_t t = 0; t < slots; ++t) inside[t] = !T.isFree(t) && !T.isGhost(t);

  std::vector<uint32_t> stack;
  if (options.fill != FillRule::Triangle) {
    applyFillRule(T, options.fill, inside);
  } else if (!keepHull) {
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
