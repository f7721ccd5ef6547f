// What the CLI writes: the mesh files, the warnings, and --stats JSON.
#pragma once

#include <string>
#include <vector>

#include "acutemesh/acutemesh.h"
#include "acutemesh/io.h"
#include "arguments.h"

namespace acutemesh::cli {

// The reader's and the mesher's warnings, and one more when exact points go into formats that
// round them.
std::vector<std::string> outputWarnings(const Arguments& args, const Input& in, const Result& r);

// Writes BASE.EXT for each format asked for; false after printing the error line.
bool writeOutputs(const Arguments& args, const Input& in, const Result& r);

// --stats: one JSON object of figures on stdout. `options` as meshed (after the input policy).
void printStats(const std::string& input, const Options& options, const Result& r,
                const std::vector<PhaseTime>& phases, const std::vector<std::string>& warnings);

}  // namespace acutemesh::cli
