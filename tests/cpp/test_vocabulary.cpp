// The vocabulary (names of modes, fill rules, formats, statuses) and the input policy.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "acutemesh/io.h"
#include "acutemesh/vocabulary.h"
#include "fixtures.h"

using namespace acutemesh;

namespace {

template <class Entry, size_t N>
void expectRoundTrip(const Entry (&table)[N]) {
  for (const Entry& e : table) {
    EXPECT_STREQ(nameOf(e.value), e.name);
    EXPECT_NE(std::string(e.description), "");
    decltype(e.value) back{};
    std::string message;
    EXPECT_TRUE(parseName(e.name, back, &message)) << message;
    EXPECT_EQ(back, e.value);
  }
}

// A small CG:SHOP 2025 instance: a 12-gon with integer corners and 20 points a little inside
// its edges, where exact altitude feet pay off (integer arithmetic only, as in the JS test).
std::string generatedInstance() {
  const int64_t cx[12] = {2995, 2812, 2411, 1900, 1416, 1088, 1005, 1188, 1589, 2100, 2584, 2912};
  const int64_t cy[12] = {2070, 2409, 2638, 2697, 2568, 2288, 1930, 1591, 1362, 1303, 1432, 1712};
  std::string xs, ys;
  for (int i = 0; i < 12; ++i) {
    xs += (i ? "," : "") + std::to_string(cx[i]);
    ys += (i ? "," : "") + std::to_string(cy[i]);
  }
  uint64_t seed = 7;
  auto next = [&seed] { return seed = seed * 48271 % 2147483647; };
  for (int k = 0; k < 20; ++k) {
    const int i = k % 12, j = (i + 1) % 12;
    const int64_t t = 20 + int64_t(next() % 61), inward = 1 + int64_t(next() % 4);
    int64_t x = cx[i] + t * (cx[j] - cx[i]) / 100, y = cy[i] + t * (cy[j] - cy[i]) / 100;
    x += (2000 - x) * inward / 100;
    y += (2000 - y) * inward / 100;
    xs += "," + std::to_string(x);
    ys += "," + std::to_string(y);
  }
  return "{\"instance_uid\": \"generated_12\", \"num_points\": 32, \"points_x\": [" + xs +
         "], \"points_y\": [" + ys +
         "], \"region_boundary\": [0,1,2,3,4,5,6,7,8,9,10,11], \"num_constraints\": 0, "
         "\"additional_constraints\": []}";
}

}  // namespace

TEST(Vocabulary, EveryNameReadsBackAsItsValue) {
  expectRoundTrip(kModes);
  expectRoundTrip(kFillRules);
  expectRoundTrip(kInputFormats);
  expectRoundTrip(kOutputFormats);
  for (const auto& e : kStatuses) EXPECT_STREQ(nameOf(e.value), e.name);
  for (const auto& e : kVertexKinds) EXPECT_STREQ(nameOf(e.value), e.name);
  EXPECT_STREQ(nameOf(Status::TargetNotMet), "target-not-met");
  EXPECT_STREQ(nameOf(Mode(99)), "?");
}

TEST(Vocabulary, UnknownNamesListTheChoicesAndSuggestTheNearest) {
  Mode mode = Mode::Cdt;
  std::string message;
  EXPECT_FALSE(parseName("fast", mode, &message));
  EXPECT_EQ(message, "unknown mode 'fast' (delaunay, cdt, quality, nonobtuse, acute)");
  EXPECT_EQ(mode, Mode::Cdt);
  EXPECT_FALSE(parseName("non-obtuse", mode, &message));
  EXPECT_EQ(message, "unknown mode 'non-obtuse' (delaunay, cdt, quality, nonobtuse, acute): "
                     "did you mean 'nonobtuse'?");
  EXPECT_FALSE(parseName("Acute", mode, &message));
  EXPECT_EQ(message.substr(message.find(')')), "): did you mean 'acute'?");
  // Too far from every name (obtuse is three letters from nonobtuse), or from two alike.
  EXPECT_FALSE(parseName("obtuse", mode, &message));
  EXPECT_EQ(message.find("did you mean"), std::string::npos);
  OutputFormat format;
  EXPECT_FALSE(parseName("png", format, &message));
  EXPECT_EQ(message, "unknown format 'png' (node, ele, poly, edge, neigh, json, off, obj, svg, msh, msh2, "
                     "vtu, cgshop)");
  EXPECT_FALSE(parseName("ofj", format, &message));  // one letter from both off and obj
  EXPECT_EQ(message.find("did you mean"), std::string::npos);
  EXPECT_FALSE(parseName("jsn", format, &message));
  EXPECT_NE(message.find("did you mean 'json'?"), std::string::npos);
  EXPECT_FALSE(parseName("jsno", format, &message));  // two letters swapped: one slip
  EXPECT_NE(message.find("did you mean 'json'?"), std::string::npos);
  FillRule fill;
  EXPECT_FALSE(parseName("holes", fill, &message));
  EXPECT_EQ(message, "unknown fill rule 'holes' (triangle, evenodd, nonzero)");
  EXPECT_FALSE(parseName("", fill, nullptr));
}

TEST(Vocabulary, OutputFormatsAreTheWriters) {
  Mesh m;
  m.points = {0, 0, 1, 0, 0, 1};
  m.triangles = {0, 1, 2};
  m.segments = {0, 1};
  EXPECT_EQ(formatMesh(OutputFormat::Node, m), formatNode(m));
  EXPECT_EQ(formatMesh(OutputFormat::Ele, m), formatEle(m));
  EXPECT_EQ(formatMesh(OutputFormat::Poly, m), formatPoly(m));
  EXPECT_EQ(formatMesh(OutputFormat::Json, m), formatJson(m));
  EXPECT_EQ(formatMesh(OutputFormat::Off, m), formatOff(m));
  EXPECT_EQ(formatMesh(OutputFormat::Obj, m), formatObj(m));
  EXPECT_EQ(formatMesh(OutputFormat::Svg, m), formatSvg(m));
  EXPECT_EQ(formatMesh(OutputFormat::Edge, m), formatEdge(m));
  EXPECT_EQ(formatMesh(OutputFormat::Neigh, m), formatNeigh(m));
  EXPECT_EQ(formatMesh(OutputFormat::Msh, m), formatMsh(m));
  EXPECT_EQ(formatMesh(OutputFormat::Msh2, m), formatMsh2(m));
  EXPECT_EQ(formatMesh(OutputFormat::Vtu, m), formatVtu(m));
  EXPECT_EQ(formatMesh(OutputFormat::Cgshop, m), "");
  for (const OutputFormatInfo& f : kOutputFormats) {
    EXPECT_EQ(&infoOf(f.value), &f);
    EXPECT_EQ(f.needsInstance, f.value == OutputFormat::Cgshop);
    // Files are BASE.NAME, but for msh2 (BASE.v2.msh: beside BASE.msh, still a .msh file).
    if (!f.needsInstance && f.value != OutputFormat::Msh2) {
      EXPECT_EQ(std::string(f.extension), "." + std::string(f.name));
    }
    // Every format a writer: the text is not empty (the solution apart).
    EXPECT_EQ(formatMesh(f.value, m).empty(), f.needsInstance) << f.name;
  }
  EXPECT_EQ(std::string(infoOf(OutputFormat::Msh2).extension), ".v2.msh");
  // The solution needs its instance: writeMeshFiles does not take it.
  ParseResult r = writeMeshFiles(m, "/nonexistent/x", {"cgshop"});
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.message, "expected an output format among node, ele, poly, edge, neigh, json, off, obj, svg, "
                       "msh, msh2, vtu, found 'cgshop'");
}

TEST(InputPolicy, CgshopInstancesAreExactAndRingsEvenOdd) {
  Options o;
  applyInputPolicy(InputFormat::CgshopInstance, false, {}, o);
  EXPECT_TRUE(o.exactSegments);
  EXPECT_TRUE(o.exactFeet);
  EXPECT_EQ(o.fill, FillRule::Triangle);

  Options off;
  ChosenOptions chosen;
  chosen.exactFeet = true;  // --no-exact-feet, or exactFeet: false in JavaScript
  applyInputPolicy(InputFormat::CgshopInstance, false, chosen, off);
  EXPECT_TRUE(off.exactSegments);
  EXPECT_FALSE(off.exactFeet);

  for (InputFormat f : {InputFormat::Unknown, InputFormat::Poly, InputFormat::Node, InputFormat::JsonPslg}) {
    Options plain;
    applyInputPolicy(f, false, {}, plain);
    EXPECT_FALSE(plain.exactSegments);
    EXPECT_FALSE(plain.exactFeet);
    EXPECT_EQ(plain.fill, FillRule::Triangle);
  }

  Options rings;
  applyInputPolicy(InputFormat::JsonPslg, true, {}, rings);
  EXPECT_EQ(rings.fill, FillRule::EvenOdd);
  Options ringsNonZero;
  ringsNonZero.fill = FillRule::NonZero;
  ChosenOptions fillChosen;
  fillChosen.fill = true;
  applyInputPolicy(InputFormat::JsonPslg, true, fillChosen, ringsNonZero);
  EXPECT_EQ(ringsNonZero.fill, FillRule::NonZero);
}

// The mesh every caller gets for a CG:SHOP instance (the CLI and the JavaScript package apply
// this same policy): exact feet and exact segment points, far fewer Steiner points than with
// the plain options, and valid for the exact checks.
TEST(InputPolicy, CgshopInstanceMeshedWithExactSegmentsAndFeet) {
  Input in;
  ParseResult parsed = parseJson(generatedInstance(), "generated.instance.json", in);
  ASSERT_TRUE(parsed.ok) << parsed.message;
  ASSERT_EQ(in.format, InputFormat::CgshopInstance);
  Options options;
  options.mode = Mode::NonObtuse;
  applyInputPolicy(in, {}, options);
  Result r = mesh(in.pslg, options);
  ASSERT_EQ(r.status, Status::Ok) << r.message;
  EXPECT_TRUE(r.stats.certified);
  EXPECT_FALSE(r.mesh.exactPoints.empty());
  EXPECT_EQ(fixtures::validationErrors(in.pslg, options, r.mesh), "");

  Options explicitly;
  explicitly.mode = Mode::NonObtuse;
  explicitly.exactSegments = explicitly.exactFeet = true;
  Result same = mesh(in.pslg, explicitly);
  EXPECT_EQ(same.mesh.points, r.mesh.points);
  EXPECT_EQ(same.mesh.triangles, r.mesh.triangles);

  Options plain;
  plain.mode = Mode::NonObtuse;
  Result other = mesh(in.pslg, plain);
  EXPECT_TRUE(other.mesh.exactPoints.empty());
  EXPECT_GT(other.stats.steiner, 2 * r.stats.steiner);
}
