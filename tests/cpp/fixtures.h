// Helpers shared by the test suites that run mesh(): where the fixtures are, loading them,
// and validate()'s findings as one message.
#pragma once

#include <gtest/gtest.h>

#include <dirent.h>

#include <algorithm>
#include <string>
#include <vector>

#include "acutemesh/acutemesh.h"
#include "acutemesh/io.h"

namespace fixtures {

inline const std::string kData = ACUTEMESH_TEST_DATA;      // tests/data
inline const std::string kShared = ACUTEMESH_SHARED_DATA;  // ../shared/data

inline acutemesh::Input load(const std::string& path) {
  acutemesh::Input in;
  acutemesh::ParseResult r = acutemesh::readInputFile(path, in);
  EXPECT_TRUE(r.ok) << r.message;
  return in;
}

// The 150 CG:SHOP 2025 instance files, sorted.
inline std::vector<std::string> cgshopInstances() {
  std::vector<std::string> files;
  std::string dir = kShared + "/cgshop2025";
  if (DIR* d = opendir(dir.c_str())) {
    while (dirent* e = readdir(d)) {
      std::string name = e->d_name;
      if (name.size() > 14 && name.substr(name.size() - 14) == ".instance.json")
        files.push_back(dir + "/" + name);
    }
    closedir(d);
  }
  std::sort(files.begin(), files.end());
  return files;
}

// validate()'s errors, one per line; empty when the mesh is valid.
inline std::string validationErrors(const acutemesh::Pslg& in, const acutemesh::Options& o,
                                    const acutemesh::Mesh& mesh) {
  acutemesh::Validation v = acutemesh::validate(in, mesh, o);
  std::string errors;
  for (const std::string& e : v.errors) errors += "\n  " + e;
  if (!v.ok && errors.empty()) errors = "\n  (invalid, no message)";
  return errors;
}

}  // namespace fixtures
