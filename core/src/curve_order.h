// Items in the order of a Hilbert curve through their places: neighbours in the plane become
// neighbours in the order. The Delaunay build inserts its vertices so (each walk starts next to
// where it ends); the improvement rounds of a large mesh visit its points, and renumber its
// triangles, so (each try finds its neighbourhood still in the cache).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace acutemesh::detail {

// Position of cell (x, y) along the Hilbert curve filling a 2^16 x 2^16 grid.
inline uint32_t hilbertIndex(uint32_t x, uint32_t y) {
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

// From this many items on, the order is sorted by radix passes (below: comparisons).
constexpr size_t kRadixFrom = 16384;

// Sorts `items` along the Hilbert curve of the square grid (2^16 cells a side) over their
// places, place(item, xy) giving each; items in one cell keep their order.
template <class Place>
void sortAlongCurve(std::vector<uint32_t>& items, Place place) {
  const size_t n = items.size();
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY}, p[2];
  for (uint32_t item : items) {
    place(item, p);
    for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  }
  const double span = std::max(hi[0] - lo[0], hi[1] - lo[1]);
  const double scale = span > 0 ? 65535.0 / span : 0.0;
  std::vector<uint32_t> key(n), order(n);
  for (size_t i = 0; i < n; ++i) {
    place(items[i], p);
    const auto gx = uint32_t((p[0] - lo[0]) * scale), gy = uint32_t((p[1] - lo[1]) * scale);
    key[i] = hilbertIndex(std::min(gx, 65535u), std::min(gy, 65535u));
    order[i] = uint32_t(i);
  }
  if (n < kRadixFrom) {
    // (A small set, such as one of the thousand islands of a country meshed part by part:
    // the radix passes' 2^16 buckets would cost more than the items.)
    std::sort(order.begin(), order.end(),
              [&](uint32_t a, uint32_t b) { return key[a] != key[b] ? key[a] < key[b] : a < b; });
  } else {
    std::vector<uint32_t> bucket(65537), tmp(n);
    for (int shift = 0; shift < 32; shift += 16) {
      std::fill(bucket.begin(), bucket.end(), 0);
      for (uint32_t i : order) ++bucket[((key[i] >> shift) & 0xFFFF) + 1];
      for (size_t b = 1; b < bucket.size(); ++b) bucket[b] += bucket[b - 1];
      for (uint32_t i : order) tmp[bucket[(key[i] >> shift) & 0xFFFF]++] = i;
      order.swap(tmp);
    }
  }
  std::vector<uint32_t> sorted(n);
  for (size_t i = 0; i < n; ++i) sorted[i] = items[order[i]];
  items.swap(sorted);
}

}  // namespace acutemesh::detail
