#include "target.h"

#include <algorithm>

#include "../build.h"

namespace acutemesh::detail {

Target::Target(const Options& options)
    : acute(options.mode == Mode::Acute),
      nonObtuse(options.mode == Mode::NonObtuse),
      feet(nonObtuse && options.exactFeet),
      strictMax(acute && options.maxAngle < 90),
      cosMax(portableCos(options.maxAngle * kDegree)),
      cosMin(portableCos(options.minAngle * kDegree)),
      cosQuality(portableCos(std::min(options.minAngle + kQualityRoom, 60.0) * kDegree)),
      minAngle(options.minAngle),
      maxArea(options.maxArea),
      sizes(options),
      searches(searchAsked(options)) {}

int Target::footCorners(const RefineState& s, uint32_t t) const {
  int mask = 0;
  const uint32_t* v = &s.T.tri[3 * t];
  for (uint32_t k = 0; k < 3; ++k) {
    const uint32_t foot = s.footOf[v[k]];
    if (foot == kNone) continue;
    mask |= kNearFoot;
    if ((s.isSubsegment(3 * t + k) && v[(k + 2) % 3] == foot) ||
        (s.isSubsegment(3 * t + (k + 2) % 3) && v[(k + 1) % 3] == foot))
      mask |= 1 << k;
  }
  return mask;
}

bool Target::starMeets(const RefineState& s, uint32_t a) const {
  uint32_t e0 = s.T.vertexEdge[a], e = e0;
  do {
    if (misses(s, e / 3)) return false;
    e = s.T.opp[prev(e)];
  } while (e != e0);
  return true;
}

bool Target::anyMissed(const RefineState& s) const {
  for (uint32_t t = 0; t < s.T.triangleSlots(); ++t)
    if (misses(s, t)) return true;
  return false;
}

}  // namespace acutemesh::detail
