// Name <-> enum lookups over the tables of vocabulary.h, and the message for a name that is
// none of them.
#include "acutemesh/vocabulary.h"

#include <algorithm>
#include <cctype>
#include <iterator>
#include <vector>

namespace acutemesh {
namespace {

// Edits (insert, delete or replace a letter, swap two neighbours) from a to b, ignoring case.
size_t editDistance(std::string_view a, std::string_view b) {
  auto same = [](char x, char y) {
    return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
  };
  const size_t w = b.size() + 1;
  std::vector<size_t> d((a.size() + 1) * w);  // d[i * w + j]: from a's first i to b's first j
  for (size_t i = 0; i <= a.size(); ++i) d[i * w] = i;
  for (size_t j = 0; j <= b.size(); ++j) d[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    for (size_t j = 1; j <= b.size(); ++j) {
      size_t best = std::min({d[(i - 1) * w + j] + 1, d[i * w + j - 1] + 1,
                              d[(i - 1) * w + j - 1] + (same(a[i - 1], b[j - 1]) ? 0 : 1)});
      if (i > 1 && j > 1 && same(a[i - 1], b[j - 2]) && same(a[i - 2], b[j - 1]))
        best = std::min(best, d[(i - 2) * w + j - 2] + 1);
      d[i * w + j] = best;
    }
  }
  return d.back();
}

template <class Entry, size_t N>
const char* nameIn(const Entry (&table)[N], decltype(Entry::value) value) {
  for (const Entry& e : table)
    if (e.value == value) return e.name;
  return "?";
}

// "unknown WHAT 'NAME' (a, b, c)", plus ": did you mean 'b'?" when exactly one name is within
// two edits and the edits change less than half of it (so 'png' does not suggest 'svg').
template <class Entry, size_t N>
std::string unknownName(const Entry (&table)[N], const char* what, std::string_view name) {
  std::string message = std::string("unknown ") + what + " '" + std::string(name) + "' (";
  const char* nearest = nullptr;
  size_t best = 3;
  bool tie = false;
  for (size_t i = 0; i < N; ++i) {
    message += i ? ", " : "";
    message += table[i].name;
    const std::string_view candidate = table[i].name;
    const size_t d = editDistance(name, candidate);
    if (2 * d >= std::max(name.size(), candidate.size())) continue;
    if (d < best) {
      best = d;
      nearest = table[i].name;
      tie = false;
    } else if (d == best) {
      tie = true;
    }
  }
  message += ")";
  if (nearest && !tie) message += std::string(": did you mean '") + nearest + "'?";
  return message;
}

template <class Entry, size_t N, class Enum>
bool lookUp(const Entry (&table)[N], const char* what, std::string_view name, Enum& out,
            std::string* message) {
  for (const Entry& e : table) {
    if (name == e.name) {
      out = e.value;
      return true;
    }
  }
  if (message) *message = unknownName(table, what, name);
  return false;
}

}  // namespace

const char* nameOf(Mode value) { return nameIn(kModes, value); }
const char* nameOf(FillRule value) { return nameIn(kFillRules, value); }
const char* nameOf(Status value) { return nameIn(kStatuses, value); }
const char* nameOf(VertexKind value) { return nameIn(kVertexKinds, value); }
const char* nameOf(InputFormat value) { return nameIn(kInputFormats, value); }
const char* nameOf(OutputFormat value) { return nameIn(kOutputFormats, value); }

const OutputFormatInfo& infoOf(OutputFormat value) {
  for (const OutputFormatInfo& f : kOutputFormats)
    if (f.value == value) return f;
  return kOutputFormats[0];  // unreachable for a value of the enum
}

bool parseName(std::string_view name, Mode& out, std::string* message) {
  return lookUp(kModes, "mode", name, out, message);
}
bool parseName(std::string_view name, FillRule& out, std::string* message) {
  return lookUp(kFillRules, "fill rule", name, out, message);
}
bool parseName(std::string_view name, InputFormat& out, std::string* message) {
  return lookUp(kInputFormats, "input format", name, out, message);
}
bool parseName(std::string_view name, OutputFormat& out, std::string* message) {
  return lookUp(kOutputFormats, "format", name, out, message);
}

// The tables list their enums in order, so a value's entry is table[value] (in JavaScript,
// vocabulary.vertexKinds[k] names the k of MeshResult.vertexKind).
namespace {
template <class Entry, size_t N>
constexpr bool inEnumOrder(const Entry (&table)[N]) {
  for (size_t i = 0; i < N; ++i)
    if (static_cast<size_t>(table[i].value) != i) return false;
  return true;
}
static_assert(inEnumOrder(kModes) && inEnumOrder(kFillRules) && inEnumOrder(kStatuses) &&
              inEnumOrder(kVertexKinds) && inEnumOrder(kInputFormats) && inEnumOrder(kOutputFormats));
// ... and every value of each: a value added to an enum needs its line in the table.
static_assert(std::size(kModes) == size_t(Mode::Acute) + 1);
static_assert(std::size(kFillRules) == size_t(FillRule::NonZero) + 1);
static_assert(std::size(kStatuses) == size_t(Status::Cancelled) + 1);
static_assert(std::size(kVertexKinds) == size_t(kFreeVertex) + 1);
static_assert(std::size(kInputFormats) == size_t(InputFormat::CgshopInstance) + 1);
static_assert(std::size(kOutputFormats) == size_t(OutputFormat::Cgshop) + 1);
}  // namespace

}  // namespace acutemesh
