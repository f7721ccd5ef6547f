// Mesh output: Triangle's .node/.ele/.poly/.edge/.neigh, JSON, OFF, OBJ, SVG, Gmsh MSH 4.1 and
// 2.2, VTK's .vtu and the CG:SHOP 2025 solution.
//
// Coordinates are written so that they read back as the same doubles: the shortest
// round-trip form (std::to_chars, or the same text made from printf where the library lacks
// it). Vertex indices
// in .node/.ele/.poly are 0-based (Triangle's -z convention), which each file states in its
// first line; OBJ is 1-based by definition. The CG:SHOP solution writes each coordinate as the
// exact rational the double is (an integer, or "p/q" with q a power of two).
#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <utility>
#include <vector>

#include "acutemesh/io.h"
#include "../exact.h"
#include "outline.h"

#if defined(__cpp_lib_to_chars) && !defined(ACUTEMESH_NO_FLOAT_CHARCONV)
#define ACUTEMESH_FLOAT_TO_CHARS 1
#else
#define ACUTEMESH_FLOAT_TO_CHARS 0
#endif

namespace acutemesh {
namespace {

const char kTriangleHeader[] = "# written by acutemesh, indices 0-based\n";

#if ACUTEMESH_FLOAT_TO_CHARS
void putDouble(std::string& s, double v) {
  char buf[40];
  std::to_chars_result r = std::to_chars(buf, buf + sizeof buf, v);
  s.append(buf, r.ptr);
}
#else
// What std::to_chars(v) writes, for libraries without it (Emscripten's libc++), so that the
// package writes the CLI's very text: the fewest significant digits that read back as v (a
// correctly rounded "%.*e" that does is the shortest), laid out plain or in scientific
// notation, whichever is shorter, plain on a tie.
void putDouble(std::string& s, double v) {
  char buf[48];
  if (!std::isfinite(v)) {
    const int n = std::snprintf(buf, sizeof buf, "%g", v);
    s.append(buf, static_cast<size_t>(n));
    return;
  }
  for (int precision = 0; precision <= 17; ++precision) {
    std::snprintf(buf, sizeof buf, "%.*e", precision, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  // buf is [-]d[.ddd]e(+|-)XX: its digits, without trailing zeros, and the exponent.
  const char* p = buf;
  const bool negative = *p == '-';
  if (negative) ++p;
  std::string digits;
  for (; *p != 'e'; ++p)
    if (*p != '.') digits += *p;
  const int exponent = std::atoi(p + 1);
  while (digits.size() > 1 && digits.back() == '0') digits.pop_back();
  const int count = static_cast<int>(digits.size());
  std::string plain;
  if (exponent < 0) {
    plain = "0." + std::string(static_cast<size_t>(-exponent - 1), '0') + digits;
  } else if (count <= exponent + 1) {  // an integer: to_chars writes its exact digits
    char whole[400];
    const int n = std::snprintf(whole, sizeof whole, "%.0f", std::fabs(v));
    plain.assign(whole, static_cast<size_t>(n));
  } else {
    plain = digits.substr(0, static_cast<size_t>(exponent + 1)) + "." +
            digits.substr(static_cast<size_t>(exponent + 1));
  }
  std::string scientific = digits.substr(0, 1);
  if (count > 1) scientific += "." + digits.substr(1);
  const int magnitude = exponent < 0 ? -exponent : exponent;
  scientific += exponent < 0 ? "e-" : "e+";
  if (magnitude < 10) scientific += '0';
  scientific += std::to_string(magnitude);
  if (negative) s += '-';
  s += plain.size() <= scientific.size() ? plain : scientific;
}
#endif

// JSON has no NaN or infinity: those become null (and are rejected when read back).
void putJsonDouble(std::string& s, double v) {
  if (std::isfinite(v)) {
    putDouble(s, v);
  } else {
    s += "null";
  }
}

void putUint(std::string& s, uint64_t v) {
  char buf[24];
  std::to_chars_result r = std::to_chars(buf, buf + sizeof buf, v);
  s.append(buf, r.ptr);
}

// Rough per-item sizes, to reserve once.
size_t pointsBytes(const Mesh& m) { return m.vertexCount() * 48; }
size_t trianglesBytes(const Mesh& m) { return m.triangleCount() * 40; }

// One numbered point of Triangle's formats: "i x y".
void putPointLine(std::string& s, size_t i, const double* p) {
  putUint(s, i);
  s += ' ';
  putDouble(s, p[0]);
  s += ' ';
  putDouble(s, p[1]);
  s += '\n';
}

void putInt(std::string& s, int64_t v) {
  if (v < 0) s += '-';
  putUint(s, v < 0 ? 0 - static_cast<uint64_t>(v) : static_cast<uint64_t>(v));
}

uint64_t edgeKey(uint32_t a, uint32_t b) {
  return static_cast<uint64_t>(std::min(a, b)) << 32 | std::max(a, b);
}

// Whether the mesh has a region attribute per triangle to write (finite ones: they are sorted
// into Gmsh's groups).
bool hasAttributes(const Mesh& m) {
  const std::vector<double>& a = m.triangleAttributes;
  return !a.empty() && a.size() == m.triangleCount() &&
         std::all_of(a.begin(), a.end(), [](double v) { return std::isfinite(v); });
}

// adjacency() of a mesh whose triangles name its vertices; nothing for one that does not (a
// writer is handed any mesh, and adjacency() indexes by vertex).
Adjacency adjacencyOf(const Mesh& m) {
  for (size_t i = 0; i < m.triangleCount() * 3; ++i)
    if (m.triangles[i] >= m.vertexCount()) return {};
  return adjacency(m);
}

// What the solver formats say besides the triangles. Markers are the mesh's own when it has
// one per item, else Triangle's defaults (0 inside, 1 on the boundary); either way a zero
// marker on the boundary becomes 1 (Triangle's rule, as adjacency() gives edges).
struct Marked {
  Adjacency adj;
  std::vector<int32_t> vertex;  // per vertex
  // a, b per line: the mesh's segment edges in order, then its boundary edges on no segment
  // (a hull kept), so that a solver finds every boundary edge among them.
  std::vector<uint32_t> lines;
  std::vector<int32_t> line;  // marker per line
  const std::vector<double>* attributes = nullptr;  // one per triangle, or none
  bool defaults = true;  // every marker is the one a mesh without markers gets

  explicit Marked(const Mesh& m) : adj(adjacencyOf(m)) {
    const size_t n = m.vertexCount();
    std::vector<uint64_t> boundary;
    std::vector<char> onBoundary(n, 0);
    for (size_t l = 0; l + 1 < adj.hullStarts.size(); ++l) {
      const uint32_t first = adj.hullStarts[l], end = adj.hullStarts[l + 1];
      for (uint32_t i = first; i < end; ++i) {
        onBoundary[adj.hull[i]] = 1;
        boundary.push_back(edgeKey(adj.hull[i], adj.hull[i + 1 < end ? i + 1 : first]));
      }
    }
    std::sort(boundary.begin(), boundary.end());
    auto has = [](const std::vector<uint64_t>& keys, uint64_t k) {
      return std::binary_search(keys.begin(), keys.end(), k);
    };
    const bool given = m.vertexMarkers.size() == n;
    vertex.resize(n);
    for (size_t v = 0; v < n; ++v) {
      const int32_t own = given ? m.vertexMarkers[v] : 0;
      vertex[v] = own == 0 && onBoundary[v] ? 1 : own;
      defaults = defaults && vertex[v] == onBoundary[v];
    }
    // A segment edge's marker as adjacency() gives its edge (the rule applied); the mesh's own
    // for an edge no triangle has.
    const size_t e = m.segments.size() / 2, edges = adj.edgeMarkers.size();
    std::vector<uint64_t> segmentKeys;
    for (size_t i = 0; i < e; ++i) {
      const uint32_t a = m.segments[2 * i], b = m.segments[2 * i + 1];
      const uint64_t k = edgeKey(a, b);
      segmentKeys.push_back(k);
      size_t lo = 0, hi = edges;  // the edge in adj.edges (sorted by key)
      while (lo < hi) {
        const size_t mid = (lo + hi) / 2;
        if (edgeKey(adj.edges[2 * mid], adj.edges[2 * mid + 1]) < k) lo = mid + 1; else hi = mid;
      }
      const bool found = lo < edges && edgeKey(adj.edges[2 * lo], adj.edges[2 * lo + 1]) == k;
      const int32_t own = m.segmentMarkers.size() == e ? m.segmentMarkers[i] : 0;
      lines.insert(lines.end(), {a, b});
      line.push_back(found ? adj.edgeMarkers[lo] : own);
      defaults = defaults && line.back() == (has(boundary, k) ? 1 : 0);
    }
    std::sort(segmentKeys.begin(), segmentKeys.end());
    for (size_t l = 0; l + 1 < adj.hullStarts.size(); ++l) {
      const uint32_t first = adj.hullStarts[l], end = adj.hullStarts[l + 1];
      for (uint32_t i = first; i < end; ++i) {
        const uint32_t a = adj.hull[i], b = adj.hull[i + 1 < end ? i + 1 : first];
        if (has(segmentKeys, edgeKey(a, b))) continue;
        lines.insert(lines.end(), {a, b});
        line.push_back(1);
      }
    }
    if (hasAttributes(m)) attributes = &m.triangleAttributes;
  }
};

// Triangle's vertex section, with the boundary marker column.
void putNodeSection(std::string& s, const Mesh& m, const Marked& marked) {
  const size_t n = m.vertexCount();
  putUint(s, n);
  s += " 2 0 1\n";
  for (size_t i = 0; i < n; ++i) {
    putPointLine(s, i, &m.points[2 * i]);
    s.back() = ' ';
    putInt(s, marked.vertex[i]);
    s += '\n';
  }
}

// Each distinct value of `values` once, in increasing order.
template <class T>
std::vector<T> distinct(std::vector<T> values) {
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  return values;
}

// Gmsh physical tags for distinct sorted values: the value itself when it is a positive
// integer a tag holds (an int32), the others numbered on from the largest such tag.
std::vector<int64_t> physicalTags(const std::vector<double>& values) {
  const auto own = [](double v) { return v >= 1 && v <= 2147483647.0 && v == std::floor(v); };
  int64_t next = 1;
  for (double v : values)
    if (own(v)) next = std::max(next, static_cast<int64_t>(v) + 1);
  std::vector<int64_t> tags;
  for (double v : values) tags.push_back(own(v) ? static_cast<int64_t>(v) : next++);
  return tags;
}

// Where a value sits in a sorted list that holds it.
template <class T>
size_t indexIn(const std::vector<T>& sorted, T v) {
  return static_cast<size_t>(std::lower_bound(sorted.begin(), sorted.end(), v) - sorted.begin());
}

// The Gmsh view of a mesh (both MSH versions): one surface per region attribute (one in all
// without attributes, physical group 1 "domain", so that tools which keep only physical
// elements keep the triangles), one curve per line marker, a physical group per attribute and
// per marker. Every element is in a group: meshio's MSH 4.1 reader fails on an entity with
// none, and so marker 0 (inner segments without a marker) has one too.
struct GmshGroups {
  std::vector<double> attributes;  // distinct, sorted: surface k + 1 has attributes[k]
  std::vector<int64_t> surfaceTags;  // its physical tag
  std::vector<int32_t> markers;    // distinct, sorted: curve k + 1 has markers[k]
  std::vector<int64_t> curveTags;  // its physical tag
  std::vector<uint32_t> surfaceOf, curveOf;  // per triangle, per line: its entity tag

  GmshGroups(const Mesh& m, const Marked& marked) {
    const size_t t = m.triangleCount();
    attributes = marked.attributes ? distinct(*marked.attributes) : std::vector<double>{};
    surfaceTags = marked.attributes ? physicalTags(attributes) : std::vector<int64_t>{1};
    for (size_t i = 0; i < t; ++i)
      surfaceOf.push_back(marked.attributes
                              ? static_cast<uint32_t>(indexIn(attributes, (*marked.attributes)[i]) + 1)
                              : 1);
    markers = distinct(marked.line);
    curveTags = physicalTags(std::vector<double>(markers.begin(), markers.end()));
    for (int32_t v : marked.line) curveOf.push_back(static_cast<uint32_t>(indexIn(markers, v) + 1));
  }

  // $PhysicalNames: "attribute A" per surface ("domain" without attributes), "marker M" per
  // curve.
  void putPhysicalNames(std::string& s) const {
    s += "$PhysicalNames\n";
    putUint(s, surfaceTags.size() + curveTags.size());
    s += '\n';
    for (size_t k = 0; k < surfaceTags.size(); ++k) {
      s += "2 ";
      putInt(s, surfaceTags[k]);
      if (attributes.empty()) {
        s += " \"domain\"\n";
      } else {
        s += " \"attribute ";
        putDouble(s, attributes[k]);
        s += "\"\n";
      }
    }
    for (size_t k = 0; k < markers.size(); ++k) {
      s += "1 ";
      putInt(s, curveTags[k]);
      s += " \"marker ";
      putInt(s, markers[k]);
      s += "\"\n";
    }
    s += "$EndPhysicalNames\n";
  }
};

// The bounding box of the finite points: minX, minY, maxX, maxY (all 0 when there are none).
std::array<double, 4> boundsOf(const Mesh& m) {
  std::array<double, 4> box{0, 0, 0, 0};
  bool any = false;
  for (size_t i = 0; i < m.vertexCount(); ++i) {
    const double x = m.points[2 * i], y = m.points[2 * i + 1];
    if (!std::isfinite(x) || !std::isfinite(y)) continue;
    if (!any) box = {x, y, x, y};
    box = {std::min(box[0], x), std::min(box[1], y), std::max(box[2], x), std::max(box[3], y)};
    any = true;
  }
  return box;
}

// Fixed-point with up to 2 decimals, trailing zeros dropped (SVG only: small, not exact).
void putShort(std::string& s, double v) {
  char buf[40];
  int n = std::snprintf(buf, sizeof buf, "%.2f", v);
  if (n <= 0 || n >= static_cast<int>(sizeof buf)) return;
  while (n > 0 && buf[n - 1] == '0') --n;
  if (n > 0 && buf[n - 1] == '.') --n;
  if (n == 2 && buf[0] == '-' && buf[1] == '0') {
    buf[0] = '0';
    n = 1;
  }
  s.append(buf, static_cast<size_t>(n));
}

// JSON string: quotes, backslashes and control characters escaped; other bytes as they are.
void putJsonString(std::string& s, const std::string& v) {
  s += '"';
  for (const char c : v) {
    if (c == '"' || c == '\\') {
      s += '\\';
      s += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(c));
      s += buf;
    } else {
      s += c;
    }
  }
  s += '"';
}

// Decimal digits of mant * 2^exp2 (exp2 >= 0), exactly, for any double's range: base 10^9
// limbs, least significant first, multiplied by at most 2^30 at a time (a limb times 2^30
// plus the carry stays below 2^61).
void putBigDecimal(std::string& s, uint64_t mant, int exp2) {
  const uint32_t kBase = 1000000000;
  std::vector<uint32_t> limbs;
  for (uint64_t v = mant; v; v /= kBase) limbs.push_back(static_cast<uint32_t>(v % kBase));
  if (limbs.empty()) limbs.push_back(0);
  while (exp2 > 0) {
    const int step = std::min(exp2, 30);
    uint64_t carry = 0;
    for (uint32_t& l : limbs) {
      const uint64_t t = (static_cast<uint64_t>(l) << step) + carry;
      l = static_cast<uint32_t>(t % kBase);
      carry = t / kBase;
    }
    for (; carry; carry /= kBase) limbs.push_back(static_cast<uint32_t>(carry % kBase));
    exp2 -= step;
  }
  putUint(s, limbs.back());
  for (size_t i = limbs.size() - 1; i-- > 0;) {
    char buf[16];
    const int n = std::snprintf(buf, sizeof buf, "%09u", static_cast<unsigned>(limbs[i]));
    s.append(buf, static_cast<size_t>(n));
  }
}

// mant * 2^exp2 (exp2 >= 0) in decimal: 64-bit when it fits, else the big routine.
void putScaled(std::string& s, uint64_t mant, int exp2) {
  int bits = 0;
  for (uint64_t v = mant; v; v >>= 1) ++bits;
  if (bits + exp2 <= 64) {
    putUint(s, mant << exp2);
  } else {
    putBigDecimal(s, mant, exp2);
  }
}

// A double exactly, as CG:SHOP 2025 solutions take coordinates: a JSON integer when the value
// is one (-0 is 0), else the string "p/q" in lowest terms (q a power of two, p odd). A finite
// double is m * 2^e with m < 2^53; trailing zero bits of m move into e. Non-finite: null.
void putExactRational(std::string& s, double v) {
  if (!std::isfinite(v)) {
    s += "null";
    return;
  }
  if (v == 0) {
    s += '0';
    return;
  }
  int e = 0;
  const double f = std::frexp(std::fabs(v), &e);  // |v| = f * 2^e, f in [0.5, 1)
  uint64_t mant = static_cast<uint64_t>(std::ldexp(f, 53));  // exact: 53 bits
  int exp2 = e - 53;
  while ((mant & 1) == 0) {
    mant >>= 1;
    ++exp2;
  }
  if (exp2 >= 0) {
    if (v < 0) s += '-';
    putScaled(s, mant, exp2);
    return;
  }
  s += v < 0 ? "\"-" : "\"";
  putUint(s, mant);
  s += '/';
  putScaled(s, 1, -exp2);  // 2^-exp2, up to 2^1074
  s += '"';
}

bool writeFile(const std::string& path, const std::string& text, std::string& error) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) {
    error = path + ": cannot write (" + std::strerror(errno) + ")";
    return false;
  }
  const size_t put = text.empty() ? 0 : std::fwrite(text.data(), 1, text.size(), f);
  int err = put == text.size() ? 0 : errno;
  if (std::fclose(f) != 0 && err == 0) err = errno ? errno : EIO;
  if (put != text.size() || err != 0) {
    error = path + ": cannot write (" + std::strerror(err ? err : EIO) + ")";
    return false;
  }
  return true;
}

}  // namespace

std::string formatNode(const Mesh& m) {
  std::string s;
  s.reserve(pointsBytes(m) + 64);
  s += kTriangleHeader;
  putNodeSection(s, m, Marked(m));
  return s;
}

std::string formatEle(const Mesh& m) {
  std::string s;
  s.reserve(trianglesBytes(m) + 64);
  s += kTriangleHeader;
  const size_t t = m.triangleCount();
  const bool attributes = hasAttributes(m);
  putUint(s, t);
  s += attributes ? " 3 1\n" : " 3 0\n";
  for (size_t i = 0; i < t; ++i) {
    putUint(s, i);
    for (int k = 0; k < 3; ++k) {
      s += ' ';
      putUint(s, m.triangles[3 * i + k]);
    }
    if (attributes) {
      s += ' ';
      putDouble(s, m.triangleAttributes[i]);
    }
    s += '\n';
  }
  return s;
}

// The mesh's segment edges, then its boundary edges on none (a hull kept), and a point in
// each hole: read back with fill 'triangle', the domain is the mesh's own.
std::string formatPoly(const Mesh& m) {
  const io::Outline outline = io::outlineOf(m);
  const Marked marked(m);
  std::string s;
  const size_t e = m.segments.size() / 2, extra = outline.boundary.size() / 2;
  const size_t holes = outline.holes.size() / 2;
  s.reserve(pointsBytes(m) + (e + extra) * 32 + holes * 48 + 64);
  s += kTriangleHeader;
  putNodeSection(s, m, marked);
  putUint(s, e + extra);
  s += " 1\n";
  for (size_t i = 0; i < e + extra; ++i) {
    const uint32_t* ab = i < e ? &m.segments[2 * i] : &outline.boundary[2 * (i - e)];
    if (i == e) s += "# boundary edges on no input segment\n";
    putUint(s, i);
    s += ' ';
    putUint(s, ab[0]);
    s += ' ';
    putUint(s, ab[1]);
    s += ' ';
    putInt(s, i < e ? marked.line[i] : 1);  // (a boundary edge: 1)
    s += '\n';
  }
  putUint(s, holes);
  s += '\n';
  for (size_t i = 0; i < holes; ++i) putPointLine(s, i, &outline.holes[2 * i]);
  return s;
}

std::string formatJson(const Mesh& m) {
  std::string s;
  s.reserve(pointsBytes(m) + trianglesBytes(m) + m.segments.size() * 16 + 64);
  s += "{\n\"vertices\": [";
  const size_t n = m.vertexCount();
  for (size_t i = 0; i < n; ++i) {
    s += i ? ",\n[" : "\n[";
    putJsonDouble(s, m.points[2 * i]);
    s += ',';
    putJsonDouble(s, m.points[2 * i + 1]);
    s += ']';
  }
  s += "],\n\"triangles\": [";
  const size_t t = m.triangleCount();
  for (size_t i = 0; i < t; ++i) {
    s += i ? ",\n[" : "\n[";
    putUint(s, m.triangles[3 * i]);
    s += ',';
    putUint(s, m.triangles[3 * i + 1]);
    s += ',';
    putUint(s, m.triangles[3 * i + 2]);
    s += ']';
  }
  // Segments and holes as formatPoly writes them: the file reads back as the same domain.
  const io::Outline outline = io::outlineOf(m);
  s += "],\n\"segments\": [";
  const size_t e = m.segments.size() / 2, extra = outline.boundary.size() / 2;
  for (size_t i = 0; i < e + extra; ++i) {
    const uint32_t* ab = i < e ? &m.segments[2 * i] : &outline.boundary[2 * (i - e)];
    s += i ? ",\n[" : "\n[";
    putUint(s, ab[0]);
    s += ',';
    putUint(s, ab[1]);
    s += ']';
  }
  s += ']';
  if (!outline.holes.empty()) {
    s += ",\n\"holes\": [";
    for (size_t i = 0; i < outline.holes.size() / 2; ++i) {
      s += i ? ",\n[" : "\n[";
      putJsonDouble(s, outline.holes[2 * i]);
      s += ',';
      putJsonDouble(s, outline.holes[2 * i + 1]);
      s += ']';
    }
    s += ']';
  }
  // Markers only when some differ from what a reader gives a file without them (0 inside, 1
  // on the boundary); one per "segments" entry, the boundary edges on no segment 1.
  const Marked marked(m);
  if (!marked.defaults) {
    s += ",\n\"vertexMarkers\": [";
    for (size_t i = 0; i < n; ++i) {
      if (i) s += ',';
      putInt(s, marked.vertex[i]);
    }
    s += "],\n\"segmentMarkers\": [";
    for (size_t i = 0; i < e + extra; ++i) {
      if (i) s += ',';
      putInt(s, i < e ? marked.line[i] : 1);
    }
    s += ']';
  }
  if (marked.attributes) {
    s += ",\n\"triangleAttributes\": [";
    for (size_t i = 0; i < t; ++i) {
      if (i) s += ',';
      putJsonDouble(s, m.triangleAttributes[i]);
    }
    s += ']';
  }
  if (!m.exactPoints.empty()) {
    s += ",\n\"exactPoints\": [";
    for (size_t i = 0; i < m.exactPoints.size(); ++i) {
      s += i ? ",\n[" : "\n[";
      putUint(s, m.exactPoints[i].vertex);
      s += ',';
      putJsonString(s, m.exactPoints[i].x);
      s += ',';
      putJsonString(s, m.exactPoints[i].y);
      s += ']';
    }
    s += ']';
  }
  s += "\n}\n";
  return s;
}

std::string formatOff(const Mesh& m) {
  std::string s;
  s.reserve(pointsBytes(m) + trianglesBytes(m) + 64);
  const size_t n = m.vertexCount(), t = m.triangleCount();
  s += "OFF\n";
  putUint(s, n);
  s += ' ';
  putUint(s, t);
  s += " 0\n";
  for (size_t i = 0; i < n; ++i) {
    putDouble(s, m.points[2 * i]);
    s += ' ';
    putDouble(s, m.points[2 * i + 1]);
    s += " 0\n";
  }
  for (size_t i = 0; i < t; ++i) {
    s += '3';
    for (int k = 0; k < 3; ++k) {
      s += ' ';
      putUint(s, m.triangles[3 * i + k]);
    }
    s += '\n';
  }
  return s;
}

std::string formatObj(const Mesh& m) {
  std::string s;
  s.reserve(pointsBytes(m) + trianglesBytes(m) + 64);
  s += "# written by acutemesh\n";
  const size_t n = m.vertexCount(), t = m.triangleCount();
  for (size_t i = 0; i < n; ++i) {
    s += "v ";
    putDouble(s, m.points[2 * i]);
    s += ' ';
    putDouble(s, m.points[2 * i + 1]);
    s += " 0\n";
  }
  for (size_t i = 0; i < t; ++i) {
    s += 'f';
    for (int k = 0; k < 3; ++k) {
      s += ' ';
      putUint(s, static_cast<uint64_t>(m.triangles[3 * i + k]) + 1);
    }
    s += '\n';
  }
  return s;
}

std::string formatSvg(const Mesh& m) {
  // Fit the bounding box into a 1000-unit square (aspect kept), y flipped to point up.
  const size_t n = m.vertexCount();
  const std::array<double, 4> box = boundsOf(m);
  const double minX = box[0], minY = box[1], maxX = box[2], maxY = box[3];
  const double extent = std::max(maxX - minX, maxY - minY);
  const double size = 1000.0;
  const double scale = extent > 0 && std::isfinite(extent) ? size / extent : 1.0;
  const double w = (maxX - minX) * scale, h = (maxY - minY) * scale;
  const double margin = 10.0;
  auto px = [&](uint32_t v) { return (m.points[2 * v] - minX) * scale; };
  auto py = [&](uint32_t v) { return (maxY - m.points[2 * v + 1]) * scale; };

  std::string s;
  s.reserve(m.triangleCount() * 48 + m.segments.size() * 16 + 512);
  s += "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"";
  putShort(s, -margin);
  s += ' ';
  putShort(s, -margin);
  s += ' ';
  putShort(s, w + 2 * margin);
  s += ' ';
  putShort(s, h + 2 * margin);
  s += "\">\n<path fill=\"#dde6f3\" stroke=\"#1f3b63\" stroke-width=\"0.6\" "
       "stroke-linejoin=\"round\" d=\"";
  const size_t t = m.triangleCount();
  for (size_t i = 0; i < t; ++i) {
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = m.triangles[3 * i + k];
      if (v >= n) continue;
      s += k ? 'L' : 'M';
      putShort(s, px(v));
      s += ' ';
      putShort(s, py(v));
    }
    s += 'Z';
  }
  s += "\"/>\n<path fill=\"none\" stroke=\"#c8102e\" stroke-width=\"2\" "
       "stroke-linecap=\"round\" d=\"";
  const size_t e = m.segments.size() / 2;
  for (size_t i = 0; i < e; ++i) {
    const uint32_t a = m.segments[2 * i], b = m.segments[2 * i + 1];
    if (a >= n || b >= n) continue;
    s += 'M';
    putShort(s, px(a));
    s += ' ';
    putShort(s, py(a));
    s += 'L';
    putShort(s, px(b));
    s += ' ';
    putShort(s, py(b));
  }
  s += "\"/>\n</svg>\n";
  return s;
}

// Every edge once (as adjacency() sorts them) with its marker.
std::string formatEdge(const Mesh& m) {
  const Adjacency adj = adjacencyOf(m);
  const size_t e = adj.edgeMarkers.size();
  std::string s;
  s.reserve(e * 32 + 64);
  s += kTriangleHeader;
  putUint(s, e);
  s += " 1\n";
  for (size_t i = 0; i < e; ++i) {
    putUint(s, i);
    s += ' ';
    putUint(s, adj.edges[2 * i]);
    s += ' ';
    putUint(s, adj.edges[2 * i + 1]);
    s += ' ';
    putInt(s, adj.edgeMarkers[i]);
    s += '\n';
  }
  return s;
}

// Neighbour k of triangle t lies opposite its corner k; -1 for none.
std::string formatNeigh(const Mesh& m) {
  const Adjacency adj = adjacencyOf(m);
  const size_t t = adj.neighbors.size() / 3;
  std::string s;
  s.reserve(trianglesBytes(m) + 64);
  s += kTriangleHeader;
  putUint(s, t);
  s += " 3\n";
  for (size_t i = 0; i < t; ++i) {
    putUint(s, i);
    for (int k = 0; k < 3; ++k) {
      s += ' ';
      putInt(s, adj.neighbors[3 * i + k]);
    }
    s += '\n';
  }
  return s;
}

namespace {

// "x y 0": a point in 3D, as Gmsh and VTK take them.
void putPoint3(std::string& s, const double* p) {
  putDouble(s, p[0]);
  s += ' ';
  putDouble(s, p[1]);
  s += " 0\n";
}

// One element's nodes, 1-based.
void putNodes1(std::string& s, const uint32_t* v, int count) {
  for (int k = 0; k < count; ++k) {
    s += ' ';
    putUint(s, static_cast<uint64_t>(v[k]) + 1);
  }
  s += '\n';
}

}  // namespace

// Gmsh MSH 4.1: every vertex a node (tag = index + 1, unused ones too, in one block on surface
// 1), triangle i element i + 1, line j element T + j + 1; one element block per entity.
std::string formatMsh(const Mesh& m) {
  const Marked marked(m);
  const GmshGroups g(m, marked);
  const size_t n = m.vertexCount(), t = m.triangleCount(), lines = marked.line.size();
  const std::array<double, 4> box = boundsOf(m);
  std::string s;
  s.reserve(pointsBytes(m) + trianglesBytes(m) + lines * 32 + 512);
  s += "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  g.putPhysicalNames(s);
  s += "$Entities\n0 ";
  putUint(s, g.markers.size());
  s += ' ';
  putUint(s, g.surfaceTags.size());
  s += " 0\n";
  // Each entity's box is the mesh's: a bounding box, if not the tightest.
  auto putEntity = [&](size_t tag, int64_t physical) {
    putUint(s, tag);
    for (int k = 0; k < 4; ++k) {
      s += ' ';
      putDouble(s, box[k]);
      if (k % 2) s += " 0";
    }
    s += " 1 ";
    putInt(s, physical);
    s += " 0\n";  // no bounding entities
  };
  for (size_t k = 0; k < g.markers.size(); ++k) putEntity(k + 1, g.curveTags[k]);
  for (size_t k = 0; k < g.surfaceTags.size(); ++k) putEntity(k + 1, g.surfaceTags[k]);
  // A section's first line: its blocks, its items, their first and last tags (1..count).
  auto putCounts = [&](size_t blocks, size_t count) {
    putUint(s, blocks);
    s += ' ';
    putUint(s, count);
    s += count ? " 1 " : " 0 ";
    putUint(s, count);
    s += '\n';
  };
  s += "$EndEntities\n$Nodes\n";
  putCounts(n ? 1 : 0, n);
  if (n) {
    s += "2 1 0 ";
    putUint(s, n);
    s += '\n';
    for (size_t i = 0; i < n; ++i) {
      putUint(s, i + 1);
      s += '\n';
    }
    for (size_t i = 0; i < n; ++i) putPoint3(s, &m.points[2 * i]);
  }
  s += "$EndNodes\n$Elements\n";
  // Blocks: the surfaces' triangles, then the curves' lines, empty ones left out.
  auto byEntity = [](const std::vector<uint32_t>& entityOf, size_t entities) {
    std::vector<std::vector<size_t>> members(entities);
    for (size_t i = 0; i < entityOf.size(); ++i) members[entityOf[i] - 1].push_back(i);
    return members;
  };
  const std::vector<std::vector<size_t>> surfaces = byEntity(g.surfaceOf, g.surfaceTags.size());
  const std::vector<std::vector<size_t>> curves = byEntity(g.curveOf, g.markers.size());
  size_t blocks = 0;
  for (const auto* list : {&surfaces, &curves})
    for (const std::vector<size_t>& members : *list) blocks += !members.empty();
  putCounts(blocks, t + lines);
  // Element i of a dimension: tag firstTag + i, `corners` vertices from v[corners * i].
  auto putBlocks = [&](const std::vector<std::vector<size_t>>& entities, int dim, size_t firstTag,
                       const uint32_t* v, int corners) {
    for (size_t k = 0; k < entities.size(); ++k) {
      if (entities[k].empty()) continue;
      putUint(s, static_cast<uint64_t>(dim));
      s += ' ';
      putUint(s, k + 1);
      s += dim == 2 ? " 2 " : " 1 ";  // element types: 3-node triangle, 2-node line
      putUint(s, entities[k].size());
      s += '\n';
      for (size_t i : entities[k]) {
        putUint(s, firstTag + i);
        putNodes1(s, v + static_cast<size_t>(corners) * i, corners);
      }
    }
  };
  putBlocks(surfaces, 2, 1, m.triangles.data(), 3);
  putBlocks(curves, 1, t + 1, marked.lines.data(), 2);
  s += "$EndElements\n";
  return s;
}

// Gmsh MSH 2.2: nodes and elements numbered as in formatMsh, each element with its physical
// tag and its entity's tag.
std::string formatMsh2(const Mesh& m) {
  const Marked marked(m);
  const GmshGroups g(m, marked);
  const size_t n = m.vertexCount(), t = m.triangleCount(), lines = marked.line.size();
  std::string s;
  s.reserve(pointsBytes(m) + trianglesBytes(m) + lines * 32 + 256);
  s += "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
  g.putPhysicalNames(s);
  s += "$Nodes\n";
  putUint(s, n);
  s += '\n';
  for (size_t i = 0; i < n; ++i) {
    putUint(s, i + 1);
    s += ' ';
    putPoint3(s, &m.points[2 * i]);
  }
  s += "$EndNodes\n$Elements\n";
  putUint(s, t + lines);
  s += '\n';
  for (size_t i = 0; i < t; ++i) {
    putUint(s, i + 1);
    s += " 2 2 ";
    putInt(s, g.surfaceTags[g.surfaceOf[i] - 1]);
    s += ' ';
    putUint(s, g.surfaceOf[i]);
    putNodes1(s, &m.triangles[3 * i], 3);
  }
  for (size_t j = 0; j < lines; ++j) {
    putUint(s, t + j + 1);
    s += " 1 2 ";
    putInt(s, g.curveTags[g.curveOf[j] - 1]);
    s += ' ';
    putUint(s, g.curveOf[j]);
    putNodes1(s, &marked.lines[2 * j], 2);
  }
  s += "$EndElements\n";
  return s;
}

// VTK XML unstructured grid, ASCII: the triangles, then the lines, as cells.
std::string formatVtu(const Mesh& m) {
  const Marked marked(m);
  const size_t n = m.vertexCount(), t = m.triangleCount(), lines = marked.line.size();
  std::string s;
  s.reserve(pointsBytes(m) + 2 * trianglesBytes(m) + lines * 48 + 1024);
  s += "<?xml version=\"1.0\"?>\n"
       "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
       "<UnstructuredGrid>\n<Piece NumberOfPoints=\"";
  putUint(s, n);
  s += "\" NumberOfCells=\"";
  putUint(s, t + lines);
  s += "\">\n<PointData>\n<DataArray type=\"Int32\" Name=\"marker\" format=\"ascii\">\n";
  for (size_t i = 0; i < n; ++i) {
    putInt(s, marked.vertex[i]);
    s += '\n';
  }
  s += "</DataArray>\n</PointData>\n<CellData>\n";
  if (marked.attributes) {
    s += "<DataArray type=\"Float64\" Name=\"attribute\" format=\"ascii\">\n";
    for (size_t i = 0; i < t; ++i) {
      putDouble(s, m.triangleAttributes[i]);
      s += '\n';
    }
    for (size_t j = 0; j < lines; ++j) s += "0\n";
    s += "</DataArray>\n";
  }
  s += "<DataArray type=\"Int32\" Name=\"marker\" format=\"ascii\">\n";
  for (size_t i = 0; i < t; ++i) s += "0\n";
  for (size_t j = 0; j < lines; ++j) {
    putInt(s, marked.line[j]);
    s += '\n';
  }
  s += "</DataArray>\n</CellData>\n<Points>\n"
       "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (size_t i = 0; i < n; ++i) putPoint3(s, &m.points[2 * i]);
  s += "</DataArray>\n</Points>\n<Cells>\n"
       "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  auto putCell = [&](const uint32_t* v, int count) {
    for (int k = 0; k < count; ++k) {
      if (k) s += ' ';
      putUint(s, v[k]);
    }
    s += '\n';
  };
  for (size_t i = 0; i < t; ++i) putCell(&m.triangles[3 * i], 3);
  for (size_t j = 0; j < lines; ++j) putCell(&marked.lines[2 * j], 2);
  s += "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (size_t i = 0; i < t + lines; ++i) {
    putUint(s, i < t ? 3 * (i + 1) : 3 * t + 2 * (i - t + 1));
    s += '\n';
  }
  s += "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (size_t i = 0; i < t + lines; ++i) s += i < t ? "5\n" : "3\n";  // VTK_TRIANGLE, VTK_LINE
  s += "</DataArray>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  return s;
}

std::string formatCgshopSolution(const Mesh& m, const std::string& instanceUid,
                                 size_t instanceVertexCount) {
  const size_t n = m.vertexCount(), t = m.triangleCount();
  auto valid = [&](size_t i) {
    return m.triangles[3 * i] < n && m.triangles[3 * i + 1] < n && m.triangles[3 * i + 2] < n;
  };
  // Steiner points: vertices from instanceVertexCount on that some triangle uses, renumbered
  // instanceVertexCount + k in index order; instance vertices keep their index.
  std::vector<uint32_t> id(n);
  std::vector<char> used(n, 0);
  for (size_t i = 0; i < t; ++i)
    if (valid(i))
      for (int k = 0; k < 3; ++k) used[m.triangles[3 * i + k]] = 1;
  std::vector<uint32_t> steiner;
  for (size_t v = 0; v < n; ++v) {
    if (v < instanceVertexCount) {
      id[v] = static_cast<uint32_t>(v);
    } else if (used[v]) {
      id[v] = static_cast<uint32_t>(instanceVertexCount + steiner.size());
      steiner.push_back(static_cast<uint32_t>(v));
    }
  }
  // Each undirected edge once, as (smaller, larger) new index, sorted.
  std::vector<uint64_t> edges;
  edges.reserve(3 * t);
  for (size_t i = 0; i < t; ++i) {
    if (!valid(i)) continue;
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = id[m.triangles[3 * i + k]], b = id[m.triangles[3 * i + (k + 1) % 3]];
      if (a == b) continue;
      edges.push_back(static_cast<uint64_t>(std::min(a, b)) << 32 | std::max(a, b));
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());

  std::string s;
  s.reserve(steiner.size() * 64 + edges.size() * 24 + instanceUid.size() + 160);
  s += "{\n\"content_type\": \"CG_SHOP_2025_Solution\",\n\"instance_uid\": ";
  putJsonString(s, instanceUid);
  // Exact points (Options::exactFeet) as their rationals, sorted by vertex.
  std::vector<const ExactPoint*> exact(n, nullptr);
  for (const ExactPoint& p : m.exactPoints)
    if (p.vertex < n) exact[p.vertex] = &p;
  for (int axis = 0; axis < 2; ++axis) {
    s += axis ? "],\n\"steiner_points_y\": [" : ",\n\"steiner_points_x\": [";
    for (size_t k = 0; k < steiner.size(); ++k) {
      s += k ? ",\n" : "\n";
      const ExactPoint* p = exact[steiner[k]];
      const std::string* text = p ? (axis ? &p->y : &p->x) : nullptr;
      detail::BigInt numerator, denominator;  // (a text that is no rational: the double)
      if (text && !detail::parseRational(*text, numerator, denominator)) text = nullptr;
      if (!text) {
        putExactRational(s, m.points[2 * steiner[k] + axis]);
      } else if (text->find('/') == std::string::npos) {
        s += *text;  // an integer: a JSON number, as for doubles
      } else {
        putJsonString(s, *text);
      }
    }
  }
  s += "],\n\"edges\": [";
  for (size_t i = 0; i < edges.size(); ++i) {
    s += i ? ",\n[" : "\n[";
    putUint(s, edges[i] >> 32);
    s += ',';
    putUint(s, edges[i] & 0xffffffffu);
    s += ']';
  }
  s += "]\n}\n";
  return s;
}

std::string formatMesh(OutputFormat format, const Mesh& m) {
  switch (format) {
    case OutputFormat::Node: return formatNode(m);
    case OutputFormat::Ele: return formatEle(m);
    case OutputFormat::Poly: return formatPoly(m);
    case OutputFormat::Json: return formatJson(m);
    case OutputFormat::Off: return formatOff(m);
    case OutputFormat::Obj: return formatObj(m);
    case OutputFormat::Svg: return formatSvg(m);
    case OutputFormat::Edge: return formatEdge(m);
    case OutputFormat::Neigh: return formatNeigh(m);
    case OutputFormat::Msh: return formatMsh(m);
    case OutputFormat::Msh2: return formatMsh2(m);
    case OutputFormat::Vtu: return formatVtu(m);
    case OutputFormat::Cgshop: break;
  }
  return {};
}

ParseResult writeMeshFiles(const Mesh& m, const std::string& base,
                           const std::vector<std::string>& formats) {
  ParseResult r;
  std::vector<OutputFormat> todo;
  for (const std::string& name : formats) {
    OutputFormat f;
    if (!parseName(name, f) || infoOf(f).needsInstance) {
      std::string names;
      for (const OutputFormatInfo& e : kOutputFormats)
        if (!e.needsInstance) names += std::string(e.name) + ", ";
      r.ok = false;
      r.message = "expected an output format among " + names + "found '" + name + "'";
      return r;
    }
    todo.push_back(f);
  }
  for (size_t i = 0; i < formats.size(); ++i) {
    std::string error;
    if (!writeFile(base + infoOf(todo[i]).extension, formatMesh(todo[i], m), error)) {
      r.ok = false;
      r.message = error;
      return r;
    }
  }
  return r;
}

}  // namespace acutemesh
