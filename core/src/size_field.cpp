#include "size_field.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <atomic>

#include "acutemesh/predicates.h"
#include "build.h"
#include "triangulation.h"

namespace acutemesh::detail {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Nodes of the background grid along the longer side of the input's box: where scattered
// sizes are sampled and the grading is applied (Persson 2006; JIGSAW limits its hfun on its
// own grid the same way).
constexpr uint32_t kBackgroundCells = 512;

using SizeFunction = std::function<double(double, double)>;

// A grid of values, bilinear in between, the nearest border value outside.
double bilinear(const SizeField::Grid& g, double x, double y) {
  auto axis = [](double u, double u0, double du, uint32_t n, uint32_t& i, double& f) {
    double s = n > 1 ? (u - u0) / du : 0;
    if (!(s > 0)) s = 0;  // (also NaN)
    if (s >= n - 1) s = n - 1;
    i = std::min(uint32_t(s), n > 1 ? n - 2 : 0);
    f = n > 1 ? s - i : 0;
  };
  uint32_t i, j;
  double fx, fy;
  axis(x, g.x0, g.dx, g.nx, i, fx);
  axis(y, g.y0, g.dy, g.ny, j, fy);
  const double* h = &g.h[i + size_t(g.nx) * j];
  const double h10 = g.nx > 1 ? h[1] : h[0];
  const double h01 = g.ny > 1 ? h[g.nx] : h[0];
  const double h11 = g.nx > 1 && g.ny > 1 ? h[g.nx + 1] : g.nx > 1 ? h10 : h01;
  return (1 - fy) * ((1 - fx) * h[0] + fx * h10) + fy * ((1 - fx) * h01 + fx * h11);
}

// The smallest of the sources a function may stand for, at (x, y).
SizeFunction smallestOf(std::vector<SizeFunction> parts) {
  if (parts.size() == 1) return parts[0];
  return [parts = std::move(parts)](double x, double y) {
    double h = kInf;
    for (const SizeFunction& f : parts) h = std::min(h, f(x, y));
    return h;
  };
}

// Scattered sizes, linear over their Delaunay triangulation, sampled at the nodes of `g`; a
// node outside the hull takes the value on the hull edge that faces it.
void sampleScattered(const SizeField& size, SizeField::Grid& g) {
  Triangulation D;
  std::vector<uint32_t> canonical, inputOf;
  Options none;
  const StepResult built = buildDelaunay(D, size.points, canonical, inputOf, Budget(none));
  const size_t n = size.sizes.size();
  // Fewer than three points in general position: the smallest size everywhere.
  if (!built.ok() || D.triangleSlots() == 0) {
    const double h = *std::min_element(size.sizes.begin(), size.sizes.end());
    for (double& v : g.h) v = std::min(v, h);
    return;
  }
  auto sizeOf = [&](uint32_t v) { return size.sizes[inputOf[v] < n ? inputOf[v] : 0]; };
  uint32_t hint = 0;
  for (uint32_t j = 0; j < g.ny; ++j)
    for (uint32_t i = 0; i < g.nx; ++i) {
      const double p[2] = {g.x0 + i * g.dx, g.y0 + j * g.dy};
      const Location loc = D.locate(p, hint);
      if (loc.where == Where::Failed) continue;
      if (loc.where == Where::OnVertex) {
        g.h[i + size_t(g.nx) * j] = std::min(g.h[i + size_t(g.nx) * j], sizeOf(loc.vertex));
        continue;
      }
      const uint32_t t = loc.where == Where::InTriangle ? loc.tri : loc.edge / 3;
      hint = t;
      const uint32_t* v = &D.tri[3 * t];
      double h;
      if (D.isGhost(t)) {
        int k = 0;  // the hull edge v[k] -> v[k+1]
        while (v[k] == kGhost || v[(k + 1) % 3] == kGhost) ++k;
        const double *a = D.point(v[k]), *b = D.point(v[(k + 1) % 3]);
        const double ux = b[0] - a[0], uy = b[1] - a[1];
        double s = ((p[0] - a[0]) * ux + (p[1] - a[1]) * uy) / (ux * ux + uy * uy);
        s = std::clamp(s, 0.0, 1.0);
        h = (1 - s) * sizeOf(v[k]) + s * sizeOf(v[(k + 1) % 3]);
      } else {
        const double *a = D.point(v[0]), *b = D.point(v[1]), *c = D.point(v[2]);
        const double area = orient2d(a, b, c);
        const double wa = orient2d(p, b, c) / area, wb = orient2d(a, p, c) / area;
        h = wa * sizeOf(v[0]) + wb * sizeOf(v[1]) + (1 - wa - wb) * sizeOf(v[2]);
      }
      g.h[i + size_t(g.nx) * j] = std::min(g.h[i + size_t(g.nx) * j], h);
    }
}

// |grad h| <= grading on the grid: h(i) <= h(j) + grading * |i - j| over the 16 neighbours
// a knight's move or less away (distances within 1.4% of Euclidean), in two sweeps (forward
// and backward, as a chamfer distance transform), repeated until nothing changes.
void limitGradient(SizeField::Grid& g, double grading) {
  struct Step {
    int di, dj;
    double d;
  };
  // The neighbours before a node in row-major order; the backward sweep mirrors them.
  const Step before[] = {{-1, 0, 1},           {-1, -1, M_SQRT2},      {0, -1, 1},
                         {1, -1, M_SQRT2},     {-2, -1, std::sqrt(5.)}, {-1, -2, std::sqrt(5.)},
                         {1, -2, std::sqrt(5.)}, {2, -1, std::sqrt(5.)}};
  const double cell = g.dx;
  const int nx = int(g.nx), ny = int(g.ny);
  for (bool changed = true; changed;) {
    changed = false;
    for (int pass = 0; pass < 2; ++pass) {
      const int sign = pass == 0 ? 1 : -1;
      for (int jj = 0; jj < ny; ++jj)
        for (int ii = 0; ii < nx; ++ii) {
          const int i = pass == 0 ? ii : nx - 1 - ii, j = pass == 0 ? jj : ny - 1 - jj;
          double& h = g.h[size_t(i) + size_t(nx) * j];
          for (const Step& s : before) {
            const int a = i + sign * s.di, b = j + sign * s.dj;
            if (a < 0 || b < 0 || a >= nx || b >= ny) continue;
            const double limit = g.h[size_t(a) + size_t(nx) * b] + grading * s.d * cell;
            if (limit < h) h = limit, changed = true;
          }
        }
    }
  }
}

// The domain's own small features as sizes on the grid, for the grading to spread: at each
// vertex of the constrained triangulation its shortest domain edge (the local feature size),
// at the grid node nearest to it. Without this a grading would have nothing to act on where
// the sizes given are uniform.
void seedFeatureSizes(const Triangulation& T, const std::vector<uint8_t>& inside, SizeField::Grid& g) {
  std::vector<double> shortest(T.vertexCount(), kInf);
  for (uint32_t t = 0; t < T.triangleSlots() && t < inside.size(); ++t) {
    if (!inside[t]) continue;
    const uint32_t* v = &T.tri[3 * t];
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = v[k], b = v[(k + 1) % 3];
      if (a == kGhost || b == kGhost) continue;
      const double *p = T.point(a), *q = T.point(b);
      const double d = std::hypot(p[0] - q[0], p[1] - q[1]);
      shortest[a] = std::min(shortest[a], d), shortest[b] = std::min(shortest[b], d);
    }
  }
  for (uint32_t v = 0; v < T.vertexCount(); ++v) {
    if (!(shortest[v] < kInf)) continue;
    const double* p = T.point(v);
    const double i = std::clamp(std::round((p[0] - g.x0) / g.dx), 0.0, double(g.nx - 1));
    const double j = std::clamp(std::round((p[1] - g.y0) / g.dy), 0.0, double(g.ny - 1));
    double& h = g.h[size_t(i) + size_t(g.nx) * size_t(j)];
    h = std::min(h, shortest[v]);
  }
}

// The input's box as a background grid of square cells, every node +infinity.
SizeField::Grid backgroundGrid(const Pslg& input) {
  double lo[2] = {kInf, kInf}, hi[2] = {-kInf, -kInf};
  for (size_t i = 0; i + 1 < input.points.size(); ++i)
    lo[i % 2] = std::min(lo[i % 2], input.points[i]), hi[i % 2] = std::max(hi[i % 2], input.points[i]);
  SizeField::Grid g;
  const double w = std::max(hi[0] - lo[0], hi[1] - lo[1]);
  const double cell = w > 0 ? w / kBackgroundCells : 1;
  g.x0 = lo[0], g.y0 = lo[1], g.dx = g.dy = cell;
  g.nx = uint32_t(std::ceil((hi[0] - lo[0]) / cell)) + 1;
  g.ny = uint32_t(std::ceil((hi[1] - lo[1]) / cell)) + 1;
  g.h.assign(size_t(g.nx) * g.ny, kInf);
  return g;
}

// A triangle's area bound by region: the constrained triangulation as it was before
// refinement, each domain triangle with its region's bound, and an exact walk from a nearby
// triangle to the one holding the point. Triangles never cross segments, so a triangle's
// centroid names its region all through refinement.
class RegionAreas {
 public:
  RegionAreas(const Triangulation& T, const std::vector<uint8_t>& inside, const Pslg& input)
      : pts_(T.pts), tri_(T.tri), opp_(T.opp) {
    const uint32_t slots = uint32_t(tri_.size() / 3);
    bound_.assign(slots, 0);
    std::vector<uint32_t> stack;
    for (const Region& r : input.regions) {  // later regions win, as in Triangle
      const double p[2] = {r.x, r.y};
      const Location loc = T.locate(p, 0);
      uint32_t t = loc.where == Where::InTriangle ? loc.tri
                   : loc.where == Where::OnEdge   ? loc.edge / 3
                   : loc.where == Where::OnVertex ? T.vertexEdge[loc.vertex] / 3
                                                  : kNone;
      if (t == kNone || t >= inside.size() || !inside[t]) continue;
      std::vector<uint8_t> seen(slots, 0);
      stack.assign(1, t);
      seen[t] = 1;
      while (!stack.empty()) {
        const uint32_t u = stack.back();
        stack.pop_back();
        bound_[u] = r.maxArea;
        for (uint32_t e = 3 * u; e < 3 * u + 3; ++e) {
          const uint32_t w = T.opp[e] / 3;
          if (T.fixed[e] || seen[w] || w >= inside.size() || !inside[w]) continue;
          seen[w] = 1;
          stack.push_back(w);
        }
      }
    }
    // A grid of cells over the box: a cell that only domain triangles of one bound overlap
    // answers at once (most of them); the others keep a start near them for the walk.
    double lo[2] = {kInf, kInf}, hi[2] = {-kInf, -kInf};
    for (size_t i = 0; i < pts_.size(); ++i)
      lo[i % 2] = std::min(lo[i % 2], pts_[i]), hi[i % 2] = std::max(hi[i % 2], pts_[i]);
    side_ = uint32_t(std::clamp(2 * std::sqrt(double(slots)), 1.0, 1024.0));
    x0_ = lo[0], y0_ = lo[1];
    cw_ = std::max(hi[0] - lo[0], 1e-300) / side_, ch_ = std::max(hi[1] - lo[1], 1e-300) / side_;
    const size_t cells = size_t(side_) * side_;
    start_.assign(cells, kNone);
    cellBound_.assign(cells, kUnset);
    for (uint32_t t = 0; t < slots; ++t) {
      if (t >= inside.size() || !inside[t]) continue;
      const uint32_t* v = &tri_[3 * t];
      double tlo[2] = {kInf, kInf}, thi[2] = {-kInf, -kInf};
      for (int k = 0; k < 3; ++k)
        for (int d = 0; d < 2; ++d)
          tlo[d] = std::min(tlo[d], pts_[2 * v[k] + d]), thi[d] = std::max(thi[d], pts_[2 * v[k] + d]);
      const size_t first = cellOf(tlo[0], tlo[1]), last = cellOf(thi[0], thi[1]);
      for (size_t j = first / side_; j <= last / side_; ++j)
        for (size_t i = first % side_; i <= last % side_; ++i) {
          const size_t c = i + side_ * j;
          if (start_[c] == kNone) start_[c] = t;
          double& b = cellBound_[c];
          b = b == kUnset || b == bound_[t] ? bound_[t] : kMixed;
        }
    }
    for (uint32_t& s : start_)
      if (s == kNone) s = anyInside(inside);
  }

  // The area bound at p (0: none).
  double at(double x, double y) const {
    const size_t cell = cellOf(x, y);
    if (cellBound_[cell] >= 0) return cellBound_[cell];
    const double p[2] = {x, y};
    uint32_t t = start_[cell];
    uint32_t entered = kNone;
    uint64_t rng = 0x9E3779B97F4A7C15ull ^ uint64_t(t);
    for (size_t step = 0; step < tri_.size(); ++step) {
      rng ^= rng << 13, rng ^= rng >> 7, rng ^= rng << 17;
      const uint32_t first = uint32_t(rng % 3);
      bool moved = false;
      for (uint32_t i = 0; i < 3 && !moved; ++i) {
        const uint32_t e = 3 * t + (first + i) % 3;
        if (e == entered) continue;
        const uint32_t a = tri_[e], b = tri_[next(e)];
        if (a == kGhost || b == kGhost) continue;
        if (orient2d(&pts_[2 * size_t(a)], &pts_[2 * size_t(b)], p) < 0) {
          entered = opp_[e];
          t = entered / 3;
          moved = true;
        }
      }
      if (!moved) return bound_[t];
      const uint32_t* v = &tri_[3 * t];
      if (v[0] == kGhost || v[1] == kGhost || v[2] == kGhost) return 0;  // (outside: none)
    }
    return 0;
  }

 private:
  size_t cellOf(double x, double y) const {
    const double i = std::clamp((x - x0_) / cw_, 0.0, double(side_ - 1));
    const double j = std::clamp((y - y0_) / ch_, 0.0, double(side_ - 1));
    return size_t(i) + size_t(side_) * size_t(j);
  }
  uint32_t anyInside(const std::vector<uint8_t>& inside) const {
    for (uint32_t t = 0; t < inside.size(); ++t)
      if (inside[t]) return t;
    return 0;
  }

  std::vector<double> pts_;
  std::vector<uint32_t> tri_, opp_;
  static constexpr double kUnset = -1, kMixed = -2;  // cellBound_ but a bound
  std::vector<double> bound_;
  std::vector<double> cellBound_;
  std::vector<uint32_t> start_;
  uint32_t side_ = 1;
  double x0_ = 0, y0_ = 0, cw_ = 1, ch_ = 1;
};

bool positive(double h) { return h > 0; }  // (+infinity too; not NaN)

}  // namespace

std::string checkSizes(const Options& o) {
  if (!(o.maxEdge >= 0) || !std::isfinite(o.maxEdge)) return "maxEdge must be a finite number >= 0";
  if (!(o.grading >= 0) || !std::isfinite(o.grading)) return "grading must be a finite number >= 0";
  const SizeField::Grid& g = o.size.grid;
  if (!g.h.empty() || g.nx || g.ny) {
    if (g.nx == 0 || g.ny == 0 || g.h.size() != size_t(g.nx) * g.ny)
      return "size grid: h must hold nx * ny = " + std::to_string(size_t(g.nx) * g.ny) +
             " values, found " + std::to_string(g.h.size());
    if (!std::isfinite(g.x0) || !std::isfinite(g.y0) || !(g.dx > 0) || !(g.dy > 0) ||
        !std::isfinite(g.dx) || !std::isfinite(g.dy))
      return "size grid: x0, y0 must be finite and dx, dy finite and > 0";
    for (size_t i = 0; i < g.h.size(); ++i)
      if (!positive(g.h[i]))
        return "size grid: h[" + std::to_string(i) + "] must be > 0, found " + shortestText(g.h[i]);
  }
  const SizeField& s = o.size;
  if (s.points.size() != 2 * s.sizes.size())
    return "size points: " + std::to_string(s.points.size()) + " coordinates for " +
           std::to_string(s.sizes.size()) + " sizes (x, y per size)";
  for (size_t i = 0; i < s.sizes.size(); ++i) {
    if (!std::isfinite(s.points[2 * i]) || !std::isfinite(s.points[2 * i + 1]))
      return "size point " + std::to_string(i) + " must have finite coordinates";
    if (!positive(s.sizes[i]))
      return "size point " + std::to_string(i) + ": its size must be > 0, found " + shortestText(s.sizes[i]);
  }
  return {};
}

struct SizeFunctionGuard::Seen {
  std::atomic<bool> any{false};
  std::mutex mutex;
  std::string message;

  double check(const char* what, double x, double y, double value) {
    if (value > 0) return value;
    if (!any.exchange(true)) {
      std::lock_guard<std::mutex> lock(mutex);
      message = std::string("size: ") + what + " returned " + shortestText(value) + " at (" +
                shortestText(x) + ", " + shortestText(y) + "); " + what +
                " values must be > 0 (+infinity: no bound there)";
    }
    return kInf;
  }
};

SizeFunctionGuard::SizeFunctionGuard(Options& o) : seen_(std::make_shared<Seen>()) {
  if (o.size.function)
    o.size.function = [f = o.size.function, seen = seen_](double x, double y) {
      return seen->check("the size function", x, y, f(x, y));
    };
  if (o.size.maxArea)
    o.size.maxArea = [f = o.size.maxArea, seen = seen_](double x, double y) {
      return seen->check("the maxArea function", x, y, f(x, y));
    };
}

std::string SizeFunctionGuard::message() const {
  if (!seen_->any) return {};
  std::lock_guard<std::mutex> lock(seen_->mutex);
  return seen_->message;
}

void scaleSizes(Options& o, int exponent) {
  if (exponent == 0) return;
  const double f = std::ldexp(1.0, -exponent);  // caller's lengths -> meshed lengths
  auto scaled = [f](double v) {
    const double s = v * f;
    return std::isinf(s) ? 0 : std::max(s, std::numeric_limits<double>::denorm_min());
  };
  if (o.maxEdge > 0) o.maxEdge = scaled(o.maxEdge);
  if (o.size.function)
    o.size.function = [h = o.size.function, f](double x, double y) { return h(x / f, y / f) * f; };
  if (o.size.maxArea)
    o.size.maxArea = [a = o.size.maxArea, f](double x, double y) { return a(x / f, y / f) * f * f; };
  SizeField::Grid& g = o.size.grid;
  g.x0 *= f, g.y0 *= f, g.dx *= f, g.dy *= f;
  for (double& h : g.h) h *= f;
  for (double& v : o.size.points) v *= f;
  for (double& h : o.size.sizes) h *= f;
}

void compileSizes(const Triangulation& T, const std::vector<uint8_t>& inside, const Pslg& input,
                  Options& o) {
  SizeField& s = o.size;
  std::vector<SizeFunction> direct;
  if (s.function) direct.push_back(s.function);
  if (!s.grid.h.empty())
    direct.push_back([g = std::make_shared<const SizeField::Grid>(std::move(s.grid))](
                         double x, double y) { return bilinear(*g, x, y); });
  s.grid = SizeField::Grid{};
  const bool background = !s.sizes.empty() || (o.grading > 0 && (!direct.empty() || o.maxEdge > 0));
  if (background) {
    SizeField::Grid g = backgroundGrid(input);
    for (uint32_t j = 0; j < g.ny; ++j)
      for (uint32_t i = 0; i < g.nx; ++i) {
        double h = o.maxEdge > 0 ? o.maxEdge : kInf;
        for (const SizeFunction& f : direct) h = std::min(h, f(g.x0 + i * g.dx, g.y0 + j * g.dy));
        g.h[i + size_t(g.nx) * j] = h;
      }
    if (!s.sizes.empty()) sampleScattered(s, g);
    if (o.grading > 0) {
      seedFeatureSizes(T, inside, g);
      limitGradient(g, o.grading);
    }
    for (double& h : g.h)
      if (std::isinf(h)) h = std::numeric_limits<double>::max();  // (bilinear of +inf: NaN)
    direct.push_back([g = std::make_shared<const SizeField::Grid>(std::move(g))](
                         double x, double y) { return bilinear(*g, x, y); });
  }
  s.points.clear(), s.sizes.clear();
  o.grading = 0;
  if (!direct.empty()) s.function = smallestOf(std::move(direct));

  bool regionBound = false;
  for (const Region& r : input.regions) regionBound |= r.maxArea > 0;
  if (regionBound) {
    auto regions = std::make_shared<const RegionAreas>(T, inside, input);
    SizeFunction own = s.maxArea;
    s.maxArea = [regions, own](double x, double y) {
      const double r = regions->at(x, y), a = own ? own(x, y) : kInf;
      return r > 0 ? std::min(r, a) : a;
    };
  }
}

double Sizes::ratio(const double* a, const double* b, const double* c) const {
  const double cx = (a[0] + b[0] + c[0]) / 3, cy = (a[1] + b[1] + c[1]) / 3;
  double r = 0;
  if (maxEdge > 0 || edge) {
    auto d2 = [](const double* p, const double* q) {
      return (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]);
    };
    const double longest = std::sqrt(std::max({d2(a, b), d2(b, c), d2(c, a)}));
    double h = maxEdge > 0 ? maxEdge : kInf;
    if (edge) h = std::min(h, edge(cx, cy));
    if (h > 0) r = longest / h;
  }
  if (area) {
    const double bound = area(cx, cy);
    if (bound > 0 && bound < kInf) r = std::max(r, std::sqrt(0.5 * std::fabs(orient2d(a, b, c)) / bound));
  }
  return r;
}

double sizeDemand(const Triangulation& T, const Options& o) {
  const Sizes sizes(o);
  if (!(o.maxArea > 0) && !sizes.any()) return 0;
  double demand = 0;
  for (uint32_t t = 0; t < T.triangleSlots(); ++t) {
    if (!T.inDomain(t)) continue;
    const double *a = T.point(T.tri[3 * t]), *b = T.point(T.tri[3 * t + 1]),
                 *c = T.point(T.tri[3 * t + 2]);
    const double area = 0.5 * orient2d(a, b, c);
    double density = o.maxArea > 0 ? 1 / o.maxArea : 0;  // triangles per unit area
    const double centroid[2] = {(a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3};
    for (const double* p : {a, b, c, centroid}) {
      double h = sizes.maxEdge > 0 ? sizes.maxEdge : kInf;
      if (sizes.edge) h = std::min(h, sizes.edge(p[0], p[1]));
      if (h > 0 && h < kInf) density = std::max(density, 4 / (std::sqrt(3.0) * h * h));
      if (sizes.area) {
        const double bound = sizes.area(p[0], p[1]);
        if (bound > 0 && bound < kInf) density = std::max(density, 1 / bound);
      }
    }
    demand += area * density;
  }
  return demand;
}

}  // namespace acutemesh::detail
