// The CLI's output: mesh files by the core's writers, the CG:SHOP solution, --stats.
#include "output.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace acutemesh::cli {
namespace {

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

// The shortest decimal that reads back as x: angleBound's tenths print as 84.3, not 84.299999999999997.
std::string shortestNumber(double x) {
  char text[32];
  for (int digits = 15; digits <= 17; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, x);
    if (std::strtod(text, nullptr) == x) break;
  }
  return text;
}

// INPUT without its extension, plus ".1", unless -o says otherwise.
std::string outputBase(const Arguments& args) {
  if (!args.output.empty()) return args.output;
  const std::string& input = args.input;
  size_t slash = input.find_last_of('/'), dot = input.find_last_of('.');
  std::string base = (dot != std::string::npos && (slash == std::string::npos || dot > slash))
                         ? input.substr(0, dot)
                         : input;
  return base + ".1";
}

bool writeText(const std::string& path, const std::string& text) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  int err = f ? 0 : (errno ? errno : EIO);
  if (f && std::fwrite(text.data(), 1, text.size(), f) != text.size()) err = errno ? errno : EIO;
  if (f && std::fclose(f) != 0 && err == 0) err = errno ? errno : EIO;
  if (err) {
    std::fprintf(stderr, "acutemesh: error: %s: cannot write (%s)\n", path.c_str(), std::strerror(err));
    return false;
  }
  return true;
}

}  // namespace

std::vector<std::string> outputWarnings(const Arguments& args, const Input& in, const Result& r) {
  std::vector<std::string> warnings = in.warnings;
  warnings.insert(warnings.end(), r.stats.warnings.begin(), r.stats.warnings.end());
  if (!args.writeOutput || r.mesh.exactPoints.empty()) return warnings;
  std::string rounding;  // the formats asked for that hold coordinates as doubles
  for (OutputFormat f : args.formats)
    if (infoOf(f).roundsExactPoints) rounding += (rounding.empty() ? "" : ", ") + std::string(nameOf(f));
  if (!rounding.empty())
    warnings.push_back(std::to_string(r.mesh.exactPoints.size()) +
                       " vertices stand at exact altitude feet, rationals that " + rounding +
                       " round (a hair from their right angles there); cgshop and json hold "
                       "them exactly (--no-exact-feet: none)");
  return warnings;
}

bool writeOutputs(const Arguments& args, const Input& in, const Result& r) {
  const std::string base = outputBase(args);
  std::vector<std::string> names;  // formats of the mesh alone; the CG:SHOP solution apart
  for (OutputFormat f : args.formats)
    if (!infoOf(f).needsInstance) names.push_back(nameOf(f));
  ParseResult written = writeMeshFiles(r.mesh, base, names);
  if (!written.ok) {
    std::fprintf(stderr, "acutemesh: error: %s\n", written.message.c_str());
    return false;
  }
  if (args.wants(OutputFormat::Cgshop))
    return writeText(base + infoOf(OutputFormat::Cgshop).extension,
                     formatCgshopSolution(r.mesh, in.instanceUid, in.pslg.vertexCount()));
  return true;
}

void printStats(const std::string& input, const Options& opt, const Result& r,
                const std::vector<PhaseTime>& phases, const std::vector<std::string>& warnings) {
  const Stats& s = r.stats;
  std::printf("{\"input\": %s, \"mode\": \"%s\", \"fill\": \"%s\", \"status\": \"%s\",\n",
              jsonString(input).c_str(), nameOf(opt.mode), nameOf(opt.fill), nameOf(r.status));
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
  std::printf(" \"smallestDomainAngle\": %.17g, \"angleFloor\": %.17g, \"angleBound\": %s,\n",
              s.smallestDomainAngle, s.angleFloor, shortestNumber(s.angleBound).c_str());
  // The largest longest-edge-to-size ratio (at most 1 when every size is met; 0 without sizes).
  std::printf(" \"sizeRatio\": %s,\n", shortestNumber(s.sizeRatio).c_str());
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

}  // namespace acutemesh::cli
