// acutemesh: the command-line tool. Reads a PSLG, meshes it, writes the mesh in the formats
// asked for. Exit status: 0 ok, 1 target not met (best mesh written), 2 bad input or usage.
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <new>
#include <stdexcept>
#include <unistd.h>
#include <string>
#include <vector>
#ifdef __GLIBC__
#include <malloc.h>
#endif

#include "acutemesh/acutemesh.h"
#include "acutemesh/io.h"

namespace {

using namespace acutemesh;

const char* kUsage = R"(usage: acutemesh [options] INPUT

Triangulates a point set or planar straight-line graph.
INPUT: .poly | .node (Triangle's formats) | .json (acutemesh PSLG or rings, CG:SHOP 2025 instance)

options:
  -o, --output BASE    write BASE.node, BASE.ele, ... (default: INPUT without extension + ".1")
  --format LIST        comma list of node,ele,poly,json,off,obj,svg,cgshop (default: node,ele)
                       cgshop: BASE.solution.json, a CG:SHOP 2025 solution (CG:SHOP input only)
  --mode MODE          delaunay: Delaunay triangulation of the vertices (segments ignored)
                       cdt: constrained Delaunay triangulation of the domain (default)
                       acute: refine until every angle < --max-angle (default 90)
                       nonobtuse: refine until every angle <= 90
                       quality: refine until every angle >= --min-angle (default 20;
                       terminates up to 40; above, falls back to 40 if it wanders)
  --max-angle DEG      acute mode's bound (exact at 90; 60 < DEG <= 90)
  --min-angle DEG      smallest angle wanted (quality; also with acute / nonobtuse)
  --max-area A         largest triangle area wanted (any refinement mode)
  --max-steiner N      give up after adding N points (exit status 1; default 50 per input
                       vertex, at least 20000)
  --fill RULE          which regions form the domain:
                       triangle: Triangle's rule: the convex hull minus what is reachable from
                                 outside or from a hole point without crossing a segment
                                 (default for .poly, .node and CG:SHOP input)
                       evenodd:  regions inside an odd number of rings (default for JSON rings)
                       nonzero:  regions with non-zero winding number (segments are directed)
  --convex-hull        keep every triangle of the convex hull (hole points still apply)
  --exact-segments     put Steiner points exactly on their segments' lines where a representable
                       point is near (integer coordinates), not within rounding of them (more
                       points; always on for CG:SHOP input, whose verifier is exact)
  --exact-feet         nonobtuse: Steiner points on segments may be exact altitude feet, rationals
                       a double cannot hold (far fewer points on tilted segments). They are exact
                       in the cgshop and json formats, rounded in the others; --stats counts
                       them as exactPoints (default for CG:SHOP input; --no-exact-feet: off)
  --time-limit S       give up after S seconds (exit status 1)
  --threads N          threads for acute and nonobtuse refinement (default: one per hardware
                       thread; 1: none besides the main one); the mesh is the same for any N
  --stats              print one JSON object of figures on stdout
  --no-output          compute, write nothing (for timing)
  -h, --help           this text
  --version            print the version

exit status: 0 ok; 1 target not met; 2 bad input or usage (one-line message on stderr)
)";

int usageError(const std::string& message) {
  std::fprintf(stderr, "acutemesh: %s\n(try 'acutemesh --help')\n", message.c_str());
  return 2;
}

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

std::string jsonString(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

const char* modeName(Mode m) {
  switch (m) {
    case Mode::Delaunay: return "delaunay";
    case Mode::Cdt: return "cdt";
    case Mode::Quality: return "quality";
    case Mode::NonObtuse: return "nonobtuse";
    case Mode::Acute: return "acute";
  }
  return "?";
}

const char* fillName(FillRule f) {
  switch (f) {
    case FillRule::Triangle: return "triangle";
    case FillRule::EvenOdd: return "evenodd";
    case FillRule::NonZero: return "nonzero";
  }
  return "?";
}

const char* statusName(Status s) {
  switch (s) {
    case Status::Ok: return "ok";
    case Status::TargetNotMet: return "target-not-met";
    case Status::BadInput: return "bad-input";
    case Status::Cancelled: return "cancelled";
  }
  return "?";
}

void printStats(const std::string& input, const Options& opt, const Result& r,
                const std::vector<PhaseTime>& phases, const std::vector<std::string>& warnings) {
  const Stats& s = r.stats;
  std::printf("{\"input\": %s, \"mode\": \"%s\", \"fill\": \"%s\", \"status\": \"%s\",\n",
              jsonString(input).c_str(), modeName(opt.mode), fillName(opt.fill),
              statusName(r.status));
  std::printf(" \"inputVertices\": %u, \"inputSegments\": %u, \"inputHoles\": %u,\n",
              s.inputVertices, s.inputSegments, s.inputHoles);
  std::printf(" \"vertices\": %u, \"triangles\": %u, \"segments\": %u, \"steiner\": %u, "
              "\"exactPoints\": %zu, \"duplicates\": %u,\n",
              s.vertices, s.triangles, s.segments, s.steiner, r.mesh.exactPoints.size(), s.duplicates);
  std::printf(" \"minAngle\": %.17g, \"maxAngle\": %.17g, \"nonAcute\": %u, \"obtuse\": %u,\n",
              s.minAngle, s.maxAngle, s.nonAcute, s.obtuse);
  std::printf(" \"targetMet\": %s, \"certified\": %s, \"smallestInputAngle\": %.17g,\n",
              s.targetMet ? "true" : "false", s.certified ? "true" : "false",
              s.smallestInputAngle);
  // Triangles (indices into the written .ele / "triangles") that miss the target.
  std::printf(" \"missedTriangles\": [");
  for (size_t i = 0; i < s.missedTriangles.size(); ++i)
    std::printf("%s%u", i ? ", " : "", s.missedTriangles[i]);
  std::printf("],\n");
  std::printf(" \"seconds\": {");
  double total = 0;
  for (size_t i = 0; i < phases.size(); ++i) {
    std::printf("%s\"%s\": %.6f", i ? ", " : "", phases[i].phase.c_str(), phases[i].seconds);
    total += phases[i].seconds;
  }
  std::printf("%s\"total\": %.6f},\n", phases.empty() ? "" : ", ", total);
  std::printf(" \"warnings\": [");
  for (size_t i = 0; i < warnings.size(); ++i)
    std::printf("%s%s", i ? ", " : "", jsonString(warnings[i]).c_str());
  std::printf("]}\n");
}

double secondsSince(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace

static int run(int argc, char** argv) {
  std::string input, output;
  std::vector<std::string> formats{"node", "ele"};
  bool cgshop = false;  // --format cgshop: BASE.solution.json, written apart from the others
  Options opt;
  bool fillGiven = false, wantStats = false, writeOutput = true;
  int exactFeet = -1;  // --exact-feet 1, --no-exact-feet 0, neither: by input format

  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto value = [&](std::string& out) {
      if (i + 1 >= argc) return false;
      out = argv[++i];
      return true;
    };
    std::string v;
    if (a == "-h" || a == "--help") {
      std::fputs(kUsage, stdout);
      return 0;
    } else if (a == "--version") {
      std::printf("acutemesh %s\n", version());
      return 0;
    } else if (a == "-o" || a == "--output") {
      if (!value(output)) return usageError(a + " needs a file name base");
    } else if (a == "--format") {
      if (!value(v)) return usageError("--format needs a list, e.g. node,ele,svg");
      formats.clear();
      cgshop = false;
      for (const std::string& f : splitList(v)) {
        if (f == "cgshop") {
          cgshop = true;
          continue;
        }
        if (f != "node" && f != "ele" && f != "poly" && f != "json" && f != "off" &&
            f != "obj" && f != "svg")
          return usageError("unknown format '" + f +
                            "' (node, ele, poly, json, off, obj, svg, cgshop)");
        formats.push_back(f);
      }
    } else if (a == "--mode") {
      if (!value(v)) return usageError("--mode needs delaunay, cdt, acute, nonobtuse or quality");
      if (v == "delaunay") opt.mode = Mode::Delaunay;
      else if (v == "cdt") opt.mode = Mode::Cdt;
      else if (v == "acute") opt.mode = Mode::Acute;
      else if (v == "nonobtuse") opt.mode = Mode::NonObtuse;
      else if (v == "quality") opt.mode = Mode::Quality;
      else return usageError("unknown mode '" + v + "' (delaunay, cdt, acute, nonobtuse, quality)");
    } else if (a == "--max-angle" || a == "--min-angle" || a == "--max-area") {
      char* end = nullptr;
      if (!value(v)) return usageError(a + " needs a number");
      double x = std::strtod(v.c_str(), &end);
      if (*end || v.empty() || !(x >= 0)) return usageError(a + " needs a number >= 0, not '" + v + "'");
      if (a == "--max-angle") {
        if (!(x > 60 && x <= 90)) return usageError("--max-angle must be above 60 and at most 90");
        opt.maxAngle = x;
      } else if (a == "--min-angle") {
        if (!(x < 60)) return usageError("--min-angle must be below 60");
        opt.minAngle = x;
      } else {
        opt.maxArea = x;
      }
    } else if (a == "--max-steiner") {
      char* end = nullptr;
      if (!value(v)) return usageError("--max-steiner needs a count");
      unsigned long long x = std::strtoull(v.c_str(), &end, 10);
      if (*end || v.empty() || x == 0 || x > 4000000000ull)
        return usageError("--max-steiner needs a positive count, not '" + v + "'");
      opt.maxSteiner = uint32_t(x);
    } else if (a == "--fill") {
      if (!value(v)) return usageError("--fill needs triangle, evenodd or nonzero");
      if (v == "triangle") opt.fill = FillRule::Triangle;
      else if (v == "evenodd") opt.fill = FillRule::EvenOdd;
      else if (v == "nonzero") opt.fill = FillRule::NonZero;
      else return usageError("unknown fill rule '" + v + "' (triangle, evenodd, nonzero)");
      fillGiven = true;
    } else if (a == "--convex-hull") {
      opt.convexHull = true;
    } else if (a == "--exact-segments") {
      opt.exactSegments = true;
    } else if (a == "--exact-feet" || a == "--no-exact-feet") {
      exactFeet = a == "--exact-feet" ? 1 : 0;
    } else if (a == "--threads") {
      char* end = nullptr;
      if (!value(v)) return usageError("--threads needs a count");
      unsigned long x = std::strtoul(v.c_str(), &end, 10);
      if (*end || v.empty() || v[0] == '-' || x == 0 || x > 1024)
        return usageError("--threads needs a count from 1 to 1024, not '" + v + "'");
      opt.threads = unsigned(x);
    } else if (a == "--time-limit") {
      char* end = nullptr;
      if (!value(v)) return usageError("--time-limit needs seconds");
      opt.timeLimit = std::strtod(v.c_str(), &end);
      if (*end || !(opt.timeLimit > 0)) return usageError("--time-limit needs a positive number");
    } else if (a == "--stats") {
      wantStats = true;
    } else if (a == "--no-output") {
      writeOutput = false;
    } else if (a.size() > 1 && a[0] == '-') {
      return usageError("unknown option '" + a + "'");
    } else if (input.empty()) {
      input = a;
    } else {
      return usageError("more than one input file ('" + input + "', '" + a + "')");
    }
  }
  if (input.empty()) return usageError("no input file");

  std::vector<PhaseTime> phases;
  auto t0 = std::chrono::steady_clock::now();
  Input in;
  ParseResult parsed = readInputFile(input, in);
  if (!parsed.ok) {
    std::fprintf(stderr, "acutemesh: error: %s\n", parsed.message.c_str());
    return 2;
  }
  phases.push_back({"read", secondsSince(t0)});
  if (cgshop && in.format != InputFormat::CgshopInstance)
    return usageError("--format cgshop needs a CG:SHOP 2025 instance as input (.json with "
                      "\"points_x\"), and " + input + " is not one");
  if (!fillGiven && in.hasRings) opt.fill = FillRule::EvenOdd;
  // The CG:SHOP verifier is exact: a split point an ulp off its segment would leave a sliver
  // between the segment and the mesh's edges.
  if (in.format == InputFormat::CgshopInstance) opt.exactSegments = true;
  // CG:SHOP solutions hold rationals: altitude feet can be exact there.
  opt.exactFeet = exactFeet < 0 ? in.format == InputFormat::CgshopInstance : exactFeet == 1;

  // On a terminal, runs longer than a second show where they are, on one stderr line.
  bool progressShown = false;
  if (isatty(fileno(stderr))) {
    opt.progress = [&](const Progress& p) {
      double elapsed = secondsSince(t0);
      if (elapsed < 1) return;
      if (p.vertices)
        std::fprintf(stderr, "\racutemesh: %-9s %10u vertices %8.1f s", p.phase, p.vertices, elapsed);
      else
        std::fprintf(stderr, "\racutemesh: %-9s %19s %8.1f s", p.phase, "", elapsed);
      std::fflush(stderr);
      progressShown = true;
    };
  }
  Result r = mesh(in.pslg, opt);
  if (progressShown) std::fprintf(stderr, "\r%60s\r", "");
  for (const PhaseTime& p : r.stats.phases) phases.push_back(p);
  std::vector<std::string> warnings = in.warnings;
  warnings.insert(warnings.end(), r.stats.warnings.begin(), r.stats.warnings.end());
  if (writeOutput && !r.mesh.exactPoints.empty()) {
    std::string rounding;  // the formats asked for that hold coordinates as doubles
    for (const std::string& f : formats)
      if (f == "node" || f == "poly" || f == "off" || f == "obj" || f == "svg")
        rounding += (rounding.empty() ? "" : ", ") + f;
    if (!rounding.empty())
      warnings.push_back(std::to_string(r.mesh.exactPoints.size()) +
                         " vertices stand at exact altitude feet, rationals that " + rounding +
                         " round (a hair from their right angles there); cgshop and json hold "
                         "them exactly (--no-exact-feet: none)");
  }
  for (const std::string& w : warnings) std::fprintf(stderr, "acutemesh: warning: %s\n", w.c_str());
  if (r.status == Status::BadInput) {
    std::fprintf(stderr, "acutemesh: error: %s: %s\n", input.c_str(), r.message.c_str());
    return 2;
  }

  if (writeOutput) {
    if (output.empty()) {
      size_t slash = input.find_last_of('/'), dot = input.find_last_of('.');
      output = (dot != std::string::npos && (slash == std::string::npos || dot > slash))
                   ? input.substr(0, dot)
                   : input;
      output += ".1";
    }
    auto tw = std::chrono::steady_clock::now();
    ParseResult written = writeMeshFiles(r.mesh, output, formats);
    if (!written.ok) {
      std::fprintf(stderr, "acutemesh: error: %s\n", written.message.c_str());
      return 2;
    }
    if (cgshop) {
      const std::string path = output + ".solution.json";
      const std::string text =
          formatCgshopSolution(r.mesh, in.instanceUid, in.pslg.vertexCount());
      std::FILE* f = std::fopen(path.c_str(), "wb");
      int err = f ? 0 : (errno ? errno : EIO);
      if (f && std::fwrite(text.data(), 1, text.size(), f) != text.size())
        err = errno ? errno : EIO;
      if (f && std::fclose(f) != 0 && err == 0) err = errno ? errno : EIO;
      if (err) {
        std::fprintf(stderr, "acutemesh: error: %s: cannot write (%s)\n", path.c_str(),
                     std::strerror(err));
        return 2;
      }
    }
    phases.push_back({"write", secondsSince(tw)});
  }
  if (wantStats) printStats(input, opt, r, phases, warnings);
  if (r.status != Status::Ok) {
    std::fprintf(stderr, "acutemesh: %s\n", r.message.c_str());
    return 1;
  }
  return 0;
}

// glibc hands large freed blocks back to the kernel (blocks of 128 KB and more are mapped on
// their own, and the heap's top is trimmed), and the next copy of a triangulation (each
// strategy's run, each improvement round) faults the same memory in again. On the cloud VMs
// we measure on a page fault costs about 12 microseconds: a 250-vertex CG:SHOP instance took
// some 900 of them, about a tenth of its time. The CLI runs once and exits, so freed memory
// stays in the process (about 750 faults, the median run of that instance 92 -> 82 ms).
namespace {
void keepFreedMemory() {
#ifdef __GLIBC__
  mallopt(M_MMAP_THRESHOLD, 32 << 20);   // glibc's largest: bigger blocks are mapped anyway
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
  mallopt(M_TOP_PAD, 64 << 20);          // grow the heap in large steps (untouched: no cost)
#endif
}
}  // namespace

// Memory running out anywhere (reading a huge file, writing a huge mesh) is an error line
// and exit status 2 like any other, not an abort.
int main(int argc, char** argv) {
  keepFreedMemory();
  try {
    return run(argc, argv);
  } catch (const std::bad_alloc&) {
    std::fputs("acutemesh: error: out of memory\n", stderr);
  } catch (const std::length_error&) {
    std::fputs("acutemesh: error: out of memory (a size beyond what a vector can hold)\n", stderr);
  }
  return 2;
}
