// Input parsing: .poly, .node, JSON (PSLGs, rings, CG:SHOP instances), numbers, files.
#if defined(__GNUC__) && !defined(__clang__)
// The allocation-tracking operator new below pairs malloc/free; GCC misreads that once the
// replaced operators inline.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>
#include <new>
#include <random>
#include <string>
#include <vector>

#include "acutemesh/io.h"
#include "fixtures.h"
#include "io/parse_context.h"
#include "reference_data.h"

namespace fs = std::filesystem;
using namespace acutemesh;
using fixtures::readText;
using fixtures::sameBits;
using fixtures::startsWith;

// ------------------------------------------------------------------------------------------
// The largest single allocation while tracking is on: parsers must not allocate what a count
// promises before the text backs it up.
namespace {
std::atomic<bool> g_track{false};
std::atomic<size_t> g_maxAlloc{0};
void noteAlloc(size_t n) {
  if (!g_track.load(std::memory_order_relaxed)) return;
  size_t cur = g_maxAlloc.load(std::memory_order_relaxed);
  while (n > cur && !g_maxAlloc.compare_exchange_weak(cur, n)) {
  }
}
}  // namespace

void* operator new(size_t n) {
  noteAlloc(n);
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](size_t n) {
  noteAlloc(n);
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, size_t) noexcept { std::free(p); }
void operator delete[](void* p, size_t) noexcept { std::free(p); }

namespace {

const std::string kData = ACUTEMESH_TEST_DATA "/io/";

// ------------------------------------------------------------------------------------------
// Whole inputs: Triangle's letter A, Lake Superior, CG:SHOP 2025 instances

TEST(IoRead, LetterA) {
  Input in;
  ParseResult r = readInputFile(ACUTEMESH_TEST_DATA "/A.poly", in);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(in.format, InputFormat::Poly);
  EXPECT_EQ(in.pslg.vertexCount(), 29u);
  EXPECT_EQ(in.pslg.segmentCount(), 29u);
  ASSERT_EQ(in.pslg.holes.size(), 2u);
  EXPECT_EQ(in.pslg.holes[0], 0.47);
  EXPECT_EQ(in.pslg.holes[1], -0.5);
  EXPECT_EQ(in.pslg.points[0], 0.2);
  EXPECT_EQ(in.pslg.points[1], -0.7764);
  // "1 29 1": 1-based endpoints come out 0-based.
  EXPECT_EQ(in.pslg.segments[0], 28u);
  EXPECT_EQ(in.pslg.segments[1], 0u);
  EXPECT_TRUE(in.warnings.empty());
}

TEST(IoRead, Superior) {
  ACUTEMESH_NEED_REFERENCE_DATA();
  Input in;
  ParseResult r = readInputFile(reference::file("poly/superior.poly"), in);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(in.pslg.vertexCount(), 303u);
  EXPECT_EQ(in.pslg.segmentCount(), 303u);
  EXPECT_EQ(in.pslg.holes.size(), 12u);
  for (uint32_t v : in.pslg.segments) EXPECT_LT(v, 303u);
}

// The number of integers in the JSON array after "key": found by plain text scanning, as an
// independent check of the parser.
long countArrayNumbers(const std::string& text, const std::string& key, bool& found) {
  size_t k = text.find("\"" + key + "\"");
  found = k != std::string::npos;
  if (!found) return -1;
  size_t p = text.find('[', k);
  int depth = 0;
  long count = 0;
  bool inNumber = false;
  for (; p < text.size(); ++p) {
    const char c = text[p];
    const bool digit = (c >= '0' && c <= '9') || c == '-';
    if (digit && !inNumber) ++count;
    inNumber = digit;
    if (c == '[') ++depth;
    if (c == ']' && --depth == 0) break;
  }
  return count;
}

long numberAfter(const std::string& text, const std::string& key) {
  size_t k = text.find("\"" + key + "\"");
  if (k == std::string::npos) return -1;
  k = text.find(':', k);
  return std::strtol(text.c_str() + k + 1, nullptr, 10);
}

// The CG:SHOP instance files in dir, sorted.
std::vector<fs::path> instanceFiles(const fs::path& dir) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (name.size() > 14 && name.substr(name.size() - 14) == ".instance.json")
      files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// Each file read as its text says: the points, the boundary ring, then the constraints.
void expectInstancesRead(const std::vector<fs::path>& files) {
  size_t withConstraints = 0;
  for (const fs::path& f : files) {
    SCOPED_TRACE(f.string());
    const std::string text = readText(f.string());
    Input in;
    ParseResult r = readInputFile(f.string(), in);
    ASSERT_TRUE(r.ok) << r.message;
    EXPECT_EQ(in.format, InputFormat::CgshopInstance);
    EXPECT_TRUE(in.warnings.empty());
    const std::string stem = f.filename().string();
    EXPECT_EQ(in.instanceUid, stem.substr(0, stem.size() - 14));
    const long n = numberAfter(text, "num_points");
    EXPECT_EQ(static_cast<long>(in.pslg.vertexCount()), n);
    bool found;
    const long boundary = countArrayNumbers(text, "region_boundary", found);
    ASSERT_TRUE(found);
    const long constraintIndices = countArrayNumbers(text, "additional_constraints", found);
    ASSERT_TRUE(found);
    EXPECT_EQ(constraintIndices / 2, numberAfter(text, "num_constraints"));
    ASSERT_EQ(static_cast<long>(in.pslg.segmentCount()), boundary + constraintIndices / 2);
    if (constraintIndices) ++withConstraints;
    // The boundary ring: consecutive, closed.
    for (long i = 0; i < boundary; ++i)
      EXPECT_EQ(in.pslg.segments[2 * i + 1], in.pslg.segments[2 * ((i + 1) % boundary)]);
    for (uint32_t v : in.pslg.segments) EXPECT_LT(v, static_cast<uint32_t>(n));
    EXPECT_TRUE(in.pslg.holes.empty());
  }
  EXPECT_GT(withConstraints, 0u);
}

TEST(IoRead, AllCgshopInstances) {
  ACUTEMESH_NEED_REFERENCE_DATA();
  const std::vector<fs::path> files = instanceFiles(reference::file("cgshop2025"));
  ASSERT_EQ(files.size(), 150u);
  expectInstancesRead(files);
}

TEST(IoRead, SyntheticCgshopInstances) {
  const std::vector<fs::path> files = instanceFiles(ACUTEMESH_TEST_DATA "/cgshop");
  ASSERT_EQ(files.size(), 8u);
  expectInstancesRead(files);
}

TEST(IoRead, CgshopExampleFromReadme) {
  const char* text = R"({
 "instance_uid": "simple_polygon_with_exterior_20_080",
 "num_points": 5,
 "points_x": [632,1330,3051,5040,5883],
 "points_y": [1588,1097,470,1077,2766],
 "region_boundary": [0,1,2,3],
 "num_constraints": 1,
 "additional_constraints": [
  [3,4]
 ]
})";
  Input in;
  ParseResult r = parseJson(text, "ex.json", in);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(in.instanceUid, "simple_polygon_with_exterior_20_080");
  EXPECT_EQ(in.pslg.points, (std::vector<double>{632, 1588, 1330, 1097, 3051, 470, 5040, 1077,
                                                 5883, 2766}));
  EXPECT_EQ(in.pslg.segments, (std::vector<uint32_t>{0, 1, 1, 2, 2, 3, 3, 0, 3, 4}));
}

// ------------------------------------------------------------------------------------------
// Fixtures

void expectSquareWithHole(const Input& in) {
  EXPECT_EQ(in.pslg.points, (std::vector<double>{0, 0, 1, 0, 1, 1, 0, 1, 0.25, 0.25, 0.75,
                                                 0.25, 0.75, 0.75, 0.25, 0.75}));
  EXPECT_EQ(in.pslg.segments,
            (std::vector<uint32_t>{0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4}));
  EXPECT_EQ(in.pslg.holes, (std::vector<double>{0.5, 0.5}));
}

TEST(IoRead, OneBasedPolyWithAttributesMarkersRegions) {
  Input in;
  ParseResult r = readInputFile(kData + "square1.poly", in);
  ASSERT_TRUE(r.ok) << r.message;
  expectSquareWithHole(in);
  EXPECT_TRUE(in.warnings.empty());
}

TEST(IoRead, ZeroBasedPolySameResult) {
  Input in;
  ParseResult r = readInputFile(kData + "square0.poly", in);
  ASSERT_TRUE(r.ok) << r.message;
  expectSquareWithHole(in);
}

TEST(IoRead, PolyWithSeparateNode) {
  Input in;
  ParseResult r = readInputFile(kData + "split.poly", in);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(in.format, InputFormat::Poly);
  EXPECT_EQ(in.pslg.points, (std::vector<double>{0, 0, 4, 0, 0, 3}));
  EXPECT_EQ(in.pslg.segments, (std::vector<uint32_t>{0, 1, 1, 2, 2, 0}));
  EXPECT_TRUE(in.pslg.holes.empty());  // hole section absent at the end

  // The same from texts; without the node text it is an error naming the poly's line.
  const std::string poly = readText(kData + "split.poly");
  r = parsePoly(poly, "split.poly", in, readText(kData + "split.node"), "split.node");
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(in.pslg.vertexCount(), 3u);
  r = parsePoly(poly, "split.poly", in);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(startsWith(r.message, "split.poly:2: expected vertices")) << r.message;
  // Errors in the node text name the node file.
  r = parsePoly(poly, "split.poly", in, "3 2 0 0\n1 0 0\n2 x 0\n3 0 1\n", "split.node");
  EXPECT_TRUE(startsWith(r.message, "split.node:3: expected x coordinate")) << r.message;
  r = parsePoly(poly, "split.poly", in, "2 2 0 0\n1 0 0\n2 1 0\n", "split.node");
  EXPECT_TRUE(startsWith(r.message, "split.poly:5: expected a vertex number in [1, 2], found '3'"))
      << r.message;
}

TEST(IoRead, CommentsBlankLinesCrlfAndSigns) {
  Input in;
  ParseResult r = readInputFile(kData + "comments.node", in);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(in.format, InputFormat::Node);
  ASSERT_EQ(in.pslg.points.size(), 6u);
  EXPECT_EQ(in.pslg.points[0], 1.5);
  EXPECT_EQ(in.pslg.points[1], -2.5);
  EXPECT_EQ(in.pslg.points[2], 1000.0);
  EXPECT_EQ(in.pslg.points[3], 0.02);
  EXPECT_TRUE(sameBits(in.pslg.points[4], -0.0));
  EXPECT_EQ(in.pslg.points[5], 7.0);
  EXPECT_TRUE(in.warnings.empty());
}

TEST(IoRead, WarningsForToleratedThings) {
  Input in;
  // First id neither 0 nor 1: 1-based, as Triangle; non-consecutive ids; trailing text.
  ParseResult r = parseNode("2 2 0 0\n5 0 0\n9 1 1\nextra\n", "w.node", in);
  ASSERT_TRUE(r.ok) << r.message;
  ASSERT_EQ(in.warnings.size(), 3u);
  EXPECT_TRUE(startsWith(in.warnings[0], "w.node:2: expected the first vertex numbered 0 or 1"));
  EXPECT_TRUE(startsWith(in.warnings[1], "w.node:3: expected vertex number 2, found 9"));
  EXPECT_TRUE(startsWith(in.warnings[2], "w.node:4: ignored the text after the vertices"));

  // Attributes and markers may be left out, as Triangle allows.
  r = parseNode("2 2 2 1\n0 0 0\n1 1 1 3.5\n", "w.node", in);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_TRUE(in.warnings.empty());
  // Header fields after the count may be left out too.
  r = parseNode("1\n0 3 4\n", "w.node", in);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(in.pslg.points, (std::vector<double>{3, 4}));
}

TEST(IoRead, OutputUnchangedOnFailure) {
  Input in;
  in.instanceUid = "keep";
  ParseResult r = parseNode("1 2 0 0\n0 nan 0\n", "x.node", in);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(in.instanceUid, "keep");
}

// ------------------------------------------------------------------------------------------
// Malformed Triangle files: each message starts "NAME:LINE: " and says what was expected.

struct BadCase {
  const char* kind;  // "poly" or "node"
  const char* text;
  const char* prefix;  // expected message start, "bad.poly:LINE: ..."
};

// One case per kind of damage: a table, long by nature.
TEST(IoRead, MalformedTriangleFiles) {
  const BadCase cases[] = {
      // empty and truncated
      {"node", "", "bad.node:1: expected the header"},
      {"node", "# only a comment\n", "bad.node:2: expected the header"},
      {"node", "3 2 0 0\n1 0.5 0.5\n2 1.5 0.5\n",
       "bad.node:4: expected vertex line 3 of 3 '<id> <x> <y>', found end of file"},
      {"node", "3 2 0 0\n1 0.5 0.5\n2 1.5 0.5", "bad.node:3: expected vertex line 3 of 3"},
      {"poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n",
       "bad.poly:5: expected the segment header '<#segments> <#boundary markers>', found end "
       "of file"},
      {"poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n3 0\n1 1 2\n2 2 3\n# the third is missing\n",
       "bad.poly:9: expected segment line 3 of 3 '<id> <endpoint> <endpoint>', found end of "
       "file"},
      {"poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0 0\n2\n1 0.1 0.1\n# one hole is missing\n",
       "bad.poly:9: expected hole line 2 of 2"},
      {"poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0 0\n0\n2\n1 0.1 0.1 5 0.5\n",
       "bad.poly:9: expected region line 2 of 2"},
      // counts the text cannot hold: found before allocating
      {"node", "1000000000 2 0 0\n1 0 0\n2 1 0\n3 0 1\n",
       "bad.node:1: expected a vertex count the rest of the text can hold (at most 3), found "
       "1000000000"},
      {"node", "3 2 0 0\n1 0 0\n2 1 0\n",
       "bad.node:1: expected a vertex count the rest of the text can hold (at most 2), found 3"},
      {"poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n4000000000 0\n1 1 2\n",
       "bad.poly:5: expected a segment count the rest of the text can hold (at most 1), found "
       "4000000000"},
      {"poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0\n99999999999 # holes\n",
       "bad.poly:6: expected a hole count the rest of the text can hold (at most 0)"},
      {"poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0\n0\n123456789\n1 0 0 1\n",
       "bad.poly:7: expected a region count the rest of the text can hold (at most 1)"},
      {"node", "99999999999999999999 2 0 0\n",
       "bad.node:1: expected the number of vertices (a non-negative integer), found "
       "'99999999999999999999'"},
      // negative counts, wrong dimension, markers
      {"node", "-3 2 0 0\n", "bad.node:1: expected the number of vertices (a non-negative "
                             "integer), found '-3'"},
      {"node", "3 3 0 0\n1 0 0\n2 1 0\n3 0 1\n", "bad.node:1: expected dimension 2, found 3"},
      {"node", "1 2 -1 0\n1 0 0\n", "bad.node:1: expected the number of attributes"},
      {"node", "1 2 0 2\n1 0 0\n", "bad.node:1: expected 0 or 1 boundary markers, found 2"},
      {"node", "1 2 0 0 7\n1 0 0\n", "bad.node:1: expected the header"},
      {"poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n-1 0\n", "bad.poly:5: expected the number of "
                                                      "segments (a non-negative integer), "
                                                      "found '-1'"},
      {"poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0 0\n-2\n", "bad.poly:6: expected the number of "
                                                         "holes"},
      // bad indices
      {"poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1 0\n1 1 4\n",
       "bad.poly:6: expected a vertex number in [1, 3], found '4'"},
      {"poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1 0\n1 0 1\n",
       "bad.poly:6: expected a vertex number in [1, 3], found '0'"},
      {"poly", "3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n1 0\n0 2 3\n",
       "bad.poly:6: expected a vertex number in [0, 2], found '3'"},
      {"poly", "3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n1 0\n0 -1 2\n",
       "bad.poly:6: expected a vertex number in [0, 2], found '-1'"},
      {"poly", "3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n1 0\n0 1.0 2\n",
       "bad.poly:6: expected a vertex number in [0, 2], found '1.0'"},
      // non-finite and malformed numbers
      {"node", "2 2 0 0\n0 0 0\n1 nan 0\n", "bad.node:3: expected a finite x coordinate, "
                                            "found 'nan'"},
      {"node", "2 2 0 0\n0 0 0\n1 0 -INF\n", "bad.node:3: expected a finite y coordinate, "
                                             "found '-INF'"},
      {"node", "2 2 0 0\n0 0 0\n1 0 Infinity\n", "bad.node:3: expected a finite y coordinate"},
      {"node", "2 2 0 0\n0 0 0\n1 1e999 0\n", "bad.node:3: expected x coordinate within "
                                              "double range, found '1e999'"},
      {"node", "2 2 0 0\n0 0 0\n1 abc 0\n", "bad.node:3: expected x coordinate (a number), "
                                            "found 'abc'"},
      {"node", "2 2 0 0\n0 0 0\n1 0x10 0\n", "bad.node:3: expected x coordinate (a number)"},
      {"node", "2 2 0 0\n0 0 0\n1 1e 0\n", "bad.node:3: expected x coordinate (a number)"},
      {"node", "2 2 0 0\n0 0 0\n1 1.5.5 0\n", "bad.node:3: expected x coordinate (a number)"},
      {"node", "2 2 0 0\n0 0 0\n1 . 0\n", "bad.node:3: expected x coordinate (a number)"},
      {"node", "2 2 0 0\n0 0 0\nx 1 0\n", "bad.node:3: expected a vertex number (an integer), "
                                          "found 'x'"},
      {"node", "2 2 1 0\n0 0 0 1\n1 1 0 q\n", "bad.node:3: expected attribute 1 (a number)"},
      {"node", "2 2 0 1\n0 0 0 1\n1 1 0 1.5\n", "bad.node:3: expected a boundary marker"},
      // wrong number of fields
      {"node", "2 2 0 0\n0 0 0\n1 12345\n", "bad.node:3: expected y coordinate, found end of "
                                           "line"},
      {"node", "2 2 0 0\n0 0 0\n1 1 2 3\n", "bad.node:3: expected '<id> <x> <y>', found an "
                                            "extra field '3'"},
      {"node", "2 2 1 1\n0 0 0\n1 1 2 3 4 5\n",
       "bad.node:3: expected '<id> <x> <y> [1 attribute] [marker]', found an extra field '5'"},
      {"poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1 0\n1 1 # no second endpoint\n",
       "bad.poly:6: expected a vertex number in [1, 3], found end of line"},
      {"poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1 0\n1 1 2 3\n",
       "bad.poly:6: expected '<id> <endpoint> <endpoint>', found an extra field '3'"},
      {"poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1 0 0\n", "bad.poly:5: expected the segment header"},
      {"poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0\n1\n1 0.5\n",
       "bad.poly:7: expected hole y coordinate, found end of line"},
      {"poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0\n1\n1 0.5 0.5 9\n",
       "bad.poly:7: expected '<id> <x> <y>', found an extra field '9'"},
      {"poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0\n1\n1 nan 0.5\n",
       "bad.poly:7: expected a finite hole x coordinate"},
      {"poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0\n0\n1\n1 0.5 0.5\n",
       "bad.poly:8: expected regional attribute, found end of line"},
      {"poly", "0 2 0 0\n", "bad.poly:1: expected vertices (a count of 0 says they are in a "
                            ".node file), found no .node text"},
  };
  for (const BadCase& c : cases) {
    SCOPED_TRACE(c.text);
    Input in;
    const bool poly = std::strcmp(c.kind, "poly") == 0;
    ParseResult r = poly ? parsePoly(c.text, "bad.poly", in) : parseNode(c.text, "bad.node", in);
    EXPECT_FALSE(r.ok);
    EXPECT_TRUE(startsWith(r.message, c.prefix)) << "message: " << r.message;
  }
}

TEST(IoRead, HugeCountsFailFastWithoutAllocating) {
  struct Huge {
    bool poly;
    std::string text;
  };
  const Huge cases[] = {
      {false, "1000000000 2 0 0\n1 0 0\n2 1 0\n3 0 1\n"},
      {false, "4294967295 2 0 0\n1 0 0\n2 1 0\n3 0 1\n"},
      {false, "18446744073709551615 2 0 0\n1 0 0\n"},
      {true, "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1000000000 0\n1 1 2\n2 2 3\n3 3 1\n"},
      {true, "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0 0\n1000000000\n1 0 0\n"},
      {true, "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0 0\n0\n1000000000\n1 0 0 0\n"},
  };
  for (const Huge& h : cases) {
    SCOPED_TRACE(h.text);
    Input in;
    g_maxAlloc = 0;
    g_track = true;
    const auto t0 = std::chrono::steady_clock::now();
    ParseResult r = h.poly ? parsePoly(h.text, "huge.poly", in) : parseNode(h.text, "huge.node", in);
    const auto t1 = std::chrono::steady_clock::now();
    g_track = false;
    EXPECT_FALSE(r.ok);
    EXPECT_LT(g_maxAlloc.load(), 4096u) << r.message;
    EXPECT_LT(std::chrono::duration<double>(t1 - t0).count(), 0.05);
  }
  // JSON has no counts to trust, and a count field that disagrees is an error.
  Input in;
  ParseResult r = parseJson(R"({"num_points": 1000000000, "points_x": [0, 1, 0],
    "points_y": [0, 0, 1], "region_boundary": [0, 1, 2]})", "huge.json", in);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(startsWith(r.message, "huge.json:1: expected \"num_points\" equal to the 3 points "
                                    "given, found 1000000000"))
      << r.message;
}

// ------------------------------------------------------------------------------------------
// JSON

TEST(IoRead, JsonPslg) {
  const char* text = R"({
  "vertices": [[0, 0], [4, 0], [4, 3.5e0], [-0.0, 3]],
  "segments": [[0, 1], [1, 2], [2, 3], [3, 0]],
  "holes": [[1, 1]]
})";
  Input in;
  ParseResult r = parseJson(text, "p.json", in);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(in.format, InputFormat::JsonPslg);
  EXPECT_FALSE(in.hasRings);
  EXPECT_EQ(in.pslg.points, (std::vector<double>{0, 0, 4, 0, 4, 3.5, 0, 3}));
  EXPECT_TRUE(sameBits(in.pslg.points[6], -0.0));
  EXPECT_EQ(in.pslg.segments, (std::vector<uint32_t>{0, 1, 1, 2, 2, 3, 3, 0}));
  EXPECT_EQ(in.pslg.holes, (std::vector<double>{1, 1}));

  // Segments and holes are optional; keys in any order; unknown keys warn.
  r = parseJson(R"({"name": {"a": [1, "x", null, true, false]}, "vertices": []})", "p.json", in);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(in.pslg.vertexCount(), 0u);
  ASSERT_EQ(in.warnings.size(), 1u);
  EXPECT_EQ(in.warnings[0], "p.json:1: ignored the unknown key \"name\"");
  r = parseJson(R"({"segments": [[1, 0]], "vertices": [[0, 0], [1, 1]]})", "p.json", in);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(in.pslg.segments, (std::vector<uint32_t>{1, 0}));
}

TEST(IoRead, JsonRings) {
  const char* text = R"({"rings": [
    [[0, 0], [10, 0], [10, 10], [0, 10], [0, 0]],
    [[2, 2], [2, 8], [8, 8]]
  ]})";
  Input in;
  ParseResult r = parseJson(text, "r.json", in);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_TRUE(in.hasRings);
  EXPECT_EQ(in.format, InputFormat::JsonPslg);
  EXPECT_EQ(in.pslg.points,
            (std::vector<double>{0, 0, 10, 0, 10, 10, 0, 10, 2, 2, 2, 8, 8, 8}));
  EXPECT_EQ(in.pslg.segments,
            (std::vector<uint32_t>{0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 4}));
  ASSERT_EQ(in.warnings.size(), 1u);
  EXPECT_TRUE(startsWith(in.warnings[0], "r.json:2: dropped the ring's last point"));
}

// A map's rings are often each closed by repeating the first point: the first few are listed
// with their lines, and one line counts them all (not thousands of lines), while other
// warnings keep their places.
TEST(IoRead, AlikeWarningsListedAFewTimesThenCounted) {
  std::string text = "{\"rings\": [\n";
  for (int i = 0; i < 9; ++i) {
    const std::string x = std::to_string(3 * i);
    text += std::string(i ? ",\n" : "") + "[[" + x + ", 0], [" + x + ".5, 0], [" + x + ", 1], [" + x + ", 0]]";
  }
  text += "\n], \"name\": \"islands\"}";
  Input in;
  ParseResult r = parseJson(text, "m.json", in);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(in.pslg.vertexCount(), 27u);
  ASSERT_EQ(in.warnings.size(), io::kListedAlike + 2) << ::testing::PrintToString(in.warnings);
  for (size_t i = 0; i < io::kListedAlike; ++i)
    EXPECT_EQ(in.warnings[i], "m.json:" + std::to_string(i + 2) +
                                  ": dropped the ring's last point, a repeat of its first (rings "
                                  "close implicitly)");
  EXPECT_EQ(in.warnings[io::kListedAlike],
            "m.json: 9 times in all (the first 5 listed): dropped the ring's last point, a repeat "
            "of its first (rings close implicitly)");
  EXPECT_EQ(in.warnings[io::kListedAlike + 1], "m.json:11: ignored the unknown key \"name\"");
}

TEST(IoRead, JsonStringsAndEscapes) {
  Input in;
  ParseResult r = parseJson(
      "{\"instance_uid\": \"a\\\"b\\\\c\\/d\\b\\f\\n\\r\\t\\u00e9\\u20AC\\ud83d\\ude00\xc3\xa9\","
      " \"points_x\": [0, 1, 0], \"points_y\": [0, 0, 1], \"region_boundary\": [0, 1, 2, 0],"
      " \"additional_constraints\": []}",
      "s.json", in);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(in.instanceUid, "a\"b\\c/d\b\f\n\r\t\xc3\xa9\xe2\x82\xac\xf0\x9f\x98\x80\xc3\xa9");
  EXPECT_EQ(in.pslg.segments, (std::vector<uint32_t>{0, 1, 1, 2, 2, 0}));
  ASSERT_EQ(in.warnings.size(), 1u);  // the repeated closing index
  EXPECT_TRUE(startsWith(in.warnings[0], "s.json:1: dropped the last index of \"region_boundary\""));
  // A byte order mark is allowed.
  r = parseJson("\xEF\xBB\xBF{\"vertices\": [[1, 2]]}", "bom.json", in);
  EXPECT_TRUE(r.ok) << r.message;
}

struct BadJson {
  const char* text;
  const char* prefix;
};

// One case per kind of damage: a table, long by nature.
TEST(IoRead, MalformedJson) {
  const BadJson cases[] = {
      {"", "bad.json:1: expected '{' starting the top-level JSON object, found end of text"},
      {"\n\n[1, 2]", "bad.json:3: expected '{' starting the top-level JSON object, found '['"},
      {"{", "bad.json:1: expected a key string, found end of text"},
      {"{}", "bad.json:1: expected the key \"vertices\", \"rings\" or \"points_x\", found none"},
      {"{\"vertices\": [[0, 0] [1, 0]]}",
       "bad.json:1: expected ',' or ']' in the \"vertices\" array, found '['"},
      {"{\n\"vertices\": [\n[0, 0],\n[1, 0],\n]\n}",
       "bad.json:5: expected '[' starting a vertex [x, y], found ']'"},
      {"{\"vertices\": [[0, 0]],}", "bad.json:1: expected a key string, found '}'"},
      {"{\"vertices\": [[0, 0]]} x", "bad.json:1: expected end of text after the top-level "
                                     "object, found 'x'"},
      {"{\"vertices\": [[0, 0]]}{}", "bad.json:1: expected end of text after the top-level "
                                     "object, found '{'"},
      {"{\"vertices\": [[NaN, 0]]}", "bad.json:1: expected an x coordinate (a number), found "
                                     "'NaN'"},
      {"{\"vertices\": [[0, Infinity]]}", "bad.json:1: expected a y coordinate (a number), "
                                          "found 'Infinity'"},
      {"{\"vertices\": [[01, 0]]}", "bad.json:1: expected an x coordinate (a number), found "
                                    "'01'"},
      {"{\"vertices\": [[+1, 0]]}", "bad.json:1: expected an x coordinate (a number)"},
      {"{\"vertices\": [[.5, 0]]}", "bad.json:1: expected an x coordinate (a number)"},
      {"{\"vertices\": [[1., 0]]}", "bad.json:1: expected an x coordinate (a number)"},
      {"{\"vertices\": [[1e999, 0]]}", "bad.json:1: expected an x coordinate within double "
                                       "range, found '1e999'"},
      {"{\"vertices\": [[0, 0, 0]]}", "bad.json:1: expected ']' ending a vertex [x, y] (exactly "
                                      "2 numbers), found ','"},
      {"{\"vertices\": [[0]]}", "bad.json:1: expected ',' between x and y, found ']'"},
      {"{\"vertices\": [0, 0]}", "bad.json:1: expected '[' starting a vertex [x, y], found '0'"},
      {"{\"vertices\": {}}", "bad.json:1: expected '[' starting the \"vertices\" array, found '{'"},
      {"{\"vertices\": [[\"0\", 0]]}", "bad.json:1: expected an x coordinate (a number), found "
                                       "the string \"0\""},
      {"{\"vertices\" [[0, 0]]}", "bad.json:1: expected ':' after the key, found '['"},
      {"{vertices: []}", "bad.json:1: expected a key string, found 'vertices'"},
      {"{'vertices': []}", "bad.json:1: expected a key string, found the byte 0x27"},
      {"{\"vertices\": [], \"vertices\": []}",
       "bad.json:1: expected each key once, found \"vertices\" again"},
      // strings
      {"{\"vert", "bad.json:1: expected a closing '\"' of the string, found the string \"vert"},
      {"{\"a\nb\": 1}", "bad.json:1: expected '\"' closing the string, found end of line"},
      {"{\"a\\x\": 1}", "bad.json:1: expected an escape"},
      {"{\"a\\u12G4\": 1}", "bad.json:1: expected 4 hex digits after '\\u', found 'G'"},
      {"{\"a\\ud800\": 1}", "bad.json:1: expected a low surrogate"},
      {"{\"a\\udc00\": 1}", "bad.json:1: expected a high surrogate before a low one"},
      {"{\"a\tb\": 1}", "bad.json:1: expected a string character, found a control character"},
      // values skipped under unknown keys are still checked
      {"{\"x\": tru, \"vertices\": []}", "bad.json:1: expected a value, found 'tru'"},
      {"{\"x\": nulls}", "bad.json:1: expected a value, found 'nulls'"},
      {"{\"x\": [1 2]}", "bad.json:1: expected ',' or ']', found '2'"},
      {"{\"x\": {\"a\" 1}}", "bad.json:1: expected ':' after the key, found '1'"},
      {"{\"x\": -}", "bad.json:1: expected a value, found '-'"},
      // indices
      {"{\"vertices\": [[0, 0], [1, 0]],\n \"segments\": [[0, 1],\n [1, 2]]}",
       "bad.json:3: expected a vertex index in \"segments\" below 2, found 2"},
      {"{\"vertices\": [[0, 0], [1, 0]], \"segments\": [[0, -1]]}",
       "bad.json:1: expected a vertex index (a non-negative integer), found '-1'"},
      {"{\"vertices\": [[0, 0], [1, 0]], \"segments\": [[0, 1.0]]}",
       "bad.json:1: expected a vertex index (a non-negative integer), found '1.0'"},
      {"{\"vertices\": [[0, 0], [1, 0]], \"segments\": [[0, 1e0]]}",
       "bad.json:1: expected a vertex index (a non-negative integer), found '1e0'"},
      {"{\"vertices\": [[0, 0], [1, 0]], \"segments\": [[0, 4294967296]]}",
       "bad.json:1: expected a vertex index (a non-negative integer), found '4294967296'"},
      {"{\"vertices\": [[0, 0], [1, 0]], \"segments\": [[0, 1, 1]]}",
       "bad.json:1: expected ']' ending a segment [i, j] (exactly 2 indices), found ','"},
      // missing and mixed fields
      {"{\"segments\": [[0, 1]]}", "bad.json:1: expected the key \"vertices\" with \"segments\", "
                                   "found none"},
      {"{\"vertices\": [], \"rings\": []}",
       "bad.json:1: expected the keys of an acutemesh PSLG (\"vertices\") as \"vertices\" says, "
       "found \"rings\""},
      {"{\"rings\": [], \"holes\": [[0, 0]]}",
       "bad.json:1: expected the keys of rings (\"rings\") as \"rings\" says, found \"holes\""},
      {"{\"points_x\": [0], \"vertices\": []}",
       "bad.json:1: expected the keys of a CG:SHOP instance (\"points_x\") as \"points_x\" says, "
       "found \"vertices\""},
      {"{\"rings\": [[[0, 0], [1, 0], [0, 0]]]}",
       "bad.json:1: expected a ring of at least 3 distinct points, found 2"},
      {"{\"rings\": [[0, 0]]}", "bad.json:1: expected '[' starting a ring point [x, y], found "
                                "'0'"},
      {"{\"rings\": [0]}", "bad.json:1: expected '[' starting a ring [[x, y], ...], found '0'"},
      {"{\"points_x\": [0, 1, 0], \"region_boundary\": [0, 1, 2]}",
       "bad.json:1: expected the key \"points_y\" of a CG:SHOP instance, found none"},
      {"{\"points_x\": [0, 1, 0], \"points_y\": [0, 1, 0]}",
       "bad.json:1: expected the key \"region_boundary\" of a CG:SHOP instance, found none"},
      {"{\"instance_uid\": \"u\", \"points_y\": [0]}",
       "bad.json:1: expected the key \"points_x\" of a CG:SHOP instance, found none"},
      {"{\"points_x\": [0, 1, 0],\n\"points_y\": [0, 1],\n\"region_boundary\": [0, 1, 2]}",
       "bad.json:2: expected 3 numbers in \"points_y\" (as in \"points_x\"), found 2"},
      {"{\"points_x\": [0, 1, 0], \"points_y\": [0, 0, 1],\n\"region_boundary\": [0, 1, 3]}",
       "bad.json:2: expected a vertex index in \"region_boundary\" below 3, found 3"},
      {"{\"points_x\": [0, 1, 0], \"points_y\": [0, 0, 1],\n\"region_boundary\": [0, 1]}",
       "bad.json:2: expected at least 3 indices in \"region_boundary\", found 2"},
      {"{\"points_x\": [0, 1, 0], \"points_y\": [0, 0, 1], \"region_boundary\": [0, 1, 2],\n"
       "\"additional_constraints\": [[0, 1], [1, 7]]}",
       "bad.json:2: expected a vertex index in \"additional_constraints\" below 3, found 7"},
      {"{\"instance_uid\": 5}", "bad.json:1: expected the instance uid (a string), found '5'"},
      {"{\"num_points\": -1}", "bad.json:1: expected a count (a non-negative integer), found '-1'"},
  };
  for (const BadJson& c : cases) {
    SCOPED_TRACE(c.text);
    Input in;
    ParseResult r = parseJson(c.text, "bad.json", in);
    EXPECT_FALSE(r.ok);
    EXPECT_TRUE(startsWith(r.message, c.prefix)) << "message: " << r.message;
  }
}

TEST(IoRead, JsonDepthLimit) {
  std::string deep = "{\"x\": ";
  for (int i = 0; i < 100000; ++i) deep += '[';
  Input in;
  ParseResult r = parseJson(deep, "deep.json", in);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(startsWith(r.message, "deep.json:1: expected nesting at most 200 deep"))
      << r.message;
  // Moderate nesting is fine.
  std::string ok = "{\"x\": ";
  for (int i = 0; i < 150; ++i) ok += '[';
  for (int i = 0; i < 150; ++i) ok += ']';
  ok += ", \"vertices\": []}";
  r = parseJson(ok, "ok.json", in);
  EXPECT_TRUE(r.ok) << r.message;
}

TEST(IoRead, CountMismatchInCgshopIsAWarning) {
  Input in;
  ParseResult r = parseJson(R"({"points_x": [0, 1, 0], "points_y": [0, 0, 1],
    "region_boundary": [0, 1, 2], "num_constraints": 2, "additional_constraints": [[0, 1]]})",
                            "c.json", in);
  ASSERT_TRUE(r.ok) << r.message;
  ASSERT_EQ(in.warnings.size(), 1u);
  EXPECT_TRUE(startsWith(in.warnings[0], "c.json:2: \"num_constraints\" says 2 but 1"));
  EXPECT_EQ(in.pslg.segmentCount(), 4u);
}

// ------------------------------------------------------------------------------------------
// Files

TEST(IoRead, FileErrors) {
  Input in;
  ParseResult r = readInputFile(kData + "no-such-file.poly", in);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.message, kData + "no-such-file.poly: cannot open (No such file or directory)");
  r = readInputFile(kData + "square1.txt", in);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.message, kData + "square1.txt: expected the extension .poly, .node or .json, "
                               "found '.txt'");
  r = readInputFile(kData + "noext", in);
  EXPECT_TRUE(startsWith(r.message, kData + "noext: expected the extension")) << r.message;

  const fs::path dir = fs::temp_directory_path() / "acutemesh_test_io_dir.node";
  fs::create_directories(dir);
  r = readInputFile(dir.string(), in);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(startsWith(r.message, dir.string() + ": cannot")) << r.message;
  fs::remove(dir);

  // A .poly without vertices and no .node beside it.
  const fs::path lone = fs::temp_directory_path() / "acutemesh_test_io_lone.POLY";
  std::FILE* f = std::fopen(lone.string().c_str(), "wb");
  ASSERT_NE(f, nullptr);
  std::fputs("0 2 0 0\n0 0\n", f);
  std::fclose(f);
  r = readInputFile(lone.string(), in);
  EXPECT_FALSE(r.ok);
  const std::string nodePath = lone.string().substr(0, lone.string().size() - 5) + ".node";
  EXPECT_EQ(r.message, nodePath + ": cannot open (No such file or directory)");
  fs::remove(lone);
}

// ------------------------------------------------------------------------------------------
// Number conversion: every double the text parsers produce equals strtod's, bit for bit.

TEST(IoRead, NumbersMatchStrtod) {
  std::mt19937_64 rng(20250101);
  std::vector<std::string> tokens;
  char buf[128];
  auto randomDouble = [&]() {
    for (;;) {
      const uint64_t bits = rng();
      double d;
      std::memcpy(&d, &bits, sizeof d);
      if (std::isfinite(d)) return d;
    }
  };
  for (int i = 0; i < 40000; ++i) {
    const double d = randomDouble();
    std::snprintf(buf, sizeof buf, "%.17g", d);
    tokens.push_back(buf);
    std::snprintf(buf, sizeof buf, "%.*g", 1 + static_cast<int>(rng() % 17), d);
    tokens.push_back(buf);
    // Coordinates of usual magnitudes with all precisions, fixed and exponent notation.
    const double u = std::ldexp(static_cast<double>(rng() >> 11), -53) *
                     std::pow(10.0, static_cast<int>(rng() % 24) - 12);
    std::snprintf(buf, sizeof buf, "%.*g", 1 + static_cast<int>(rng() % 20), u);
    tokens.push_back(buf);
    std::snprintf(buf, sizeof buf, "%.*f", static_cast<int>(rng() % 25), u);
    tokens.push_back(buf);
    std::snprintf(buf, sizeof buf, "%.*e", static_cast<int>(rng() % 22), -u);
    tokens.push_back(buf);
  }
  // Random digit strings: up to 30 digits, a point anywhere, exponents far and near, which
  // also exercise halfway cases, subnormals, underflow to zero and the slow paths.
  for (int i = 0; i < 60000; ++i) {
    std::string t;
    if (rng() % 4 == 0) t += (rng() % 2) ? '-' : '+';
    const int digits = 1 + static_cast<int>(rng() % 30);
    const int point = static_cast<int>(rng() % (digits + 2)) - 1;
    for (int k = 0; k < digits; ++k) {
      if (k == point) t += '.';
      t += static_cast<char>('0' + (k == 0 && rng() % 3 == 0 ? 0 : rng() % 10));
    }
    if (rng() % 2) {
      t += (rng() % 2) ? 'e' : 'E';
      const int range = (rng() % 2) ? 30 : 700;
      t += std::to_string(static_cast<int>(rng() % (2 * range + 1)) - range);
    }
    tokens.push_back(t);
  }
  // Halfway and boundary cases.
  for (const char* t :
       {"9007199254740993", "9007199254740992.5", "2.2250738585072011e-308",
        "2.2250738585072014e-308", "4.9406564584124654e-324", "2.4703282292062328e-324",
        "2.4703282292062327e-324", "1.7976931348623157e308", "1.7976931348623158e308",
        "0.1", "0.30000000000000004", "123456789012345678901234567890", "1e-400", "-1e-400",
        "0e999999999999", "000000000000000000000000001.5", "1.00000000000000011102230246251565",
        "4503599627370496.5", "4503599627370497.5", "7.2057594037927933e16",
        "1e23", "8.98846567431158e307", "3.0e-5", ".5", "5.", "-0", "+0.0"})
    tokens.push_back(t);

  std::vector<double> expected;
  std::string text = std::to_string(tokens.size()) + " 2 0 0\n";
  size_t kept = 0;
  for (const std::string& t : tokens) {
    const double d = std::strtod(t.c_str(), nullptr);
    if (std::isinf(d)) continue;  // overflow: an error, tested elsewhere
    text += std::to_string(kept++) + " " + t + " 0\n";
    expected.push_back(d);
  }
  text.replace(0, text.find(' '), std::to_string(kept));
  Input in;
  ParseResult r = parseNode(text, "num.node", in);
  ASSERT_TRUE(r.ok) << r.message;
  ASSERT_EQ(in.pslg.vertexCount(), kept);
  size_t bad = 0;
  for (size_t i = 0; i < kept; ++i) {
    if (!sameBits(in.pslg.points[2 * i], expected[i]) && bad++ < 10)
      ADD_FAILURE() << "line " << i + 2 << ": got " << in.pslg.points[2 * i] << " expected "
                    << expected[i];
  }
  EXPECT_EQ(bad, 0u);
}

TEST(IoRead, OverflowIsAnError) {
  Input in;
  for (const char* t : {"1.7976931348623159e308", "1e309", "-1e400", "1e99999999999999999999"}) {
    SCOPED_TRACE(t);
    const std::string text = std::string("1 2 0 0\n0 0 ") + t + "\n";
    ParseResult r = parseNode(text, "o.node", in);
    EXPECT_FALSE(r.ok);
    EXPECT_TRUE(startsWith(r.message, "o.node:2: expected y coordinate within double range"))
        << r.message;
  }
}

}  // namespace
