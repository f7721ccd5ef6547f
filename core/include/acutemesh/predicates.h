// Exact geometric predicates on double coordinates. Each returns the exact sign of its
// determinant (as a double whose sign is the answer, 0 exactly when degenerate): a fast
// floating-point evaluation with a proven error bound, falling back to exact expansion
// arithmetic only when the bound cannot decide. Compiled with -ffp-contract=off: a fused
// multiply-add would break the error bounds.
#pragma once

namespace acutemesh {

// > 0 if a, b, c are counter-clockwise, < 0 if clockwise, 0 if collinear.
double orient2d(const double* a, const double* b, const double* c);

// > 0 if d lies inside the circle through a, b, c (which must be counter-clockwise),
// < 0 outside, 0 on it.
double incircle(const double* a, const double* b, const double* c, const double* d);

// Sign of (b - a) . (c - a): > 0 iff the angle at a in triangle abc is acute (< 90 degrees),
// 0 iff it is exactly right.
double dot2d(const double* a, const double* b, const double* c);

// dot2d at each corner of triangle p0, p1, p2 at once: out[k] has the sign of
// dot2d(p[k], p[k + 1], p[k + 2]) (indices mod 3), and its value where the filter decides.
void cornerDots(const double* p0, const double* p1, const double* p2, double out[3]);

inline int sign(double v) { return (v > 0) - (v < 0); }

// Exact sign helpers: -1, 0 or +1, with exactly the meaning of the predicate they wrap.
// All predicates are exact unless an intermediate result overflows or underflows; that
// cannot happen while every coordinate is 0 or has magnitude in roughly [1e-50, 1e50].

// +1 if a, b, c are counter-clockwise, -1 if clockwise, 0 if exactly collinear.
inline int orientSign(const double* a, const double* b, const double* c) {
  return sign(orient2d(a, b, c));
}

// +1 if d is strictly inside the circle through counter-clockwise a, b, c, -1 if strictly
// outside, 0 if the four points are exactly cocircular (or a, b, c are collinear and d is
// on their line). Swapping any two arguments negates the result.
inline int incircleSign(const double* a, const double* b, const double* c, const double* d) {
  return sign(incircle(a, b, c, d));
}

// Sign of (b - a) . (c - a): +1 if the angle at a is acute, 0 if exactly right (or b == a
// or c == a), -1 if obtuse.
inline int dotSign(const double* a, const double* b, const double* c) {
  return sign(dot2d(a, b, c));
}

}  // namespace acutemesh
