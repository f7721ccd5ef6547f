// Corner fans. Where segments meet at a small angle, refinement alone spirals into the
// corner: points placed in or next to the wedge encroach the short subsegments at its apex,
// and their splits make the triangles there smaller still. So an input vertex with a small
// domain sector between its segments (kSmallAngle; non-obtuse kSmallAngleNonObtuse) gets a
// fan: every segment at it is split at the same distance r, and every domain sector around it
// is cut by points on the circle of radius r into isosceles triangles with apex angles of at
// most kFanAngle. The fan's outer edges (chords) stay fixed while refinement runs, so the fan
// stays as built; a chord that must be split is split on its arc (Boundary). r is just under
// half the distance from the vertex to its link (kFanFactor): the fan's disk holds no other
// vertex or segment, its triangles are Delaunay, and the fans of two vertices keep apart.
#pragma once

#include <cstdint>
#include <vector>

#include "job.h"
#include "state.h"

namespace acutemesh::detail {

class CornerFans {
 public:
  CornerFans(RefineState& s, const Job& job) : s_(s), job_(job) {}

  // Fans before refinement: every radius first (from the triangulation as it is), then the
  // fans. With Strategy::lazyFans only where a small sector already holds a bad triangle
  // (repairs add the others); with Strategy::wideFans as wide as their neighbours allow.
  void buildAll();
  // The fan radius input vertex v calls for (0: none): it has a small domain sector, and with
  // onlyWhereBad one that holds a triangle missing the target.
  double radiusFor(uint32_t v, bool onlyWhereBad);
  void build(uint32_t v, double r);

 private:
  struct Spoke {
    uint32_t to;        // the other end of the fixed edge
    double direction;   // radians
    bool sectorInside;  // the sector from this spoke counter-clockwise to the next is in the domain
    bool sectorBad;     // ... and holds a triangle that misses the target
  };
  struct FanCentre {
    uint32_t vertex;
    double radius;
    double sector;  // its smallest domain sector (radians)
    double widest;  // kWideFan times the distance to its link (set by widen)
  };
  double readStar(uint32_t v);
  double sectorAngle(size_t i) const;
  double smallestSector() const;
  void widen(std::vector<FanCentre>& centres) const;

  RefineState& s_;
  const Job& job_;
  std::vector<Spoke> spokes_;  // readStar's
  std::vector<uint32_t> ring_;
};

}  // namespace acutemesh::detail
