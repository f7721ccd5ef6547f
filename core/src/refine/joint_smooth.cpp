#include "joint_smooth.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "geometry.h"
#include "params.h"

namespace acutemesh::detail {
namespace {

// A point that moves: freely, or along the line of its segment.
struct Mover {
  uint32_t v;
  uint32_t segment = kNone;  // on a segment: its input segment (kNone on a hull edge)
  bool onLine = false;
  double ends[4] = {0, 0, 0, 0};  // on a line: its neighbours there (a hull edge's line)
  double scale2 = 0;              // its shortest edge, squared: the step's scale
  double from[2] = {0, 0}, step[2] = {0, 0};
};

// Whether v moves, and how (RefineState::slideOf), with its shortest edge.
bool moverOf(const RefineState& s, uint32_t v, Mover& m) {
  const Triangulation& T = s.T;
  uint32_t ends[2];
  m = Mover{};
  if (!s.slideOf(v, ends, m.segment)) return false;
  m.v = v, m.onLine = ends[0] != kNone, m.scale2 = INFINITY;
  for (int k = 0; k < 2 && m.onLine; ++k)
    m.ends[2 * k] = T.point(ends[k])[0], m.ends[2 * k + 1] = T.point(ends[k])[1];
  uint32_t e0 = T.vertexEdge[v], e = e0;
  do {
    if (T.tri[next(e)] != kGhost)
      m.scale2 = std::min(m.scale2, dist2(T.point(v), T.point(T.tri[next(e)])));
    e = T.opp[prev(e)];
  } while (e != e0);
  return true;
}

// The penalty: the sum over the domain's corners of the squared excess (radians) of the angle
// over `aim`; with `grad`, its gradient by vertex (x, y pairs) added there.
double penalty(const Triangulation& T, double aim, std::vector<double>* grad) {
  double sum = 0;
  for (uint32_t t = 0; t < T.triangleSlots(); ++t) {
    if (!T.inDomain(t)) continue;
    const uint32_t* c = &T.tri[3 * t];
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = c[k], b = c[(k + 1) % 3], d = c[(k + 2) % 3];
      const double *pa = T.point(a), *pb = T.point(b), *pd = T.point(d);
      const double ux = pb[0] - pa[0], uy = pb[1] - pa[1], wx = pd[0] - pa[0], wy = pd[1] - pa[1];
      const double angle = std::atan2(ux * wy - uy * wx, ux * wx + uy * wy);
      if (angle <= aim) continue;
      const double excess = angle - aim;
      sum += excess * excess;
      if (!grad) continue;
      // d angle / d b = (uy, -ux) / |u|^2, d angle / d d = (-wy, wx) / |w|^2, a the opposite.
      const double f = 2 * excess, u2 = ux * ux + uy * uy, w2 = wx * wx + wy * wy;
      const double gb[2] = {f * uy / u2, -f * ux / u2}, gd[2] = {-f * wy / w2, f * wx / w2};
      double* g = grad->data();
      g[2 * b] += gb[0], g[2 * b + 1] += gb[1];
      g[2 * d] += gd[0], g[2 * d + 1] += gd[1];
      g[2 * a] -= gb[0] + gd[0], g[2 * a + 1] -= gb[1] + gd[1];
    }
  }
  return sum;
}

// Every triangle at a mover counter-clockwise (exact) and its edges no shorter than minEdge2.
bool valid(const Triangulation& T, const std::vector<Mover>& movers, double minEdge2) {
  for (const Mover& m : movers) {
    uint32_t e0 = T.vertexEdge[m.v], e = e0;
    do {
      const uint32_t* c = &T.tri[3 * (e / 3)];
      const uint32_t w = T.tri[next(e)];
      if (!T.isGhost(e / 3) && orient2d(T.point(c[0]), T.point(c[1]), T.point(c[2])) <= 0)
        return false;
      if (w != kGhost && dist2(T.point(m.v), T.point(w)) < minEdge2) return false;
      e = T.opp[prev(e)];
    } while (e != e0);
  }
  return true;
}

// Each mover from its place by h times its step (no further than kJointFarthest of its
// shortest edge; a point on a segment put on its line).
void stepBy(Triangulation& T, const Job& job, const std::vector<Mover>& movers, double h) {
  for (const Mover& m : movers) {
    double dx = h * m.step[0], dy = h * m.step[1];
    const double far = std::sqrt((dx * dx + dy * dy) / m.scale2) / kJointFarthest;
    if (far > 1) dx /= far, dy /= far;
    const double q[2] = {m.from[0] + dx, m.from[1] + dy};
    double* p = &T.pts[2 * size_t(m.v)];
    if (m.onLine) {
      const SegmentLine line = job.line(m.segment, m.ends, m.ends + 2);
      line.at(line.param(q), p);
    } else {
      p[0] = q[0], p[1] = q[1];
    }
  }
}

}  // namespace

size_t smoothJointly(RefineState& s, const Job& job, double aimDegrees, int steps) {
  Triangulation& T = s.T;
  std::vector<Mover> movers;
  for (uint32_t v = uint32_t(job.input.vertexCount()); v < T.vertexCount(); ++v) {
    Mover m;
    if (moverOf(s, v, m)) movers.push_back(m);
  }
  if (movers.empty()) return 0;
  const double aim = aimDegrees * kDegree;
  std::vector<double> grad(2 * size_t(T.vertexCount()));
  double h = kJointFirstStep;
  size_t taken = 0;
  for (int i = 0; i < steps && !job.budget.stop(); ++i) {
    std::fill(grad.begin(), grad.end(), 0.0);
    const double now = penalty(T, aim, &grad);
    if (now == 0) break;
    // Each point's step: down its gradient (along its line, for a point on a segment), scaled
    // by its shortest edge squared (an angle changes by about the move over the edge's length).
    for (Mover& m : movers) {
      const double* p = T.point(m.v);
      m.from[0] = p[0], m.from[1] = p[1];
      double gx = -grad[2 * m.v] * m.scale2, gy = -grad[2 * m.v + 1] * m.scale2;
      if (m.onLine) {
        const SegmentLine line = job.line(m.segment, m.ends, m.ends + 2);
        const double along = (gx * line.ux + gy * line.uy) / line.u2;
        gx = along * line.ux, gy = along * line.uy;
      }
      m.step[0] = gx, m.step[1] = gy;
    }
    // Backtracking: the step halved until the penalty drops with every triangle valid.
    bool took = false;
    for (int tries = 0; tries < kJointTries; ++tries) {
      stepBy(T, job, movers, h);
      took = valid(T, movers, job.minEdge2) && penalty(T, aim, nullptr) < now;
      if (took) break;
      for (const Mover& m : movers)
        T.pts[2 * size_t(m.v)] = m.from[0], T.pts[2 * size_t(m.v) + 1] = m.from[1];
      h *= 0.5;
    }
    if (!took) break;
    ++taken;
    h = std::min(2 * h, kJointFirstStep);
  }
  return taken;
}

}  // namespace acutemesh::detail
