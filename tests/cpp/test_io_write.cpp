// Mesh output: Triangle's formats, OFF, OBJ, JSON, SVG, numbers that read back as the same
// doubles, files.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "acutemesh/io.h"
#include "fixtures.h"

namespace fs = std::filesystem;
using namespace acutemesh;
using fixtures::readText;
using fixtures::sameBits;
using fixtures::startsWith;

namespace {


Mesh twoTriangles() {
  Mesh m;
  m.points = {0, 0, 2, 0, 2, 1, 0, 1};
  m.triangles = {0, 1, 2, 0, 2, 3};
  m.segments = {0, 1, 1, 2, 2, 3, 3, 0};
  m.vertexKind = {0, 0, 0, 0};
  return m;
}

TEST(IoWrite, TriangleFormats) {
  const Mesh m = twoTriangles();
  // No markers in the mesh: Triangle's defaults, 1 on the boundary (here every vertex, edge).
  EXPECT_EQ(formatNode(m), "# written by acutemesh, indices 0-based\n4 2 0 1\n0 0 0 1\n1 2 0 1\n"
                           "2 2 1 1\n3 0 1 1\n");
  EXPECT_EQ(formatEle(m), "# written by acutemesh, indices 0-based\n2 3 0\n0 0 1 2\n1 0 2 3\n");
  EXPECT_EQ(formatPoly(m),
            "# written by acutemesh, indices 0-based\n4 2 0 1\n0 0 0 1\n1 2 0 1\n2 2 1 1\n"
            "3 0 1 1\n4 1\n0 0 1 1\n1 1 2 1\n2 2 3 1\n3 3 0 1\n0\n");
}

TEST(IoWrite, OffObjJson) {
  const Mesh m = twoTriangles();
  EXPECT_EQ(formatOff(m), "OFF\n4 2 0\n0 0 0\n2 0 0\n2 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n");
  EXPECT_EQ(formatObj(m), "# written by acutemesh\nv 0 0 0\nv 2 0 0\nv 2 1 0\nv 0 1 0\n"
                          "f 1 2 3\nf 1 3 4\n");
  EXPECT_EQ(formatJson(m),
            "{\n\"vertices\": [\n[0,0],\n[2,0],\n[2,1],\n[0,1]],\n\"triangles\": [\n[0,1,2],\n"
            "[0,2,3]],\n\"segments\": [\n[0,1],\n[1,2],\n[2,3],\n[3,0]]\n}\n");
  Mesh empty;
  EXPECT_EQ(formatJson(empty), "{\n\"vertices\": [],\n\"triangles\": [],\n\"segments\": []\n}\n");
  Input in;
  ParseResult r = parseJson(formatJson(empty), "e.json", in);
  EXPECT_TRUE(r.ok) << r.message;
}

TEST(IoWrite, Svg) {
  const Mesh m = twoTriangles();
  const std::string svg = formatSvg(m);
  EXPECT_TRUE(startsWith(svg, "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"-10 -10 1020 "
                              "520\">"))
      << svg;
  // y up: the vertex (0, 1) is at the top (y = 0), (0, 0) at the bottom (y = 500).
  EXPECT_NE(svg.find("M0 500L1000 500L1000 0Z"), std::string::npos) << svg;
  EXPECT_NE(svg.find("M0 500L1000 500M1000 500L1000 0"), std::string::npos) << svg;
  EXPECT_EQ(std::count(svg.begin(), svg.end(), '\n'), 4);  // two paths, small
  // Degenerate inputs do not divide by zero.
  Mesh one;
  one.points = {3, 4};
  EXPECT_NE(formatSvg(one).find("viewBox=\"-10 -10 20 20\""), std::string::npos);
  EXPECT_NE(formatSvg(Mesh()).find("<svg"), std::string::npos);
}

Mesh awkwardDoubles() {
  Mesh m;
  const double values[] = {0.1,
                           1.0 / 3,
                           -0.0,
                           5e-324,
                           2.2250738585072014e-308,
                           1.7976931348623157e308,
                           -1e-300,
                           3.141592653589793,
                           123456789.123456789,
                           std::nextafter(1.0, 2.0),
                           9007199254740993.0,
                           1e21,
                           1e22,
                           1e23,
                           0.30000000000000004,
                           -2.5e-7,
                           6.02214076e23,
                           std::nextafter(0.0, -1.0)};
  for (double v : values) {
    m.points.push_back(v);
    m.points.push_back(-v / 7);
  }
  m.segments = {0, 1, 1, 2, 17, 0};
  m.triangles = {0, 1, 2};
  return m;
}

TEST(IoWrite, RoundTripExactDoubles) {
  const Mesh m = awkwardDoubles();
  Input node, poly, json;
  ParseResult r = parseNode(formatNode(m), "rt.node", node);
  ASSERT_TRUE(r.ok) << r.message;
  r = parsePoly(formatPoly(m), "rt.poly", poly);
  ASSERT_TRUE(r.ok) << r.message;
  r = parseJson(formatJson(m), "rt.json", json);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_TRUE(json.warnings.empty());
  for (const Input* in : {&node, &poly, &json}) {
    ASSERT_EQ(in->pslg.points.size(), m.points.size());
    for (size_t i = 0; i < m.points.size(); ++i)
      EXPECT_TRUE(sameBits(in->pslg.points[i], m.points[i]))
          << i << ": " << in->pslg.points[i] << " vs " << m.points[i];
  }
  // The mesh's segment edges, then its boundary edge on none (2 -> 0): the same domain.
  std::vector<uint32_t> segments = m.segments;
  segments.insert(segments.end(), {2, 0});
  EXPECT_EQ(poly.pslg.segments, segments);
  EXPECT_EQ(json.pslg.segments, segments);
  EXPECT_TRUE(poly.pslg.holes.empty());
}

TEST(IoWrite, RoundTripRandomDoubles) {
  std::mt19937_64 rng(7);
  Mesh m;
  for (int i = 0; i < 20000; ++i) {
    uint64_t bits = rng();
    double d;
    std::memcpy(&d, &bits, sizeof d);
    if (!std::isfinite(d)) d = 0.5;
    m.points.push_back(d);
    m.points.push_back(std::ldexp(static_cast<double>(rng() >> 11), -53) * 1000 - 500);
  }
  Input node, json;
  ASSERT_TRUE(parseNode(formatNode(m), "r.node", node).ok);
  ASSERT_TRUE(parseJson(formatJson(m), "r.json", json).ok);
  size_t bad = 0;
  for (size_t i = 0; i < m.points.size(); ++i) {
    bad += !sameBits(node.pslg.points[i], m.points[i]);
    bad += !sameBits(json.pslg.points[i], m.points[i]);
  }
  EXPECT_EQ(bad, 0u);
}

TEST(IoWrite, WriteMeshFiles) {
  const Mesh m = twoTriangles();
  const fs::path dir = fs::temp_directory_path() / "acutemesh_test_io_out";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string base = (dir / "mesh").string();
  ParseResult r = writeMeshFiles(m, base, {"node", "ele", "poly", "json", "off", "obj", "svg",
                                           "edge", "neigh", "msh", "msh2", "vtu"});
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(readText(base + ".node"), formatNode(m));
  EXPECT_EQ(readText(base + ".ele"), formatEle(m));
  EXPECT_EQ(readText(base + ".poly"), formatPoly(m));
  EXPECT_EQ(readText(base + ".json"), formatJson(m));
  EXPECT_EQ(readText(base + ".off"), formatOff(m));
  EXPECT_EQ(readText(base + ".obj"), formatObj(m));
  EXPECT_EQ(readText(base + ".svg"), formatSvg(m));
  EXPECT_EQ(readText(base + ".edge"), formatEdge(m));
  EXPECT_EQ(readText(base + ".neigh"), formatNeigh(m));
  EXPECT_EQ(readText(base + ".msh"), formatMsh(m));
  EXPECT_EQ(readText(base + ".v2.msh"), formatMsh2(m));
  EXPECT_EQ(readText(base + ".vtu"), formatVtu(m));
  // What was written reads back.
  Input in;
  r = readInputFile(base + ".poly", in);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(in.pslg.points, m.points);
  EXPECT_EQ(in.pslg.segments, m.segments);
  r = readInputFile(base + ".json", in);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(in.pslg.points, m.points);

  // An unknown format fails before anything is written.
  const std::string base2 = (dir / "other").string();
  r = writeMeshFiles(m, base2, {"node", "stl"});
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.message, "expected an output format among node, ele, poly, edge, neigh, json, off, "
                       "obj, svg, msh, msh2, vtu, found 'stl'");
  EXPECT_FALSE(fs::exists(base2 + ".node"));
  // A place that cannot be written.
  const std::string bad = (dir / "missing" / "mesh").string();
  r = writeMeshFiles(m, bad, {"off"});
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.message, bad + ".off: cannot write (No such file or directory)");
  fs::remove_all(dir);
}

}  // namespace
