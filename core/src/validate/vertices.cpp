#include "vertices.h"

#include <cmath>

#include "coord_table.h"

namespace acutemesh::validation {
namespace {

bool finite(const double* p) { return std::isfinite(p[0]) && std::isfinite(p[1]); }

bool allCollinear(const Topology& t) {
  uint32_t a = 0, b = 1;
  while (b < t.n && t.P(b)[0] == t.P(a)[0] && t.P(b)[1] == t.P(a)[1]) ++b;
  for (uint32_t v = b + 1; v < t.n; ++v)
    if (orient2d(t.P(a), t.P(b), t.P(v)) != 0) return false;
  return true;
}

}  // namespace

bool checkSizes(const Pslg& in, const Mesh& m, ErrorLog& log) {
  bool fatal = false;
  auto bad = [&](auto&&... parts) {
    log.add(parts...);
    fatal = true;
  };
  if (in.points.size() % 2) bad("input points has odd length ", in.points.size());
  if (in.segments.size() % 2) bad("input segments has odd length ", in.segments.size());
  if (in.holes.size() % 2) bad("input holes has odd length ", in.holes.size());
  if (m.points.size() % 2) bad("mesh points has odd length ", m.points.size());
  if (m.triangles.size() % 3)
    bad("mesh triangles has length ", m.triangles.size(), ", not a multiple of 3");
  if (m.segments.size() % 2) bad("mesh segments has odd length ", m.segments.size());
  if (m.points.size() / 2 >= kNone || m.triangles.size() >= (size_t(1) << 31))
    bad("mesh too large for 32-bit indices");
  if (fatal) return false;
  const uint32_t nIn = uint32_t(in.vertexCount());
  const uint32_t n = uint32_t(m.vertexCount());
  const uint32_t T = uint32_t(m.triangleCount());
  auto inP = [&](uint32_t v) { return &in.points[2 * size_t(v)]; };
  auto P = [&](uint32_t v) { return &m.points[2 * size_t(v)]; };
  auto corners = [&](uint32_t t) { return &m.triangles[3 * size_t(t)]; };
  if (n < nIn) bad("mesh has ", n, " vertices, fewer than the ", nIn, " input vertices");
  if (!m.vertexKind.empty() && m.vertexKind.size() != n)
    bad("vertexKind has ", m.vertexKind.size(), " entries for ", n, " vertices");
  for (uint32_t v = 0; v < nIn; ++v)
    if (!finite(inP(v))) bad("input vertex ", v, ' ', Xy{inP(v)}, " is not finite");
  for (uint32_t v = 0; v < n; ++v)
    if (!finite(P(v))) bad("vertex ", v, ' ', Xy{P(v)}, " is not finite");
  for (uint32_t s = 0; s < in.segmentCount(); ++s)
    for (int k = 0; k < 2; ++k)
      if (in.segments[2 * s + k] >= nIn)
        bad("input segment ", s, " (", in.segments[2 * s], "->", in.segments[2 * s + 1],
            ") refers to vertex ", in.segments[2 * s + k], ", but there are ", nIn,
            " input vertices");
  for (uint32_t t = 0; t < T; ++t)
    for (int k = 0; k < 3; ++k)
      if (corners(t)[k] >= n)
        bad(Tri{t, corners(t)}, " has index ", corners(t)[k], " out of range (", n, " vertices)");
  for (size_t s = 0; s < m.segments.size(); ++s)
    if (m.segments[s] >= n)
      bad("mesh segment ", s / 2, " has index ", m.segments[s], " out of range (", n, " vertices)");
  if (fatal) return false;
  for (uint32_t v = 0; v < nIn; ++v)
    if (!(P(v)[0] == inP(v)[0] && P(v)[1] == inP(v)[1]))
      log.add("mesh vertex ", v, ' ', Xy{P(v)}, " differs from input vertex ", v, ' ', Xy{inP(v)});
  return true;
}

VertexMap mapVertices(const Check& c, const Topology& t) {
  VertexMap map;
  map.used.assign(t.n, 0);
  for (uint32_t v = 0; v < t.n; ++v) map.used[v] = t.anyOut[v] != kNone;
  CoordTable table(t.m.points.data(), t.n);
  for (uint32_t v = 0; v < t.n; ++v) {
    if (!map.used[v]) continue;
    uint32_t first = table.insert(v);
    if (first != v)
      c.log.add("vertices ", first, " and ", v, " are both used and both at ", Xy{t.P(v)});
  }
  map.rep.assign(c.nIn, kNone);
  for (uint32_t v = 0; v < c.nIn; ++v)
    map.rep[v] = map.used[v] && t.P(v)[0] == c.inP(v)[0] && t.P(v)[1] == c.inP(v)[1]
                     ? v
                     : table.find(c.inP(v));
  map.twinOfUnused.assign(t.n, kNone);
  int flat = -1;  // whether all vertices are collinear; worked out when first needed
  for (uint32_t v = 0; v < t.n; ++v) {
    if (map.used[v]) continue;
    uint32_t u = table.find(t.P(v));
    map.twinOfUnused[v] = u;
    if (u == kNone && c.hullDomain() && (c.opt.mode == Mode::Delaunay || c.in.holes.empty())) {
      if (flat < 0) flat = allCollinear(t);
      if (!flat)
        c.log.add("vertex ", v, ' ', Xy{t.P(v)},
                  " is used by no triangle, but the whole convex hull is meshed");
    }
    if (u == kNone || v >= c.nIn) continue;
    if (u >= c.nIn)
      c.log.add("input vertex ", v, ' ', Xy{t.P(v)}, " is unused, but Steiner vertex ", u,
                " is at the same point");
    else if (u > v)
      c.log.add("input vertex ", v, ' ', Xy{t.P(v)}, " is unused, but its later duplicate ", u,
                " is used (the first copy should be kept)");
  }
  return map;
}

void checkKinds(const Check& c, const Topology& t, const VertexMap& vertices,
                const std::vector<uint32_t>& onSegment) {
  if (t.m.vertexKind.empty()) return;
  static const char* names[] = {"input", "unused", "segment", "free"};
  for (uint32_t v = 0; v < t.n; ++v) {
    uint8_t kind = t.m.vertexKind[v];
    if (kind > kFreeVertex) {
      c.log.add("vertex ", v, " has unknown kind ", int(kind));
      continue;
    }
    uint8_t want = kind;
    if (v < c.nIn)
      want = vertices.used[v] ? kInputVertex : kUnusedVertex;
    else if (kind < kSegmentVertex)
      want = kFreeVertex;
    else if (c.opt.mode != Mode::Delaunay && vertices.used[v])
      want = onSegment[v] != kNone ? kSegmentVertex : kFreeVertex;
    if (want == kind) continue;
    if (v >= c.nIn && want == kSegmentVertex)
      c.log.add("vertex ", v, ' ', Xy{t.P(v)}, " has kind free, but lies on input segment ",
                onSegment[v]);
    else if (v >= c.nIn && kind == kSegmentVertex)
      c.log.add("vertex ", v, ' ', Xy{t.P(v)}, " has kind segment, but lies on no input segment");
    else
      c.log.add("vertex ", v, ' ', Xy{t.P(v)}, " has kind ", names[kind], ", expected ",
                names[want]);
  }
}

}  // namespace acutemesh::validation
