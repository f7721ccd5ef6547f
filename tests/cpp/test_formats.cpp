// The solver formats (Gmsh MSH 4.1 and 2.2, VTK .vtu, Triangle's .edge and .neigh) and the
// markers and attributes the Triangle formats and JSON carry: exact texts on small meshes
// whose markers and attributes are filled by hand, and Triangle's defaults when they are not.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "acutemesh/io.h"
#include "fixtures.h"

using namespace acutemesh;

namespace {

// Two unit squares side by side, split by the segment 1-4, each cut along a diagonal; vertex 6
// is used by no triangle.
//   5 --- 4 --- 3
//   |   / |   / |
//   0 --- 1 --- 2
Mesh twoSquares() {
  Mesh m;
  m.points = {0, 0, 1, 0, 2, 0, 2, 1, 1, 1, 0, 1, 5, 5};
  m.triangles = {0, 1, 4, 0, 4, 5, 1, 2, 3, 1, 3, 4};
  m.segments = {0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 0, 1, 4};
  m.vertexKind = {0, 0, 0, 0, 0, 0, kUnusedVertex};
  return m;
}

// The same with markers and attributes: a zero marker on the boundary (segment 2-3, vertex
// 2) comes out 1; the inner segment keeps its 3; a negative marker and a fractional attribute
// get numbered physical tags.
Mesh marked() {
  Mesh m = twoSquares();
  m.vertexMarkers = {5, 5, 0, -2, 7, 7, 0};
  m.segmentMarkers = {5, 5, 0, -2, 7, 7, 3};
  m.triangleAttributes = {1, 1, 2.5, 2.5};
  return m;
}

const char kHeader[] = "# written by acutemesh, indices 0-based\n";

// Triangle's formats with the mesh's markers and attributes: a zero marker on the boundary
// comes out 1; vertex 6, used by nothing, keeps its 0.
TEST(Formats, TriangleFormatsCarryMarkersAndAttributes) {
  const Mesh m = marked();
  EXPECT_EQ(formatNode(m), std::string(kHeader) +
      "7 2 0 1\n0 0 0 5\n1 1 0 5\n2 2 0 1\n3 2 1 -2\n4 1 1 7\n5 0 1 7\n6 5 5 0\n");
  EXPECT_EQ(formatEle(m), std::string(kHeader) +
      "4 3 1\n0 0 1 4 1\n1 0 4 5 1\n2 1 2 3 2.5\n3 1 3 4 2.5\n");
  EXPECT_EQ(formatPoly(m), std::string(kHeader) +
      "7 2 0 1\n0 0 0 5\n1 1 0 5\n2 2 0 1\n3 2 1 -2\n4 1 1 7\n5 0 1 7\n6 5 5 0\n"
      "7 1\n0 0 1 5\n1 1 2 5\n2 2 3 1\n3 3 4 -2\n4 4 5 7\n5 5 0 7\n6 1 4 3\n0\n");
  // Every edge, sorted; inner ones 0 but the segment 1-4 (3).
  EXPECT_EQ(formatEdge(m), std::string(kHeader) +
      "9 1\n0 0 1 5\n1 0 4 0\n2 0 5 7\n3 1 2 5\n4 1 3 0\n5 1 4 3\n6 2 3 1\n7 3 4 -2\n"
      "8 4 5 7\n");
  // Neighbour k opposite corner k: triangle 0 (0 1 4) meets 3 across 1-4, 1 across 4-0.
  EXPECT_EQ(formatNeigh(m), std::string(kHeader) +
      "4 3\n0 3 1 -1\n1 -1 -1 0\n2 -1 3 -1\n3 -1 0 2\n");
  // .poly reads back with its markers' columns (parsePoly reads them).
  Input in;
  const ParseResult r = parsePoly(formatPoly(m), "m.poly", in);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(in.pslg.points, m.points);
  EXPECT_EQ(in.pslg.segments, m.segments);
}

// Without markers: Triangle's defaults from the boundary alone (1 there, 0 inside and on the
// unused vertex); without attributes .ele has no column.
TEST(Formats, TriangleFormatsWithoutMarkersUseTheBoundary) {
  const Mesh m = twoSquares();
  EXPECT_EQ(formatNode(m), std::string(kHeader) +
      "7 2 0 1\n0 0 0 1\n1 1 0 1\n2 2 0 1\n3 2 1 1\n4 1 1 1\n5 0 1 1\n6 5 5 0\n");
  EXPECT_EQ(formatEle(m), std::string(kHeader) +
      "4 3 0\n0 0 1 4\n1 0 4 5\n2 1 2 3\n3 1 3 4\n");
  EXPECT_EQ(formatEdge(m), std::string(kHeader) +
      "9 1\n0 0 1 1\n1 0 4 0\n2 0 5 1\n3 1 2 1\n4 1 3 0\n5 1 4 0\n6 2 3 1\n7 3 4 1\n"
      "8 4 5 1\n");
  const std::string poly = formatPoly(m);
  EXPECT_NE(poly.find("7 1\n0 0 1 1\n1 1 2 1\n2 2 3 1\n3 3 4 1\n4 4 5 1\n5 5 0 1\n6 1 4 0\n"),
            std::string::npos) << poly;
  // Markers that a file without them would get are left out of JSON.
  const std::string json = formatJson(m);
  EXPECT_EQ(json.find("Markers"), std::string::npos) << json;
  EXPECT_EQ(json.find("triangleAttributes"), std::string::npos) << json;
  // Markers given that are the defaults are left out too.
  Mesh same = twoSquares();
  same.vertexMarkers = {1, 1, 1, 1, 1, 1, 0};
  same.segmentMarkers = {1, 1, 1, 1, 1, 1, 0};
  EXPECT_EQ(formatJson(same), json);
  EXPECT_EQ(formatNode(same), formatNode(m));
  EXPECT_EQ(formatMsh(same), formatMsh(m));
}

TEST(Formats, JsonCarriesMarkersAndAttributes) {
  const std::string json = formatJson(marked());
  EXPECT_NE(json.find("\"segments\": [\n[0,1],\n[1,2],\n[2,3],\n[3,4],\n[4,5],\n[5,0],\n[1,4]],\n"
                      "\"vertexMarkers\": [5,5,1,-2,7,7,0],\n"
                      "\"segmentMarkers\": [5,5,1,-2,7,7,3],\n"
                      "\"triangleAttributes\": [1,1,2.5,2.5]\n}\n"),
            std::string::npos) << json;
  Input in;
  const ParseResult r = parseJson(json, "m.json", in);
  EXPECT_TRUE(r.ok) << r.message;
}

// The files in tests/data/io/two-squares are marked()'s, written by these writers and checked
// by hand; tests/cli/formats_readback.py reads them with meshio too.
std::string golden(const std::string& extension) {
  return fixtures::readText(fixtures::kData + "/io/two-squares/marked" + extension);
}

// Gmsh 4.1: physical tags are the attribute 1 and the positive markers; 2.5 and -2 are
// numbered after the largest such (2 and 8). Entities by increasing value; the triangles of
// each surface in one block, element tags = .ele index + 1, lines after them.
TEST(Formats, GoldenFiles) {
  const Mesh m = marked();
  EXPECT_EQ(formatMsh(m), golden(".msh"));
  EXPECT_EQ(formatMsh2(m), golden(".v2.msh"));
  // Cells: the triangles, then the lines (segment edges, then boundary edges on none).
  EXPECT_EQ(formatVtu(m), golden(".vtu"));
  EXPECT_EQ(formatNode(m), golden(".node"));
  EXPECT_EQ(formatEle(m), golden(".ele"));
  EXPECT_EQ(formatEdge(m), golden(".edge"));
  EXPECT_EQ(formatNeigh(m), golden(".neigh"));
  // The files' names are the ones writeMeshFiles gives.
  const std::string base = testing::TempDir() + "acutemesh_formats_marked";
  const ParseResult r = writeMeshFiles(m, base, {"msh", "msh2", "vtu"});
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(fixtures::readText(base + ".v2.msh"), golden(".v2.msh"));
  std::remove((base + ".msh").c_str());
  std::remove((base + ".v2.msh").c_str());
  std::remove((base + ".vtu").c_str());
}

// Without attributes or markers, one physical surface "domain"; the inner segment's marker 0
// has a group of its own, numbered after marker 1; no "attribute" cell data.
TEST(Formats, GmshAndVtkWithoutMarkers) {
  const Mesh m = twoSquares();
  const std::string msh = formatMsh(m);
  EXPECT_NE(msh.find("$PhysicalNames\n3\n2 1 \"domain\"\n1 2 \"marker 0\"\n1 1 \"marker 1\"\n"
                     "$EndPhysicalNames\n$Entities\n0 2 1 0\n1 0 0 0 5 5 0 1 2 0\n"
                     "2 0 0 0 5 5 0 1 1 0\n1 0 0 0 5 5 0 1 1 0\n$EndEntities\n"),
            std::string::npos) << msh;
  EXPECT_NE(msh.find("$Elements\n3 11 1 11\n2 1 2 4\n"), std::string::npos) << msh;
  EXPECT_NE(msh.find("1 1 1 1\n11 2 5\n1 2 1 6\n5 1 2\n"), std::string::npos) << msh;
  const std::string msh2 = formatMsh2(m);
  EXPECT_NE(msh2.find("1 2 2 1 1 1 2 5\n"), std::string::npos) << msh2;
  EXPECT_NE(msh2.find("11 1 2 2 1 2 5\n"), std::string::npos) << msh2;  // marker 0: group 2
  const std::string vtu = formatVtu(m);
  EXPECT_EQ(vtu.find("attribute"), std::string::npos);
  EXPECT_NE(vtu.find("Name=\"marker\" format=\"ascii\">\n1\n1\n1\n1\n1\n1\n0\n"), std::string::npos);
}

// A mesh with no segments on its boundary (a convex hull kept): its boundary edges become
// lines of marker 1, after the segment edges, in MSH and VTU.
TEST(Formats, BoundaryEdgesOnNoSegmentAreLines) {
  Mesh m = twoSquares();
  m.segments = {1, 4};
  m.segmentMarkers = {3};
  const std::string msh2 = formatMsh2(m);
  EXPECT_NE(msh2.find("$Elements\n11\n"), std::string::npos) << msh2;
  EXPECT_NE(msh2.find("5 1 2 3 2 2 5\n"), std::string::npos) << msh2;   // the segment, marker 3
  EXPECT_NE(msh2.find("6 1 2 1 1 "), std::string::npos) << msh2;        // then the boundary
  const std::string vtu = formatVtu(m);
  EXPECT_NE(vtu.find("NumberOfCells=\"11\""), std::string::npos);
  EXPECT_NE(vtu.find("0\n0\n0\n0\n3\n1\n1\n1\n1\n1\n1\n</DataArray>"), std::string::npos) << vtu;
}

// Physical tags: an attribute that is a positive integer is its own tag; others (0, negative,
// fractional, too large) are numbered after the largest such tag, in increasing order.
TEST(Formats, PhysicalTagsOfOddValues) {
  Mesh m = twoSquares();
  m.triangleAttributes = {0, 4e9, 3, -1};
  const std::string msh = formatMsh(m);
  EXPECT_NE(msh.find("$PhysicalNames\n6\n2 4 \"attribute -1\"\n2 5 \"attribute 0\"\n"
                     "2 3 \"attribute 3\"\n2 6 \"attribute 4e+09\"\n"),
            std::string::npos) << msh;
}

// Attributes that are not one finite number per triangle are none (Gmsh groups them by value).
TEST(Formats, AttributesOnlyWhenOneFinitePerTriangle) {
  const Mesh plain = twoSquares();
  for (const std::vector<double>& bad :
       {std::vector<double>{1, 2, 3}, std::vector<double>{1, 2, std::nan(""), 4}}) {
    Mesh m = twoSquares();
    m.triangleAttributes = bad;
    EXPECT_EQ(formatEle(m), formatEle(plain));
    EXPECT_EQ(formatMsh(m), formatMsh(plain));
    EXPECT_EQ(formatVtu(m), formatVtu(plain));
    EXPECT_EQ(formatJson(m), formatJson(plain));
  }
}

// An empty mesh writes well-formed empty sections.
TEST(Formats, EmptyMesh) {
  const Mesh m;
  EXPECT_NE(formatMsh(m).find("$Nodes\n0 0 0 0\n$EndNodes\n$Elements\n0 0 0 0\n$EndElements\n"),
            std::string::npos);
  EXPECT_EQ(formatEdge(m), std::string(kHeader) + "0 1\n");
  EXPECT_EQ(formatNeigh(m), std::string(kHeader) + "0 3\n");
  EXPECT_NE(formatVtu(m).find("NumberOfPoints=\"0\" NumberOfCells=\"0\""), std::string::npos);
}

}  // namespace
