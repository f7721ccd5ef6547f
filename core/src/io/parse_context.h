// What every reader shares: the text's name for messages, the first error, the warnings, and
// how input text is quoted in them. Errors read "NAME:LINE: expected X, found Y"; things
// tolerated go to Input::warnings in the same form.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "acutemesh/io.h"

namespace acutemesh::io {

// Vertex indices and item counts must fit 32 bits.
constexpr uint64_t kMaxIndexCount = std::numeric_limits<uint32_t>::max();

// Of the warnings alike (the same text at other lines) the first kListedAlike are listed, and
// one more line counts them all (a map's rings each closed by repeating their first point made
// 3,354 lines for the United States).
constexpr size_t kListedAlike = 5;

struct Ctx {
  const std::string& name;
  std::vector<std::string>* warnings;
  std::string message;
  struct Alike {
    size_t count = 0;
    size_t line = 0;  // where in *warnings the count stands, once past kListedAlike
  };
  std::map<std::string, Alike> alike = {};  // by warning text

  bool fail(size_t line, const std::string& what) {
    message = name + ":" + std::to_string(line) + ": " + what;
    return false;
  }
  void warn(size_t line, const std::string& what) {
    if (!warnings) return;
    Alike& a = alike[what];
    if (++a.count <= kListedAlike) {
      warnings->push_back(name + ":" + std::to_string(line) + ": " + what);
      return;
    }
    if (a.count == kListedAlike + 1) a.line = warnings->size(), warnings->emplace_back();
    (*warnings)[a.line] = name + ": " + std::to_string(a.count) + " times in all (the first " +
                          std::to_string(kListedAlike) + " listed): " + what;
  }
};

ParseResult failure(std::string message);

// Input text as it may appear in a one-line message: control characters, DEL and bytes
// above 0x7F (random bytes, or UTF-8 that a terminal may not show) become \xNN, so a message
// never breaks its line or carries a terminal escape; shortened to `max` bytes of input.
std::string printable(std::string_view t, size_t max = 40);

// A token quoted for a message.
std::string quote(std::string_view t);

}  // namespace acutemesh::io
