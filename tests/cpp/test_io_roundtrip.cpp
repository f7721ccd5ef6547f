// A mesh written as .poly or JSON reads back as the same domain: meshed again (constrained
// Delaunay), it covers the same triangles' worth of area with the same boundary, holes, hulls
// and islands included.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "acutemesh/io.h"
#include "fixtures.h"

using namespace acutemesh;

namespace {

// The mesh's boundary: each edge a->b of a triangle whose twin b->a is in none, sorted.
std::vector<uint64_t> boundaryOf(const Mesh& m) {
  std::vector<uint64_t> edges;
  for (size_t i = 0; i < m.triangles.size(); i += 3)
    for (int k = 0; k < 3; ++k)
      edges.push_back(uint64_t(m.triangles[i + k]) << 32 | m.triangles[i + (k + 1) % 3]);
  std::sort(edges.begin(), edges.end());
  std::vector<uint64_t> boundary;
  for (uint64_t e : edges)
    if (!std::binary_search(edges.begin(), edges.end(), e << 32 | e >> 32)) boundary.push_back(e);
  return boundary;
}

double areaOf(const Mesh& m) {
  double area = 0;
  for (size_t i = 0; i < m.triangles.size(); i += 3) {
    const double* a = &m.points[2 * m.triangles[i]];
    const double* b = &m.points[2 * m.triangles[i + 1]];
    const double* c = &m.points[2 * m.triangles[i + 2]];
    area += ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) / 2;
  }
  return area;
}

struct Case {
  const char* file;
  Options options;
  size_t holes;  // hole points the written files hold
};

Options with(Mode mode, bool convexHull = false) {
  Options o;
  o.mode = mode;
  o.convexHull = convexHull;
  return o;
}

// Reads `text` back with `parse`, meshes it (cdt) and compares with `original`.
template <class Parse>
void expectSameDomain(const std::string& what, const std::string& text, Parse parse,
                      const Mesh& original, size_t holes) {
  SCOPED_TRACE(what);
  Input in;
  const ParseResult parsed = parse(text, in);
  ASSERT_TRUE(parsed.ok) << parsed.message;
  EXPECT_EQ(in.pslg.holes.size() / 2, holes);
  Options cdt;
  applyInputPolicy(in, {}, cdt);
  const Result again = mesh(in.pslg, cdt);
  ASSERT_EQ(again.status, Status::Ok) << again.message;
  EXPECT_EQ(again.mesh.vertexCount(), original.vertexCount());
  EXPECT_EQ(again.mesh.triangleCount(), original.triangleCount());
  EXPECT_EQ(boundaryOf(again.mesh), boundaryOf(original));
  EXPECT_NEAR(areaOf(again.mesh), areaOf(original), 1e-12 * areaOf(original));
}

TEST(IoRoundTrip, PolyAndJsonReadBackAsTheSameDomain) {
  const Case cases[] = {
      // An enclave (the hole) holding an island, and an island far off: South Africa's shape.
      {"io/enclave.poly", with(Mode::Cdt), 1},
      {"io/enclave.poly", with(Mode::Acute), 1},
      {"io/enclave.poly", with(Mode::Quality), 1},
      {"io/enclave.poly", with(Mode::Cdt, true), 1},  // the hull kept, the enclave still out
      {"io/enclave.poly", with(Mode::Acute, true), 1},
      {"io/enclave.poly", with(Mode::Delaunay), 0},
      {"plate.poly", with(Mode::Cdt), 4},
      {"plate.poly", with(Mode::NonObtuse), 4},
      {"A.poly", with(Mode::Acute), 1},
      {"naca0012.poly", with(Mode::Quality), 1},
      // Rings under the non-zero rule: the letters' counters become holes.
      {"acute-text.json",
       [] {
         Options o = with(Mode::Cdt);
         o.fill = FillRule::NonZero;
         return o;
       }(),
       2},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(std::string(c.file) + " " + nameOf(c.options.mode) +
                 (c.options.convexHull ? " convex hull" : ""));
    const Input in = fixtures::load(fixtures::kData + "/" + c.file);
    Options options = c.options;
    applyInputPolicy(in, {true, false}, options);
    const Result r = mesh(in.pslg, options);
    ASSERT_NE(r.status, Status::BadInput) << r.message;
    expectSameDomain(
        "poly", formatPoly(r.mesh),
        [](const std::string& t, Input& out) { return parsePoly(t, "m.poly", out); }, r.mesh,
        c.holes);
    expectSameDomain(
        "json", formatJson(r.mesh),
        [](const std::string& t, Input& out) { return parseJson(t, "m.json", out); }, r.mesh,
        c.holes);
  }
}

// A hole point lies strictly inside its hole even when the hole is a sliver: a thin wedge cut
// into a square, whose only triangles are needles.
TEST(IoRoundTrip, HolePointOfASliverHole) {
  Pslg square;
  square.points = {0, 0, 1, 0, 1, 1, 0, 1, 0.2, 0.5, 0.8, 0.5 + 1e-9, 0.8, 0.5 - 1e-9};
  square.segments = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 4};
  square.holes = {0.7, 0.5};
  const Result r = mesh(square, with(Mode::Cdt));
  ASSERT_EQ(r.status, Status::Ok) << r.message;
  expectSameDomain(
      "poly", formatPoly(r.mesh),
      [](const std::string& t, Input& out) { return parsePoly(t, "m.poly", out); }, r.mesh, 1);
}

}  // namespace
