// The solver formats (Gmsh MSH 4.1 and 2.2, VTK .vtu, Triangle's .edge and .neigh) and the
// markers and attributes the Triangle formats and JSON carry: exact texts on small meshes
// whose markers and attributes are filled by hand, and Triangle's defaults when they are not.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "acutemesh/io.h"

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

// Gmsh 4.1: physical tags are the attribute 1 and the positive markers; 2.5 and -2 are
// numbered after the largest such (2 and 8). Entities by increasing value; the triangles of
// each surface in one block, element tags = .ele index + 1, lines after them.
TEST(Formats, Msh41) {
  EXPECT_EQ(formatMsh(marked()),
      "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n7\n2 1 \"attribute 1\"\n"
      "2 2 \"attribute 2.5\"\n1 8 \"marker -2\"\n1 1 \"marker 1\"\n1 3 \"marker 3\"\n"
      "1 5 \"marker 5\"\n1 7 \"marker 7\"\n$EndPhysicalNames\n$Entities\n0 5 2 0\n"
      "1 0 0 0 5 5 0 1 8 0\n2 0 0 0 5 5 0 1 1 0\n3 0 0 0 5 5 0 1 3 0\n4 0 0 0 5 5 0 1 5 0\n"
      "5 0 0 0 5 5 0 1 7 0\n1 0 0 0 5 5 0 1 1 0\n2 0 0 0 5 5 0 1 2 0\n$EndEntities\n"
      "$Nodes\n1 7 1 7\n2 1 0 7\n1\n2\n3\n4\n5\n6\n7\n0 0 0\n1 0 0\n2 0 0\n2 1 0\n1 1 0\n"
      "0 1 0\n5 5 0\n$EndNodes\n$Elements\n7 11 1 11\n2 1 2 2\n1 1 2 5\n2 1 5 6\n2 2 2 2\n"
      "3 2 3 4\n4 2 4 5\n1 1 1 1\n8 4 5\n1 2 1 1\n7 3 4\n1 3 1 1\n11 2 5\n1 4 1 2\n5 1 2\n"
      "6 2 3\n1 5 1 2\n9 5 6\n10 6 1\n$EndElements\n");
}

TEST(Formats, Msh22) {
  EXPECT_EQ(formatMsh2(marked()),
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n7\n2 1 \"attribute 1\"\n"
      "2 2 \"attribute 2.5\"\n1 8 \"marker -2\"\n1 1 \"marker 1\"\n1 3 \"marker 3\"\n"
      "1 5 \"marker 5\"\n1 7 \"marker 7\"\n$EndPhysicalNames\n$Nodes\n7\n1 0 0 0\n2 1 0 0\n"
      "3 2 0 0\n4 2 1 0\n5 1 1 0\n6 0 1 0\n7 5 5 0\n$EndNodes\n$Elements\n11\n"
      "1 2 2 1 1 1 2 5\n2 2 2 1 1 1 5 6\n3 2 2 2 2 2 3 4\n4 2 2 2 2 2 4 5\n5 1 2 5 4 1 2\n"
      "6 1 2 5 4 2 3\n7 1 2 1 2 3 4\n8 1 2 8 1 4 5\n9 1 2 7 5 5 6\n10 1 2 7 5 6 1\n"
      "11 1 2 3 3 2 5\n$EndElements\n");
}

// Cells: the triangles, then the lines (segment edges, then boundary edges on none).
TEST(Formats, Vtu) {
  EXPECT_EQ(formatVtu(marked()),
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "<UnstructuredGrid>\n<Piece NumberOfPoints=\"7\" NumberOfCells=\"11\">\n<PointData>\n"
      "<DataArray type=\"Int32\" Name=\"marker\" format=\"ascii\">\n5\n5\n1\n-2\n7\n7\n0\n"
      "</DataArray>\n</PointData>\n<CellData>\n"
      "<DataArray type=\"Float64\" Name=\"attribute\" format=\"ascii\">\n1\n1\n2.5\n2.5\n"
      "0\n0\n0\n0\n0\n0\n0\n</DataArray>\n"
      "<DataArray type=\"Int32\" Name=\"marker\" format=\"ascii\">\n0\n0\n0\n0\n5\n5\n1\n"
      "-2\n7\n7\n3\n</DataArray>\n</CellData>\n<Points>\n"
      "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n0 0 0\n"
      "1 0 0\n2 0 0\n2 1 0\n1 1 0\n0 1 0\n5 5 0\n</DataArray>\n</Points>\n<Cells>\n"
      "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n0 1 4\n0 4 5\n"
      "1 2 3\n1 3 4\n0 1\n1 2\n2 3\n3 4\n4 5\n5 0\n1 4\n</DataArray>\n"
      "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n3\n6\n9\n12\n14\n16\n"
      "18\n20\n22\n24\n26\n</DataArray>\n"
      "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n5\n5\n5\n5\n3\n3\n3\n3\n"
      "3\n3\n3\n</DataArray>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n");
}

// Without attributes or markers, one physical surface "domain"; the inner segment's marker 0
// has a curve but no physical group; no "attribute" cell data.
TEST(Formats, GmshAndVtkWithoutMarkers) {
  const Mesh m = twoSquares();
  const std::string msh = formatMsh(m);
  EXPECT_NE(msh.find("$PhysicalNames\n2\n2 1 \"domain\"\n1 1 \"marker 1\"\n$EndPhysicalNames\n"
                     "$Entities\n0 2 1 0\n1 0 0 0 5 5 0 0 0\n2 0 0 0 5 5 0 1 1 0\n"
                     "1 0 0 0 5 5 0 1 1 0\n$EndEntities\n"),
            std::string::npos) << msh;
  EXPECT_NE(msh.find("$Elements\n3 11 1 11\n2 1 2 4\n"), std::string::npos) << msh;
  EXPECT_NE(msh.find("1 1 1 1\n11 2 5\n1 2 1 6\n5 1 2\n"), std::string::npos) << msh;
  const std::string msh2 = formatMsh2(m);
  EXPECT_NE(msh2.find("1 2 2 1 1 1 2 5\n"), std::string::npos) << msh2;
  EXPECT_NE(msh2.find("11 1 2 0 1 2 5\n"), std::string::npos) << msh2;  // marker 0: no group
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
  EXPECT_NE(msh.find("$PhysicalNames\n5\n2 4 \"attribute -1\"\n2 5 \"attribute 0\"\n"
                     "2 3 \"attribute 3\"\n2 6 \"attribute 4e+09\"\n"),
            std::string::npos) << msh;
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
