// libFuzzer harness: Triangle's .poly and .node readers on arbitrary bytes. The first byte
// picks the reader; for a .poly with a vertex count of 0, the bytes after the first '\f' are
// its .node text.
#include <string>
#include <string_view>

#include "fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
  acutemesh::Input in;
  if (data[0] & 1) {
    fuzz::checkParse(acutemesh::parseNode(text, "f.node", in), in, "f.node");
    return 0;
  }
  std::string_view poly = text, node;
  size_t split = text.find('\f');
  if (split != std::string_view::npos) poly = text.substr(0, split), node = text.substr(split + 1);
  // Errors and warnings in the .node text name the .node file.
  fuzz::checkParse(acutemesh::parsePoly(poly, "f.poly", in, node, "f.node"), in, "f.poly", "f.node");
  return 0;
}
