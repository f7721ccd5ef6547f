// Exact adaptive-precision geometric predicates.
//
// Written from the description in J. R. Shewchuk, "Adaptive Precision Floating-Point
// Arithmetic and Fast Robust Geometric Predicates" (Discrete & Computational Geometry 18,
// 1997): floating-point expansions (a value represented exactly as an unevaluated sum of
// doubles, ordered by increasing magnitude, nonoverlapping), the error-free transformations
// Two-Sum / Fast-Two-Sum / Two-Product (Dekker split), Scale-Expansion and the merge-based
// Fast-Expansion-Sum with zero elimination, and the paper's staged error bounds.
//
// Requirements: IEEE-754 binary64 arithmetic with round-to-nearest-even and no extended
// precision or contraction (this file is compiled with -ffp-contract=off; x87 is not
// supported, SSE2 / AArch64 / WebAssembly are fine). Results are exact unless an
// intermediate value overflows or underflows, which cannot happen for coordinates that are
// 0 or of magnitude in roughly [1e-50, 1e50].
//
// No heap allocation, no exceptions: every expansion lives in a fixed-size stack array sized
// for the worst case of the computation that fills it.

#include "acutemesh/predicates.h"

#include <cmath>

// Belt and braces for builds that miss the -ffp-contract=off flag (GCC in ISO mode does not
// contract; clang and MSVC can be told here).
#if defined(__clang__)
#pragma clang fp contract(off)
#elif defined(_MSC_VER)
#pragma fp_contract(off)
#endif

namespace acutemesh {
namespace {

#if defined(_MSC_VER)
#define ACUTEMESH_NOINLINE __declspec(noinline)
#define ACUTEMESH_ALWAYS_INLINE __forceinline
#else
#define ACUTEMESH_NOINLINE __attribute__((noinline))
#define ACUTEMESH_ALWAYS_INLINE inline __attribute__((always_inline))
#endif

// Half an ulp of 1.0 (the unit roundoff of binary64 round-to-nearest).
constexpr double kEps = 0x1p-53;
// 2^ceil(53/2) + 1: multiplying by it splits a double into two 26-bit halves.
constexpr double kSplitter = 0x1p27 + 1.0;

// Error bound on the rounded sum of an expansion's components, relative to its magnitude.
constexpr double kResultErrBound = (3.0 + 8.0 * kEps) * kEps;
// orient2d (and dot2d, which has the same evaluation structure) error bounds, relative to
// the permanent |detleft| + |detright|, for stage A (plain floating point), stage B (exact
// over the rounded coordinate differences) and stage C (B plus first-order tail terms).
constexpr double kCcwErrBoundA = (3.0 + 16.0 * kEps) * kEps;
constexpr double kCcwErrBoundB = (2.0 + 12.0 * kEps) * kEps;
constexpr double kCcwErrBoundC = (9.0 + 64.0 * kEps) * kEps * kEps;
// incircle error bounds, relative to its permanent, for the same three stages.
constexpr double kIccErrBoundA = (10.0 + 96.0 * kEps) * kEps;
constexpr double kIccErrBoundB = (4.0 + 48.0 * kEps) * kEps;
constexpr double kIccErrBoundC = (44.0 + 576.0 * kEps) * kEps * kEps;

// fabs compiles to a sign-bit mask; a compare-and-negate would become a branch.
ACUTEMESH_ALWAYS_INLINE double absval(double x) { return std::fabs(x); }

// An exact two-component result: hi is the rounded value, lo the rounding error, so that
// hi + lo equals the exact result and |lo| <= ulp(hi) / 2.
struct Pair {
  double hi;
  double lo;
};

// ---------------------------------------------------------------------------------------
// Error-free transformations.

// a + b exactly, for any a, b.
ACUTEMESH_ALWAYS_INLINE Pair twoSum(double a, double b) {
  const double s = a + b;
  const double bPart = s - a;  // the part of b that made it into s
  const double aPart = s - bPart;
  return {s, (a - aPart) + (b - bPart)};
}

// a + b exactly; requires |a| >= |b| (or a == 0).
ACUTEMESH_ALWAYS_INLINE Pair fastTwoSum(double a, double b) {
  const double s = a + b;
  return {s, b - (s - a)};
}

// Rounding error of the already computed difference d = fl(a - b).
ACUTEMESH_ALWAYS_INLINE double twoDiffTail(double a, double b, double d) {
  const double bPart = a - d;  // the part of b that was subtracted
  const double aPart = d + bPart;
  return (a - aPart) + (bPart - b);
}

// a - b exactly, for any a, b.
ACUTEMESH_ALWAYS_INLINE Pair twoDiff(double a, double b) {
  const double d = a - b;
  return {d, twoDiffTail(a, b, d)};
}

// Dekker's split: a == hi + lo with hi and lo each fitting in 26 significant bits.
ACUTEMESH_ALWAYS_INLINE Pair split(double a) {
  const double c = kSplitter * a;
  const double big = c - a;
  const double hi = c - big;
  return {hi, a - hi};
}

// a * b exactly, with b already split into bs.
ACUTEMESH_ALWAYS_INLINE Pair twoProductSplit(double a, double b, Pair bs) {
  const double p = a * b;
  const Pair as = split(a);
  const double err1 = p - as.hi * bs.hi;
  const double err2 = err1 - as.lo * bs.hi;
  const double err3 = err2 - as.hi * bs.lo;
  return {p, as.lo * bs.lo - err3};
}

// a * b exactly.
ACUTEMESH_ALWAYS_INLINE Pair twoProduct(double a, double b) {
  return twoProductSplit(a, b, split(b));
}

// (a.hi + a.lo) - (b.hi + b.lo) as a 4-component nonoverlapping expansion in out[0..3]
// (smallest first, components may be zero). Expansion-Sum specialised to two 2-expansions:
// grow a by -b.lo, then grow the upper part of the result by -b.hi.
ACUTEMESH_ALWAYS_INLINE void twoTwoDiff(Pair a, Pair b, double* out) {
  const Pair d0 = twoDiff(a.lo, b.lo);
  out[0] = d0.lo;
  const Pair s0 = twoSum(a.hi, d0.hi);
  const Pair d1 = twoDiff(s0.lo, b.hi);
  out[1] = d1.lo;
  const Pair s1 = twoSum(s0.hi, d1.hi);
  out[2] = s1.lo;
  out[3] = s1.hi;
}

// a*b - c*d exactly, as a 4-component expansion.
ACUTEMESH_ALWAYS_INLINE void productDiff(double a, double b, double c, double d, double* out) {
  twoTwoDiff(twoProduct(a, b), twoProduct(c, d), out);
}

// ---------------------------------------------------------------------------------------
// Expansion arithmetic. An expansion e[0..n) is ordered by increasing magnitude with
// nonoverlapping components; the routines below eliminate zero components from their
// output but always write at least one component (a lone 0 for the value zero), so the
// sign of a produced expansion is the sign of its last component.

// h = e + f. h needs room for elen + flen components. Merges e and f by magnitude, then
// accumulates with Fast-Two-Sum on the two smallest and Two-Sum afterwards (Shewchuk's
// Fast-Expansion-Sum; correct under round-to-nearest-even).
int expansionSum(int elen, const double* e, int flen, const double* f, double* h) {
  int i = 0;
  int j = 0;
  auto next = [&]() -> double {
    if (j >= flen || (i < elen && absval(e[i]) <= absval(f[j]))) return e[i++];
    return f[j++];
  };
  const int total = elen + flen;
  int n = 0;
  double q = next();
  if (total > 1) {
    const Pair s = fastTwoSum(next(), q);
    if (s.lo != 0.0) h[n++] = s.lo;
    q = s.hi;
    for (int k = 2; k < total; ++k) {
      const Pair t = twoSum(q, next());
      if (t.lo != 0.0) h[n++] = t.lo;
      q = t.hi;
    }
  }
  if (q != 0.0 || n == 0) h[n++] = q;
  return n;
}

// h = b * e. h needs room for 2 * elen components.
int scaleExpansion(int elen, const double* e, double b, double* h) {
  const Pair bs = split(b);
  const Pair p = twoProductSplit(e[0], b, bs);
  int n = 0;
  if (p.lo != 0.0) h[n++] = p.lo;
  double q = p.hi;
  for (int i = 1; i < elen; ++i) {
    const Pair t = twoProductSplit(e[i], b, bs);
    const Pair s = twoSum(q, t.lo);
    if (s.lo != 0.0) h[n++] = s.lo;
    const Pair u = fastTwoSum(t.hi, s.hi);
    if (u.lo != 0.0) h[n++] = u.lo;
    q = u.hi;
  }
  if (q != 0.0 || n == 0) h[n++] = q;
  return n;
}

// h = (x^2 + y^2) * e for elen <= 12. h needs room for 8 * elen components.
int liftScale(int elen, const double* e, double x, double y, double* h) {
  double t[24], xx[48], yy[48];
  int n = scaleExpansion(elen, e, x, t);
  const int nx = scaleExpansion(n, t, x, xx);
  n = scaleExpansion(elen, e, y, t);
  const int ny = scaleExpansion(n, t, y, yy);
  return expansionSum(nx, xx, ny, yy, h);
}

// Approximate value of an expansion (the sum of its components, smallest first).
double estimate(int n, const double* e) {
  double s = e[0];
  for (int i = 1; i < n; ++i) s += e[i];
  return s;
}

// The largest nonzero component of a (possibly not zero-eliminated) expansion, or 0: its
// sign is the exact sign of the expansion.
double topComponent(int n, const double* e) {
  for (int i = n - 1; i >= 0; --i) {
    if (e[i] != 0.0) return e[i];
  }
  return 0.0;
}

// ---------------------------------------------------------------------------------------
// orient2d slow path: stages B, C and the exact stage D.

ACUTEMESH_NOINLINE double orient2dAdapt(const double* a, const double* b, const double* c,
                                         double detsum) {
  const double acx = a[0] - c[0];
  const double bcx = b[0] - c[0];
  const double acy = a[1] - c[1];
  const double bcy = b[1] - c[1];

  // Stage B: the determinant of the rounded differences, exactly.
  double B[4];
  productDiff(acx, bcy, acy, bcx, B);
  double det = estimate(4, B);
  double errbound = kCcwErrBoundB * detsum;
  if (absval(det) >= errbound) return det;

  const double acxTail = twoDiffTail(a[0], c[0], acx);
  const double bcxTail = twoDiffTail(b[0], c[0], bcx);
  const double acyTail = twoDiffTail(a[1], c[1], acy);
  const double bcyTail = twoDiffTail(b[1], c[1], bcy);
  // All differences were exact, so B is the exact determinant.
  if (acxTail == 0.0 && acyTail == 0.0 && bcxTail == 0.0 && bcyTail == 0.0) {
    return topComponent(4, B);
  }

  // Stage C: add the first-order tail terms in floating point.
  errbound = kCcwErrBoundC * detsum + kResultErrBound * absval(det);
  det += (acx * bcyTail + bcy * acxTail) - (acy * bcxTail + bcx * acyTail);
  if (absval(det) >= errbound) return det;

  // Stage D: the exact determinant
  //   (acx + acxTail)(bcy + bcyTail) - (acy + acyTail)(bcx + bcxTail).
  double u[4], c1[8], c2[12], d[16];
  productDiff(acxTail, bcy, acyTail, bcx, u);
  const int n1 = expansionSum(4, B, 4, u, c1);
  productDiff(acx, bcyTail, acy, bcxTail, u);
  const int n2 = expansionSum(n1, c1, 4, u, c2);
  productDiff(acxTail, bcyTail, acyTail, bcxTail, u);
  const int n3 = expansionSum(n2, c2, 4, u, d);
  return d[n3 - 1];
}

// ---------------------------------------------------------------------------------------
// incircle slow path.

// Stage D: the exact determinant from the original coordinates. Expanding the 4x4 lifted
// determinant | x y x^2+y^2 1 | (rows a, b, c, d) along the lift column gives
//   lift(a) O(b,c,d) - lift(b) O(a,c,d) + lift(c) O(a,b,d) - lift(d) O(a,b,c),
// where O(p,q,r) = pq + qr + rp and pq = px*qy - qx*py, all exact expansions.
ACUTEMESH_NOINLINE double incircleExact(const double* a, const double* b, const double* c,
                                        const double* d) {
  double ab[4], bc[4], cd[4], da[4], ca[4], db[4];
  productDiff(a[0], b[1], b[0], a[1], ab);
  productDiff(b[0], c[1], c[0], b[1], bc);
  productDiff(c[0], d[1], d[0], c[1], cd);
  productDiff(d[0], a[1], a[0], d[1], da);
  productDiff(c[0], a[1], a[0], c[1], ca);
  productDiff(d[0], b[1], b[0], d[1], db);

  double t[8], bcd[12], acd[12], abd[12], abc[12];
  int n = expansionSum(4, bc, 4, cd, t);
  const int nbcd = expansionSum(n, t, 4, db, bcd);
  double ac[4];
  for (int i = 0; i < 4; ++i) ac[i] = -ca[i];
  n = expansionSum(4, ac, 4, cd, t);
  const int nacd = expansionSum(n, t, 4, da, acd);
  double bd[4];
  for (int i = 0; i < 4; ++i) bd[i] = -db[i];
  n = expansionSum(4, ab, 4, bd, t);
  const int nabd = expansionSum(n, t, 4, da, abd);
  n = expansionSum(4, ab, 4, bc, t);
  const int nabc = expansionSum(n, t, 4, ca, abc);
  // Negate the terms that enter with a minus sign.
  for (int i = 0; i < nacd; ++i) acd[i] = -acd[i];
  for (int i = 0; i < nabc; ++i) abc[i] = -abc[i];

  double la[96], lb[96], lc[96], ld[96], s1[192], s2[192], det[384];
  const int na = liftScale(nbcd, bcd, a[0], a[1], la);
  const int nb = liftScale(nacd, acd, b[0], b[1], lb);
  const int nc = liftScale(nabd, abd, c[0], c[1], lc);
  const int nd = liftScale(nabc, abc, d[0], d[1], ld);
  const int n1 = expansionSum(na, la, nb, lb, s1);
  const int n2 = expansionSum(nc, lc, nd, ld, s2);
  const int nf = expansionSum(n1, s1, n2, s2, det);
  return det[nf - 1];
}

// Stages B and C, then the exact stage.
ACUTEMESH_NOINLINE double incircleAdapt(const double* a, const double* b, const double* c,
                                        const double* d, double permanent) {
  const double adx = a[0] - d[0];
  const double bdx = b[0] - d[0];
  const double cdx = c[0] - d[0];
  const double ady = a[1] - d[1];
  const double bdy = b[1] - d[1];
  const double cdy = c[1] - d[1];

  // Stage B: the determinant of the rounded differences, exactly.
  double bc[4], ca[4], ab[4];
  productDiff(bdx, cdy, cdx, bdy, bc);
  productDiff(cdx, ady, adx, cdy, ca);
  productDiff(adx, bdy, bdx, ady, ab);
  double adet[32], bdet[32], cdet[32], abdet[64], fin[96];
  const int na = liftScale(4, bc, adx, ady, adet);
  const int nb = liftScale(4, ca, bdx, bdy, bdet);
  const int nc = liftScale(4, ab, cdx, cdy, cdet);
  const int nab = expansionSum(na, adet, nb, bdet, abdet);
  const int nfin = expansionSum(nab, abdet, nc, cdet, fin);
  double det = estimate(nfin, fin);
  double errbound = kIccErrBoundB * permanent;
  if (absval(det) >= errbound) return det;

  const double adxTail = twoDiffTail(a[0], d[0], adx);
  const double bdxTail = twoDiffTail(b[0], d[0], bdx);
  const double cdxTail = twoDiffTail(c[0], d[0], cdx);
  const double adyTail = twoDiffTail(a[1], d[1], ady);
  const double bdyTail = twoDiffTail(b[1], d[1], bdy);
  const double cdyTail = twoDiffTail(c[1], d[1], cdy);
  // All differences were exact, so fin is the exact determinant.
  if (adxTail == 0.0 && bdxTail == 0.0 && cdxTail == 0.0 && adyTail == 0.0 &&
      bdyTail == 0.0 && cdyTail == 0.0) {
    return fin[nfin - 1];
  }

  // Stage C: add the first-order tail terms (the derivative of the determinant along the
  // tails) in floating point.
  errbound = kIccErrBoundC * permanent + kResultErrBound * absval(det);
  det += ((adx * adx + ady * ady) *
              ((bdx * cdyTail + cdy * bdxTail) - (bdy * cdxTail + cdx * bdyTail)) +
          2.0 * (adx * adxTail + ady * adyTail) * (bdx * cdy - bdy * cdx)) +
         ((bdx * bdx + bdy * bdy) *
              ((cdx * adyTail + ady * cdxTail) - (cdy * adxTail + adx * cdyTail)) +
          2.0 * (bdx * bdxTail + bdy * bdyTail) * (cdx * ady - cdy * adx)) +
         ((cdx * cdx + cdy * cdy) *
              ((adx * bdyTail + bdy * adxTail) - (ady * bdxTail + bdx * adyTail)) +
          2.0 * (cdx * cdxTail + cdy * cdyTail) * (adx * bdy - ady * bdx));
  if (absval(det) >= errbound) return det;

  return incircleExact(a, b, c, d);
}

// ---------------------------------------------------------------------------------------
// dot2d slow path: exact (bax + baxTail)(cax + caxTail) + (bay + bayTail)(cay + cayTail).

// (p.hi + p.lo) * (q.hi + q.lo) exactly; h needs room for 8 components.
int pairProduct(Pair p, Pair q, double* h) {
  const double e[2] = {p.lo, p.hi};
  double t1[4], t2[4];
  const int n1 = scaleExpansion(2, e, q.lo, t1);
  const int n2 = scaleExpansion(2, e, q.hi, t2);
  return expansionSum(n1, t1, n2, t2, h);
}

ACUTEMESH_NOINLINE double dot2dExact(const double* a, const double* b, const double* c) {
  const Pair bax = twoDiff(b[0], a[0]);
  const Pair cax = twoDiff(c[0], a[0]);
  const Pair bay = twoDiff(b[1], a[1]);
  const Pair cay = twoDiff(c[1], a[1]);
  if (bax.lo == 0.0 && cax.lo == 0.0 && bay.lo == 0.0 && cay.lo == 0.0) {
    const Pair px = twoProduct(bax.hi, cax.hi);
    const Pair py = twoProduct(bay.hi, cay.hi);
    const double ex[2] = {px.lo, px.hi};
    const double ey[2] = {py.lo, py.hi};
    double h[4];
    const int n = expansionSum(2, ex, 2, ey, h);
    return h[n - 1];
  }
  double x[8], y[8], h[16];
  const int nx = pairProduct(bax, cax, x);
  const int ny = pairProduct(bay, cay, y);
  const int n = expansionSum(nx, x, ny, y, h);
  return h[n - 1];
}

}  // namespace

// ---------------------------------------------------------------------------------------
// Public predicates: only stage A (floating point with a proven error bound) lives here, kept
// small and branch-light; everything slower is in the noinline functions above.

double orient2d(const double* a, const double* b, const double* c) {
  const double detleft = (a[0] - c[0]) * (b[1] - c[1]);
  const double detright = (a[1] - c[1]) * (b[0] - c[0]);
  const double det = detleft - detright;
  // Branch-free filter (sign tests on random data mispredict): when the products have
  // opposite signs |det| ~ detsum passes trivially, and detsum == 0 means both products
  // are exactly zero, so det == 0 is then exact too.
  const double detsum = absval(detleft) + absval(detright);
  if (absval(det) >= kCcwErrBoundA * detsum) return det;
  return orient2dAdapt(a, b, c, detsum);
}

double incircle(const double* a, const double* b, const double* c, const double* d) {
  const double adx = a[0] - d[0];
  const double bdx = b[0] - d[0];
  const double cdx = c[0] - d[0];
  const double ady = a[1] - d[1];
  const double bdy = b[1] - d[1];
  const double cdy = c[1] - d[1];

  const double bdxcdy = bdx * cdy;
  const double cdxbdy = cdx * bdy;
  const double alift = adx * adx + ady * ady;
  const double cdxady = cdx * ady;
  const double adxcdy = adx * cdy;
  const double blift = bdx * bdx + bdy * bdy;
  const double adxbdy = adx * bdy;
  const double bdxady = bdx * ady;
  const double clift = cdx * cdx + cdy * cdy;

  const double det = alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) +
                     clift * (adxbdy - bdxady);
  const double permanent = (absval(bdxcdy) + absval(cdxbdy)) * alift +
                           (absval(cdxady) + absval(adxcdy)) * blift +
                           (absval(adxbdy) + absval(bdxady)) * clift;
  if (absval(det) > kIccErrBoundA * permanent) return det;
  return incircleAdapt(a, b, c, d, permanent);
}

void cornerDots(const double* p0, const double* p1, const double* p2, double out[3]) {
  // The differences each corner's dot2d would take, shared: p1 - p0, p2 - p0, p2 - p1 (the
  // others are their exact negatives, so every product and sum is the one dot2d rounds).
  const double ux = p1[0] - p0[0], uy = p1[1] - p0[1];
  const double vx = p2[0] - p0[0], vy = p2[1] - p0[1];
  const double wx = p2[0] - p1[0], wy = p2[1] - p1[1];
  const double px[3] = {ux * vx, -(wx * ux), vx * wx};
  const double py[3] = {uy * vy, -(wy * uy), vy * wy};
  const double* const p[3] = {p0, p1, p2};
  for (int k = 0; k < 3; ++k) {
    const double det = px[k] + py[k];
    out[k] = absval(det) >= kCcwErrBoundA * (absval(px[k]) + absval(py[k]))
                 ? det
                 : dot2dExact(p[k], p[(k + 1) % 3], p[(k + 2) % 3]);
  }
}

double dot2d(const double* a, const double* b, const double* c) {
  const double px = (b[0] - a[0]) * (c[0] - a[0]);
  const double py = (b[1] - a[1]) * (c[1] - a[1]);
  const double det = px + py;
  // Same filter as orient2d (a sum instead of a difference of two rounded products of
  // rounded differences, so the same error bound applies).
  if (absval(det) >= kCcwErrBoundA * (absval(px) + absval(py))) return det;
  return dot2dExact(a, b, c);
}

}  // namespace acutemesh
