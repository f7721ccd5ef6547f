// Size files (acutemesh/io.h, parseSizeField): a JSON grid or JSON points with sizes, read
// with the tokenizer of json.h into a SizeField. Values are checked here for form; mesh()
// checks them for meaning (positive sizes, the grid's shape).
#include <cstdio>

#include "../build.h"
#include "json.h"
#include "parse_context.h"

namespace acutemesh::io {
namespace {

bool readGrid(JsonReader& r, SizeField::Grid& g) {
  bool has[7] = {};
  const char* names[7] = {"x0", "y0", "dx", "dy", "nx", "ny", "h"};
  size_t objectLine = r.line();
  bool ok = r.object("the \"grid\" object", [&](const std::string& key, size_t line) {
    double* number[4] = {&g.x0, &g.y0, &g.dx, &g.dy};
    for (int k = 0; k < 7; ++k) {
      if (key != names[k]) continue;
      has[k] = true;
      if (k < 4) return r.number(*number[k], ("a number for \"" + key + "\"").c_str());
      if (k < 6) {
        uint64_t n = 0;
        if (!r.index(n, ("a count for \"" + key + "\"").c_str())) return false;
        if (n == 0 || n > (1u << 16))
          return r.ctx().fail(line, "expected \"" + key + "\" from 1 to 65536, found " + std::to_string(n));
        (k == 4 ? g.nx : g.ny) = uint32_t(n);
        return true;
      }
      return r.array("\"h\"", [&] {
        double v;
        if (!r.number(v, "a size (a number) in \"h\"")) return false;
        if (!(v > 0)) return r.ctx().fail(r.line(), "expected sizes > 0 in \"h\", found " + detail::shortestText(v));
        g.h.push_back(v);
        return true;
      });
    }
    r.ctx().warn(line, "unknown key \"" + printable(key) + "\" in \"grid\" skipped");
    return r.skipValue(1);
  });
  if (!ok) return false;
  for (int k = 0; k < 7; ++k)
    if (!has[k]) return r.ctx().fail(objectLine, std::string("expected \"") + names[k] + "\" in \"grid\"");
  if (!(g.dx > 0) || !(g.dy > 0))
    return r.ctx().fail(objectLine, "expected \"dx\" and \"dy\" > 0 in \"grid\"");
  if (g.h.size() != size_t(g.nx) * g.ny)
    return r.ctx().fail(objectLine, "expected nx * ny = " + std::to_string(size_t(g.nx) * g.ny) +
                                        " sizes in \"h\", found " + std::to_string(g.h.size()));
  return true;
}

bool readPoints(JsonReader& r, SizeField& s) {
  return r.array("\"points\"", [&] {
    double v[3];
    int k = 0;
    const bool ok = r.array("a point [x, y, size]", [&] {
      if (k == 3) return r.fail("']' after [x, y, size]");
      return r.number(v[k++], "a number in [x, y, size]");
    });
    if (!ok) return false;
    if (k != 3) return r.fail("3 numbers [x, y, size] before ']'");
    if (!(v[2] > 0)) return r.ctx().fail(r.line(), "expected a size > 0 in [x, y, size], found " + detail::shortestText(v[2]));
    s.points.insert(s.points.end(), {v[0], v[1]});
    s.sizes.push_back(v[2]);
    return true;
  });
}

}  // namespace
}  // namespace acutemesh::io

namespace acutemesh {

ParseResult parseSizeField(std::string_view text, const std::string& name, SizeField& out,
                           std::vector<std::string>* warnings) {
  io::Ctx c{name, warnings, {}};
  io::JsonReader r(text, c);
  SizeField s;
  bool any = false;
  r.ws();
  const size_t line = r.line();
  bool ok = r.object("the top-level JSON object", [&](const std::string& key, size_t keyLine) {
    if (key == "grid" || key == "points") {
      any = true;
      return key == "grid" ? io::readGrid(r, s.grid) : io::readPoints(r, s);
    }
    c.warn(keyLine, "unknown key \"" + io::printable(key) + "\" skipped");
    return r.skipValue(1);
  });
  if (ok) {
    r.ws();
    if (!r.atEnd()) ok = r.fail("end of text after the top-level object");
  }
  if (ok && !any) ok = c.fail(line, "expected \"grid\" or \"points\" in a size file");
  if (!ok) return io::failure(std::move(c.message));
  out.grid = std::move(s.grid);
  out.points = std::move(s.points);
  out.sizes = std::move(s.sizes);
  return {};
}

}  // namespace acutemesh
