// The command line: options into an Arguments value, and the help text.
#include "arguments.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <string_view>
#include <vector>

namespace acutemesh::cli {
namespace {

std::vector<std::string> splitList(const std::string& s) {
  std::vector<std::string> out;
  size_t start = 0;
  while (start <= s.size()) {
    size_t comma = s.find(',', start);
    if (comma == std::string::npos) comma = s.size();
    if (comma > start) out.push_back(s.substr(start, comma - start));
    start = comma + 1;
  }
  return out;
}

// "a, b or c": the names of a vocabulary table.
template <class Entry, size_t N>
std::string choices(const Entry (&table)[N]) {
  std::string out;
  for (size_t i = 0; i < N; ++i) out += std::string(i == 0 ? "" : i + 1 < N ? ", " : " or ") + table[i].name;
  return out;
}

bool takesValue(const std::string& a) {
  for (const char* option : {"-o", "--output", "--format", "--mode", "--max-angle", "--min-angle",
                             "--max-area", "--max-edge", "--size", "--grading", "--max-steiner",
                             "--fill", "--threads", "--time-limit", "--optimize", "--optimize-tries",
                             "--seed"})
    if (a == option) return true;
  return false;
}

// The message for an option given last, without its value.
std::string missingValue(const std::string& a) {
  if (a == "-o" || a == "--output") return a + " needs a file name base";
  if (a == "--format") return "--format needs a list, e.g. node,ele,svg";
  if (a == "--mode") return "--mode needs " + choices(kModes);
  if (a == "--fill") return "--fill needs " + choices(kFillRules);
  if (a == "--max-steiner") return "--max-steiner needs a count";
  if (a == "--threads") return "--threads needs a count";
  if (a == "--time-limit") return "--time-limit needs seconds";
  if (a == "--optimize") return "--optimize needs seconds";
  if (a == "--optimize-tries") return "--optimize-tries needs a count";
  if (a == "--seed") return "--seed needs a number";
  if (a == "--max-angle") return "--max-angle needs a number or auto";
  if (a == "--size") return "--size needs a size file (.json: a grid or points with sizes)";
  return a + " needs a number";
}

std::string readFormats(const std::string& v, Arguments& args) {
  args.formats.clear();
  for (const std::string& name : splitList(v)) {
    OutputFormat f;
    std::string message;
    if (!parseName(name, f, &message)) return message;
    args.formats.push_back(f);
  }
  return {};
}

std::string readBound(const std::string& a, const std::string& v, Options& opt) {
  if (a == "--max-angle" && v == "auto") {
    opt.maxAngle = kAutoMaxAngle;
    return {};
  }
  char* end = nullptr;
  const double x = std::strtod(v.c_str(), &end);
  if (a == "--max-angle" && (*end || v.empty()))
    return "--max-angle needs a number or auto, not '" + v + "'";
  if (*end || v.empty() || !(x >= 0)) return a + " needs a number >= 0, not '" + v + "'";
  if (a == "--max-angle") {
    if (!(x > 60 && x <= 90)) return "--max-angle must be above 60 and at most 90, or auto";
    opt.maxAngle = x;
  } else if (a == "--min-angle") {
    if (!(x < 60)) return "--min-angle must be below 60";
    opt.minAngle = x;
  } else if (a == "--max-edge" || a == "--grading") {
    if (!std::isfinite(x)) return a + " needs a finite number >= 0, not '" + v + "'";
    (a == "--max-edge" ? opt.maxEdge : opt.grading) = x;
  } else {
    opt.maxArea = x;
  }
  return {};
}

// A whole number from 0 to 2^64 - 1, in decimal: false (x unchanged) for anything else.
bool readWhole(const std::string& v, uint64_t& x) {
  char* end = nullptr;
  errno = 0;
  const unsigned long long n = std::strtoull(v.c_str(), &end, 10);
  if (*end || v.empty() || v[0] == '-' || errno == ERANGE) return false;
  x = n;
  return true;
}

std::string readCount(const std::string& a, const std::string& v, Options& opt) {
  char* end = nullptr;
  if (a == "--max-steiner") {
    const unsigned long long x = std::strtoull(v.c_str(), &end, 10);
    if (*end || v.empty() || x == 0 || x > 4000000000ull)
      return "--max-steiner needs a positive count, not '" + v + "'";
    opt.maxSteiner = uint32_t(x);
  } else {
    const unsigned long x = std::strtoul(v.c_str(), &end, 10);
    if (*end || v.empty() || v[0] == '-' || x == 0 || x > 1024)
      return "--threads needs a count from 1 to 1024, not '" + v + "'";
    opt.threads = unsigned(x);
  }
  return {};
}

// Applies option `a` with its value `v`: an error message, or empty.
std::string readValue(const std::string& a, const std::string& v, Arguments& args) {
  Options& opt = args.options;
  std::string message;
  if (a == "-o" || a == "--output") {
    args.output = v;
  } else if (a == "--format") {
    return readFormats(v, args);
  } else if (a == "--mode") {
    if (!parseName(v, opt.mode, &message)) return message;
  } else if (a == "--fill") {
    if (!parseName(v, opt.fill, &message)) return message;
    args.chosen.fill = true;
  } else if (a == "--size") {
    args.sizeFile = v;
  } else if (a == "--max-steiner" || a == "--threads") {
    return readCount(a, v, opt);
  } else if (a == "--time-limit") {
    char* end = nullptr;
    opt.timeLimit = std::strtod(v.c_str(), &end);
    if (*end || !(opt.timeLimit > 0)) return "--time-limit needs a positive number";
  } else if (a == "--optimize") {
    char* end = nullptr;
    opt.optimize = std::strtod(v.c_str(), &end);
    if (*end || v.empty() || !(opt.optimize >= 0) || opt.optimize > 1e6)
      return "--optimize needs seconds, 0 to 1000000, not '" + v + "'";
  } else if (a == "--optimize-tries") {
    if (!readWhole(v, opt.optimizeTries))
      return "--optimize-tries needs a whole number of tries, not '" + v + "'";
  } else if (a == "--seed") {
    if (!readWhole(v, opt.seed))
      return "--seed needs a whole number from 0 to 2^64 - 1, not '" + v + "'";
  } else {
    return readBound(a, v, opt);
  }
  return {};
}

// Applies flag `a` (an option without a value): false when there is no such flag.
bool readFlag(const std::string& a, Arguments& args) {
  if (a == "--convex-hull") {
    args.options.convexHull = true;
  } else if (a == "--exact-segments") {
    args.options.exactSegments = true;
  } else if (a == "--exact-feet" || a == "--no-exact-feet") {
    args.options.exactFeet = a == "--exact-feet";
    args.chosen.exactFeet = true;
  } else if (a == "--stats") {
    args.stats = true;
  } else if (a == "--no-output") {
    args.writeOutput = false;
  } else {
    return false;
  }
  return true;
}

// A refinement target says which mode it is for: --max-angle alone means acute, --min-angle,
// --max-area or a size alone quality (as Triangle's -q and -a switch refinement on). A mode that has no
// use for a target given with it is an error rather than a target silently ignored.
std::string modeForTargets(bool modeGiven, bool maxAngle, bool quality, Mode& mode) {
  if (!modeGiven) {
    if (maxAngle) mode = Mode::Acute;
    else if (quality) mode = Mode::Quality;
    return "";
  }
  const std::string name = std::string(nameOf(mode));
  if ((mode == Mode::Delaunay || mode == Mode::Cdt) && (maxAngle || quality))
    return std::string(maxAngle ? "--max-angle" : "--min-angle / --max-area / --max-edge / --size") +
           " has no effect with --mode " + name +
           ", which does not refine: use --mode acute, nonobtuse or quality (or leave --mode out)";
  if (maxAngle && mode != Mode::Acute)
    return "--max-angle is a target of --mode acute only, not of --mode " + name;
  return "";
}

}  // namespace

bool Arguments::wants(OutputFormat f) const {
  for (OutputFormat g : formats)
    if (g == f) return true;
  return false;
}

CommandLine parseCommandLine(int argc, const char* const* argv) {
  CommandLine c;
  Arguments& args = c.arguments;
  auto fail = [&c](std::string message) {
    c.action = CommandLine::UsageError;
    c.error = std::move(message);
    return c;
  };
  // The refinement targets given, for the mode they imply or contradict.
  bool modeGiven = false, maxAngleGiven = false, minAngleGiven = false, maxAreaGiven = false,
       gradingGiven = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    modeGiven |= a == "--mode", maxAngleGiven |= a == "--max-angle";
    minAngleGiven |= a == "--min-angle";
    maxAreaGiven |= a == "--max-area" || a == "--max-edge" || a == "--size";
    gradingGiven |= a == "--grading";
    if (a == "-h" || a == "--help") {
      c.action = CommandLine::Help;
      return c;
    } else if (a == "--version") {
      c.action = CommandLine::Version;
      return c;
    } else if (takesValue(a)) {
      if (i + 1 >= argc) return fail(missingValue(a));
      std::string error = readValue(a, argv[++i], args);
      if (!error.empty()) return fail(error);
    } else if (readFlag(a, args)) {
      continue;
    } else if (a.size() > 1 && a[0] == '-') {
      return fail("unknown option '" + a + "'");
    } else if (args.input.empty()) {
      args.input = a;
    } else {
      return fail("more than one input file ('" + args.input + "', '" + a + "')");
    }
  }
  if (args.input.empty()) return fail("no input file");
  if (gradingGiven && args.options.maxEdge == 0 && args.sizeFile.empty())
    return fail("--grading limits how fast sizes grow: give --max-edge or --size too");
  std::string error = modeForTargets(modeGiven, maxAngleGiven, minAngleGiven || maxAreaGiven,
                                     args.options.mode);
  if (!error.empty()) return fail(error);
  return c;
}

namespace {

constexpr size_t kHelpColumn = 23;  // where the descriptions of options start
constexpr size_t kHelpWidth = 100;

// `label` padded to the description column, then `text` wrapped to the help's width (lines
// after the first indented two more).
void addWrapped(std::string& out, const std::string& label, std::string_view text) {
  std::string line = label;
  line.resize(std::max(line.size() + 1, kHelpColumn), ' ');
  const std::string indent(kHelpColumn + 2, ' ');
  bool lineEmpty = true;
  while (!text.empty()) {
    const size_t space = text.find(' ');
    const std::string_view word = text.substr(0, space);
    text = space == std::string_view::npos ? std::string_view() : text.substr(space + 1);
    if (!lineEmpty && line.size() + 1 + word.size() > kHelpWidth) {
      out += line + "\n";
      line = indent;
      lineEmpty = true;
    }
    if (!lineEmpty) line += ' ';
    line += word;
    lineEmpty = false;
  }
  out += line + "\n";
}

// One line (or more, wrapped) per entry of a table: "name: description", the default marked;
// the first beside `label`.
template <class Entry, size_t N, class Enum>
void addChoices(std::string& out, std::string label, const Entry (&table)[N], Enum byDefault) {
  for (const Entry& e : table) {
    std::string text = std::string(e.name) + ": " + e.description;
    if (e.value == byDefault) text += " (default)";
    addWrapped(out, label, text);
    label.clear();
  }
}

}  // namespace

std::string usageText() {
  const Arguments defaults;
  std::string formats, defaultFormats;
  std::vector<std::string> special;  // the formats whose extension is not their name
  for (const OutputFormatInfo& f : kOutputFormats) {
    formats += std::string(formats.empty() ? "" : ",") + f.name;
    if (f.extension != "." + std::string(f.name))
      special.push_back(std::string(f.name) + ": BASE" + f.extension + ", " + f.description);
  }
  for (OutputFormat f : defaults.formats) defaultFormats += std::string(defaultFormats.empty() ? "" : ",") + nameOf(f);

  std::string s =
      "usage: acutemesh [options] INPUT\n\n"
      "Triangulates a point set or planar straight-line graph.\n"
      "INPUT: .poly | .node (Triangle's formats) | .json (acutemesh PSLG or rings, CG:SHOP 2025 instance)\n\n"
      "options:\n";
  addWrapped(s, "  -o, --output BASE", "write BASE.node, BASE.ele, ... (default: INPUT without extension + \".1\")");
  addWrapped(s, "  --format LIST", "comma list of " + formats + " (default: " + defaultFormats + ")");
  for (const std::string& line : special) addWrapped(s, "", line);
  addChoices(s, "  --mode MODE", kModes, defaults.options.mode);
  s += R"(  --max-angle DEG      acute: every angle below DEG (60 < DEG <= 90, default 90), certified
                       exactly. auto: the lowest bound the run reaches, said on stderr. At or
                       below the domain's floor (--stats: angleFloor): said, aims as auto, exit 1
  --min-angle DEG      smallest angle wanted (quality; also with acute / nonobtuse). Quality
                       terminates up to 40; above, it falls back to 40 if it wanders
  --max-area A         largest triangle area wanted (any refinement mode; a .poly's regional
                       area bounds also hold in their regions)
  --max-edge L         longest edge wanted (any refinement mode)
  --size FILE          edge sizes over the plane (any refinement mode): a .json with "grid"
                       {x0, y0, dx, dy, nx, ny, h: [nx * ny sizes]} (bilinear) and/or "points"
                       [[x, y, size], ...] (linear between them), or a .node whose first
                       vertex attribute is the size
  --grading G          sizes grow at most G per unit of distance from --max-edge, --size and
                       the input's small features (0.2 to 0.5 is usual; default: no limit)
  --max-steiner N      give up after adding N points (exit status 1; default 50 per input
                       vertex, at least 20000)
  --fill RULE          which regions form the domain:
)";
  addChoices(s, "", kFillRules, defaults.options.fill);
  s += R"(  --convex-hull        keep every triangle of the convex hull (hole points still apply)
  --exact-segments     put Steiner points exactly on their segments' lines where a representable
                       point is near (integer coordinates), not within rounding of them (more
                       points; always on for CG:SHOP input, whose verifier is exact)
  --exact-feet         nonobtuse: Steiner points on segments may be exact altitude feet, rationals
                       a double cannot hold (far fewer points on tilted segments). They are exact
                       in the cgshop and json formats, rounded in the others; --stats counts
                       them as exactPoints (default for CG:SHOP input; --no-exact-feet: off)
  --time-limit S       give up after S seconds (exit status 1)
  --optimize S         after refinement, spend S seconds looking for a mesh with fewer Steiner
                       points (acute, at any --max-angle; nonobtuse; quality with a
                       --min-angle, sized too): the best mesh found is kept, never one with
                       more points
  --optimize-tries N   at most N tries of that search per thread (with no --optimize, the
                       search runs until N): the same seed, threads and N make the same mesh
                       on any machine, which seconds do not
  --seed N             the --optimize search's random choices (default 1)
  --threads N          threads for acute and nonobtuse refinement (default: one per hardware
                       thread; 1: none besides the main one); the mesh is the same for any N
  --stats              print one JSON object of figures on stdout
  --no-output          compute, write nothing (for timing)
  -h, --help           this text
  --version            print the version

exit status: 0 ok; 1 target not met; 2 bad input or usage (one-line message on stderr)
)";
  return s;
}

}  // namespace acutemesh::cli
