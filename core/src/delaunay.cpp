#include <algorithm>
#include <cmath>

#include "acutemesh/predicates.h"
#include "build.h"
#include "curve_order.h"

namespace acutemesh::detail {
namespace {

bool samePoint(const double* a, const double* b) { return a[0] == b[0] && a[1] == b[1]; }

}  // namespace

void placeVertices(Triangulation& T, const std::vector<double>& points,
                   const std::vector<uint32_t>& inputOf) {
  const size_t count = inputOf.size();
  T.pts.resize(2 * count);
  T.vertexEdge.assign(count, kNone);
  for (size_t k = 0; k < count; ++k) {
    T.pts[2 * k] = points[2 * size_t(inputOf[k])];
    T.pts[2 * k + 1] = points[2 * size_t(inputOf[k]) + 1];
  }
}

void firstTriangle(const Triangulation& T, uint32_t end, uint32_t& b, uint32_t& c) {
  b = c = kNone;
  for (uint32_t k = 1; k < end && b == kNone; ++k)
    if (!samePoint(T.point(k), T.point(0))) b = k;
  for (uint32_t k = b == kNone ? end : b + 1; k < end && c == kNone; ++k)
    if (orient2d(T.point(0), T.point(b), T.point(k)) != 0) c = k;
}

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
  placeVertices(T, points, inputOf);
  canonical.resize(count);
  for (uint32_t k = 0; k < count; ++k) canonical[inputOf[k]] = k;

  uint32_t b, c;
  firstTriangle(T, count, b, c);
  if (b == kNone)
    return {Status::BadInput, "all " + std::to_string(count) + " input vertices coincide"};
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
