#include "query_grid.h"

#include <cmath>
#include <limits>

namespace acutemesh::validation {

QueryGrid::QueryGrid(std::vector<Query> queries) : q_(std::move(queries)) {
  if (q_.empty()) return;
  lo_[0] = hi_[0] = q_[0].xy[0];
  lo_[1] = hi_[1] = q_[0].xy[1];
  for (const Query& q : q_)
    for (int k = 0; k < 2; ++k)
      lo_[k] = std::min(lo_[k], q.xy[k]), hi_[k] = std::max(hi_[k], q.xy[k]);
  // An extent beyond the double range (a non-finite hole point, say, which validate() reports)
  // gets one column or row: the grid only narrows the search, cell() clamps every point.
  double w = hi_[0] - lo_[0], h = hi_[1] - lo_[1], cells = double(q_.size());
  if (!std::isfinite(w)) w = 0;
  if (!std::isfinite(h)) h = 0;
  if (w > 0 && h > 0) {
    nx_ = int(std::clamp(std::sqrt(cells * w / h), 1.0, cells));
    ny_ = int(std::clamp(cells / nx_, 1.0, cells));
  } else {
    nx_ = w > 0 ? int(cells) : 1;
    ny_ = h > 0 ? int(cells) : 1;
  }
  step_[0] = w > 0 ? w / nx_ : 0;
  step_[1] = h > 0 ? h / ny_ : 0;
  scale_[0] = w > 0 ? nx_ / w : 0;
  scale_[1] = h > 0 ? ny_ / h : 0;
  start_.assign(size_t(nx_) * ny_ + 1, 0);
  for (const Query& q : q_) ++start_[cellOf(q) + 1];
  for (size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
  order_.resize(q_.size());
  std::vector<uint32_t> fill(start_.begin(), start_.end() - 1);
  for (uint32_t i = 0; i < q_.size(); ++i) order_[fill[cellOf(q_[i])]++] = i;
}

// x-extent of the convex hull of pts within ya <= y <= yb (approximate: callers widen it).
// Any order of the points will do.
bool QueryGrid::xExtentInStrip(const double* const* pts, int count, double ya, double yb,
                               double& xa, double& xb) {
  xa = std::numeric_limits<double>::infinity();
  xb = -xa;
  auto take = [&](double x) { xa = std::min(xa, x), xb = std::max(xb, x); };
  for (int i = 0; i < count; ++i) {
    const double* p = pts[i];
    if (p[1] >= ya && p[1] <= yb) take(p[0]);
    for (int j = i + 1; j < count; ++j) {  // every pair: the hull's edges are among them
      const double* q = pts[j];
      for (double y : {ya, yb})
        if ((p[1] < y && y < q[1]) || (q[1] < y && y < p[1]))
          take(p[0] + (y - p[1]) * (q[0] - p[0]) / (q[1] - p[1]));
    }
  }
  return xa <= xb;
}

}  // namespace acutemesh::validation
