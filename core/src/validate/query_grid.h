// A uniform grid over the few points validate() must locate among the triangles, so that
// locating them costs no all-pairs test.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace acutemesh::validation {

// A point to locate among the triangles.
struct Query {
  enum Kind : uint8_t { Unused, Boundary, Hole } kind;
  uint32_t id;  // vertex index, or hole index
  double xy[2];
};

// forEachNear() visits a superset of the points in the closed convex hull of a few given
// points (a triangle, or a box around a segment), touching only the grid cells the shape can
// reach (row by row for a big shape).
class QueryGrid {
 public:
  explicit QueryGrid(std::vector<Query> queries);

  const std::vector<Query>& queries() const { return q_; }

  template <class F>
  void forEachNear(const double* const* pts, int count, F&& visit) const {
    if (q_.empty()) return;
    double box[2][2];  // [axis][min, max]
    for (int k = 0; k < 2; ++k) {
      box[k][0] = box[k][1] = pts[0][k];
      for (int i = 1; i < count; ++i)
        box[k][0] = std::min(box[k][0], pts[i][k]), box[k][1] = std::max(box[k][1], pts[i][k]);
      if (box[k][1] < lo_[k] || box[k][0] > hi_[k]) return;
    }
    int i0 = cell(0, box[0][0]), i1 = cell(0, box[0][1]);
    int j0 = cell(1, box[1][0]), j1 = cell(1, box[1][1]);
    if (j0 == j1 || (i1 - i0 + 1) * (j1 - j0 + 1) <= 16) {
      for (int j = j0; j <= j1; ++j) visitRow(j, i0, i1, box, visit);
      return;
    }
    // Big shape: per row, only the cells under the shape's x-extent within that row (widened
    // by half a row and a cell each way, which covers any rounding of these float bounds).
    double slack = 1e-9 * (std::fabs(box[0][0]) + std::fabs(box[0][1]) + std::fabs(box[1][0]) +
                           std::fabs(box[1][1]));
    for (int j = j0; j <= j1; ++j) {
      double ya = lo_[1] + (j - 0.5) * step_[1] - slack, yb = lo_[1] + (j + 1.5) * step_[1] + slack;
      double xa, xb;
      if (!xExtentInStrip(pts, count, ya, yb, xa, xb)) continue;
      int ia = std::max(i0, cell(0, xa - slack) - 1), ib = std::min(i1, cell(0, xb + slack) + 1);
      visitRow(j, ia, ib, box, visit);
    }
  }

 private:
  // Monotone in x, so a point inside [a, b] lands in a cell between a's and b's.
  int cell(int axis, double x) const {
    double f = (x - lo_[axis]) * scale_[axis];
    int n = axis == 0 ? nx_ : ny_;
    if (!(f > 0)) return 0;
    if (f >= n) return n - 1;
    return int(f);
  }
  size_t cellOf(const Query& q) const { return size_t(cell(1, q.xy[1])) * nx_ + cell(0, q.xy[0]); }

  template <class F>
  void visitRow(int j, int i0, int i1, const double box[2][2], F& visit) const {
    for (int i = i0; i <= i1; ++i) {
      size_t c = size_t(j) * nx_ + i;
      for (uint32_t k = start_[c]; k < start_[c + 1]; ++k) {
        const Query& q = q_[order_[k]];
        if (q.xy[0] >= box[0][0] && q.xy[0] <= box[0][1] && q.xy[1] >= box[1][0] &&
            q.xy[1] <= box[1][1])
          visit(q);
      }
    }
  }

  static bool xExtentInStrip(const double* const* pts, int count, double ya, double yb, double& xa,
                             double& xb);

  std::vector<Query> q_;
  std::vector<uint32_t> start_, order_;
  double lo_[2] = {0, 0}, hi_[2] = {0, 0}, step_[2] = {0, 0}, scale_[2] = {0, 0};
  int nx_ = 1, ny_ = 1;
};

}  // namespace acutemesh::validation
