// The mesh as half-edges: twins, boundary half-edges and the fans around each vertex, which
// every later check walks. Building it checks orientation and that each directed edge is
// used once; checkStars then checks that no vertex star wraps around more than once.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "acutemesh/acutemesh.h"
#include "acutemesh/predicates.h"
#include "error_log.h"

namespace acutemesh::validation {

// Half-edge h = 3t + k runs from corner k of triangle t to its next corner.
struct Topology {
  const Mesh& m;
  uint32_t n, T;                           // vertices, triangles
  std::vector<uint8_t> good;               // per triangle: strictly counter-clockwise
  std::vector<uint8_t> boundaryVertex;     // per vertex: an end of a boundary half-edge
  std::vector<uint32_t> boundary;          // half-edges without a twin
  std::vector<uint32_t> cover;             // per vertex: its triangles covering the +x direction
  std::vector<uint32_t> twin;              // per half-edge: its twin, or kNone
  std::vector<uint32_t> anyOut;            // per vertex: a half-edge leaving it, or kNone (unused)
  std::vector<uint32_t> fanOff, fanStart;  // per vertex: its boundary half-edges (open fans)

  explicit Topology(const Mesh& mesh)
      : m(mesh), n(uint32_t(mesh.vertexCount())), T(uint32_t(mesh.triangleCount())) {}

  const double* P(uint32_t v) const { return &m.points[2 * size_t(v)]; }
  const uint32_t* corners(uint32_t t) const { return &m.triangles[3 * size_t(t)]; }
  Tri tri(uint32_t t) const { return {t, corners(t)}; }
  static uint32_t nextHe(uint32_t h) { return h % 3 == 2 ? h - 2 : h + 1; }
  static uint32_t prevHe(uint32_t h) { return h % 3 == 0 ? h + 2 : h - 1; }
  uint32_t org(uint32_t h) const { return m.triangles[h]; }
  uint32_t dst(uint32_t h) const { return m.triangles[nextHe(h)]; }
  // One half-edge stands for each undirected edge: the smaller of a twin pair.
  uint32_t canon(uint32_t h) const { return twin[h] == kNone ? h : std::min(h, twin[h]); }

  // Calls f(h) for every half-edge h leaving v, turning counter-clockwise around v fan by
  // fan: each open fan from its first (boundary) edge, else the one closed fan through any
  // half-edge leaving v. (A second closed fan at v is a fold, reported by checkStars.)
  template <class F>
  void forEachOut(uint32_t v, F&& f) const {
    auto fan = [&](uint32_t first) {
      uint32_t h = first;
      do {
        f(h);
        h = twin[prevHe(h)];
      } while (h != kNone && h != first);
    };
    if (fanOff[v] == fanOff[v + 1]) {
      if (anyOut[v] != kNone) fan(anyOut[v]);
    } else {
      for (uint32_t k = fanOff[v]; k < fanOff[v + 1]; ++k) fan(fanStart[k]);
    }
  }
  // Calls f(neighbour, half-edge) for every mesh edge at v: the half-edges leaving v, and the
  // boundary half-edges ending each open fan (their reverse is no half-edge).
  template <class F>
  void forEachEdge(uint32_t v, F&& f) const {
    forEachOut(v, [&](uint32_t h) {
      f(dst(h), h);
      if (twin[prevHe(h)] == kNone) f(org(prevHe(h)), prevHe(h));
    });
  }
  // The mesh edge u-v (either direction), or kNone.
  uint32_t meshEdge(uint32_t u, uint32_t v) const {
    uint32_t found = kNone;
    forEachEdge(u, [&](uint32_t w, uint32_t h) {
      if (w == v) found = h;
    });
    return found;
  }
  // A triangle of v's star that the direction from v toward point d points into, or kNone.
  // Each triangle (v, p, q) owns the half-open wedge of directions [p - v, q - v), so a
  // direction along an edge belongs to exactly one triangle (when the star is valid).
  uint32_t triangleToward(uint32_t v, const double* d) const {
    uint32_t found = kNone;
    forEachOut(v, [&](uint32_t h) {
      if (found == kNone && orient2d(P(v), P(dst(h)), d) >= 0 &&
          orient2d(P(v), d, P(org(prevHe(h)))) > 0)
        found = h / 3;
    });
    return found;
  }
};

// The half-edge structure of m, whose arrays have valid lengths and indices. Logs each
// triangle that is not strictly counter-clockwise (left out of the structure) and each
// directed edge used twice.
Topology buildTopology(const Mesh& m, ErrorLog& log);

// Logs each vertex whose star wraps around it more than once, or does not close around an
// interior vertex, and boundary edges that several of a vertex's triangles overlap.
void checkStars(const Topology& topo, ErrorLog& log);

}  // namespace acutemesh::validation
