#include <algorithm>
#include <cmath>

#include "acutemesh/predicates.h"
#include "build.h"
#include "curve_order.h"

namespace acutemesh::detail {
namespace {

bool samePoint(const double* a, const double* b) { return a[0] == b[0] && a[1] == b[1]; }

}  // namespace

StepResult buildDelaunay(Triangulation& T, const std::vector<double>& points,
                         std::vector<uint32_t>& canonical, std::vector<uint32_t>& inputOf,
                         const Budget& budget) {
  uint32_t count = uint32_t(points.size() / 2);
  if (count < 3)
    return {Status::BadInput, "input has " + std::to_string(count) +
                                  (count == 1 ? " vertex" : " vertices") +
                                  "; a triangulation needs at least 3"};
  // Vertices are stored in insertion order: neighbours in the mesh are then neighbours in
  // memory, which matters more than anything else for speed on large inputs.
  inputOf.resize(count);
  for (uint32_t i = 0; i < count; ++i) inputOf[i] = i;
  sortAlongCurve(inputOf, [&](uint32_t i, double* p) {
    p[0] = points[2 * size_t(i)], p[1] = points[2 * size_t(i) + 1];
  });
  T.pts.resize(2 * size_t(count));
  T.vertexEdge.assign(count, kNone);
  canonical.resize(count);
  for (uint32_t k = 0; k < count; ++k) {
    T.pts[2 * size_t(k)] = points[2 * size_t(inputOf[k])];
    T.pts[2 * size_t(k) + 1] = points[2 * size_t(inputOf[k]) + 1];
    canonical[inputOf[k]] = k;
  }

  // The first triangle: vertex 0, the next distinct one, the next not collinear with both.
  uint32_t b = kNone, c = kNone;
  for (uint32_t k = 1; k < count && b == kNone; ++k)
    if (!samePoint(T.point(k), T.point(0))) b = k;
  if (b == kNone)
    return {Status::BadInput, "all " + std::to_string(count) + " input vertices coincide"};
  for (uint32_t k = b + 1; k < count && c == kNone; ++k)
    if (orient2d(T.point(0), T.point(b), T.point(k)) != 0) c = k;
  if (c == kNone)
    return {Status::BadInput, "all " + std::to_string(count) +
                                  " input vertices are collinear: there is no triangle to make"};
  T.init(0, b, c);

  uint32_t hint = T.vertexEdge[0] / 3;
  for (uint32_t v = 1; v < count; ++v) {
    if (v == b || v == c) continue;
    if ((v & 0xFFFF) == 0 && budget.stop())
      return {budget.cancelled() ? Status::Cancelled : Status::TargetNotMet,
              "stopped while triangulating the input vertices"};
    uint32_t r = T.insert(v, hint);
    if (r == kNone) return {Status::BadInput, "could not locate vertex " + std::to_string(inputOf[v])};
    canonical[inputOf[v]] = r;
    hint = T.vertexEdge[r] / 3;
  }
  return {};
}

}  // namespace acutemesh::detail
