// The queue of bad triangles repairs work through, in one of four orders:
// - largest (squared shortest edge) first, exact (a binary heap on size, then index): acute
//   and non-obtuse refinement come out with the fewest points this way, and the vertex spacing
//   stays even (newest first instead lets refinement spiral into one spot);
// - skinniest first (the cosine of the smallest angle, in the same heap): min-angle refinement
//   without sizes, which then removes what is not needed; its points settle the worst angles
//   first, and at 40-42 degrees it ends with far fewer points (docs/TUNING.md);
// - by factors of two, newest first within one (a stack per binary exponent of the size):
//   with an area bound, where most of the work is area refinement of large meshes; working
//   near the last insertion keeps the mesh in cache;
// - fewest bad triangles left first (Strategy::fewestBadFirst): by the gain an entry carries
//   (the bad triangles its repair takes away, less those it makes), then largest first.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace acutemesh::detail {

class RepairQueue {
 public:
  enum class Order { Largest, SkinniestFirst, FactorsOfTwo, FewestBadFirst };
  struct Entry {
    int gain;  // FewestBadFirst only (0 otherwise)
    double size;  // the squared shortest edge (SkinniestFirst: the smallest angle's cosine)
    uint32_t t;
    bool operator<(const Entry& o) const {
      return gain != o.gain ? gain < o.gain : size != o.size ? size < o.size : t < o.t;
    }
  };
  void reset(Order order) {
    rough_ = order == Order::FactorsOfTwo;
    heap_.clear();
    for (auto& b : buckets_) b.clear();
    top_ = 0;
  }
  void push(const Entry& entry) {
    if (!rough_) {
      heap_.push_back(entry);
      std::push_heap(heap_.begin(), heap_.end());
      return;
    }
    int e = 0;
    std::frexp(entry.size, &e);
    size_t b = size_t(std::clamp(e + kBias, 0, kBuckets - 1));
    if (buckets_.empty()) buckets_.resize(kBuckets);
    buckets_[b].push_back(entry);
    top_ = std::max(top_, b + 1);
  }
  // Entries queued (progress reports only).
  size_t size() const {
    size_t n = heap_.size();
    for (size_t b = 0; b < top_ && rough_; ++b) n += buckets_[b].size();
    return n;
  }
  bool pop(Entry& entry) {
    std::vector<Entry>* from = &heap_;
    if (rough_) {
      while (top_ > 0 && buckets_[top_ - 1].empty()) --top_;
      if (top_ == 0) return false;
      from = &buckets_[top_ - 1];
    } else {
      if (heap_.empty()) return false;
      std::pop_heap(heap_.begin(), heap_.end());
    }
    entry = from->back();
    from->pop_back();
    return true;
  }

 private:
  static constexpr int kBuckets = 2200, kBias = 1100;  // binary exponents of doubles, shifted
  bool rough_ = false;
  std::vector<Entry> heap_;
  std::vector<std::vector<Entry>> buckets_;
  size_t top_ = 0;
};

}  // namespace acutemesh::detail
