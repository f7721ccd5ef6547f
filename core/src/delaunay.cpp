#include <algorithm>
#include <cmath>

#include "acutemesh/predicates.h"
#include "build.h"

namespace acutemesh::detail {
namespace {

// Position of cell (x, y) along the Hilbert curve filling a 2^16 x 2^16 grid.
uint32_t hilbertIndex(uint32_t x, uint32_t y) {
  uint32_t d = 0;
  for (uint32_t s = 1u << 15; s > 0; s >>= 1) {
    uint32_t rx = (x & s) ? 1 : 0, ry = (y & s) ? 1 : 0;
    d += s * s * ((3 * rx) ^ ry);
    if (ry == 0) {
      if (rx == 1) {
        x = s - 1 - x;
        y = s - 1 - y;
      }
      std::swap(x, y);
    }
    x &= s - 1;
    y &= s - 1;
  }
  return d;
}

// From this many points on, the Hilbert order is sorted by radix passes (below: comparisons).
constexpr uint32_t kRadixFrom = 16384;

// Vertex indices sorted along a Hilbert curve (two 16-bit radix passes), so that each
// insertion's walk starts next to where it ends; ties in input order.
std::vector<uint32_t> hilbertOrder(const std::vector<double>& pts, uint32_t count) {
  double minX = INFINITY, minY = INFINITY, maxX = -INFINITY, maxY = -INFINITY;
  for (uint32_t i = 0; i < count; ++i) {
    minX = std::min(minX, pts[2 * i]), maxX = std::max(maxX, pts[2 * i]);
    minY = std::min(minY, pts[2 * i + 1]), maxY = std::max(maxY, pts[2 * i + 1]);
  }
  double span = std::max(maxX - minX, maxY - minY);
  double scale = span > 0 ? 65535.0 / span : 0.0;
  std::vector<uint32_t> key(count), order(count), tmp(count);
  for (uint32_t i = 0; i < count; ++i) {
    auto gx = uint32_t((pts[2 * i] - minX) * scale), gy = uint32_t((pts[2 * i + 1] - minY) * scale);
    key[i] = hilbertIndex(std::min(gx, 65535u), std::min(gy, 65535u));
    order[i] = i;
  }
  // (A small input, such as one of the thousand islands of a country meshed part by part: a
  // comparison sort, as the radix passes' 2^16 buckets would cost more than the points.)
  if (count < kRadixFrom) {
    std::sort(order.begin(), order.end(),
              [&](uint32_t a, uint32_t b) { return key[a] != key[b] ? key[a] < key[b] : a < b; });
    return order;
  }
  std::vector<uint32_t> bucket(65537);
  for (int shift = 0; shift < 32; shift += 16) {
    std::fill(bucket.begin(), bucket.end(), 0);
    for (uint32_t i : order) ++bucket[((key[i] >> shift) & 0xFFFF) + 1];
    for (size_t b = 1; b < bucket.size(); ++b) bucket[b] += bucket[b - 1];
    for (uint32_t i : order) tmp[bucket[(key[i] >> shift) & 0xFFFF]++] = i;
    order.swap(tmp);
  }
  return order;
}

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
  inputOf = hilbertOrder(points, count);
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
