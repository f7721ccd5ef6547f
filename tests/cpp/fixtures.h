// Helpers shared by the test suites that run mesh(): where the fixtures are, loading them,
// and validate()'s findings as one message. The reference data beside the repository:
// reference_data.h.
#pragma once

#include <gtest/gtest.h>

#include <dirent.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "acutemesh/acutemesh.h"
#include "acutemesh/io.h"
#include "reference_data.h"

namespace fixtures {

inline const std::string kData = ACUTEMESH_TEST_DATA;  // tests/data
// The synthetic CG:SHOP 2025 instances, of the official ones' five kinds (tests/data/cgshop).
inline const std::string kSyntheticCgshop = kData + "/cgshop";
inline constexpr size_t kSyntheticCgshopCount = 8;

inline acutemesh::Input load(const std::string& path) {
  acutemesh::Input in;
  acutemesh::ParseResult r = acutemesh::readInputFile(path, in);
  EXPECT_TRUE(r.ok) << r.message;
  return in;
}

// The CG:SHOP 2025 instance files in dir, sorted: the synthetic ones in tests/data/cgshop
// (made by its make.mjs), or the 150 official ones, reference::file("cgshop2025").
inline std::vector<std::string> cgshopInstances(const std::string& dir) {
  std::vector<std::string> files;
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

// A file's bytes ("" if it cannot be read).
inline std::string readText(const std::string& path) {
  std::string s;
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return s;
  char buf[4096];
  size_t got;
  while ((got = std::fread(buf, 1, sizeof buf, f)) > 0) s.append(buf, got);
  std::fclose(f);
  return s;
}

inline bool startsWith(const std::string& s, const std::string& prefix) {
  return s.compare(0, prefix.size(), prefix) == 0;
}

// The same double to the bit (0 and -0 differ, a NaN equals itself).
inline bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// `count` islands on a 4-wide grid 3 apart, island i a ring of `corners` points at
// radius(i, angle) around (3 (i % 4), 3 (i / 4)) with a region of attribute i at its centre:
// enough of them make a domain meshed part by part (kPartsFrom triangles).
inline acutemesh::Pslg archipelago(int count, int corners, double (*radius)(int, double)) {
  acutemesh::Pslg in;
  for (int i = 0; i < count; ++i) {
    const double cx = 3.0 * (i % 4), cy = 3.0 * (i / 4);
    const uint32_t first = uint32_t(in.vertexCount());
    for (int k = 0; k < corners; ++k) {
      const double a = 2 * M_PI * k / corners, r = radius(i, a);
      in.points.insert(in.points.end(), {cx + r * std::cos(a), cy + r * std::sin(a)});
      in.segments.insert(in.segments.end(), {first + k, first + (k + 1) % corners});
    }
    acutemesh::Region g;
    g.x = cx, g.y = cy, g.attribute = i;
    in.regions.push_back(g);
  }
  return in;
}

// Adds the closed ring xy (x, y per point) to `in`: its points and a segment along each side.
inline void addRing(acutemesh::Pslg& in, const std::vector<double>& xy) {
  const uint32_t first = uint32_t(in.vertexCount()), n = uint32_t(xy.size() / 2);
  in.points.insert(in.points.end(), xy.begin(), xy.end());
  for (uint32_t k = 0; k < n; ++k)
    in.segments.insert(in.segments.end(), {first + k, first + (k + 1) % n});
}

// A random star-shaped polygon of n edges (bench/gen.mjs's kind): sorted random angles,
// radii in [0.5, 1]. Its edges are long against the vertices' spacing: spikes.
inline acutemesh::Pslg starPolygon(int n, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<double> angles(static_cast<size_t>(n));
  for (double& a : angles) a = 2 * M_PI * u(rng);
  std::sort(angles.begin(), angles.end());
  acutemesh::Pslg in;
  for (int i = 0; i < n; ++i) {
    const double r = 0.5 + 0.5 * u(rng), a = angles[size_t(i)];
    in.points.insert(in.points.end(), {r * std::cos(a), r * std::sin(a)});
    in.segments.insert(in.segments.end(), {uint32_t(i), uint32_t((i + 1) % n)});
  }
  return in;
}

// A generated coastline (the kind of outline maps bring): a polygon of `corners` corners
// around (cx, cy), each edge split `levels` times at a point pushed off its middle along its
// normal by up to 0.12 of its length (corners * 2^levels vertices), from `rng`.
inline std::vector<double> coastline(std::mt19937_64& rng, double cx, double cy, double radius,
                                     int corners, int levels) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<double> xy;
  for (int i = 0; i < corners; ++i) {
    const double a = 2 * M_PI * i / corners;
    xy.insert(xy.end(), {cx + radius * std::cos(a), cy + radius * std::sin(a)});
  }
  for (int level = 0; level < levels; ++level) {
    std::vector<double> finer;
    const size_t n = xy.size() / 2;
    for (size_t i = 0; i < n; ++i) {
      const double *p = &xy[2 * i], *q = &xy[2 * ((i + 1) % n)];
      const double off = 0.12 * u(rng);
      finer.insert(finer.end(), {p[0], p[1], (p[0] + q[0]) / 2 - off * (q[1] - p[1]),
                                 (p[1] + q[1]) / 2 + off * (q[0] - p[0])});
    }
    xy = std::move(finer);
  }
  return xy;
}

// The largest area of the mesh's triangles (as doubles compute it).
inline double largestTriangleArea(const acutemesh::Mesh& m) {
  double largest = 0;
  for (size_t t = 0; t < m.triangles.size(); t += 3) {
    const double* a = &m.points[2 * m.triangles[t]];
    const double* b = &m.points[2 * m.triangles[t + 1]];
    const double* c = &m.points[2 * m.triangles[t + 2]];
    largest = std::max(largest, ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) / 2);
  }
  return largest;
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
