// The external reference data (the 150 CG:SHOP 2025 instances, Lake Superior, ...), which is
// not in the repository. One rule for the C++, CLI and JavaScript tests alike:
//   $ACUTEMESH_DATA when set (a relative path is taken from the repository root; set but empty
//   means "none"), else ../shared/data beside the repository root when it exists, else none.
// Tests that need it call ACUTEMESH_NEED_REFERENCE_DATA() first: they run when it is there and
// are skipped, saying why, when it is not; a named directory that is missing fails them.
// (tests/cli/cli_test.sh and tests/js/helpers.mjs apply the same rule.)
#pragma once

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace reference {

inline const std::string kRoot = ACUTEMESH_SOURCE_DIR;  // the repository root

struct Data {
  std::string dir;    // the directory, or "" when there is none
  std::string error;  // set when ACUTEMESH_DATA names a directory that is not there
};

inline bool isDirectory(const std::string& path) {
  struct stat s;
  return stat(path.c_str(), &s) == 0 && S_ISDIR(s.st_mode);
}

inline const Data& data() {
  static const Data d = [] {
    Data out;
    // Under node (the wasm build) getenv sees node's environment through tests/cpp/node_env.js.
    const char* env = std::getenv("ACUTEMESH_DATA");
    if (env && *env) {
      const std::string dir = env[0] == '/' ? env : kRoot + "/" + env;
      if (isDirectory(dir))
        out.dir = dir;
      else
        out.error = "ACUTEMESH_DATA=" + std::string(env) + ": no such directory";
    } else if (!env && isDirectory(kRoot + "/../shared/data")) {
      out.dir = kRoot + "/../shared/data";
    }
    return out;
  }();
  return d;
}

// A file of the reference data, by its path inside it (call after ACUTEMESH_NEED_REFERENCE_DATA).
inline std::string file(const std::string& path) { return data().dir + "/" + path; }

// The reason given when a test is skipped.
inline std::string absence() {
  const char* env = std::getenv("ACUTEMESH_DATA");
  if (env && !*env) return "needs the reference data, and ACUTEMESH_DATA is set empty (none)";
  return "needs the reference data: set ACUTEMESH_DATA to its directory, or put it at " + kRoot +
         "/../shared/data";
}

// Notes the skip in the file $ACUTEMESH_TEST_SKIPS names (scripts/test.sh counts them).
inline void noteSkip() {
  const char* log = std::getenv("ACUTEMESH_TEST_SKIPS");
  const testing::TestInfo* t = testing::UnitTest::GetInstance()->current_test_info();
  if (!log || !*log || !t) return;
  if (std::FILE* f = std::fopen(log, "a")) {
    std::fprintf(f, "C++ %s.%s\n", t->test_suite_name(), t->name());
    std::fclose(f);
  }
}

}  // namespace reference

// First statement of a test that needs the reference data: skips it when there is none.
#define ACUTEMESH_NEED_REFERENCE_DATA()                                               \
  do {                                                                                \
    if (!reference::data().error.empty()) FAIL() << reference::data().error;          \
    if (reference::data().dir.empty()) {                                              \
      reference::noteSkip();                                                          \
      GTEST_SKIP() << reference::absence();                                           \
    }                                                                                 \
  } while (0)
