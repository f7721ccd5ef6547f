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

inline int sign(double v) { return (v > 0) - (v < 0); }

}  // namespace acutemesh
