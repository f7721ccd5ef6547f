// acutemesh: the command-line tool. Reads a PSLG, meshes it, writes the mesh in the formats
// asked for. Exit status: 0 ok, 1 target not met (best mesh written), 2 bad input or usage.
// The command line is read in arguments.cpp, the options completed by the core's input policy
// (io.h: applyInputPolicy), the files and --stats written in output.cpp.
#include <chrono>
#include <cstdio>
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

// mesh(), and on a terminal, for runs longer than a second, where it is on one stderr line.
Result meshShowingProgress(const Pslg& pslg, Options options, Clock::time_point t0) {
  bool progressShown = false;
  if (isatty(fileno(stderr))) {
    options.progress = [&](const Progress& p) {
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
  Result r = mesh(pslg, options);
  if (progressShown) std::fprintf(stderr, "\r%60s\r", "");
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
// VMs (docs/TUNING.md). The CLI runs once and exits, so freed memory stays in the process.
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
