// Times the acutemesh library call on a Triangle-format input, the counterpart of bench_cgal.
//
//   bench_acutemesh [--mode delaunay|cdt|acute|nonobtuse|quality] [--fill RULE] [--repeat N] FILE
//
// Reads FILE once with acutemesh's own reader (io.h: readInputFile), then times
// acutemesh::mesh(input, options) only, best of 3 by default, and prints one line of
// key=value pairs. Mode defaults by extension: .node -> delaunay, .poly -> cdt. The
// refinement modes are here for bench/wasm.sh, which compares this with the wasm build.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "acutemesh/acutemesh.h"
#include "acutemesh/io.h"

namespace {
[[noreturn]] void die(const std::string& msg, int code = 2) {
  std::fprintf(stderr, "bench_acutemesh: %s\n", msg.c_str());
  std::exit(code);
}
}  // namespace

int main(int argc, char** argv) {
  std::string mode, file, fill;
  int repeat = 3;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--mode" && i + 1 < argc) mode = argv[++i];
    else if (a == "--fill" && i + 1 < argc) fill = argv[++i];
    else if (a == "--repeat" && i + 1 < argc) repeat = std::max(1, std::atoi(argv[++i]));
    else if (!a.empty() && a[0] != '-' && file.empty()) file = a;
    else die("usage: bench_acutemesh [--mode delaunay|cdt|acute|nonobtuse|quality] [--fill RULE] [--repeat N] FILE");
  }
  if (file.empty()) die("no input file");
  bool poly = file.size() > 5 && file.compare(file.size() - 5, 5, ".poly") == 0;
  if (mode.empty()) mode = poly ? "cdt" : "delaunay";

  acutemesh::Options opts;
  if (mode == "delaunay") opts.mode = acutemesh::Mode::Delaunay;
  else if (mode == "cdt") opts.mode = acutemesh::Mode::Cdt;
  else if (mode == "acute") opts.mode = acutemesh::Mode::Acute;
  else if (mode == "nonobtuse") opts.mode = acutemesh::Mode::NonObtuse;
  else if (mode == "quality") opts.mode = acutemesh::Mode::Quality;
  else die("unknown mode " + mode);
  if (fill == "evenodd") opts.fill = acutemesh::FillRule::EvenOdd;
  else if (fill == "nonzero") opts.fill = acutemesh::FillRule::NonZero;
  else if (!fill.empty() && fill != "triangle") die("unknown fill rule " + fill);

  auto t0 = std::chrono::steady_clock::now();
  acutemesh::Input input;
  acutemesh::ParseResult pr = acutemesh::readInputFile(file, input);
  double readMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  if (!pr.ok) die(pr.message);
  if (fill.empty() && input.hasRings) opts.fill = acutemesh::FillRule::EvenOdd;

  double best = 1e300;
  size_t triangles = 0, vertices = 0;
  bool certified = false;
  for (int r = 0; r < repeat; ++r) {
    auto t = std::chrono::steady_clock::now();
    acutemesh::Result res = acutemesh::mesh(input.pslg, opts);
    double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
    // A refinement that misses its target still times the whole job (certified=0 says so).
    if (res.status != acutemesh::Status::Ok && res.status != acutemesh::Status::TargetNotMet)
      die("mesh() failed (status " + std::to_string(int(res.status)) + "): " + res.message, 1);
    triangles = res.mesh.triangleCount();
    vertices = res.mesh.vertexCount();
    certified = res.stats.certified;
    best = std::min(best, ms);  // res's destruction is not timed
  }
  std::printf("tool=acutemesh mode=%s file=%s vertices=%zu triangles=%zu certified=%d read_ms=%.1f "
              "best_ms=%.3f repeat=%d\n",
              mode.c_str(), file.c_str(), vertices, triangles, int(certified), readMs, best, repeat);
  return 0;
}
