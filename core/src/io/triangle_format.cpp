// Triangle's line-oriented formats: .node (vertices) and .poly (vertices, segments, holes,
// regional attributes). Lines are read straight from the text; a count the rest of the text
// cannot hold is an error before anything is allocated for it.
#include "triangle_format.h"

#include <algorithm>
#include <cstdint>
#include <cstring>

#include "../build.h"
#include "numbers.h"
#include "parse_context.h"

namespace acutemesh::io {
namespace {

inline bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// Yields the lines that have content once the '#' comment is cut off.
struct Lines {
  std::string_view text;
  size_t pos = 0;
  size_t lineNo = 0;      // line number of the line last returned
  size_t nextLineNo = 1;  // line number of the line starting at pos

  explicit Lines(std::string_view t) : text(t) {}

  bool next(std::string_view& content) {
    const char* base = text.data();
    const size_t size = text.size();
    while (pos < size) {
      const char* b = base + pos;
      const size_t rem = size - pos;
      const char* nl = static_cast<const char*>(std::memchr(b, '\n', rem));
      size_t len = nl ? static_cast<size_t>(nl - b) : rem;
      pos += nl ? len + 1 : len;
      lineNo = nextLineNo++;
      const char* hash = static_cast<const char*>(std::memchr(b, '#', len));
      if (hash) len = static_cast<size_t>(hash - b);
      size_t i = 0;
      while (i < len && isBlank(b[i])) ++i;
      if (i < len) {
        content = std::string_view(b + i, len - i);
        return true;
      }
    }
    return false;
  }

  size_t remaining() const { return text.size() - pos; }

  // The common vertex line "<id> <x> <y> [marker]" (no attributes, no comment; the marker
  // only when `marker`, 0 when left out) parsed in one pass. Returns false, consuming nothing,
  // for anything else: the caller then reads the line with next() and the general, checking
  // code.
  bool fastVertexLine(bool marker, int64_t& id, double& x, double& y, int32_t& mark) {
    const char* const base = text.data();
    const char* const e = base + text.size();
    const char* p = base + pos;
    while (p < e && (*p == ' ' || *p == '\t')) ++p;
    const char* d = p;
    uint64_t v = 0;
    while (p < e && isDigit(*p) && p - d < 18) {
      v = v * 10 + static_cast<unsigned>(*p - '0');
      ++p;
    }
    if (p == d || p == e || (*p != ' ' && *p != '\t')) return false;
    while (p < e && (*p == ' ' || *p == '\t')) ++p;
    const char* stop;
    if (parseDecimalPrefix(p, e, stop, x) != NumErr::Ok || stop == e ||
        (*stop != ' ' && *stop != '\t'))
      return false;
    p = stop;
    while (p < e && (*p == ' ' || *p == '\t')) ++p;
    if (parseDecimalPrefix(p, e, stop, y) != NumErr::Ok) return false;
    p = stop;
    while (p < e && (*p == ' ' || *p == '\t')) ++p;
    int64_t m = 0;
    if (marker && p < e && (isDigit(*p) || *p == '-')) {
      const char* const from = p;
      const bool negative = *p == '-';
      if (negative) ++p;
      while (p < e && isDigit(*p) && p - from < 11) m = m * 10 + (*p++ - '0');
      if (p == from + negative || (p < e && *p != ' ' && *p != '\t' && *p != '\r' && *p != '\n'))
        return false;
      if (negative) m = -m;
      if (m < INT32_MIN || m > INT32_MAX) return false;  // (the checking code says why)
      while (p < e && (*p == ' ' || *p == '\t')) ++p;
    }
    if (p < e && *p == '\r') ++p;
    if (p < e) {
      if (*p != '\n') return false;
      ++p;
    }
    id = static_cast<int64_t>(v);
    mark = static_cast<int32_t>(m);
    pos = static_cast<size_t>(p - base);
    lineNo = nextLineNo++;
    return true;
  }

  // The line number at the end of the text (where a missing item was expected).
  size_t eofLine() const {
    if (text.empty()) return 1;
    return text.back() == '\n' ? nextLineNo : nextLineNo - 1;
  }
};

// Whitespace-separated fields of one line's content.
struct Fields {
  const char* p;
  const char* e;
  explicit Fields(std::string_view line) : p(line.data()), e(line.data() + line.size()) {}

  // Skips blanks; true if a field follows.
  bool more() {
    const char* q = p;  // locals in loops: a char read may alias the members
    const char* end = e;
    while (q < end && isBlank(*q)) ++q;
    p = q;
    return q != end;
  }
  // The field at p, not consumed (for messages).
  std::string_view peek() const {
    const char* q = p;
    const char* end = e;
    while (q < end && !isBlank(*q)) ++q;
    return std::string_view(p, static_cast<size_t>(q - p));
  }
  bool next(std::string_view& tok) {
    if (!more()) return false;
    tok = peek();
    p += tok.size();
    return true;
  }
  // An integer field at p (after more()), consumed when it is one.
  bool integer(int64_t& v) {
    const char* stop;
    int64_t x;
    if (!parseIntPrefix(p, e, stop, x) || (stop != e && !isBlank(*stop))) return false;
    p = stop;
    v = x;
    return true;
  }
  // A number field at p (after more()), consumed when it is one.
  NumErr number(double& v) {
    const char* stop;
    double x;
    const NumErr r = parseDecimalPrefix(p, e, stop, x);
    if (r != NumErr::Ok) return r;
    if (stop != e && !isBlank(*stop)) return NumErr::NotNumber;
    p = stop;
    v = x;
    return NumErr::Ok;
  }
};

// A line with at least `minBytes` characters plus a line break per item: how many items
// `remaining` bytes can hold at most.
uint64_t maxItems(size_t remaining, size_t minBytes) {
  return (static_cast<uint64_t>(remaining) + 1) / (minBytes + 1);
}

// Reads a count field (non-negative integer). Absent fields take `def` when `optional`.
bool readCount(Fields& f, Ctx& c, size_t line, const std::string& what, bool optional, uint64_t def,
               uint64_t& v) {
  std::string_view tok;
  if (!f.next(tok)) {
    if (optional) {
      v = def;
      return true;
    }
    return c.fail(line, "expected " + what + ", found end of line");
  }
  int64_t x;
  if (!parseFieldInt(tok, x) || x < 0)
    return c.fail(line, "expected " + what + " (a non-negative integer), found " + quote(tok));
  v = static_cast<uint64_t>(x);
  return true;
}

bool noMoreFields(Fields& f, Ctx& c, size_t line, const std::string& expected) {
  std::string_view tok;
  if (f.next(tok))
    return c.fail(line, "expected " + expected + ", found an extra field " + quote(tok));
  return true;
}

bool readMarkerCount(Fields& f, Ctx& c, size_t line, uint64_t& v) {
  if (!readCount(f, c, line, "the number of boundary markers", true, 0, v)) return false;
  if (v > 1) return c.fail(line, "expected 0 or 1 boundary markers, found " + std::to_string(v));
  return true;
}

bool coordError(Fields& f, Ctx& c, size_t line, const char* what, NumErr e) {
  if (f.p == f.e) return c.fail(line, std::string("expected ") + what + ", found end of line");
  const std::string tok = quote(f.peek());
  switch (e) {
    case NumErr::NonFinite:
      return c.fail(line, std::string("expected a finite ") + what + ", found " + tok);
    case NumErr::OutOfRange:
      return c.fail(line, std::string("expected ") + what + " within double range, found " + tok);
    default:
      break;
  }
  return c.fail(line, std::string("expected ") + what + " (a number), found " + tok);
}

// A coordinate field: finite double.
inline bool readCoord(Fields& f, Ctx& c, size_t line, const char* what, double& v) {
  if (!f.more()) return coordError(f, c, line, what, NumErr::NotNumber);
  const NumErr e = f.number(v);
  return e == NumErr::Ok || coordError(f, c, line, what, e);
}

// A leading item id: an integer (ignored except for a vertex list's first id).
inline bool readId(Fields& f, Ctx& c, size_t line, const char* what, int64_t& id) {
  // The line has content, so there is a first field.
  if (f.more() && f.integer(id)) return true;
  return c.fail(line,
                std::string("expected ") + what + " number (an integer), found " + quote(f.peek()));
}

// Optional trailing fields: up to `attrs` numbers (ignored: acutemesh has no vertex
// attributes) then up to `markers` (0 or 1) integers, the marker. Triangle lets attributes and
// markers default to 0.
bool readExtras(Fields& f, Ctx& c, size_t line, uint64_t attrs, uint64_t markers,
                const std::string& layout, int32_t& marker, double* firstAttribute = nullptr) {
  marker = 0;
  std::string_view tok;
  for (uint64_t i = 0; i < attrs + markers; ++i) {
    if (!f.next(tok)) return true;
    if (i < attrs) {
      double d = 0;
      NumErr e = parseFieldDouble(tok, d);
      if (e == NumErr::NotNumber)
        return c.fail(line, "expected attribute " + std::to_string(i + 1) + " (a number), found " +
                                quote(tok));
      if (i == 0 && firstAttribute) *firstAttribute = d;
    } else {
      int64_t m;
      if (!parseFieldInt(tok, m) || m < INT32_MIN || m > INT32_MAX)
        return c.fail(line, "expected a boundary marker (a 32-bit integer), found " + quote(tok));
      marker = static_cast<int32_t>(m);
    }
  }
  return noMoreFields(f, c, line, layout);
}

std::string vertexLayout(uint64_t attrs, uint64_t markers) {
  std::string s = "'<id> <x> <y>";
  if (attrs) s += " [" + std::to_string(attrs) + (attrs == 1 ? " attribute]" : " attributes]");
  if (markers) s += " [marker]";
  return s + "'";
}

struct VertexList {
  uint32_t first = 0;  // number of the first vertex: 0 or 1
  size_t count = 0;
};

// The "<#vertices> <dim> <#attributes> <#markers>" line.
struct NodeHeader {
  uint64_t count = 0, attrs = 0, markers = 0;
  size_t line = 0;
};

bool readNodeHeader(Lines& L, Ctx& c, NodeHeader& h) {
  std::string_view line;
  const char* expected = "the header '<#vertices> <dimension> <#attributes> <#boundary markers>'";
  if (!L.next(line))
    return c.fail(L.eofLine(), std::string("expected ") + expected + ", found end of file");
  h.line = L.lineNo;
  Fields f(line);
  uint64_t dim;
  if (!readCount(f, c, h.line, "the number of vertices", false, 0, h.count) ||
      !readCount(f, c, h.line, "the dimension", true, 2, dim))
    return false;
  if (dim != 2) return c.fail(h.line, "expected dimension 2, found " + std::to_string(dim));
  if (!readCount(f, c, h.line, "the number of attributes", true, 0, h.attrs) ||
      !readMarkerCount(f, c, h.line, h.markers) || !noMoreFields(f, c, h.line, expected))
    return false;
  if (h.count > kMaxIndexCount)
    return c.fail(h.line, "expected at most " + std::to_string(kMaxIndexCount) +
                              " vertices, found " + std::to_string(h.count));
  return true;
}

// The vertex lines after a header, appended to `pts` and, when the header announces them,
// their markers to `markers` (the caller's vectors are empty).
bool readVertexLines(Lines& L, Ctx& c, const NodeHeader& h, std::vector<double>& pts,
                     std::vector<int32_t>& markers, VertexList& vl,
                     std::vector<double>* firstAttributes = nullptr) {
  const uint64_t room = maxItems(L.remaining(), 5);  // "0 0 0"
  if (h.count > room)
    return c.fail(h.line, "expected a vertex count the rest of the text can hold (at most " +
                              std::to_string(room) + "), found " + std::to_string(h.count));
  pts.reserve(static_cast<size_t>(h.count) * 2);
  if (h.markers) markers.reserve(static_cast<size_t>(h.count));
  const std::string layout = vertexLayout(h.attrs, h.markers);
  bool warnedIds = false;
  std::string_view line;
  for (uint64_t i = 0; i < h.count; ++i) {
    int64_t id;
    double x, y;
    int32_t marker = 0;
    double attribute = 0;  // (Triangle's default for a missing one)
    const bool fast = L.fastVertexLine(h.attrs == 0 && h.markers == 1, id, x, y, marker);
    if (!fast && !L.next(line))
      return c.fail(L.eofLine(), "expected vertex line " + std::to_string(i + 1) + " of " +
                                     std::to_string(h.count) + " " + layout +
                                     ", found end of file");
    const size_t ln = L.lineNo;
    Fields f(line);
    if (!fast && !readId(f, c, ln, "a vertex", id)) return false;
    if (i == 0) {
      if (id == 0 || id == 1) {
        vl.first = static_cast<uint32_t>(id);
      } else {
        vl.first = 1;
        c.warn(ln, "expected the first vertex numbered 0 or 1, found " + std::to_string(id) +
                       "; indices taken as 1-based, as Triangle does");
      }
    } else if (!warnedIds && id != static_cast<int64_t>(vl.first + i)) {
      warnedIds = true;
      c.warn(ln, "expected vertex number " + std::to_string(vl.first + i) + ", found " +
                     std::to_string(id) + "; vertices are numbered by their position");
    }
    if (!fast &&
        (!readCoord(f, c, ln, "x coordinate", x) || !readCoord(f, c, ln, "y coordinate", y) ||
         !readExtras(f, c, ln, h.attrs, h.markers, layout, marker, &attribute)))
      return false;
    pts.push_back(x);
    pts.push_back(y);
    if (firstAttributes) firstAttributes->push_back(attribute);
    if (h.markers) markers.push_back(marker);
  }
  vl.count = static_cast<size_t>(h.count);
  return true;
}

void warnTrailing(Lines& L, Ctx& c, const char* after) {
  std::string_view line;
  if (L.next(line)) c.warn(L.lineNo, std::string("ignored the text after ") + after);
}

bool parseNodeInto(std::string_view text, Ctx& c, std::vector<double>& pts,
                   std::vector<int32_t>& markers, VertexList& vl, bool warnTrail) {
  Lines L(text);
  NodeHeader h;
  if (!readNodeHeader(L, c, h) || !readVertexLines(L, c, h, pts, markers, vl)) return false;
  if (warnTrail) warnTrailing(L, c, "the vertices");
  return true;
}

std::string indexRange(const VertexList& vl) {
  if (vl.count == 0) return "a vertex number (there are no vertices)";
  return "a vertex number in [" + std::to_string(vl.first) + ", " +
         std::to_string(vl.first + vl.count - 1) + "]";
}

bool readEndpoint(Fields& f, Ctx& c, size_t line, const VertexList& vl, uint32_t& out) {
  if (!f.more()) return c.fail(line, "expected " + indexRange(vl) + ", found end of line");
  const std::string_view tok = f.peek();
  int64_t v;
  if (!f.integer(v) || v < static_cast<int64_t>(vl.first) ||
      v >= static_cast<int64_t>(vl.first + vl.count))
    return c.fail(line, "expected " + indexRange(vl) + ", found " + quote(tok));
  out = static_cast<uint32_t>(v - vl.first);
  return true;
}

// Reads a "<#items> ..." line: returns false with an error, sets `present` false at EOF when
// the section may be absent.
bool readSectionHeader(Lines& L, Ctx& c, const char* expected, bool mayBeAbsent, bool& present,
                       size_t& line, Fields& f) {
  std::string_view content;
  if (!L.next(content)) {
    present = false;
    if (mayBeAbsent) return true;
    return c.fail(L.eofLine(), std::string("expected ") + expected + ", found end of file");
  }
  present = true;
  line = L.lineNo;
  f = Fields(content);
  return true;
}

bool checkRoom(Lines& L, Ctx& c, size_t line, uint64_t count, size_t minBytes, const char* items) {
  const uint64_t room = maxItems(L.remaining(), minBytes);
  if (count > room)
    return c.fail(line, std::string("expected a ") + items +
                            " count the rest of the text can hold (at most " +
                            std::to_string(room) + "), found " + std::to_string(count));
  return true;
}

// The vertices of a .poly: after its header, or in the .node text when its count is 0.
bool readPolyVertices(Lines& L, Ctx& c, Input& in, std::string_view nodeText,
                      const std::string& nodeName, VertexList& vl) {
  NodeHeader h;
  if (!readNodeHeader(L, c, h)) return false;
  if (h.count != 0) return readVertexLines(L, c, h, in.pslg.points, in.pslg.vertexMarkers, vl);
  if (nodeText.empty() && nodeName.empty())
    return c.fail(h.line,
                  "expected vertices (a count of 0 says they are in a .node file), found "
                  "no .node text");
  Ctx nc{nodeName, c.warnings, {}};
  if (!parseNodeInto(nodeText, nc, in.pslg.points, in.pslg.vertexMarkers, vl, true)) {
    c.message = nc.message;
    return false;
  }
  return true;
}

// The segments, and their markers when the header announces them.
bool readSegments(Lines& L, Ctx& c, const VertexList& vl, std::vector<uint32_t>& segments,
                  std::vector<int32_t>& segmentMarkers) {
  bool present;
  size_t line = 0;
  Fields f{std::string_view()};
  uint64_t count, markers;
  const char* segHeader = "the segment header '<#segments> <#boundary markers>'";
  if (!readSectionHeader(L, c, segHeader, false, present, line, f) ||
      !readCount(f, c, line, "the number of segments", false, 0, count) ||
      !readMarkerCount(f, c, line, markers) || !noMoreFields(f, c, line, segHeader) ||
      !checkRoom(L, c, line, count, 5, "segment"))
    return false;
  const std::string segLayout =
      markers ? "'<id> <endpoint> <endpoint> [marker]'" : "'<id> <endpoint> <endpoint>'";
  segments.reserve(static_cast<size_t>(count) * 2);
  if (markers) segmentMarkers.reserve(static_cast<size_t>(count));
  std::string_view content;
  for (uint64_t i = 0; i < count; ++i) {
    if (!L.next(content))
      return c.fail(L.eofLine(), "expected segment line " + std::to_string(i + 1) + " of " +
                                     std::to_string(count) + " " + segLayout +
                                     ", found end of file");
    const size_t ln = L.lineNo;
    Fields g(content);
    int64_t id;
    uint32_t a, b;
    int32_t marker;
    if (!readId(g, c, ln, "a segment", id) || !readEndpoint(g, c, ln, vl, a) ||
        !readEndpoint(g, c, ln, vl, b) || !readExtras(g, c, ln, 0, markers, segLayout, marker))
      return false;
    segments.push_back(a);
    segments.push_back(b);
    if (markers) segmentMarkers.push_back(marker);
  }
  return true;
}

// The hole section, which may be missing at the end of the file (present false).
bool readHoles(Lines& L, Ctx& c, std::vector<double>& holes, bool& present) {
  size_t line = 0;
  Fields f{std::string_view()};
  uint64_t count;
  const char* holeHeader = "the hole count '<#holes>'";
  if (!readSectionHeader(L, c, holeHeader, true, present, line, f)) return false;
  if (!present) return true;
  if (!readCount(f, c, line, "the number of holes", false, 0, count) ||
      !noMoreFields(f, c, line, holeHeader) || !checkRoom(L, c, line, count, 5, "hole"))
    return false;
  holes.reserve(static_cast<size_t>(count) * 2);
  std::string_view content;
  for (uint64_t i = 0; i < count; ++i) {
    if (!L.next(content))
      return c.fail(L.eofLine(), "expected hole line " + std::to_string(i + 1) + " of " +
                                     std::to_string(count) + " '<id> <x> <y>', found end of file");
    const size_t ln = L.lineNo;
    Fields g(content);
    int64_t id;
    double x, y;
    if (!readId(g, c, ln, "a hole", id) || !readCoord(g, c, ln, "hole x coordinate", x) ||
        !readCoord(g, c, ln, "hole y coordinate", y) || !noMoreFields(g, c, ln, "'<id> <x> <y>'"))
      return false;
    holes.push_back(x);
    holes.push_back(y);
  }
  return true;
}

// Optional regional attributes and area constraints (a negative or missing area: none, as in
// Triangle).
bool readRegions(Lines& L, Ctx& c, std::vector<Region>& regions) {
  bool present;
  size_t line = 0;
  Fields f{std::string_view()};
  uint64_t count;
  const char* regionHeader = "the regional attribute count '<#regions>'";
  if (!readSectionHeader(L, c, regionHeader, true, present, line, f)) return false;
  if (!present) return true;
  if (!readCount(f, c, line, "the number of regional attributes", false, 0, count) ||
      !noMoreFields(f, c, line, regionHeader) || !checkRoom(L, c, line, count, 7, "region"))
    return false;
  const char* regionLayout = "'<id> <x> <y> <attribute> [maximum area]'";
  std::string_view content;
  for (uint64_t i = 0; i < count; ++i) {
    if (!L.next(content))
      return c.fail(L.eofLine(), "expected region line " + std::to_string(i + 1) + " of " +
                                     std::to_string(count) + " " + regionLayout +
                                     ", found end of file");
    const size_t ln = L.lineNo;
    Fields g(content);
    int64_t id;
    Region region;
    if (!readId(g, c, ln, "a region", id) ||
        !readCoord(g, c, ln, "region x coordinate", region.x) ||
        !readCoord(g, c, ln, "region y coordinate", region.y) ||
        !readCoord(g, c, ln, "regional attribute", region.attribute))
      return false;
    if (g.more() && !readCoord(g, c, ln, "maximum area", region.maxArea)) return false;
    if (!noMoreFields(g, c, ln, regionLayout)) return false;
    region.maxArea = std::max(region.maxArea, 0.0);
    regions.push_back(region);
  }
  warnTrailing(L, c, "the regional attributes");
  return true;
}

bool parsePolyImpl(std::string_view text, Ctx& c, Input& in, std::string_view nodeText,
                   const std::string& nodeName) {
  Lines L(text);
  VertexList vl;
  bool holesPresent;
  if (!readPolyVertices(L, c, in, nodeText, nodeName, vl) ||
      !readSegments(L, c, vl, in.pslg.segments, in.pslg.segmentMarkers) ||
      !readHoles(L, c, in.pslg.holes, holesPresent))
    return false;
  return !holesPresent || readRegions(L, c, in.pslg.regions);
}

}  // namespace

bool polyHasNoVertices(std::string_view text) {
  Lines L(text);
  std::string_view line, tok;
  if (!L.next(line)) return false;
  Fields f(line);
  int64_t v;
  return f.next(tok) && parseFieldInt(tok, v) && v == 0;
}

}  // namespace acutemesh::io

namespace acutemesh {

using io::Ctx;
using io::failure;

ParseResult parsePoly(std::string_view text, const std::string& name, Input& out,
                      std::string_view nodeText, const std::string& nodeName) {
  Input in;
  Ctx c{name, &in.warnings, {}};
  if (!io::parsePolyImpl(text, c, in, nodeText, nodeName)) return failure(std::move(c.message));
  in.format = InputFormat::Poly;
  out = std::move(in);
  return {};
}

ParseResult parseSizeNode(std::string_view text, const std::string& name, SizeField& out,
                          std::vector<std::string>* warnings) {
  std::vector<std::string> notes;
  io::Ctx c{name, &notes, {}};
  io::Lines L(text);
  io::NodeHeader h;
  io::VertexList vl;
  std::vector<double> points, sizes;
  std::vector<int32_t> markers;
  if (!io::readNodeHeader(L, c, h)) return failure(std::move(c.message));
  if (h.attrs == 0)
    return failure(name + ":" + std::to_string(h.line) +
                   ": expected at least one attribute per vertex (its size) in the header, found 0");
  if (!io::readVertexLines(L, c, h, points, markers, vl, &sizes)) return failure(std::move(c.message));
  for (size_t i = 0; i < sizes.size(); ++i)
    if (!(sizes[i] > 0))
      return failure(name + ": vertex " + std::to_string(vl.first + i) +
                     ": expected a size > 0 (its first attribute), found " + detail::shortestText(sizes[i]));
  io::warnTrailing(L, c, "the vertices");
  out.points = std::move(points);
  out.sizes = std::move(sizes);
  if (warnings) warnings->insert(warnings->end(), notes.begin(), notes.end());
  return {};
}

ParseResult parseNode(std::string_view text, const std::string& name, Input& out) {
  Input in;
  Ctx c{name, &in.warnings, {}};
  io::VertexList vl;
  if (!io::parseNodeInto(text, c, in.pslg.points, in.pslg.vertexMarkers, vl, true))
    return failure(std::move(c.message));
  in.format = InputFormat::Node;
  out = std::move(in);
  return {};
}

}  // namespace acutemesh
