// libFuzzer harness: the JSON reader (acutemesh PSLG, rings, CG:SHOP 2025 instances) on
// arbitrary bytes.
#include <string_view>

#include "fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string_view text(reinterpret_cast<const char*>(data), size);
  acutemesh::Input in;
  fuzz::checkParse(acutemesh::parseJson(text, "f.json", in), in, "f.json");
  return 0;
}
