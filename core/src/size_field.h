// Sizes: Options::maxEdge, Options::size (a function, a grid, scattered sizes, an area
// function), Options::grading and the regions' area bounds, made into what refinement asks of
// a triangle: is it larger than the sizes allow? One place for that rule; the target
// (refine/target.h) and the output's certificate (mesh.cpp) both ask here.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "acutemesh/acutemesh.h"

namespace acutemesh::detail {

class Triangulation;

// An option out of range, or empty: maxEdge, grading, a grid's shape and values, scattered
// sizes' arrays.
std::string checkSizes(const Options& options);

// Watches the caller's size and area functions: the first value that is not > 0 (NaN, 0,
// negative) is kept with its place, and counts as no bound there. mesh() reports it as
// BadInput after the run (message() empty: none seen). Safe across refinement's threads.
class SizeFunctionGuard {
 public:
  explicit SizeFunctionGuard(Options& options);  // wraps options.size.function and .maxArea
  std::string message() const;

 private:
  struct Seen;
  std::shared_ptr<Seen> seen_;
};

// The sizes for an input scaled by 2^-exponent (meshScaled): lengths and grid places scaled,
// areas by the square, the functions called at the caller's coordinates.
void scaleSizes(Options& options, int exponent);

// Folds the grid, the scattered sizes and the grading into options.size.function, and the
// regions' area bounds (Pslg::regions, found on T's domain: inside per triangle slot) into
// options.size.maxArea, leaving grid, points and grading empty: what a part's run (parts.h)
// and the target read. Idempotent. (A region point outside the domain bounds nothing here;
// the output's labels warn about it.)
void compileSizes(const Triangulation& T, const std::vector<uint8_t>& inside, const Pslg& input,
                  Options& options);

// The compiled sizes a triangle is held to (after compileSizes): what the target and the
// certificate read.
struct Sizes {
  double maxEdge = 0;
  std::function<double(double, double)> edge, area;  // size and area bound at a point

  Sizes() = default;
  explicit Sizes(const Options& o) : maxEdge(o.maxEdge), edge(o.size.function), area(o.size.maxArea) {}
  bool any() const { return maxEdge > 0 || bool(edge) || bool(area); }
  // The triangle a, b, c: its longest edge over the size at its centroid, and
  // sqrt(area / bound) for the area bound there; the larger (0 without sizes). Over 1: too
  // large.
  double ratio(const double* a, const double* b, const double* c) const;
};

// About how many triangles Options::maxArea and the sizes ask for over T's domain (sampled at
// each domain triangle's corners and centroid; 0 without either): for the Steiner budget and
// the room reserved up front.
double sizeDemand(const Triangulation& T, const Options& options);

}  // namespace acutemesh::detail
