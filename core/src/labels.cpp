// Output labels (labels.h). Every rule is a pass over the mesh's arrays; the half-edge twins
// (the store's, or found) are the only thing held per half-edge, and Options::adjacency keeps
// them.
#include "labels.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "acutemesh/predicates.h"
#include "build.h"

namespace acutemesh::detail {
namespace {

uint32_t nextEdge(uint32_t e) { return e - e % 3 + (e % 3 + 1) % 3; }

// The marker of input segment i (0 without markers).
int32_t segmentMarker(const Pslg& in, uint32_t i) {
  return i < in.segmentMarkers.size() ? in.segmentMarkers[i] : 0;
}

// Triangle's vertex rule: a vertex keeps its input marker; one without (0, or a Steiner point)
// takes the marker of the lowest-numbered input segment with a non-zero marker it lies on
// (the segments whose mesh edges end at it); a zero marker on the boundary becomes 1.
void markVertices(const Pslg& in, const HalfEdges& h, Mesh& mesh) {
  const size_t n = mesh.vertexCount(), inputCount = std::min(n, in.vertexCount());
  mesh.vertexMarkers.assign(n, 0);
  if (!in.vertexMarkers.empty())
    std::copy(in.vertexMarkers.begin(), in.vertexMarkers.begin() + inputCount,
              mesh.vertexMarkers.begin());
  const bool segmentMarked = std::any_of(in.segmentMarkers.begin(), in.segmentMarkers.end(),
                                         [](int32_t m) { return m != 0; });
  if (segmentMarked && mesh.segmentInput.size() * 2 == mesh.segments.size()) {
    // The segment each unmarked vertex took its marker from (kNone: none yet).
    std::vector<uint32_t> from(n, kNone);
    for (size_t s = 0; s < mesh.segmentInput.size(); ++s) {
      const uint32_t i = mesh.segmentInput[s];
      const int32_t m = segmentMarker(in, i);
      if (m == 0) continue;
      for (int k = 0; k < 2; ++k) {
        const uint32_t v = mesh.segments[2 * s + k];
        const bool own = v < inputCount && !in.vertexMarkers.empty() && in.vertexMarkers[v] != 0;
        if (!own && i < from[v]) from[v] = i, mesh.vertexMarkers[v] = m;
      }
    }
  }
  for (uint32_t e = 0; e < h.twin.size(); ++e)
    if (h.twin[e] < 0)
      for (uint32_t v : {mesh.triangles[e], mesh.triangles[nextEdge(e)]})
        if (mesh.vertexMarkers[v] == 0) mesh.vertexMarkers[v] = 1;
}

// Per mesh segment edge its input segment's marker, a zero one on the boundary 1.
void markSegments(const Pslg& in, const HalfEdges& h, Mesh& mesh) {
  const size_t count = mesh.segments.size() / 2;
  mesh.segmentMarkers.assign(count, 0);
  for (size_t s = 0; s < count; ++s) {
    const int32_t m = s < mesh.segmentInput.size() ? segmentMarker(in, mesh.segmentInput[s]) : 0;
    const int32_t e = h.segmentEdge[s];
    mesh.segmentMarkers[s] = m == 0 && (e < 0 || h.twin[size_t(e)] < 0) ? 1 : m;
  }
}

// The triangle holding each region point (on an edge or a corner counts), the first in
// triangle order; -1 for none. The points go in a grid of about one per cell, and each
// triangle tests the points of the cells its bounding box covers, so many regions cost
// about one pass over the triangles, not one each.
std::vector<int64_t> locateRegions(const Mesh& mesh, const std::vector<Region>& regions) {
  const size_t r = regions.size();
  std::vector<int64_t> at(r, -1);
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (const Region& g : regions) {
    lo[0] = std::min(lo[0], g.x), hi[0] = std::max(hi[0], g.x);
    lo[1] = std::min(lo[1], g.y), hi[1] = std::max(hi[1], g.y);
  }
  const uint32_t side = std::max<uint32_t>(1, uint32_t(std::ceil(std::sqrt(double(r)))));
  double step[2];
  for (int d = 0; d < 2; ++d) step[d] = hi[d] > lo[d] ? (hi[d] - lo[d]) / side : 1;
  // (Monotone in x: a point within a box lies in a cell between those of the box's corners.)
  auto cell = [&](int d, double x) {
    const double c = std::floor((x - lo[d]) / step[d]);
    return c <= 0 ? 0u : c >= side - 1 ? side - 1 : uint32_t(c);
  };
  std::vector<uint32_t> start(size_t(side) * side + 1, 0), order(r);
  auto cellOf = [&](const Region& g) { return cell(0, g.x) + side * cell(1, g.y); };
  for (const Region& g : regions) ++start[cellOf(g) + 1];
  for (size_t c = 0; c + 1 < start.size(); ++c) start[c + 1] += start[c];
  std::vector<uint32_t> fill(start.begin(), start.end() - 1);
  for (uint32_t i = 0; i < r; ++i) order[fill[cellOf(regions[i])]++] = i;

  size_t left = r;
  for (size_t t = 0; t < mesh.triangleCount() && left > 0; ++t) {
    const double* p[3];
    for (int k = 0; k < 3; ++k) p[k] = &mesh.points[2 * size_t(mesh.triangles[3 * t + k])];
    double blo[2], bhi[2];
    bool apart = false;  // (the box misses every point)
    for (int d = 0; d < 2; ++d) {
      blo[d] = std::min({p[0][d], p[1][d], p[2][d]});
      bhi[d] = std::max({p[0][d], p[1][d], p[2][d]});
      apart |= bhi[d] < lo[d] || blo[d] > hi[d];
    }
    if (apart) continue;
    for (uint32_t cy = cell(1, blo[1]); cy <= cell(1, bhi[1]); ++cy)
      for (uint32_t cx = cell(0, blo[0]); cx <= cell(0, bhi[0]); ++cx)
        for (uint32_t k = start[cx + side * cy]; k < start[cx + side * cy + 1]; ++k) {
          const uint32_t i = order[k];
          if (at[i] >= 0) continue;
          const double q[2] = {regions[i].x, regions[i].y};
          if (acutemesh::orientSign(p[0], p[1], q) >= 0 && acutemesh::orientSign(p[1], p[2], q) >= 0 &&
              acutemesh::orientSign(p[2], p[0], q) >= 0)
            at[i] = int64_t(t), --left;
        }
  }
  return at;
}

// Per triangle the attribute of its region: each region floods the triangles it reaches
// without crossing a mesh segment edge. Later regions go first and a triangle is claimed once,
// so a later region wins and each triangle is visited once.
void attributeTriangles(const Pslg& in, const Pslg& reported, const HalfEdges& h, Mesh& mesh,
                        std::vector<std::string>& warnings) {
  mesh.triangleAttributes.clear();
  if (in.regions.empty()) return;
  const std::vector<int64_t> at = locateRegions(mesh, in.regions);
  for (size_t i = 0; i < at.size(); ++i)
    if (at[i] < 0) {
      const Region& g = i < reported.regions.size() ? reported.regions[i] : in.regions[i];
      warnings.push_back("region " + std::to_string(i) + " at (" + shortestText(g.x) + ", " +
                         shortestText(g.y) + ") lies in no triangle of the mesh; ignored");
    }
  // A segment's edges stop the flood (twins that cross one are marked).
  std::vector<uint8_t> wall(h.twin.size(), 0);
  for (int32_t e : h.segmentEdge)
    if (e >= 0) {
      wall[size_t(e)] = 1;
      if (h.twin[size_t(e)] >= 0) wall[size_t(h.twin[size_t(e)])] = 1;
    }
  // NaN: not claimed yet (attributes are finite).
  const double unclaimed = std::numeric_limits<double>::quiet_NaN();
  mesh.triangleAttributes.assign(mesh.triangleCount(), unclaimed);
  std::vector<uint32_t> stack;
  for (size_t i = at.size(); i-- > 0;) {
    if (at[i] < 0 || !std::isnan(mesh.triangleAttributes[size_t(at[i])])) continue;
    const double value = in.regions[i].attribute;
    mesh.triangleAttributes[size_t(at[i])] = value;
    stack.push_back(uint32_t(at[i]));
    while (!stack.empty()) {
      const uint32_t t = stack.back();
      stack.pop_back();
      for (uint32_t e = 3 * t; e < 3 * t + 3; ++e) {
        const int32_t twin = h.twin[e];
        if (twin < 0 || wall[e]) continue;
        const uint32_t u = uint32_t(twin) / 3;
        if (std::isnan(mesh.triangleAttributes[u])) {
          mesh.triangleAttributes[u] = value;
          stack.push_back(u);
        }
      }
    }
  }
  for (double& a : mesh.triangleAttributes)
    if (std::isnan(a)) a = 0;
}

}  // namespace

HalfEdges labelMesh(const Pslg& input, const Pslg& reported, Mesh& mesh,
                    std::vector<std::string>& warnings) {
  HalfEdges h = halfEdges(mesh, std::move(mesh.adjacency.halfedges));
  mesh.adjacency = Adjacency{};
  markSegments(input, h, mesh);
  markVertices(input, h, mesh);
  attributeTriangles(input, reported, h, mesh, warnings);
  return h;
}

}  // namespace acutemesh::detail
