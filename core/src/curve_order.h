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

// The Hilbert curve level by level: at each level, a cell's quadrant bits (x, y), seen
// through the flip (both complemented: bit 0) and the turn (swapped: bit 1) that the levels
// above left, give the level's digit (3x ^ y) and the flip and turn for the levels below.
// A table takes four levels (x's and y's nibbles) at a time: digits and the state after.
struct HilbertTable {
  uint8_t digits[4][256], state[4][256];
};
constexpr HilbertTable makeHilbertTable() {
  HilbertTable table{};
  for (uint32_t start = 0; start < 4; ++start)
    for (uint32_t nibbles = 0; nibbles < 256; ++nibbles) {
      uint32_t state = start, digits = 0;
      for (int level = 3; level >= 0; --level) {
        uint32_t x = ((nibbles >> (4 + level)) & 1) ^ (state & 1);
        uint32_t y = ((nibbles >> level) & 1) ^ (state & 1);
        if (state & 2) {
          const uint32_t t = x;
          x = y, y = t;
        }
        digits = (digits << 2) | ((3 * x) ^ y);
        if (y == 0) state ^= x == 1 ? 3 : 2;
      }
      table.digits[start][nibbles] = uint8_t(digits);
      table.state[start][nibbles] = uint8_t(state);
    }
  return table;
}
inline constexpr HilbertTable kHilbertTable = makeHilbertTable();

// Position of cell (x, y) along the Hilbert curve filling a 2^16 x 2^16 grid.
inline uint32_t hilbertIndex(uint32_t x, uint32_t y) {
  uint32_t d = 0, state = 0;
  for (int shift = 12; shift >= 0; shift -= 4) {
    const uint32_t nibbles = (((x >> shift) & 15) << 4) | ((y >> shift) & 15);
    d = (d << 8) | kHilbertTable.digits[state][nibbles];
    state = kHilbertTable.state[state][nibbles];
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
