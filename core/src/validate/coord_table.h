// Exact-coordinate lookup: which vertex, if any, sits at exactly these coordinates.
#pragma once

#include <cstdint>
#include <cstring>
#include <vector>

#include "error_log.h"

namespace acutemesh::validation {

// Open-addressing table from exact coordinates to the first vertex stored with them. Each
// slot keeps 32 bits of the hash beside the vertex, so probing rarely touches coordinates.
class CoordTable {
 public:
  CoordTable(const double* xy, size_t count) : xy_(xy) {
    size_t size = 16;
    while (size < 2 * count) size <<= 1;
    slots_.assign(size, kEmpty);
  }
  // The vertex already stored with v's coordinates, or v after storing it.
  uint32_t insert(uint32_t v) {
    const double* p = xy_ + 2 * size_t(v);
    uint64_t h = hash(p);
    size_t i = probe(h, p);
    if (slots_[i] == kEmpty) slots_[i] = (h & ~uint64_t(kNone)) | v;
    return uint32_t(slots_[i]);
  }
  // The vertex stored with p's coordinates, or kNone.
  uint32_t find(const double* p) const { return uint32_t(slots_[probe(hash(p), p)]); }

 private:
  static constexpr uint64_t kEmpty = ~uint64_t(0);
  // The slot holding p's coordinates, or the empty slot where they would go.
  size_t probe(uint64_t h, const double* p) const {
    size_t mask = slots_.size() - 1;
    for (size_t i = size_t(h) & mask;; i = (i + 1) & mask) {
      uint64_t s = slots_[i];
      if (s == kEmpty) return i;
      const double* q = xy_ + 2 * size_t(uint32_t(s));
      if ((s >> 32) == (h >> 32) && q[0] == p[0] && q[1] == p[1]) return i;
    }
  }
  static uint64_t mix(uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  static uint64_t hash(const double* p) {
    double x = p[0] + 0.0, y = p[1] + 0.0;  // -0.0 + 0.0 == +0.0: equal values, equal bits
    uint64_t a, b;
    std::memcpy(&a, &x, 8);
    std::memcpy(&b, &y, 8);
    return mix(a ^ mix(b));
  }
  const double* xy_;
  std::vector<uint64_t> slots_;
};

}  // namespace acutemesh::validation
