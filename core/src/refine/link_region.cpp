#include "link_region.h"

#include <algorithm>
#include <cmath>

namespace acutemesh::detail {

bool LinkRegion::leavesRoom() const {
  if (!target_.boundsLargest()) return true;
  const size_t n = edges.size();
  for (size_t i = 0; i < n; ++i) {
    const uint32_t y = edges[i][1];
    for (size_t k = 1; k < n; ++k) {  // the next edge first: links come in order
      const auto& after = edges[(i + k) % n];
      if (after[0] != y) continue;
      const double turn = orient2d(s_.P(edges[i][0]), s_.P(y), s_.P(after[1]));
      if (target_.nonObtuse ? turn < 0 : turn <= 0) return false;
      break;
    }
  }
  return true;
}

void LinkRegion::clip(bool wedges) {
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (const auto& edge : edges)
    for (int k = 0; k < 2; ++k)
      lo[k] = std::min(lo[k], s_.P(edge[0])[k]), hi[k] = std::max(hi[k], s_.P(edge[0])[k]);
  const bool largest = target_.boundsLargest(), smallest = target_.minAngle > 0;
  // Every clip adds at most one corner: the buffers are sized before the loops, which run on
  // raw pointers (the hottest loop of the improvement rounds).
  const size_t clips = edges.size() * (1 + 2 * largest + 2 * smallest);
  const size_t room = 4 + clips + 1;
  if (work_.size() < 2 * room) work_.resize(2 * room);
  if (side_.size() < room + 1) side_.resize(room + 1);
  std::array<double, 2>* poly = work_.data();
  std::array<double, 2>* next = poly + room;
  double* f = side_.data();
  size_t n = 4;
  poly[0] = {lo[0], lo[1]}, poly[1] = {hi[0], lo[1]}, poly[2] = {hi[0], hi[1]},
  poly[3] = {lo[0], hi[1]};
  auto clipTo = [&](double nx, double ny, double c) {  // keep n.p > c
    size_t kept = 0;
    for (size_t i = 0; i < n; ++i) {
      f[i] = nx * poly[i][0] + ny * poly[i][1] - c;
      kept += f[i] > 0;
    }
    if (kept == n) return;  // (this is where the time goes: most clips cut nothing)
    f[n] = f[0];
    size_t m = 0;
    for (size_t i = 0; i < n && kept > 0; ++i) {
      const auto &p = poly[i], &q = poly[i + 1 < n ? i + 1 : 0];
      double fp = f[i], fq = f[i + 1];
      if (fp > 0) next[m++] = p;
      if ((fp > 0) != (fq > 0) && fp != fq) {
        double s = fp / (fp - fq);
        next[m++] = {p[0] + s * (q[0] - p[0]), p[1] + s * (q[1] - p[1])};
      }
    }
    std::swap(poly, next);
    n = m;
  };
  const double c = wedges ? target_.cosMax : 0, s = wedges ? std::sqrt(1 - c * c) : 1;
  const double cm = target_.cosMin, sm = std::sqrt(1 - cm * cm);
  for (size_t i = 0; i < edges.size() && n > 0; ++i) {
    const double *x = s_.P(edges[i][0]), *y = s_.P(edges[i][1]);
    double dx = y[0] - x[0], dy = y[1] - x[1];
    if (largest) {
      double rx = dx * c - dy * s, ry = dx * s + dy * c;   // x->y turned by the bound about x
      clipTo(ry, -rx, ry * x[0] - rx * x[1]);              // p right of that ray
      double qx = -dx * c - dy * s, qy = dx * s - dy * c;  // y->x turned back by it about y
      clipTo(-qy, qx, -qy * y[0] + qx * y[1]);             // p left of that ray
    }
    if (smallest) {  // the same rays for the smallest angle, p on their far sides
      double rx = dx * cm - dy * sm, ry = dx * sm + dy * cm;
      clipTo(-ry, rx, -ry * x[0] + rx * x[1]);
      double qx = -dx * cm - dy * sm, qy = dx * sm - dy * cm;
      clipTo(qy, -qx, qy * y[0] - qx * y[1]);
    }
    clipTo(-dy, dx, -dy * x[0] + dx * x[1]);
  }
  corners_.assign(poly, poly + n);
}

bool LinkRegion::centroid(double* out) const {
  if (corners_.size() < 3) return false;
  out[0] = out[1] = 0;
  for (const auto& p : corners_)
    out[0] += p[0] / double(corners_.size()), out[1] += p[1] / double(corners_.size());
  return true;
}

}  // namespace acutemesh::detail
