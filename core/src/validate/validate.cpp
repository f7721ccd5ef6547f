// validate(): invariant checks of an output mesh against its input (see acutemesh.h).
//
// Every decision is an exact predicate sign or an exact comparison of doubles. The one
// allowance: a segment's chain may pass through a vertex within rounding reach of the segment
// when a listed segment edge leads there, since crossing and split points are rounded
// constructions (segment_walker.h). The work is O(n log n): per-vertex sorted half-edge lists
// give twins and stars, a hash table matches coordinates, uniform grids over the few points
// that need locating replace all-pairs tests, and winding numbers are propagated across
// edges, with one ray cast per connected piece of the mesh.
#include "../build.h"
#include "acutemesh/acutemesh.h"
#include "check.h"
#include "domain.h"
#include "error_log.h"
#include "query_grid.h"
#include "segment_walk.h"
#include "topology.h"
#include "vertices.h"
#include "winding.h"

namespace acutemesh {
namespace {

using namespace validation;

// The checks in order: each later one relies on what the earlier ones built, and the order
// is the order of the messages.
void run(const Pslg& in, const Mesh& m, const Options& opt, Validation& out) {
  ErrorLog log(out);
  if (!checkSizes(in, m, log)) return log.finish();
  const Check c{in, opt, log, uint32_t(in.vertexCount())};
  const Topology topo = buildTopology(m, log);
  checkStars(topo, log);
  const VertexMap vertices = mapVertices(c, topo);
  const QueryGrid points = pointsToLocate(c, topo, vertices);
  const SegmentEdges edges = walkSegments(c, topo, vertices);
  checkKinds(c, topo, vertices, edges.onSegment);
  checkBoundaryEdges(c, topo, vertices, edges);
  checkFillRule(c, topo, edges);
  locatePoints(c, topo, edges, points);
  log.finish();
}

}  // namespace

Validation validate(const Pslg& input, const Mesh& mesh, const Options& options) {
  Validation result;
  // Far from 1 (1e300, 1e-300), or with tiny coordinates beside large ones, the predicates
  // would overflow or underflow: check an exactly scaled copy, as mesh() meshes one (scaled
  // for the input, as there; the mesh's own points go along). Input mesh() refuses cannot be
  // checked either.
  detail::CoordinateRange range;
  range.add(input.points);
  range.add(input.holes);
  int exponent = 0;
  if (!detail::exactScale(range, exponent)) {
    result.ok = false;
    result.errors.push_back("cannot check exactly: input " + detail::rangeMessage(range));
    return result;
  }
  if (exponent != 0) {
    Pslg in = input;
    Mesh m = mesh;
    if (detail::scaleExactly(in.points, -exponent) && detail::scaleExactly(in.holes, -exponent) &&
        detail::scaleExactly(m.points, -exponent)) {
      run(in, m, options, result);
      return result;
    }
  }
  run(input, mesh, options, result);
  return result;
}

}  // namespace acutemesh
