// Floating-point constructions refinement shares: distances, circumcentres, points on a
// segment's line. Predicates (exact) decide topology; these only propose points.
//
// The WebAssembly build must make the very meshes the native one makes, and the two link
// different maths libraries: only +, -, *, / and sqrt are exact IEEE operations everywhere. So
// constructions use those alone (sin, cos and atan2 too: portable_math.h), never hypot, pow,
// exp2 or log2.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "../triangulation.h"
#include "acutemesh/acutemesh.h"
#include "acutemesh/predicates.h"

namespace acutemesh::detail {

inline double dist2(const double* a, const double* b) {
  double dx = a[0] - b[0], dy = a[1] - b[1];
  return dx * dx + dy * dy;
}

// Circumcentre of a, b, c (relative to a for accuracy).
inline void circumcenter(const double* a, const double* b, const double* c, double* out) {
  double bx = b[0] - a[0], by = b[1] - a[1], cx = c[0] - a[0], cy = c[1] - a[1];
  double d = 2 * (bx * cy - by * cx);
  double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  out[0] = a[0] + (cy * b2 - by * c2) / d;
  out[1] = a[1] + (bx * c2 - cx * b2) / d;
}

// The power of two nearest x > 0 in the log scale: round(log2 x), from x's exponent and
// whether its mantissa m (x = m 2^e, 0.5 <= m < 1) is at least sqrt(1/2).
inline double powerOfTwoNear(double x) {
  int e = 0;
  double m = std::frexp(x, &e);
  return std::ldexp(1.0, m >= M_SQRT1_2 ? e : e - 1);
}

// Candidate Steiner points: x, y and the squared distance to the nearest vertex.
using Candidates = std::vector<std::array<double, 3>>;

// Farthest first, ties in the order found: an insertion sort (a few dozen entries; the same
// order in every standard library).
inline void sortFarthestFirst(Candidates& points) {
  for (size_t i = 1; i < points.size(); ++i)
    for (size_t j = i; j > 0 && points[j - 1][2] < points[j][2]; --j)
      std::swap(points[j - 1], points[j]);
}

// The line of an input segment (or of p-q for a hull edge). Points on a segment are made from
// it, by their parameter along it, never from rounded points on it, so that rounding does not
// accumulate along a segment.
struct SegmentLine {
  const double *start, *end;
  double ux, uy, u2;
  // With `exact` (Options::exactSegments) at() moves t to the nearest parameter with few enough
  // bits that the point lies exactly on the line, if there is one within 2^-24 of the
  // segment's length (there is for integer coordinates): the finest such.
  bool exact = false;
  double param(const double* x) const {
    return ((x[0] - start[0]) * ux + (x[1] - start[1]) * uy) / u2;
  }
  void at(double t, double* out) const {
    out[0] = start[0] + t * ux, out[1] = start[1] + t * uy;
    if (!exact || orient2d(start, end, out) == 0) return;
    for (int bits = 60; bits >= 24; bits -= 2) {
      double s = std::ldexp(std::nearbyint(std::ldexp(t, bits)), -bits);
      double m[2] = {start[0] + s * ux, start[1] + s * uy};
      if (orient2d(start, end, m) == 0) {
        out[0] = m[0], out[1] = m[1];
        return;
      }
    }
  }
};

// The line of input segment seg, or of p-q where seg is kNone (a hull edge).
inline SegmentLine segmentLine(const Pslg& input, bool exact, uint32_t seg, const double* p,
                               const double* q) {
  const double *A = p, *B = q;
  if (seg != kNone) {
    A = &input.points[2 * size_t(input.segments[2 * size_t(seg)])];
    B = &input.points[2 * size_t(input.segments[2 * size_t(seg) + 1])];
  }
  double ux = B[0] - A[0], uy = B[1] - A[1];
  return {A, B, ux, uy, ux * ux + uy * uy, exact};
}

// Size of a triangle for the repair order: its shortest edge, squared.
inline double shortestEdge2(const Triangulation& T, uint32_t t) {
  const uint32_t* v = &T.tri[3 * t];
  const double *a = T.point(v[0]), *b = T.point(v[1]), *c = T.point(v[2]);
  return std::min({dist2(a, b), dist2(b, c), dist2(c, a)});
}

// The cosine of a triangle's smallest angle (the one facing its shortest edge), for the
// skinniest-first repair order.
inline double smallestAngleCos(const Triangulation& T, uint32_t t) {
  const uint32_t* v = &T.tri[3 * t];
  const double *a = T.point(v[0]), *b = T.point(v[1]), *c = T.point(v[2]);
  double e[3] = {dist2(b, c), dist2(c, a), dist2(a, b)};
  std::sort(e, e + 3);
  return (e[1] + e[2] - e[0]) / (2 * std::sqrt(e[1] * e[2]));
}

// Walks the straight line from the centroid of t to x: the first fixed half-edge it crosses,
// else kNone with the triangle holding x in `reached` (kNone too if the walk meets a vertex
// or leaves the triangulation).
uint32_t firstFixedCrossed(const Triangulation& T, uint32_t t, const double* x, uint32_t& reached);

// The shortest edge refinement makes, squared: 2^-kMinEdgeBits of the input's extent, and
// far from the origin (an input moved by 1e15), where the coordinates' resolution is coarse,
// at least 2^-kMinEdgeUlpBits of the largest coordinate, or split points round off their
// segments by a visible fraction of the edge. Deeper refinement (a narrow wedge it cannot
// fill) stops there and leaves the triangle to the certificate.
double smallestEdge2(const Pslg& input);


}  // namespace acutemesh::detail
