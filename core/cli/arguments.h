// The CLI's command line as a value, and its help text. Names of modes, fill rules and
// formats come from the core's vocabulary (acutemesh/vocabulary.h).
#pragma once

#include <string>
#include <vector>

#include "acutemesh/acutemesh.h"
#include "acutemesh/io.h"

namespace acutemesh::cli {

struct Arguments {
  std::string input;
  std::string output;  // file name base; empty: INPUT without its extension, plus ".1"
  std::string sizeFile;  // --size: read into options.size once the input is read
  std::vector<OutputFormat> formats{OutputFormat::Node, OutputFormat::Ele};
  Options options;       // as given; the input policy completes them once the input is read
  ChosenOptions chosen;  // which of them the user set, so the policy leaves them alone
  bool stats = false;    // --stats: one JSON object on stdout
  bool writeOutput = true;

  bool wants(OutputFormat f) const;
};

struct CommandLine {
  enum Action { Mesh, Help, Version, UsageError } action = Mesh;
  Arguments arguments;
  std::string error;  // UsageError: the one line to print
};

// Reads argv; touches no file and prints nothing.
CommandLine parseCommandLine(int argc, const char* const* argv);

// What --help prints.
std::string usageText();

}  // namespace acutemesh::cli
