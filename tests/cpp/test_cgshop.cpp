// The CG:SHOP 2025 solution writer: exact coordinates, renumbering, and every instance (the
// synthetic ones in tests/data/cgshop; the 150 official ones of the reference data when it is
// there) meshed (Mode::Cdt) and read back by a small JSON reader here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "acutemesh/io.h"
#include "exact.h"
#include "reference_data.h"

namespace fs = std::filesystem;
using namespace acutemesh;

namespace {

// ------------------------------------------------------------------------------------------
// A minimal strict JSON reader: numbers are kept as their text, strings decoded (\uXXXX only
// below 0x80, which is all the writer produces).
struct Json {
  enum Kind { Null, Bool, Number, String, Array, Object } kind = Null;
  std::string text;  // Number: the literal; String: the decoded value; Bool: true/false
  std::vector<Json> items;
  std::vector<std::pair<std::string, Json>> members;

  const Json* get(const std::string& key) const {
    for (const auto& m : members)
      if (m.first == key) return &m.second;
    return nullptr;
  }
};

class Reader {
 public:
  explicit Reader(const std::string& s) : s_(s) {}
  bool document(Json& out) {
    if (!value(out, 0)) return false;
    ws();
    return i_ == s_.size();
  }

 private:
  void ws() {
    while (i_ < s_.size() && std::strchr(" \t\r\n", s_[i_])) ++i_;
  }
  bool eat(char c) {
    ws();
    if (i_ < s_.size() && s_[i_] == c) return ++i_, true;
    return false;
  }
  bool literal(const char* w) {
    const size_t n = std::strlen(w);
    if (s_.compare(i_, n, w) != 0) return false;
    i_ += n;
    return true;
  }
  bool string(std::string& out) {
    if (!eat('"')) return false;
    out.clear();
    while (i_ < s_.size()) {
      const char c = s_[i_++];
      if (c == '"') return true;
      if (static_cast<unsigned char>(c) < 0x20) return false;
      if (c != '\\') {
        out += c;
        continue;
      }
      if (i_ >= s_.size()) return false;
      const char e = s_[i_++];
      if (e == 'u') {
        if (i_ + 4 > s_.size()) return false;
        const unsigned long u = std::stoul(s_.substr(i_, 4), nullptr, 16);
        if (u >= 0x80) return false;
        out += static_cast<char>(u);
        i_ += 4;
      } else if (e == '"' || e == '\\' || e == '/') {
        out += e;
      } else if (e == 'n') {
        out += '\n';
      } else if (e == 't') {
        out += '\t';
      } else if (e == 'r') {
        out += '\r';
      } else if (e == 'b') {
        out += '\b';
      } else if (e == 'f') {
        out += '\f';
      } else {
        return false;
      }
    }
    return false;
  }
  bool number(std::string& out) {
    const size_t start = i_;
    if (i_ < s_.size() && s_[i_] == '-') ++i_;
    auto digits = [&] {
      const size_t d = i_;
      while (i_ < s_.size() && s_[i_] >= '0' && s_[i_] <= '9') ++i_;
      return i_ > d;
    };
    if (i_ < s_.size() && s_[i_] == '0') {
      ++i_;
    } else if (!digits()) {
      return false;
    }
    if (i_ < s_.size() && s_[i_] == '.' && (++i_, !digits())) return false;
    if (i_ < s_.size() && (s_[i_] == 'e' || s_[i_] == 'E')) {
      ++i_;
      if (i_ < s_.size() && (s_[i_] == '+' || s_[i_] == '-')) ++i_;
      if (!digits()) return false;
    }
    out = s_.substr(start, i_ - start);
    return true;
  }
  bool value(Json& v, int depth) {
    if (depth > 16) return false;
    ws();
    if (i_ >= s_.size()) return false;
    const char c = s_[i_];
    if (c == '{') {
      ++i_;
      v.kind = Json::Object;
      if (eat('}')) return true;
      do {
        std::pair<std::string, Json> m;
        if (!string(m.first) || !eat(':') || !value(m.second, depth + 1)) return false;
        v.members.push_back(std::move(m));
      } while (eat(','));
      return eat('}');
    }
    if (c == '[') {
      ++i_;
      v.kind = Json::Array;
      if (eat(']')) return true;
      do {
        v.items.emplace_back();
        if (!value(v.items.back(), depth + 1)) return false;
      } while (eat(','));
      return eat(']');
    }
    if (c == '"') return v.kind = Json::String, string(v.text);
    if (literal("null")) return v.kind = Json::Null, true;
    if (literal("true")) return v.kind = Json::Bool, v.text = "true", true;
    if (literal("false")) return v.kind = Json::Bool, v.text = "false", true;
    return v.kind = Json::Number, number(v.text);
  }

  const std::string& s_;
  size_t i_ = 0;
};

Json parse(const std::string& text) {
  Json j;
  EXPECT_TRUE(Reader(text).document(j)) << "not JSON:\n" << text.substr(0, 2000);
  return j;
}

// A coordinate as written: a number literal as is, a string in quotes.
std::string token(const Json& v) {
  if (v.kind == Json::Null) return "null";
  return v.kind == Json::String ? "\"" + v.text + "\"" : v.text;
}

// ------------------------------------------------------------------------------------------
// Independent exactness check of a written coordinate, by decimal-string halving (the writer
// multiplies limbs instead): an integer must be m * 2^e, "p/q" must have q = 2^k (k > 0) and p
// odd, and either way the value rebuilt with ldexp (exact here) must be v itself.
void halve(std::string& d) {  // d /= 2 in decimal (d even, not 0)
  int carry = 0;
  for (char& c : d) {
    const int x = carry * 10 + (c - '0');
    c = static_cast<char>('0' + x / 2);
    carry = x % 2;
  }
  if (d[0] == '0') d.erase(0, 1);
}

// Splits a decimal string into odd * 2^twos; false when the odd part exceeds 2^53.
bool oddTimesPowerOfTwo(std::string d, uint64_t& odd, int& twos) {
  twos = 0;
  if (d.empty() || d.find_first_not_of("0123456789") != std::string::npos) return false;
  if (d == "0" || d[0] == '0') return false;  // no zero, no leading zeros
  while ((d.back() - '0') % 2 == 0) {
    halve(d);
    ++twos;
  }
  if (d.size() > 16) return false;
  odd = std::stoull(d);
  return odd < (uint64_t{1} << 53);
}

::testing::AssertionResult exactly(const Json& j, double v) {
  const std::string t = token(j);
  if (v == 0) {
    if (j.kind == Json::Number && j.text == "0") return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "0 written as " << t;
  }
  std::string body = j.text;
  const bool neg = !body.empty() && body[0] == '-';
  if (neg) body.erase(0, 1);
  if (neg != (v < 0)) return ::testing::AssertionFailure() << v << ": sign of " << t;
  uint64_t m = 0;
  int e = 0;
  double back;
  if (j.kind == Json::Number) {
    if (!oddTimesPowerOfTwo(body, m, e))
      return ::testing::AssertionFailure() << v << ": not an integer m*2^e: " << t;
    back = std::ldexp(static_cast<double>(m), e);
  } else if (j.kind == Json::String) {
    const size_t slash = body.find('/');
    uint64_t one = 0;
    int k = 0;
    if (slash == std::string::npos || !oddTimesPowerOfTwo(body.substr(0, slash), m, e) ||
        e != 0 || !oddTimesPowerOfTwo(body.substr(slash + 1), one, k) || one != 1 || k < 1)
      return ::testing::AssertionFailure() << v << ": not \"odd/2^k\" in lowest terms: " << t;
    back = std::ldexp(static_cast<double>(m), -k);
  } else {
    return ::testing::AssertionFailure() << v << ": neither a number nor a string: " << t;
  }
  if (std::fabs(v) != back)
    return ::testing::AssertionFailure() << v << " written as " << t << " (that is " << back
                                         << ")";
  return ::testing::AssertionSuccess();
}

// A solution with one Steiner point at (x, y): vertices 0, 1 from the "instance".
Json oneSteiner(double x, double y) {
  Mesh m;
  m.points = {0, 0, 1, 0, x, y};
  m.triangles = {0, 1, 2};
  return parse(formatCgshopSolution(m, "t", 2));
}

std::string xToken(double x) {
  const Json j = oneSteiner(x, 0.25);
  const Json* xs = j.get("steiner_points_x");
  if (!xs || xs->items.size() != 1) return "(missing)";
  return token(xs->items[0]);
}

// ------------------------------------------------------------------------------------------
// Exact coordinates.

TEST(CgshopCoordinates, SmallValues) {
  EXPECT_EQ(xToken(0.5), "\"1/2\"");
  EXPECT_EQ(xToken(3), "3");
  EXPECT_EQ(xToken(-0.375), "\"-3/8\"");
  EXPECT_EQ(xToken(-7), "-7");
  EXPECT_EQ(xToken(1.5), "\"3/2\"");
  EXPECT_EQ(xToken(123456.75), "\"493827/4\"");
  EXPECT_EQ(xToken(0.0), "0");
  EXPECT_EQ(xToken(-0.0), "0");
  EXPECT_EQ(xToken(1e22), "10000000000000000000000");
}

TEST(CgshopCoordinates, TenthIsItsExactDyadic) {
  EXPECT_EQ(xToken(0.1), "\"3602879701896397/36028797018963968\"");
  EXPECT_EQ(xToken(-0.1), "\"-3602879701896397/36028797018963968\"");
}

// Expected strings: Python's fractions.Fraction(float) of the same doubles.
TEST(CgshopCoordinates, ExtremeValues) {
  EXPECT_EQ(xToken(1e-300),
            "\"6032057205060441/603205720506044084884212454315773567705025225174850578179661506"
            "4961622344493727293370973578138265743708225425014400837164813540499979063179105919"
            "5977669510221933550917078960348506840390590791803967883491060955842900874460764137"
            "7146894047724155067075314551760293122439242402954742999382412988923515814561436497"
            "2941312\"");
  EXPECT_EQ(xToken(1e300),
            "1000000000000000052504760255204420248704468581108159154915854115511802457988908195"
            "7863713750804478640437044438328838781769425232353604305756447921847867069828483872"
            "0092657580373783023379478809005936895323497079994508111903896764088007465274278014"
            "2494579258788820056842838115669472196386865459400540160");
  EXPECT_EQ(xToken(std::numeric_limits<double>::denorm_min()),
            "\"1/202402253307310618352495346718917307049556649764142118356901358027430339567995"
            "3468919603837014371244951870778643168119113898087373857934768670133999407385099215"
            "1742427656636136446690774209321634123976767847274506856200748342469269861810335564"
            "9159556340810056512358769552333414615230502532186327508646006263307707741093494784"
            "\"");
  EXPECT_EQ(xToken(std::numeric_limits<double>::max()),
            "1797693134862315708145274237317043567980705675258449965989174768031572607800285387"
            "6058955863276687817154045895351438246423432132688946418276846754670353751698604991"
            "0576551282076245490090389328944075868508455133942304583236903222948165808559332123"
            "348274797826204144723168738177180919299881250404026184124858368");
  EXPECT_EQ(xToken(-std::numeric_limits<double>::min()),
            "\"-1/44942328371557897693232629769725618340449424473557664318357520289433168951375"
            "2407831771193306018840052800284699678483394146974422036041556232118576598685310944"
            "4197335621637131907555490031152352986327073802125144220953767058561572036847827763"
            "5206809290837627671146574559986811484619929076208839082406056034304\"");
}

// Where the writer switches from 64-bit to big arithmetic.
TEST(CgshopCoordinates, SixtyFourBitBoundaries) {
  EXPECT_EQ(xToken(std::ldexp(1.0, 63)), "9223372036854775808");
  EXPECT_EQ(xToken(std::ldexp(1.0, 64)), "18446744073709551616");
  EXPECT_EQ(xToken(std::ldexp(1.0, -63)), "\"1/9223372036854775808\"");
  EXPECT_EQ(xToken(std::ldexp(1.0, -64)), "\"1/18446744073709551616\"");
  const double m53 = static_cast<double>((uint64_t{1} << 53) - 1);
  EXPECT_EQ(xToken(m53), "9007199254740991");
  EXPECT_EQ(xToken(std::ldexp(m53, 10)), "9223372036854774784");
  EXPECT_EQ(xToken(std::ldexp(m53, 11)), "18446744073709549568");
  EXPECT_EQ(xToken(-std::ldexp(m53, 12)), "-36893488147419099136");
  EXPECT_EQ(xToken(std::ldexp(m53, -53)), "\"9007199254740991/9007199254740992\"");
}

TEST(CgshopCoordinates, RandomDoublesAreExact) {
  std::mt19937_64 rng(2025);
  int checked = 0;
  for (int i = 0; i < 3000; ++i) {
    double v;
    const uint64_t bits = rng();
    std::memcpy(&v, &bits, sizeof v);
    if (!std::isfinite(v)) continue;
    if (i % 3 == 0) v = std::ldexp(std::fmod(std::fabs(v), 1.0) + 1, static_cast<int>(i % 80) - 40);
    const Json j = oneSteiner(v, -v);
    const Json* xs = j.get("steiner_points_x");
    const Json* ys = j.get("steiner_points_y");
    ASSERT_TRUE(xs && ys && xs->items.size() == 1 && ys->items.size() == 1);
    EXPECT_TRUE(exactly(xs->items[0], v));
    EXPECT_TRUE(exactly(ys->items[0], -v));
    ++checked;
  }
  EXPECT_GT(checked, 2900);
}

TEST(CgshopCoordinates, NonFiniteIsNull) {
  // mesh() never makes one; the writer stays valid JSON (the verifier then rejects it).
  EXPECT_EQ(xToken(std::numeric_limits<double>::quiet_NaN()), "null");
  EXPECT_EQ(xToken(-std::numeric_limits<double>::infinity()), "null");
}

// ------------------------------------------------------------------------------------------
// Structure and renumbering.

TEST(CgshopSolution, RenumbersUsedSteinerPointsAndListsEachEdgeOnce) {
  Mesh m;
  // 0..3 instance (3 unused), 4 an unused Steiner point, 5 and 6 used ones.
  m.points = {0, 0, 4, 0, 4, 4, 9, 9, 7, 7, 2, 1, 3.5, 2};
  m.triangles = {0, 1, 5, 1, 2, 6, 1, 6, 5};
  const Json j = parse(formatCgshopSolution(m, "case", 4));
  ASSERT_EQ(j.kind, Json::Object);
  std::vector<std::string> keys;
  for (const auto& kv : j.members) keys.push_back(kv.first);
  EXPECT_EQ(keys, (std::vector<std::string>{"content_type", "instance_uid", "steiner_points_x",
                                            "steiner_points_y", "edges"}));
  EXPECT_EQ(j.get("content_type")->kind, Json::String);
  EXPECT_EQ(j.get("content_type")->text, "CG_SHOP_2025_Solution");
  EXPECT_EQ(j.get("instance_uid")->text, "case");
  std::vector<std::string> xs, ys;
  for (const Json& v : j.get("steiner_points_x")->items) xs.push_back(token(v));
  for (const Json& v : j.get("steiner_points_y")->items) ys.push_back(token(v));
  EXPECT_EQ(xs, (std::vector<std::string>{"2", "\"7/2\""}));
  EXPECT_EQ(ys, (std::vector<std::string>{"1", "2"}));
  std::vector<std::pair<int, int>> edges;
  for (const Json& e : j.get("edges")->items) {
    ASSERT_EQ(e.items.size(), 2u);
    edges.emplace_back(std::stoi(e.items[0].text), std::stoi(e.items[1].text));
  }
  // Vertex 5 -> 4, 6 -> 5.
  EXPECT_EQ(edges, (std::vector<std::pair<int, int>>{
                       {0, 1}, {0, 4}, {1, 2}, {1, 4}, {1, 5}, {2, 5}, {4, 5}}));
}

// Exact points go in as their rationals (an integer as a number); a text that is no rational
// (a C++ caller's mistake) leaves the double, so the solution stays valid JSON.
TEST(CgshopSolution, ExactPointsAsTheirRationals) {
  Mesh m;
  m.points = {0, 0, 4, 0, 4, 4, 2, 1, 3.5, 2};
  m.triangles = {0, 1, 3, 1, 2, 4, 1, 4, 3};
  m.exactPoints = {{3, "7/3", "-2"}, {4, "x", "1/0"}};
  const Json j = parse(formatCgshopSolution(m, "exact", 3));
  ASSERT_EQ(j.kind, Json::Object);
  std::vector<std::string> xs, ys;
  for (const Json& v : j.get("steiner_points_x")->items) xs.push_back(token(v));
  for (const Json& v : j.get("steiner_points_y")->items) ys.push_back(token(v));
  EXPECT_EQ(xs, (std::vector<std::string>{"\"7/3\"", "\"7/2\""}));
  EXPECT_EQ(ys, (std::vector<std::string>{"-2", "2"}));
}

TEST(CgshopSolution, EmptyMeshAndEscapedUid) {
  const std::string uid = "odd \"uid\" \\ with\nnewline\tand tab\x01";
  const Json j = parse(formatCgshopSolution(Mesh{}, uid, 0));
  EXPECT_EQ(j.get("instance_uid")->text, uid);
  EXPECT_TRUE(j.get("steiner_points_x")->items.empty());
  EXPECT_TRUE(j.get("steiner_points_y")->items.empty());
  EXPECT_EQ(j.get("edges")->kind, Json::Array);
  EXPECT_TRUE(j.get("edges")->items.empty());
}

TEST(CgshopSolution, TrianglesWithIndicesOutOfRangeAreSkipped) {
  Mesh m;
  m.points = {0, 0, 1, 0, 0, 1};
  m.triangles = {0, 1, 2, 0, 1, 7};
  const Json j = parse(formatCgshopSolution(m, "x", 3));
  EXPECT_EQ(j.get("edges")->items.size(), 3u);
}

// ------------------------------------------------------------------------------------------
// Meshed instances, read back.

// Checks `text` against mesh `m` of an instance with n0 points; returns the Steiner count.
size_t checkSolution(const std::string& text, const Mesh& m, size_t n0, const std::string& uid,
                     const std::string& what) {
  SCOPED_TRACE(what);
  const Json j = parse(text);
  EXPECT_EQ(j.kind, Json::Object);
  const Json* ct = j.get("content_type");
  const Json* id = j.get("instance_uid");
  const Json* xs = j.get("steiner_points_x");
  const Json* ys = j.get("steiner_points_y");
  const Json* es = j.get("edges");
  if (!ct || !id || !xs || !ys || !es) {
    ADD_FAILURE() << "a key is missing";
    return 0;
  }
  EXPECT_EQ(ct->text, "CG_SHOP_2025_Solution");
  EXPECT_EQ(id->text, uid);

  // The Steiner points the writer must list, in index order.
  const size_t n = m.vertexCount();
  std::vector<char> used(n, 0);
  for (uint32_t v : m.triangles) used[v] = 1;
  std::vector<size_t> newId(n, SIZE_MAX), steiner;
  for (size_t v = 0; v < n; ++v) {
    if (v < n0) {
      newId[v] = v;
      EXPECT_TRUE(used[v]) << "instance vertex " << v << " unused";
    } else if (used[v]) {
      newId[v] = n0 + steiner.size();
      steiner.push_back(v);
    }
  }
  EXPECT_EQ(xs->items.size(), steiner.size());
  EXPECT_EQ(ys->items.size(), steiner.size());
  std::vector<const ExactPoint*> exact(n, nullptr);
  for (const ExactPoint& p : m.exactPoints) exact[p.vertex] = &p;
  for (size_t k = 0; k < steiner.size() && k < xs->items.size() && k < ys->items.size(); ++k) {
    if (const ExactPoint* p = exact[steiner[k]]) {  // its rational: a number if an integer
      const bool integer = p->x.find('/') == std::string::npos;
      EXPECT_EQ(xs->items[k].kind, integer ? Json::Number : Json::String);
      EXPECT_EQ(xs->items[k].text, p->x);
      EXPECT_EQ(ys->items[k].text, p->y);
      continue;
    }
    EXPECT_TRUE(exactly(xs->items[k], m.points[2 * steiner[k]]));
    EXPECT_TRUE(exactly(ys->items[k], m.points[2 * steiner[k] + 1]));
  }

  std::set<std::pair<size_t, size_t>> meshEdges, written;
  for (size_t t = 0; t < m.triangleCount(); ++t)
    for (int k = 0; k < 3; ++k) {
      size_t a = newId[m.triangles[3 * t + k]], b = newId[m.triangles[3 * t + (k + 1) % 3]];
      meshEdges.insert({std::min(a, b), std::max(a, b)});
    }
  const size_t limit = n0 + steiner.size();
  for (const Json& e : es->items) {
    EXPECT_EQ(e.kind, Json::Array);
    EXPECT_EQ(e.items.size(), 2u);
    if (e.items.size() != 2) continue;
    const size_t a = std::stoul(e.items[0].text), b = std::stoul(e.items[1].text);
    EXPECT_LT(a, limit);
    EXPECT_LT(b, limit);
    EXPECT_NE(a, b);
    EXPECT_TRUE(written.insert({std::min(a, b), std::max(a, b)}).second)
        << "edge " << a << "-" << b << " twice";
  }
  EXPECT_EQ(es->items.size(), meshEdges.size());
  EXPECT_EQ(written, meshEdges);  // every triangle edge present, nothing else
  return steiner.size();
}

// Every instance file in dir meshed and its solution read back; returns the file count.
size_t expectEveryInstanceMeshedAndReadBack(const fs::path& dir) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (name.size() > 14 && name.compare(name.size() - 14, 14, ".instance.json") == 0)
      files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  size_t steinerTotal = 0;
  for (const fs::path& f : files) {
    Input in;
    const ParseResult p = readInputFile(f.string(), in);
    EXPECT_TRUE(p.ok) << p.message;
    EXPECT_EQ(in.format, InputFormat::CgshopInstance) << f;
    EXPECT_FALSE(in.instanceUid.empty()) << f;
    const Result r = mesh(in.pslg);
    EXPECT_EQ(r.status, Status::Ok) << f << ": " << r.message;
    EXPECT_TRUE(validate(in.pslg, r.mesh).ok) << f;
    const size_t n0 = in.pslg.vertexCount();
    steinerTotal += checkSolution(formatCgshopSolution(r.mesh, in.instanceUid, n0), r.mesh, n0,
                                  in.instanceUid, f.filename().string());
  }
  testing::Test::RecordProperty("instances", static_cast<int>(files.size()));
  testing::Test::RecordProperty("steiner", static_cast<int>(steinerTotal));
  return files.size();
}

TEST(CgshopSolution, EverySharedInstanceMeshedAndReadBack) {
  ACUTEMESH_NEED_REFERENCE_DATA();
  EXPECT_EQ(expectEveryInstanceMeshedAndReadBack(reference::file("cgshop2025")), 150u);
}

TEST(CgshopSolution, EverySyntheticInstanceMeshedAndReadBack) {
  EXPECT_EQ(expectEveryInstanceMeshedAndReadBack(ACUTEMESH_TEST_DATA "/cgshop"), 8u);
}

// Exact altitude feet (Options::exactFeet) on instances whose boundaries are tilted, where
// input vertices stand close to them: certified with the exact places, each on its segment
// line and within rounding of its double, the solution written with them, and fewer Steiner
// points than without (the double nearest a foot is not one). tests/cli/verify_cgshop.mjs
// checks such solutions on their own (rational arithmetic in JavaScript). The instances are
// dir/NAME.instance.json; together they must have more than minExactPoints exact points.
void expectExactFeetPay(const fs::path& dir, const std::vector<std::string>& names,
                        size_t minExactPoints) {
  namespace detail = acutemesh::detail;
  size_t withFeet = 0, without = 0, exactPoints = 0;
  for (const std::string& name : names) {
    SCOPED_TRACE(name);
    Input in;
    const fs::path path = dir / (name + ".instance.json");
    ASSERT_TRUE(fs::exists(path)) << path;
    ASSERT_TRUE(readInputFile(path.string(), in).ok);
    Options o;
    o.mode = Mode::NonObtuse;
    o.exactSegments = true;
    const Result plain = mesh(in.pslg, o);
    o.exactFeet = true;
    const Result r = mesh(in.pslg, o);
    ASSERT_EQ(r.status, Status::Ok) << r.message;
    ASSERT_EQ(plain.status, Status::Ok) << plain.message;
    EXPECT_TRUE(r.stats.certified);
    EXPECT_EQ(r.stats.obtuse, 0u);
    EXPECT_TRUE(validate(in.pslg, r.mesh, o).ok);
    withFeet += r.stats.steiner, without += plain.stats.steiner;
    exactPoints += r.mesh.exactPoints.size();
    EXPECT_TRUE(plain.mesh.exactPoints.empty());

    // Each exact point: on the line of a segment edge at it, near its double; every triangle
    // at it counter-clockwise and non-obtuse there, exactly.
    const Mesh& m = r.mesh;
    std::vector<detail::RationalPoint> at(m.vertexCount());
    std::vector<char> isExact(m.vertexCount(), 0);
    for (size_t v = 0; v < m.vertexCount(); ++v) at[v] = detail::exactPoint(&m.points[2 * v]);
    for (const ExactPoint& p : m.exactPoints) {
      ASSERT_LT(p.vertex, m.vertexCount());
      ASSERT_TRUE(detail::parseRationalPoint(p.x, p.y, at[p.vertex])) << p.x << ", " << p.y;
      isExact[p.vertex] = 1;
      const double x = at[p.vertex].x.toDouble() / at[p.vertex].w.toDouble();
      const double y = at[p.vertex].y.toDouble() / at[p.vertex].w.toDouble();
      EXPECT_NEAR(x, m.points[2 * p.vertex], 1e-6 * (1 + std::fabs(x)));
      EXPECT_NEAR(y, m.points[2 * p.vertex + 1], 1e-6 * (1 + std::fabs(y)));
      int onLine = 0;
      for (size_t i = 0; i + 1 < m.segments.size(); i += 2) {
        const uint32_t a = m.segments[i], b = m.segments[i + 1];
        if (a != p.vertex && b != p.vertex) continue;
        const uint32_t other = a == p.vertex ? b : a;
        // The segment's line: through the other end and the double's position (both on it).
        onLine += detail::orientSign(detail::exactPoint(&m.points[2 * other]),
                                     detail::exactPoint(&m.points[2 * p.vertex]), at[p.vertex]) == 0;
      }
      EXPECT_GE(onLine, 1) << "exact point " << p.vertex << " off its segment's line";
    }
    size_t checked = 0;
    for (size_t t = 0; t < m.triangleCount(); ++t) {
      const uint32_t* v = &m.triangles[3 * t];
      if (!isExact[v[0]] && !isExact[v[1]] && !isExact[v[2]]) continue;
      ++checked;
      EXPECT_GT(detail::orientSign(at[v[0]], at[v[1]], at[v[2]]), 0) << "triangle " << t;
      for (int k = 0; k < 3; ++k)
        EXPECT_GE(detail::dotSign(at[v[k]], at[v[(k + 1) % 3]], at[v[(k + 2) % 3]]), 0) << "triangle " << t;
    }
    EXPECT_EQ(checked == 0, m.exactPoints.empty());
    const size_t n0 = in.pslg.vertexCount();
    checkSolution(formatCgshopSolution(m, in.instanceUid, n0), m, n0, in.instanceUid, name);
  }
  EXPECT_GT(exactPoints, minExactPoints);
  EXPECT_LT(withFeet * 10, without * 7) << withFeet << " Steiner points with exact feet, " << without
                                        << " without";
  testing::Test::RecordProperty("steiner_exact_feet", static_cast<int>(withFeet));
  testing::Test::RecordProperty("steiner_without", static_cast<int>(without));
}

TEST(CgshopSolution, ExactFeetOnTiltedBoundaries) {
  ACUTEMESH_NEED_REFERENCE_DATA();
  expectExactFeetPay(reference::file("cgshop2025"),
                     {"point-set_250_3c338713", "simple-polygon-exterior_80_d87f15e8",
                      "simple-polygon-exterior-20_100_7ed1ca87", "simple-polygon_100_cb23308c",
                      "ortho_40_56a6f463"},
                     50);
}

// The synthetic point set's bottom and top hull edges are tilted, with rows of points a unit
// or so inside them.
TEST(CgshopSolution, ExactFeetOnSyntheticTiltedBoundaries) {
  expectExactFeetPay(ACUTEMESH_TEST_DATA "/cgshop",
                     {"point-set_120_tilted", "simple-polygon-exterior_50_synthetic"}, 40);
}

// Crossing constraints make rounded crossing points: fractional Steiner coordinates.
TEST(CgshopSolution, CrossingConstraintsGiveExactFractionalSteinerPoints) {
  const std::string text = R"({"instance_uid": "crossings", "num_points": 8,
    "points_x": [0, 100, 100, 0, 10, 80, 20, 90], "points_y": [0, 0, 100, 100, 20, 70, 90, 10],
    "region_boundary": [0, 1, 2, 3], "num_constraints": 3,
    "additional_constraints": [[4, 5], [6, 7], [4, 2]]})";
  Input in;
  const ParseResult p = parseJson(text, "crossings.json", in);
  ASSERT_TRUE(p.ok) << p.message;
  const Result r = mesh(in.pslg);
  ASSERT_EQ(r.status, Status::Ok) << r.message;
  ASSERT_TRUE(validate(in.pslg, r.mesh).ok);
  ASSERT_GT(r.stats.steiner, 0u);
  const std::string out = formatCgshopSolution(r.mesh, in.instanceUid, 8);
  EXPECT_EQ(checkSolution(out, r.mesh, 8, "crossings", "crossings"), r.stats.steiner);
  EXPECT_NE(out.find('/'), std::string::npos) << "expected a fractional coordinate";
}

}  // namespace
