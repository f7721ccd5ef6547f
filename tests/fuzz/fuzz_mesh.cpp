// libFuzzer harness: mesh() on small PSLGs decoded from the bytes, in every mode and fill
// rule, with a small Steiner and time budget so each run is short. Every mesh returned must
// pass validate(), its Stats must count exactly what it holds, and when the status is Ok the
// angle certificate must hold (exact dot-product signs, recounted here).
//
// Layout: byte 0 = mode (bits 0-2), fill rule (bits 3-4), convex hull (bit 5), area bound
// (quality) or exact segments and feet (non-obtuse) (bit 6), minimum angle (bit 7: quality 44
// degrees with an area bound, 40 without, 25 in the other modes); byte 1 = coordinate scale (a
// power of two, so extreme scales are reached); byte 2 = vertex count; then 2 bytes per vertex
// (a small lattice, so collinear and cocircular points, duplicates and overlaps are common; a
// high bit adds an ulp-sized nudge); then segments as index pairs and, after them, hole points.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "acutemesh/predicates.h"
#include "exact.h"
#include "fuzz_common.h"

using namespace acutemesh;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 3) return 0;
  const Mode modes[] = {Mode::Delaunay, Mode::Cdt, Mode::Quality, Mode::NonObtuse, Mode::Acute};
  Options o;
  o.mode = modes[(data[0] & 7) % 5];
  o.fill = FillRule((data[0] >> 3) % 3);
  o.convexHull = data[0] & 32;
  o.maxSteiner = 150;
  o.timeLimit = 1;
  if (o.mode == Mode::Quality && (data[0] & 64)) o.maxArea = 4;
  if (o.mode == Mode::NonObtuse && (data[0] & 64)) o.exactSegments = o.exactFeet = true;
  // A high minimum angle (relocation and locally optimal points), also with the angle bounds;
  // with an area bound one beyond 40 degrees (best effort: refined to 40 when it wanders).
  if (data[0] & 128) o.minAngle = o.mode != Mode::Quality ? 25 : o.maxArea > 0 ? 44 : 40;
  int exponent = int(data[1] % 64) * 32 - 1024;  // 2^-1024 .. 2^992, in steps of 2^32
  if (!(data[1] & 64)) exponent = int(data[1] % 8) - 4;
  size_t n = std::min<size_t>(data[2], 40), at = 3;
  Pslg in;
  auto coordinate = [&](uint8_t b) {
    double x = double(int(b & 63) - 32);
    if (b & 64) x = std::nextafter(x, b & 128 ? 1e9 : -1e9);  // an ulp off the lattice
    return std::ldexp(x, exponent);
  };
  for (size_t i = 0; i < n && at + 1 < size; ++i, at += 2) {
    in.points.push_back(coordinate(data[at]));
    in.points.push_back(coordinate(data[at + 1]));
  }
  n = in.vertexCount();
  for (; at + 1 < size && n > 0; at += 2) {
    if (data[at] == 0xFF) {  // the rest: hole points
      ++at;
      for (; at + 1 < size; at += 2) {
        in.holes.push_back(coordinate(data[at]));
        in.holes.push_back(coordinate(data[at + 1]));
      }
      break;
    }
    in.segments.push_back(data[at] % n);
    in.segments.push_back(data[at + 1] % n);
  }
  o.maxArea = std::ldexp(o.maxArea, 2 * exponent);
  Result r = mesh(in, o);
  if (r.status == Status::BadInput) {
    if (!fuzz::oneLine(r.message)) fuzz::fail("BadInput message not one line: " + r.message);
    if (r.mesh.triangleCount()) fuzz::fail("BadInput with triangles");
    return 0;
  }
  if (r.status == Status::Cancelled) fuzz::fail("cancelled without a cancel flag");
  Validation v = validate(in, r.mesh, o);
  if (!v.ok) fuzz::fail("invalid mesh: " + (v.errors.empty() ? std::string() : v.errors[0]));
  // Recounted on the lattice's own scale: at 2^-1024 or 2^992 the predicates' products
  // would underflow or overflow (mesh() scales the same way, exactly).
  Mesh m = r.mesh;
  for (double& x : m.points) x = std::ldexp(x, -exponent);
  // Exact points (exactFeet) at their rationals, scaled the same way.
  using acutemesh::detail::RationalPoint;
  std::vector<RationalPoint> exact(m.vertexCount());
  std::vector<char> isExact(m.vertexCount(), 0);
  if (!r.mesh.exactPoints.empty() && !o.exactFeet) fuzz::fail("exact points without exactFeet");
  for (const ExactPoint& p : r.mesh.exactPoints) {
    if (p.vertex >= m.vertexCount()) fuzz::fail("exact point out of range");
    RationalPoint q;
    if (!acutemesh::detail::parseRationalPoint(p.x, p.y, q)) fuzz::fail("exact point not a rational");
    if (exponent > 0) q.w = q.w.shifted(exponent);
    else q.x = q.x.shifted(-exponent), q.y = q.y.shifted(-exponent);
    exact[p.vertex] = q, isExact[p.vertex] = 1;
  }
  uint32_t nonAcute = 0, obtuse = 0;
  for (size_t t = 0; t < m.triangleCount(); ++t) {
    bool right = false, blunt = false;
    const uint32_t* v = &m.triangles[3 * t];
    const bool atExact = isExact[v[0]] || isExact[v[1]] || isExact[v[2]];
    RationalPoint q[3];
    for (int k = 0; atExact && k < 3; ++k)
      q[k] = isExact[v[k]] ? exact[v[k]] : acutemesh::detail::exactPoint(&m.points[2 * size_t(v[k])]);
    if (atExact && acutemesh::detail::orientSign(q[0], q[1], q[2]) <= 0)
      fuzz::fail("a triangle at an exact point is not counter-clockwise there");
    for (int k = 0; k < 3; ++k) {
      int d = atExact ? acutemesh::detail::dotSign(q[k], q[(k + 1) % 3], q[(k + 2) % 3])
                      : sign(dot2d(&m.points[2 * size_t(v[k])], &m.points[2 * size_t(v[(k + 1) % 3])],
                                   &m.points[2 * size_t(v[(k + 2) % 3])]));
      right |= d <= 0;
      blunt |= d < 0;
    }
    nonAcute += right, obtuse += blunt;
  }
  if (r.stats.nonAcute != nonAcute || r.stats.obtuse != obtuse) fuzz::fail("angle counts differ");
  if (r.stats.triangles != m.triangleCount() || r.stats.vertices != m.vertexCount())
    fuzz::fail("counts differ");
  if (r.status == Status::Ok) {
    if (o.mode == Mode::Acute && nonAcute) fuzz::fail("Ok but not acute");
    if (o.mode == Mode::NonObtuse && obtuse) fuzz::fail("Ok but obtuse");
  }
  return 0;
}
