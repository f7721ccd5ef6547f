// acutemesh: the command-line tool. Reads a PSLG, meshes it, writes the mesh in the formats
// asked for. Exit status: 0 ok, 1 target not met (best mesh written), 2 bad input or usage.
// The command line is read in arguments.cpp, the options completed by the core's input policy
// (io.h: applyInputPolicy), the files and --stats written in output.cpp.
#include <algorithm>
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
#include "arguments.h"
#include "output.h"

namespace {

using namespace acutemesh;
using namespace acutemesh::cli;
using Clock = std::chrono::steady_clock;

int usageError(const std::string& message) {
  std::fprintf(stderr, "acutemesh: %s\n(try 'acutemesh --help')\n", message.c_str());
  return 2;
}

double secondsSince(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// What is left of a refinement, from how long its first `fraction` took: "" until the
// fraction says enough (the first few percent mostly measure the start-up).
std::string timeLeft(double fraction, double seconds) {
  if (fraction < 0.05 || seconds < 2) return "";
  const double left = seconds * (1 - fraction) / fraction;
  char text[48];
  if (left < 90)
    std::snprintf(text, sizeof text, ", about %.0f s left", std::max(1.0, left));
  else
    std::snprintf(text, sizeof text, ", about %.0f min left", left / 60);
  return text;
}

// mesh(), and on a terminal, for runs longer than a second, where it is on one stderr line:
// the phase, the vertex count, the share of the refinement done and what is likely left.
Result meshShowingProgress(const Pslg& pslg, Options options, Clock::time_point t0) {
  bool progressShown = false;
  double refineStart = -1;  // (seconds since t0)
  if (isatty(fileno(stderr))) {
    options.progress = [&](const Progress& p) {
      const double elapsed = secondsSince(t0);
      const bool refining =
          std::strcmp(p.phase, "refine") == 0 || std::strcmp(p.phase, "improve") == 0;
      if (refining && refineStart < 0) refineStart = elapsed;
      if (elapsed < 1) return;
      std::string line = "acutemesh: " + std::string(p.phase);
      line.resize(std::max<size_t>(line.size(), 20), ' ');
      char figures[64];
      // (Not while improving: the count then includes the points taken out.)
      if (p.vertices && std::strcmp(p.phase, "improve") != 0) {
        std::snprintf(figures, sizeof figures, "%10u vertices", p.vertices);
        line += figures;
      }
      if (refining && p.fraction >= 0) {
        std::snprintf(figures, sizeof figures, " %3.0f%%", 100 * p.fraction);
        line += figures;
      }
      std::snprintf(figures, sizeof figures, " %8.1f s", elapsed);
      line += figures;
      if (refining) line += timeLeft(p.fraction, elapsed - refineStart);
      std::fprintf(stderr, "\r%-78s", line.c_str());
      std::fflush(stderr);
      progressShown = true;
    };
  }
  Result r = mesh(pslg, options);
  if (progressShown) std::fprintf(stderr, "\r%78s\r", "");
  return r;
}

// Reads, meshes and writes as `args` say; the exit status.
int meshFile(const Arguments& args) {
  std::vector<PhaseTime> phases;
  const Clock::time_point t0 = Clock::now();
  Input in;
  ParseResult parsed = readInputFile(args.input, in);
  if (!parsed.ok) {
    std::fprintf(stderr, "acutemesh: error: %s\n", parsed.message.c_str());
    return 2;
  }
  phases.push_back({"read", secondsSince(t0)});
  if (args.wants(OutputFormat::Cgshop) && in.format != InputFormat::CgshopInstance)
    return usageError("--format cgshop needs a CG:SHOP 2025 instance as input (.json with "
                      "\"points_x\"), and " + args.input + " is not one");

  Options options = args.options;
  if (!args.sizeFile.empty()) {
    parsed = readSizeFile(args.sizeFile, options.size, &in.warnings);
    if (!parsed.ok) {
      std::fprintf(stderr, "acutemesh: error: %s\n", parsed.message.c_str());
      return 2;
    }
  }
  applyInputPolicy(in, args.chosen, options);
  Result r = meshShowingProgress(in.pslg, options, t0);
  phases.insert(phases.end(), r.stats.phases.begin(), r.stats.phases.end());
  const std::vector<std::string> warnings = outputWarnings(args, in, r);
  for (const std::string& w : warnings) std::fprintf(stderr, "acutemesh: warning: %s\n", w.c_str());
  if (r.status == Status::BadInput) {
    std::fprintf(stderr, "acutemesh: error: %s: %s\n", args.input.c_str(), r.message.c_str());
    return 2;
  }

  if (args.writeOutput) {
    const Clock::time_point tw = Clock::now();
    if (!writeOutputs(args, in, r)) return 2;
    phases.push_back({"write", secondsSince(tw)});
  }
  if (args.stats) printStats(args.input, options, r, phases, warnings);
  // What --max-angle auto reached (a run that falls short says it in its message).
  if (options.maxAngle == kAutoMaxAngle && r.status == Status::Ok)
    std::fprintf(stderr, "acutemesh: every angle is below %g degrees (certified; the domain's floor is %g)\n",
                 r.stats.angleBound, r.stats.angleFloor);
  if (r.status != Status::Ok) {
    std::fprintf(stderr, "acutemesh: %s\n", r.message.c_str());
    return 1;
  }
  return 0;
}

int run(int argc, char** argv) {
  const CommandLine command = parseCommandLine(argc, argv);
  switch (command.action) {
    case CommandLine::Help:
      std::fputs(usageText().c_str(), stdout);
      return 0;
    case CommandLine::Version:
      std::printf("acutemesh %s\n", version());
      return 0;
    case CommandLine::UsageError:
      return usageError(command.error);
    case CommandLine::Mesh:
      break;
  }
  return meshFile(command.arguments);
}

}  // namespace

// glibc hands large freed blocks back to the kernel, and the next copy of a triangulation (each
// strategy's run, each improvement round) faults the same memory in again, at a real cost on
// VMs (docs/TUNING.md). The CLI runs once and exits, so freed memory stays in the process; and
// in one arena, where what one thread frees another reuses (a part's state on each thread).
namespace {
void keepFreedMemory() {
#ifdef __GLIBC__
  mallopt(M_MMAP_THRESHOLD, 32 << 20);   // glibc's largest: bigger blocks are mapped anyway
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
  mallopt(M_TOP_PAD, 64 << 20);          // grow the heap in large steps (untouched: no cost)
  mallopt(M_ARENA_MAX, 1);
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
