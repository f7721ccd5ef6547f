// Mesh output: Triangle's .node/.ele/.poly, JSON, OFF, OBJ, SVG and the CG:SHOP 2025 solution.
//
// Coordinates are written so that they read back as the same doubles: the shortest
// round-trip form (std::to_chars) where the library has it, "%.17g" otherwise. Vertex indices
// in .node/.ele/.poly are 0-based (Triangle's -z convention), which each file states in its
// first line; OBJ is 1-based by definition. The CG:SHOP solution writes each coordinate as the
// exact rational the double is (an integer, or "p/q" with q a power of two).
#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
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

void putDouble(std::string& s, double v) {
  char buf[40];
#if ACUTEMESH_FLOAT_TO_CHARS
  std::to_chars_result r = std::to_chars(buf, buf + sizeof buf, v);
  s.append(buf, r.ptr);
#else
  const int n = std::snprintf(buf, sizeof buf, "%.17g", v);
  s.append(buf, static_cast<size_t>(n));
#endif
}

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

void putNodeSection(std::string& s, const Mesh& m) {
  const size_t n = m.vertexCount();
  putUint(s, n);
  s += " 2 0 0\n";
  for (size_t i = 0; i < n; ++i) putPointLine(s, i, &m.points[2 * i]);
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
  putNodeSection(s, m);
  return s;
}

std::string formatEle(const Mesh& m) {
  std::string s;
  s.reserve(trianglesBytes(m) + 64);
  s += kTriangleHeader;
  const size_t t = m.triangleCount();
  putUint(s, t);
  s += " 3 0\n";
  for (size_t i = 0; i < t; ++i) {
    putUint(s, i);
    for (int k = 0; k < 3; ++k) {
      s += ' ';
      putUint(s, m.triangles[3 * i + k]);
    }
    s += '\n';
  }
  return s;
}

// The mesh's segment edges, then its boundary edges on none (a hull kept), and a point in
// each hole: read back with fill 'triangle', the domain is the mesh's own.
std::string formatPoly(const Mesh& m) {
  const io::Outline outline = io::outlineOf(m);
  std::string s;
  const size_t e = m.segments.size() / 2, extra = outline.boundary.size() / 2;
  const size_t holes = outline.holes.size() / 2;
  s.reserve(pointsBytes(m) + (e + extra) * 32 + holes * 48 + 64);
  s += kTriangleHeader;
  putNodeSection(s, m);
  putUint(s, e + extra);
  s += " 0\n";
  for (size_t i = 0; i < e + extra; ++i) {
    const uint32_t* ab = i < e ? &m.segments[2 * i] : &outline.boundary[2 * (i - e)];
    if (i == e) s += "# boundary edges on no input segment\n";
    putUint(s, i);
    s += ' ';
    putUint(s, ab[0]);
    s += ' ';
    putUint(s, ab[1]);
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
  double minX = 0, minY = 0, maxX = 0, maxY = 0;
  bool any = false;
  for (size_t i = 0; i < n; ++i) {
    const double x = m.points[2 * i], y = m.points[2 * i + 1];
    if (!std::isfinite(x) || !std::isfinite(y)) continue;
    if (!any) {
      minX = maxX = x;
      minY = maxY = y;
      any = true;
    } else {
      minX = std::min(minX, x);
      maxX = std::max(maxX, x);
      minY = std::min(minY, y);
      maxY = std::max(maxY, y);
    }
  }
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
