// How a run goes about the boundary and the choice of points. No one way wins everywhere:
// strategies.cpp runs several and keeps the best.
#pragma once

namespace acutemesh::detail {

struct Strategy {
  bool cutAtFeetFirst = false;  // non-obtuse: cut slivers at altitude feet before the fans
  bool footOnSegments = false;  // non-obtuse: split an encroached subsegment at the altitude foot
  bool lazyFans = false;        // fans only at small sectors where a bad triangle turns up
  bool wideFans = false;        // fans at the smallest corners as wide as their neighbours allow
  // Non-obtuse: slide a segment vertex to the middle of the longest stretch where its star
  // meets the target before trying a few sampled places.
  bool exactSlide = false;
  // Candidate points spare the segments and are weighed: of the Voronoi vertices in the bad
  // triangle's circumdisk that encroach no subsegment, the one that leaves the fewest bad
  // triangles goes in (quality: the first that encroaches none), and a subsegment split by the
  // boundary rule goes where it leaves the fewest. Without (acute's fallbacks): the seed's
  // farthest point of the slice, whatever it encroaches, and the usual split places.
  bool weighPoints = true;
  // Repair first the bad triangle whose repair leaves the fewest bad triangles, not the
  // largest (acute and non-obtuse).
  bool fewestBadFirst = false;
  // The descent below 90 degrees (below90.h): a fan at every input corner, its sectors as
  // near 60 degrees as whole numbers of them allow.
  bool fansEverywhere = false;
  bool fallback = false;  // run only if no strategy before it met the target
};

}  // namespace acutemesh::detail
