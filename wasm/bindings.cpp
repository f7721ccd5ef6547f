// Embind bindings: the core's C++ API (mesh, validate, the io readers and writers, the
// vocabulary and the input policy) as plain functions over typed arrays. Bindings only: the
// checks of argument types and the defaults live in the JS facade (wasm/js/api.js), which takes
// the names and defaults it checks against from core_vocabulary(). Enums cross as their names
// (vocabulary.h), already checked by the facade; results are plain JS objects that own copies
// of the data (nothing for JS to delete()).
#include <emscripten/bind.h>
#include <emscripten/emscripten.h>
#include <emscripten/val.h>
#include <malloc.h>

#include <atomic>
#include <functional>
#include <cstdlib>
#include <new>
#include <string>
#include <vector>

#include "acutemesh/acutemesh.h"
#include "acutemesh/io.h"
#include "acutemesh/vocabulary.h"

using emscripten::val;

// Out of memory (the heap cannot grow): operator new calls this handler, which marks the
// instance so the facade can tell this abort from an internal error, then aborts as it
// would have anyway (exceptions are off, so there is no unwinding to recover in place; the
// facade replaces the instance).
EM_JS(void, markOutOfMemory, (), { Module['outOfMemory'] = true; });

namespace {

[[noreturn]] void onOutOfMemory() {
  markOutOfMemory();
  std::abort();
}
[[maybe_unused]] const bool kNewHandlerInstalled = (std::set_new_handler(onOutOfMemory), true);

using namespace acutemesh;

// A JS typed array (or array of numbers) into a vector: one TypedArray.set into wasm memory.
template <class T>
std::vector<T> fromJs(const val& array) {
  if (array.isUndefined() || array.isNull()) return {};
  return emscripten::convertJSArrayToNumberVector<T>(array);
}

// A vector out as a typed array that JS owns (slice copies out of the wasm heap, so the view
// never dangles when memory grows or the vector is freed).
template <class T>
val toJs(const std::vector<T>& v) {
  return val(emscripten::typed_memory_view(v.size(), v.data())).call<val>("slice");
}

// Text in and out as UTF-8 bytes (a Uint8Array from the facade's TextEncoder; a string made by
// TextDecoder) rather than through Embind's std::string conversion, whose buffer comes from a
// malloc nobody checks: with the heap full it would write through a null pointer. Here the
// buffer is allocated by operator new, so a big text meets the out-of-memory handler instead.
std::string textFromJs(const val& bytes) {
  std::string s(bytes["length"].as<size_t>(), '\0');
  val(emscripten::typed_memory_view(s.size(), reinterpret_cast<uint8_t*>(s.data())))
      .call<void>("set", bytes);
  return s;
}

val textToJs(const std::string& s) {
  static const val decoder = val::global("TextDecoder").new_();
  return decoder.call<val>(
      "decode", val(emscripten::typed_memory_view(s.size(), reinterpret_cast<const uint8_t*>(s.data()))));
}

val stringsToJs(const std::vector<std::string>& strings) {
  val out = val::array();
  for (const std::string& s : strings) out.call<void>("push", s);
  return out;
}

// `labels` (undefined, or the facade's checked {vertexMarkers, segmentMarkers, regions}, the
// regions as a Float64Array of x, y, attribute, maxArea per region).
Pslg pslgFromJs(const val& points, const val& segments, const val& holes,
                const val& labels = val::undefined()) {
  Pslg p;
  p.points = fromJs<double>(points);
  p.segments = fromJs<uint32_t>(segments);
  p.holes = fromJs<double>(holes);
  if (labels.isUndefined()) return p;
  p.vertexMarkers = fromJs<int32_t>(labels["vertexMarkers"]);
  p.segmentMarkers = fromJs<int32_t>(labels["segmentMarkers"]);
  const std::vector<double> regions = fromJs<double>(labels["regions"]);
  for (size_t i = 0; i + 3 < regions.size(); i += 4) {
    Region r;
    r.x = regions[i], r.y = regions[i + 1], r.attribute = regions[i + 2], r.maxArea = regions[i + 3];
    p.regions.push_back(r);
  }
  return p;
}

// Regions out as the facade takes them in: x, y, attribute, maxArea per region.
val regionsToJs(const std::vector<Region>& regions) {
  std::vector<double> flat;
  flat.reserve(4 * regions.size());
  for (const Region& r : regions) flat.insert(flat.end(), {r.x, r.y, r.attribute, r.maxArea});
  return toJs(flat);
}

Mesh meshFromJs(const val& m) {
  Mesh mesh;
  mesh.points = fromJs<double>(m["points"]);
  mesh.triangles = fromJs<uint32_t>(m["triangles"]);
  mesh.segments = fromJs<uint32_t>(m["segments"]);
  mesh.vertexKind = fromJs<uint8_t>(m["vertexKind"]);
  // (Labels as mesh() made them, for the writers; the facade drops those of the wrong length.)
  mesh.segmentInput = fromJs<uint32_t>(m["segmentInput"]);
  mesh.vertexMarkers = fromJs<int32_t>(m["vertexMarkers"]);
  mesh.segmentMarkers = fromJs<int32_t>(m["segmentMarkers"]);
  mesh.triangleAttributes = fromJs<double>(m["triangleAttributes"]);
  const val exact = m["exactPoints"];  // checked by the facade: [{vertex, x, y}]
  const unsigned count = exact.isUndefined() ? 0 : exact["length"].as<unsigned>();
  for (unsigned i = 0; i < count; ++i)
    mesh.exactPoints.push_back({exact[i]["vertex"].as<uint32_t>(), exact[i]["x"].as<std::string>(),
                                exact[i]["y"].as<std::string>()});
  return mesh;
}

// A JS function of (x, y) as the core's size function: called on this thread (the wasm build
// runs one). The facade's wrapper catches what the caller's function throws and returns NaN,
// which the core reports as a bad size.
std::function<double(double, double)> functionFromJs(const val& f) {
  if (f.typeOf().as<std::string>() != "function") return {};
  return [f](double x, double y) { return f(x, y).as<double>(); };
}

// options.size as the facade normalised it: {function, grid: {x0, y0, dx, dy, nx, ny, h},
// points, sizes, maxArea}, each optional.
SizeField sizeFromJs(const val& s) {
  SizeField size;
  size.function = functionFromJs(s["function"]);
  size.maxArea = functionFromJs(s["maxArea"]);
  const val g = s["grid"];
  if (!g.isUndefined()) {
    size.grid.x0 = g["x0"].as<double>(), size.grid.y0 = g["y0"].as<double>();
    size.grid.dx = g["dx"].as<double>(), size.grid.dy = g["dy"].as<double>();
    size.grid.nx = g["nx"].as<uint32_t>(), size.grid.ny = g["ny"].as<uint32_t>();
    size.grid.h = fromJs<double>(g["h"]);
  }
  size.points = fromJs<double>(s["points"]);
  size.sizes = fromJs<double>(s["sizes"]);
  return size;
}

// Options from the facade's checked object: mode and fill arrive as names it has checked.
Options optionsFromJs(const val& o) {
  Options opt;
  parseName(o["mode"].as<std::string>(), opt.mode);
  parseName(o["fill"].as<std::string>(), opt.fill);
  opt.convexHull = o["convexHull"].as<bool>();
  opt.exactSegments = o["exactSegments"].as<bool>();
  opt.exactFeet = o["exactFeet"].as<bool>();
  // 'auto', or degrees the facade has checked.
  opt.maxAngle = o["maxAngle"].isString() ? kAutoMaxAngle : o["maxAngle"].as<double>();
  opt.minAngle = o["minAngle"].as<double>();
  opt.maxArea = o["maxArea"].as<double>();
  opt.maxSteiner = o["maxSteiner"].as<uint32_t>();
  opt.timeLimit = o["timeLimit"].as<double>();
  opt.adjacency = !o["adjacency"].isUndefined() && o["adjacency"].as<bool>();
  if (!o["optimize"].isUndefined()) opt.optimize = o["optimize"].as<double>();
  if (!o["optimizeTries"].isUndefined())
    opt.optimizeTries = uint64_t(o["optimizeTries"].as<double>());
  if (!o["seed"].isUndefined()) opt.seed = uint64_t(o["seed"].as<double>());
  if (!o["maxEdge"].isUndefined()) opt.maxEdge = o["maxEdge"].as<double>();
  if (!o["grading"].isUndefined()) opt.grading = o["grading"].as<double>();
  if (!o["size"].isUndefined()) opt.size = sizeFromJs(o["size"]);
  return opt;
}

val statsToJs(const Stats& s) {
  val o = val::object();
  o.set("inputVertices", s.inputVertices);
  o.set("inputSegments", s.inputSegments);
  o.set("inputHoles", s.inputHoles);
  o.set("vertices", s.vertices);
  o.set("triangles", s.triangles);
  o.set("segments", s.segments);
  o.set("steiner", s.steiner);
  o.set("duplicates", s.duplicates);
  o.set("minAngle", s.minAngle);
  o.set("maxAngle", s.maxAngle);
  o.set("nonAcute", s.nonAcute);
  o.set("obtuse", s.obtuse);
  o.set("targetMet", s.targetMet);
  o.set("certified", s.certified);
  o.set("smallestInputAngle", s.smallestInputAngle);
  o.set("smallestDomainAngle", s.smallestDomainAngle);
  o.set("angleFloor", s.angleFloor);
  o.set("angleBound", s.angleBound);
  o.set("sizeRatio", s.sizeRatio);
  val phases = val::object();
  for (const PhaseTime& p : s.phases) phases.set(p.phase, p.seconds);
  o.set("phases", phases);
  o.set("seconds", s.seconds);
  o.set("warnings", stringsToJs(s.warnings));
  return o;
}

// mesh(): `onProgress(phase, fraction, vertices)` is called synchronously from inside the
// core; a truthy return value asks the core to stop (status Cancelled). The JS facade turns
// AbortSignals and exceptions thrown by the user's callback into that return value, so no JS
// exception ever unwinds through C++ frames (which would leak their memory).
val meshJs(const val& points, const val& segments, const val& holes, const val& labels,
           const val& options, const val& onProgress) {
  Pslg input = pslgFromJs(points, segments, holes, labels);
  Options opt = optionsFromJs(options);
  std::atomic<bool> cancel{false};
  opt.cancel = &cancel;
  if (onProgress.typeOf().as<std::string>() == "function") {
    opt.progress = [&](const Progress& p) {
      if (onProgress(std::string(p.phase), p.fraction, p.vertices).as<bool>()) cancel = true;
    };
  }
  Result r = mesh(input, opt);
  val out = val::object();
  out.set("status", std::string(nameOf(r.status)));
  out.set("message", r.message);
  out.set("points", toJs(r.mesh.points));
  out.set("triangles", toJs(r.mesh.triangles));
  out.set("segments", toJs(r.mesh.segments));
  out.set("vertexKind", toJs(r.mesh.vertexKind));
  out.set("segmentInput", toJs(r.mesh.segmentInput));
  out.set("vertexMarkers", toJs(r.mesh.vertexMarkers));
  out.set("segmentMarkers", toJs(r.mesh.segmentMarkers));
  if (!r.mesh.triangleAttributes.empty())
    out.set("triangleAttributes", toJs(r.mesh.triangleAttributes));
  if (opt.adjacency) {
    const Adjacency& a = r.mesh.adjacency;
    out.set("halfedges", toJs(a.halfedges));
    out.set("neighbors", toJs(a.neighbors));
    out.set("edges", toJs(a.edges));
    out.set("edgeMarkers", toJs(a.edgeMarkers));
    out.set("hull", toJs(a.hull));
    out.set("hullStarts", toJs(a.hullStarts));
  }
  val exact = val::array();
  for (const ExactPoint& p : r.mesh.exactPoints) {
    val e = val::object();
    e.set("vertex", p.vertex);
    e.set("x", p.x);
    e.set("y", p.y);
    exact.call<void>("push", e);
  }
  out.set("exactPoints", exact);
  out.set("stats", statsToJs(r.stats));
  return out;
}

val validateJs(const val& points, const val& segments, const val& holes, const val& mesh,
               const val& options) {
  Validation v = validate(pslgFromJs(points, segments, holes), meshFromJs(mesh),
                          optionsFromJs(options));
  val out = val::object();
  out.set("ok", v.ok);
  out.set("errors", stringsToJs(v.errors));
  return out;
}

// Parsers: {ok, message} on failure, else the PSLG and what the text said about it: its
// format, and the fill rule the input policy gives it when that is not the default (rings).
val inputToJs(const ParseResult& r, const Input& in) {
  val out = val::object();
  out.set("ok", r.ok);
  out.set("message", r.message);
  if (!r.ok) return out;
  out.set("points", toJs(in.pslg.points));
  out.set("segments", toJs(in.pslg.segments));
  out.set("holes", toJs(in.pslg.holes));
  out.set("vertexMarkers", toJs(in.pslg.vertexMarkers));
  out.set("segmentMarkers", toJs(in.pslg.segmentMarkers));
  out.set("regions", regionsToJs(in.pslg.regions));
  out.set("format", std::string(nameOf(in.format)));
  Options implied;
  applyInputPolicy(in, {}, implied);
  if (implied.fill != Options{}.fill) out.set("fill", std::string(nameOf(implied.fill)));
  out.set("instanceUid", in.instanceUid);
  out.set("warnings", stringsToJs(in.warnings));
  return out;
}

val parsePolyJs(const val& text, const std::string& name, const val& nodeText,
                const std::string& nodeName) {
  Input in;
  ParseResult r = parsePoly(textFromJs(text), name, in, textFromJs(nodeText), nodeName);
  return inputToJs(r, in);
}

val parseNodeJs(const val& text, const std::string& name) {
  Input in;
  ParseResult r = parseNode(textFromJs(text), name, in);
  return inputToJs(r, in);
}

val parseJsonJs(const val& text, const std::string& name) {
  Input in;
  ParseResult r = parseJson(textFromJs(text), name, in);
  return inputToJs(r, in);
}

// Writers, by the format's name (one the facade checked, not needing an instance).
val formatJs(const std::string& name, const val& m) {
  OutputFormat format = OutputFormat::Node;
  parseName(name, format);
  return textToJs(formatMesh(format, meshFromJs(m)));
}

val formatCgshopJs(const val& m, const std::string& uid, uint32_t instanceVertices) {
  return textToJs(formatCgshopSolution(meshFromJs(m), uid, instanceVertices));
}

// The wasm heap: its size (grows, never shrinks) and the bytes malloc has handed out and not
// taken back. The tests use `allocated` to show that calls leave nothing behind.
val memoryJs() {
  struct mallinfo mi = mallinfo();
  val out = val::object();
  out.set("heapSize", double(__builtin_wasm_memory_size(0)) * 65536);
  out.set("allocated", double(mi.uordblks));
  return out;
}

std::string versionJs() { return version(); }

// --- the vocabulary and the input policy ---------------------------------------------------

template <class Entry, size_t N>
val namedToJs(const Entry (&table)[N]) {
  val out = val::array();
  for (const Entry& e : table) {
    val o = val::object();
    o.set("name", std::string(e.name));
    o.set("value", int(e.value));
    o.set("description", std::string(e.description));
    out.call<void>("push", o);
  }
  return out;
}

// Options' defaults, by the names the facade's options have.
val defaultsToJs() {
  const Options d;
  val o = val::object();
  o.set("mode", std::string(nameOf(d.mode)));
  o.set("fill", std::string(nameOf(d.fill)));
  o.set("convexHull", d.convexHull);
  o.set("exactSegments", d.exactSegments);
  o.set("exactFeet", d.exactFeet);
  o.set("maxAngle", d.maxAngle);
  o.set("minAngle", d.minAngle);
  o.set("maxArea", d.maxArea);
  o.set("maxEdge", d.maxEdge);
  o.set("grading", d.grading);
  o.set("maxSteiner", d.maxSteiner);
  o.set("timeLimit", d.timeLimit);
  o.set("adjacency", d.adjacency);
  o.set("optimize", d.optimize);
  o.set("optimizeTries", double(d.optimizeTries));
  o.set("seed", double(d.seed));
  o.set("qualityMinAngle", kQualityDefaultMinAngle);
  // The fill rule the input policy gives rings (fromRings' default, as for JSON rings).
  Options rings;
  applyInputPolicy(InputFormat::JsonPslg, true, {}, rings);
  o.set("ringsFill", std::string(nameOf(rings.fill)));
  return o;
}

// The tables of vocabulary.h and the defaults: what the facade checks names against, and what
// it exports as `vocabulary`.
val vocabularyJs() {
  val out = val::object();
  out.set("modes", namedToJs(kModes));
  out.set("fillRules", namedToJs(kFillRules));
  out.set("statuses", namedToJs(kStatuses));
  out.set("vertexKinds", namedToJs(kVertexKinds));
  out.set("inputFormats", namedToJs(kInputFormats));
  val formats = val::array();
  for (const OutputFormatInfo& f : kOutputFormats) {
    val o = val::object();
    o.set("name", std::string(f.name));
    o.set("value", int(f.value));
    o.set("extension", std::string(f.extension));
    o.set("mediaType", std::string(f.mediaType));
    o.set("roundsExactPoints", f.roundsExactPoints);
    o.set("needsInstance", f.needsInstance);
    o.set("description", std::string(f.description));
    formats.call<void>("push", o);
  }
  out.set("outputFormats", formats);
  out.set("defaults", defaultsToJs());
  return out;
}

// The core's message for a name that is not one of `kind`'s ("mode", "fill", "inputFormat",
// "outputFormat"): the choices, and the nearest name when one is close.
std::string unknownNameJs(const std::string& kind, const std::string& name) {
  std::string message;
  Mode mode;
  FillRule fill;
  InputFormat input;
  OutputFormat output;
  if (kind == "mode") parseName(name, mode, &message);
  else if (kind == "fill") parseName(name, fill, &message);
  else if (kind == "inputFormat") parseName(name, input, &message);
  else parseName(name, output, &message);
  return message;
}

// The input policy for an input of `format` (a checked name) meshed with the facade's
// options: the exact flags it sets. The fill rule is the caller's here (a parsed input's
// implied fill came with the parse, see inputToJs).
val inputPolicyJs(const std::string& format, bool exactFeetChosen, const val& options) {
  InputFormat f = InputFormat::Unknown;
  parseName(format, f);
  Options opt = optionsFromJs(options);
  ChosenOptions chosen;
  chosen.fill = true;
  chosen.exactFeet = exactFeetChosen;
  applyInputPolicy(f, false, chosen, opt);
  val out = val::object();
  out.set("exactSegments", opt.exactSegments);
  out.set("exactFeet", opt.exactFeet);
  return out;
}

}  // namespace

EMSCRIPTEN_BINDINGS(acutemesh) {
  emscripten::function("core_mesh", &meshJs);
  emscripten::function("core_validate", &validateJs);
  emscripten::function("core_parsePoly", &parsePolyJs);
  emscripten::function("core_parseNode", &parseNodeJs);
  emscripten::function("core_parseJson", &parseJsonJs);
  emscripten::function("core_format", &formatJs);
  emscripten::function("core_formatCgshop", &formatCgshopJs);
  emscripten::function("core_memory", &memoryJs);
  emscripten::function("core_version", &versionJs);
  emscripten::function("core_vocabulary", &vocabularyJs);
  emscripten::function("core_unknownName", &unknownNameJs);
  emscripten::function("core_inputPolicy", &inputPolicyJs);
}
