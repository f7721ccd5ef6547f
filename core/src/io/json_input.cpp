// The JSON inputs: an acutemesh PSLG, rings, or a CG:SHOP 2025 instance (acutemesh/io.h,
// parseJson), read with the tokenizer of json.h into a JsonDoc, then checked and mapped to
// a PSLG.
#include <utility>
#include <vector>

#include "json.h"
#include "parse_context.h"

namespace acutemesh::io {
namespace {

// Indices as read, with the line of each, range-checked once the vertex count is known.
struct IndexList {
  std::vector<uint64_t> values;
  std::vector<uint32_t> lines;
  void push(uint64_t v, size_t line) {
    values.push_back(v);
    lines.push_back(static_cast<uint32_t>(line));
  }
  size_t size() const { return values.size(); }
};

bool checkIndices(const IndexList& l, size_t n, const char* key, Ctx& c) {
  for (size_t i = 0; i < l.size(); ++i)
    if (l.values[i] >= n)
      return c.fail(l.lines[i],
                    std::string("expected a vertex index in ") + key +
                        (n ? " below " + std::to_string(n) : " (there are no vertices)") +
                        ", found " + std::to_string(l.values[i]));
  return true;
}

enum class JsonKind { None, Pslg, Rings, Cgshop };

const char* kindName(JsonKind k) {
  switch (k) {
    case JsonKind::Pslg:
      return "an acutemesh PSLG (\"vertices\")";
    case JsonKind::Rings:
      return "rings (\"rings\")";
    case JsonKind::Cgshop:
      return "a CG:SHOP instance (\"points_x\")";
    case JsonKind::None:
      break;
  }
  return "nothing";
}

struct JsonDoc {
  JsonKind kind = JsonKind::None;
  std::string kindKey;  // the key that decided the kind
  size_t objectLine = 1;

  bool hasVertices = false, hasRings = false, hasPx = false, hasPy = false, hasBoundary = false,
       hasNumPoints = false, hasNumConstraints = false;
  size_t pyLine = 0, numPointsLine = 0, boundaryLine = 0, numConstraintsLine = 0;
  std::vector<double> points, holes, px, py;
  IndexList segments, boundary, constraints;
  std::vector<uint32_t> ringSegments;
  std::vector<uint32_t> ringSizes;  // segments per ring, for "ringMarkers"
  // Markers and regions, with the line of each key for the counts' messages.
  struct Markers {
    std::vector<int32_t> values;
    size_t line = 0;
    bool given = false;
  } vertexMarkers, segmentMarkers, ringMarkers;
  size_t regionsLine = 0;
  bool hasRegions = false;
  std::vector<Region> regions;
  uint64_t numPoints = 0, numConstraints = 0;
  std::string uid;
};

bool readPoint(JsonReader& r, std::vector<double>& dst, const char* what) {
  double x, y;
  if (!r.expect('[', "'[' starting ", what, " [x, y]") || !r.number(x, "an x coordinate") ||
      !r.expect(',', "',' between x and y") || !r.number(y, "a y coordinate") ||
      !r.expect(']', "']' ending ", what, " [x, y] (exactly 2 numbers)"))
    return false;
  dst.push_back(x);
  dst.push_back(y);
  return true;
}

bool readPair(JsonReader& r, IndexList& dst, const char* what) {
  uint64_t a, b;
  r.ws();
  const size_t line = r.line();
  if (!r.expect('[', "'[' starting ", what, " [i, j]") ||
      !r.index(a, "a vertex index (a non-negative integer)") ||
      !r.expect(',', "',' between the two indices"))
    return false;
  r.ws();
  const size_t line2 = r.line();
  if (!r.index(b, "a vertex index (a non-negative integer)") ||
      !r.expect(']', "']' ending ", what, " [i, j] (exactly 2 indices)"))
    return false;
  dst.push(a, line);
  dst.push(b, line2);
  return true;
}

bool readRing(JsonReader& r, JsonDoc& d) {
  r.ws();
  const size_t ringLine = r.line();
  std::vector<double> ring;
  if (!r.array("a ring [[x, y], ...]", [&] { return readPoint(r, ring, "a ring point"); }))
    return false;
  size_t n = ring.size() / 2;
  if (n >= 2 && ring[0] == ring[2 * n - 2] && ring[1] == ring[2 * n - 1]) {
    --n;
    ring.resize(2 * n);
    r.ctx().warn(ringLine,
                 "dropped the ring's last point, a repeat of its first (rings close "
                 "implicitly)");
  }
  if (n < 3)
    return r.ctx().fail(
        ringLine, "expected a ring of at least 3 distinct points, found " + std::to_string(n));
  const size_t base = d.points.size() / 2;
  if (base + n > kMaxIndexCount)
    return r.ctx().fail(ringLine, "expected at most " + std::to_string(kMaxIndexCount) +
                                      " vertices in all, found more");
  d.points.insert(d.points.end(), ring.begin(), ring.end());
  for (size_t i = 0; i < n; ++i) {
    d.ringSegments.push_back(static_cast<uint32_t>(base + i));
    d.ringSegments.push_back(static_cast<uint32_t>(base + (i + 1) % n));
  }
  d.ringSizes.push_back(static_cast<uint32_t>(n));
  return true;
}

// A region [x, y, attribute] or [x, y, attribute, maxArea].
bool readRegion(JsonReader& r, std::vector<Region>& dst) {
  Region g;
  if (!r.expect('[', "'[' starting a region [x, y, attribute, maxArea?]") ||
      !r.number(g.x, "a region's x coordinate") || !r.expect(',', "',' after the region's x") ||
      !r.number(g.y, "a region's y coordinate") || !r.expect(',', "',' after the region's y") ||
      !r.number(g.attribute, "a region's attribute"))
    return false;
  r.ws();
  if (r.peek() == ',') {
    r.advance();
    r.ws();
    if (r.peek() == '-') return r.fail("a region's maximum area (a number >= 0; 0: none)");
    if (!r.number(g.maxArea, "a region's maximum area")) return false;
  }
  if (!r.expect(']', "']' ending a region [x, y, attribute, maxArea?] (3 or 4 numbers)"))
    return false;
  dst.push_back(g);
  return true;
}

// An array of 32-bit integers (markers).
bool readMarkers(JsonReader& r, const char* what, std::vector<int32_t>& dst) {
  return r.array(what, [&] {
    int32_t m;
    if (!r.int32(m, "a marker (an integer of 32 bits)")) return false;
    dst.push_back(m);
    return true;
  });
}

// A marker array's length, when given: `count` items, one marker each.
bool checkMarkerCount(const JsonDoc::Markers& markers, size_t count, const char* key,
                      const char* item, Ctx& c) {
  if (!markers.given || markers.values.size() == count) return true;
  return c.fail(markers.line, "expected " + std::to_string(count) + (count == 1 ? " marker" : " markers") +
                          " in \"" + key + "\" (one per " +
                          item + "), found " + std::to_string(markers.values.size()));
}

JsonKind keyKind(const std::string& key) {
  if (key == "vertices" || key == "segments" || key == "holes" || key == "triangles" ||
      key == "exactPoints" || key == "vertexMarkers" || key == "segmentMarkers")
    return JsonKind::Pslg;
  if (key == "rings" || key == "ringMarkers") return JsonKind::Rings;
  if (key == "instance_uid" || key == "num_points" || key == "points_x" || key == "points_y" ||
      key == "region_boundary" || key == "num_constraints" || key == "additional_constraints")
    return JsonKind::Cgshop;
  return JsonKind::None;
}

bool readMember(JsonReader& r, JsonDoc& d, const std::string& key, size_t keyLine) {
  Ctx& c = r.ctx();
  // Regions go with a PSLG and with rings alike (buildCgshop refuses them).
  if (key == "regions") {
    d.hasRegions = true;
    d.regionsLine = keyLine;
    return r.array("the \"regions\" array", [&] { return readRegion(r, d.regions); });
  }
  const JsonKind k = keyKind(key);
  if (k == JsonKind::None) {
    c.warn(keyLine, "ignored the unknown key \"" + printable(key) + "\"");
    return r.skipValue(1);
  }
  if (d.kind == JsonKind::None) {
    d.kind = k;
    d.kindKey = key;
  } else if (d.kind != k) {
    return c.fail(keyLine, std::string("expected the keys of ") + kindName(d.kind) + " as \"" +
                               d.kindKey + "\" says, found \"" + key + "\"");
  }
  // A mesh written by formatJson: its triangles and exact points are ignored.
  if (key == "triangles" || key == "exactPoints") return r.skipValue(1);
  if (key == "vertices") {
    d.hasVertices = true;
    return r.array("the \"vertices\" array", [&] { return readPoint(r, d.points, "a vertex"); });
  }
  if (key == "segments")
    return r.array("the \"segments\" array", [&] { return readPair(r, d.segments, "a segment"); });
  if (key == "holes")
    return r.array("the \"holes\" array", [&] { return readPoint(r, d.holes, "a hole"); });
  if (key == "vertexMarkers" || key == "segmentMarkers" || key == "ringMarkers") {
    JsonDoc::Markers& m = key == "vertexMarkers"    ? d.vertexMarkers
                          : key == "segmentMarkers" ? d.segmentMarkers
                                                    : d.ringMarkers;
    m.given = true;
    m.line = keyLine;
    const std::string what = "the \"" + key + "\" array";
    return readMarkers(r, what.c_str(), m.values);
  }
  if (key == "rings") {
    d.hasRings = true;
    return r.array("the \"rings\" array", [&] { return readRing(r, d); });
  }
  if (key == "points_x" || key == "points_y") {
    std::vector<double>& dst = key == "points_x" ? d.px : d.py;
    (key == "points_x" ? d.hasPx : d.hasPy) = true;
    if (key == "points_y") d.pyLine = keyLine;
    const std::string what = "the \"" + key + "\" array";
    return r.array(what.c_str(), [&] {
      double v;
      if (!r.number(v, "a coordinate")) return false;
      dst.push_back(v);
      return true;
    });
  }
  if (key == "region_boundary") {
    d.hasBoundary = true;
    d.boundaryLine = keyLine;
    return r.array("the \"region_boundary\" array", [&] {
      uint64_t v;
      r.ws();
      const size_t ln = r.line();
      if (!r.index(v, "a vertex index (a non-negative integer)")) return false;
      d.boundary.push(v, ln);
      return true;
    });
  }
  if (key == "additional_constraints")
    return r.array("the \"additional_constraints\" array",
                   [&] { return readPair(r, d.constraints, "a constraint"); });
  if (key == "num_points" || key == "num_constraints") {
    const bool pts = key == "num_points";
    (pts ? d.hasNumPoints : d.hasNumConstraints) = true;
    (pts ? d.numPointsLine : d.numConstraintsLine) = keyLine;
    return r.index(pts ? d.numPoints : d.numConstraints, "a count (a non-negative integer)");
  }
  // instance_uid
  return r.string(d.uid, "the instance uid (a string)");
}

// A CG:SHOP 2025 instance: the region boundary (a ring of indices) becomes segments, then
// the additional constraints.
bool buildCgshop(JsonDoc& d, Ctx& c, Input& in) {
  if (d.hasRegions)
    return c.fail(d.regionsLine, "expected the keys of a CG:SHOP instance as \"" + d.kindKey +
                                     "\" says, found \"regions\"");
  if (!d.hasPx || !d.hasPy || !d.hasBoundary) {
    const char* missing = !d.hasPx ? "points_x" : !d.hasPy ? "points_y" : "region_boundary";
    return c.fail(d.objectLine, std::string("expected the key \"") + missing +
                                    "\" of a CG:SHOP instance, found none");
  }
  const size_t n = d.px.size();
  if (d.py.size() != n)
    return c.fail(d.pyLine, "expected " + std::to_string(n) +
                                " numbers in \"points_y\" (as in \"points_x\"), found " +
                                std::to_string(d.py.size()));
  if (d.hasNumPoints && d.numPoints != n)
    return c.fail(d.numPointsLine, "expected \"num_points\" equal to the " + std::to_string(n) +
                                       " points given, found " + std::to_string(d.numPoints));
  if (n > kMaxIndexCount)
    return c.fail(d.objectLine, "expected at most " + std::to_string(kMaxIndexCount) +
                                    " points, found " + std::to_string(n));
  if (!checkIndices(d.boundary, n, "\"region_boundary\"", c) ||
      !checkIndices(d.constraints, n, "\"additional_constraints\"", c))
    return false;
  std::vector<uint64_t>& ring = d.boundary.values;
  if (ring.size() >= 2 && ring.front() == ring.back()) {
    ring.pop_back();
    c.warn(d.boundaryLine,
           "dropped the last index of \"region_boundary\", a repeat of its "
           "first (the ring closes implicitly)");
  }
  if (ring.size() < 3)
    return c.fail(d.boundaryLine, "expected at least 3 indices in \"region_boundary\", found " +
                                      std::to_string(ring.size()));
  if (d.hasNumConstraints && d.numConstraints != d.constraints.size() / 2)
    c.warn(d.numConstraintsLine, "\"num_constraints\" says " + std::to_string(d.numConstraints) +
                                     " but " + std::to_string(d.constraints.size() / 2) +
                                     " constraints are given; using those given");
  in.format = InputFormat::CgshopInstance;
  in.instanceUid = std::move(d.uid);
  in.pslg.points.resize(2 * n);
  for (size_t i = 0; i < n; ++i) {
    in.pslg.points[2 * i] = d.px[i];
    in.pslg.points[2 * i + 1] = d.py[i];
  }
  in.pslg.segments.reserve(2 * ring.size() + d.constraints.size());
  for (size_t i = 0; i < ring.size(); ++i) {
    in.pslg.segments.push_back(static_cast<uint32_t>(ring[i]));
    in.pslg.segments.push_back(static_cast<uint32_t>(ring[(i + 1) % ring.size()]));
  }
  for (uint64_t v : d.constraints.values) in.pslg.segments.push_back(static_cast<uint32_t>(v));
  return true;
}

bool buildInput(JsonDoc& d, Ctx& c, Input& in) {
  switch (d.kind) {
    case JsonKind::None:
      return c.fail(d.objectLine,
                    "expected the key \"vertices\", \"rings\" or \"points_x\", "
                    "found none of them");
    case JsonKind::Pslg: {
      if (!d.hasVertices)
        return c.fail(d.objectLine,
                      "expected the key \"vertices\" with \"" + d.kindKey + "\", found none");
      const size_t n = d.points.size() / 2;
      if (n > kMaxIndexCount)
        return c.fail(d.objectLine, "expected at most " + std::to_string(kMaxIndexCount) +
                                        " vertices, found " + std::to_string(n));
      if (!checkIndices(d.segments, n, "\"segments\"", c)) return false;
      if (!checkMarkerCount(d.vertexMarkers, n, "vertexMarkers", "vertex", c) ||
          !checkMarkerCount(d.segmentMarkers, d.segments.size() / 2, "segmentMarkers", "segment",
                            c))
        return false;
      in.format = InputFormat::JsonPslg;
      in.pslg.points = std::move(d.points);
      in.pslg.holes = std::move(d.holes);
      in.pslg.segments.assign(d.segments.values.begin(), d.segments.values.end());
      in.pslg.vertexMarkers = std::move(d.vertexMarkers.values);
      in.pslg.segmentMarkers = std::move(d.segmentMarkers.values);
      in.pslg.regions = std::move(d.regions);
      return true;
    }
    case JsonKind::Rings:
      if (!checkMarkerCount(d.ringMarkers, d.ringSizes.size(), "ringMarkers", "ring", c))
        return false;
      in.format = InputFormat::JsonPslg;
      in.hasRings = true;
      in.pslg.points = std::move(d.points);
      in.pslg.segments = std::move(d.ringSegments);
      // Each ring's segments take its marker.
      if (d.ringMarkers.given)
        for (size_t i = 0; i < d.ringSizes.size(); ++i)
          in.pslg.segmentMarkers.insert(in.pslg.segmentMarkers.end(), d.ringSizes[i],
                                        d.ringMarkers.values[i]);
      in.pslg.regions = std::move(d.regions);
      return true;
    case JsonKind::Cgshop:
      return buildCgshop(d, c, in);
  }
  return false;
}

bool parseJsonImpl(std::string_view text, Ctx& c, Input& in) {
  JsonReader r(text, c);
  JsonDoc d;
  r.ws();
  d.objectLine = r.line();
  if (!r.expect('{', "'{' starting the top-level JSON object")) return false;
  std::vector<std::string> seen;
  r.ws();
  if (r.peek() == '}') {
    r.advance();
  } else {
    std::string key;
    while (true) {
      r.ws();
      const size_t keyLine = r.line();
      if (!r.string(key, "a key string")) return false;
      for (const std::string& s : seen)
        if (s == key)
          return c.fail(keyLine, "expected each key once, found \"" + printable(key) + "\" again");
      seen.push_back(key);
      if (!r.expect(':', "':' after the key") || !readMember(r, d, key, keyLine)) return false;
      r.ws();
      if (r.peek() == ',') {
        r.advance();
        continue;
      }
      if (r.peek() == '}') {
        r.advance();
        break;
      }
      return r.fail("',' or '}' in the top-level object");
    }
  }
  r.ws();
  if (!r.atEnd()) return r.fail("end of text after the top-level object");
  return buildInput(d, c, in);
}

}  // namespace
}  // namespace acutemesh::io

namespace acutemesh {

ParseResult parseJson(std::string_view text, const std::string& name, Input& out) {
  Input in;
  io::Ctx c{name, &in.warnings, {}};
  if (!io::parseJsonImpl(text, c, in)) return io::failure(std::move(c.message));
  out = std::move(in);
  return {};
}

}  // namespace acutemesh
