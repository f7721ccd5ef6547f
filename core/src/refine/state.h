// The refinement state: the triangulation and what refinement knows of each vertex. It is one
// value: a strategy's run, a round that may be undone and the second half of a round in halves
// each work on a copy of it.
#pragma once

#include <cstdint>
#include <vector>

#include "../triangulation.h"
#include "acutemesh/acutemesh.h"

namespace acutemesh::detail {

// kOnHull: on a boundary edge no segment lies on (hull of a point set); kept in place like
// kOnSegment, reported like kFree (no input segment holds it). kArc: on the arc of a corner
// fan (fans.h); never moved while refinement runs, an ordinary free Steiner point once the
// target is met.
enum VertexRole : uint8_t { kInput, kOnSegment, kOnHull, kFree, kArc };

struct RefineState {
  // The triangulation, with T.inside marking the domain.
  Triangulation T;
  std::vector<uint8_t> role;  // per vertex: a VertexRole
  // Per vertex: the input vertex whose corner fan it belongs to (on its arc, or where the fan
  // meets a segment), else kNone. Per input vertex: its fan's radius (0: none).
  std::vector<uint32_t> fanCenter;
  std::vector<double> fanRadius;
  // Per vertex (Options::exactFeet): for a segment vertex standing for the exact altitude foot
  // of a vertex, that vertex (exact_feet.h), else kNone.
  std::vector<uint32_t> footOf;

  // The state refinement starts from: T (the domain marked in T.inside) with every vertex
  // past the input's on a segment (the CDT's crossing points), and the domain's edges that no
  // segment lies on (a point set's hull) fixed, so that the boundary rule applies to them.
  static RefineState start(Triangulation T, size_t inputVertices);

  const double* P(uint32_t v) const { return T.point(v); }
  uint32_t addVertex(const double* p, VertexRole r, uint32_t fan = kNone) {
    role.push_back(r);
    fanCenter.push_back(fan);
    footOf.push_back(kNone);
    return T.addVertex(p[0], p[1]);
  }
  // A change tried in place (the descent's moves), while T.journal is set: mark() before it,
  // undoTo() takes it back (Triangulation::undoTo), per-vertex data and fan radii too.
  Journal::Mark mark() const { return T.mark(); }
  void undoTo(const Journal::Mark& m) {
    std::vector<std::pair<uint32_t, double>>& radii = T.journal->radii;
    for (size_t i = radii.size(); i-- > m.radii;) fanRadius[radii[i].first] = radii[i].second;
    radii.resize(m.radii);
    T.undoTo(m);
    role.resize(m.vertices), fanCenter.resize(m.vertices), footOf.resize(m.vertices);
  }
  void setFanRadius(uint32_t v, double r) {
    if (T.journal) T.journal->radii.push_back({v, fanRadius[v]});
    fanRadius[v] = r;
  }
  // Takes back the vertex just added, which no triangle uses.
  void dropLastVertex() {
    T.pts.resize(T.pts.size() - 2);
    T.vertexEdge.pop_back();
    role.pop_back();
    fanCenter.pop_back();
    footOf.pop_back();
  }
  // A chord of a corner fan: a fixed edge between two points of the same fan.
  bool isChord(uint32_t e) const {
    uint32_t c = fanCenter[T.tri[e]];
    return c != kNone && c == fanCenter[T.tri[next(e)]];
  }
  // A fixed edge on a segment or the hull (not a chord).
  bool isSubsegment(uint32_t e) const { return T.isFixed(e) && !isChord(e); }
  // The state without what can be rebuilt (Triangulation::Compact): a polish round's way
  // back, about half a copy; restore() makes the very state again.
  struct Compact {
    Triangulation::Compact T;
    std::vector<uint8_t> role;
    std::vector<uint32_t> fanCenter, footOf;
    std::vector<double> fanRadius;
  };
  Compact compact() const { return {T.compact(), role, fanCenter, footOf, fanRadius}; }
  void restore(Compact&& c) {
    T.restore(std::move(c.T));
    role = std::move(c.role), fanCenter = std::move(c.fanCenter), footOf = std::move(c.footOf);
    fanRadius = std::move(c.fanRadius);
  }
  // Reserves room for about `vertices` vertices in all (refinement to an area bound).
  void reserve(size_t vertices);
  // Chords are fixed only while refinement runs; the output knows them as plain edges.
  void releaseChords();
  // How Steiner point v may move when points are smoothed toward a bound below 90
  // (descent.h, joint_smooth.h): false if it stands (an input vertex, a fan's point, a free
  // point with a fixed edge, a segment point with other fixed edges); else `ends` its two
  // neighbours along its segment and `segment` that segment (kNone on a hull edge), both kNone
  // for a free point. A point on the hull has ghost triangles: its hull edges still count.
  bool slideOf(uint32_t v, uint32_t ends[2], uint32_t& segment) const;
  // The vertices from..to-1 in the order the improvement passes visit them: by index, or from
  // kSpatialOrderFrom on along a Hilbert curve of their places, so that each try finds its
  // neighbourhood still in the cache from the one before (index order scatters them: a
  // country's mainland ran at half the triangles per second of a small island).
  void visitOrder(uint32_t from, uint32_t to, std::vector<uint32_t>& order) const;
  // From kSpatialOrderFrom live Steiner points on: renumbers the triangles along the same curve
  // (by the middle of their corners), so that a vertex's star lies in a few cache lines rather
  // than wherever refinement made or freed its slots. Nothing may hold triangle numbers.
  void compactTriangles(size_t inputVertices);
  // Steiner points in the mesh (vertexCount() also counts those removed).
  size_t liveSteiner(size_t inputVertices) const;
  // Per vertex: 1 for the Steiner points on no input segment (Mesh::vertexKind kFreeVertex).
  void markFree(std::vector<uint8_t>& out) const;
};

}  // namespace acutemesh::detail
