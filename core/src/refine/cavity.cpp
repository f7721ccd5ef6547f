#include "cavity.h"

#include <algorithm>

namespace acutemesh::detail {

Cavity::Rim Cavity::examine(uint32_t from, const double* x) {
  cavity_.assign(1, from);
  return grow(x);
}

// The triangles reachable from those in cavity_ without crossing a fixed edge whose
// circumcircle holds x. Fixed edges on its rim are the subsegments x could encroach.
Cavity::Rim Cavity::grow(const double* x) {
  const Triangulation& T = s_.T;
  uint32_t encroached = kNone, beyond = kNone;
  double encroachedLen = -1;
  for (size_t i = 0; i < cavity_.size(); ++i) {
    uint32_t t = cavity_[i];
    for (uint32_t e = 3 * t; e < 3 * t + 3; ++e) {
      uint32_t n = T.opp[e] / 3;
      const double *a = s_.P(T.tri[e]), *b = s_.P(T.tri[next(e)]);
      if (T.isFixed(e)) {
        double d = dot2d(x, a, b);
        // x in the closed diametral disk: the angle at x too large (right allowed non-obtuse).
        bool inDisk = job_.target.tooLarge(d);
        if (inDisk && dist2(a, b) > encroachedLen) encroached = e, encroachedLen = dist2(a, b);
        if (orient2d(a, b, x) < 0 && beyond == kNone) beyond = e;
        continue;
      }
      if (T.isGhost(n) || std::find(cavity_.begin(), cavity_.end(), n) != cavity_.end()) continue;
      const uint32_t* w = &T.tri[3 * n];
      if (incircle(s_.P(w[0]), s_.P(w[1]), s_.P(w[2]), x) > 0) cavity_.push_back(n);
    }
    if (cavity_.size() > kCavityExamined) break;
  }
  return {encroached, beyond};
}

// The cavity's triangles give way to those joining x to its rim.
int Cavity::badChange(const double* x, uint32_t split, uint32_t footOf) const {
  const Triangulation& T = s_.T;
  const Target& target = job_.target;
  int change = 0;
  for (uint32_t t : cavity_) {
    change -= target.worstCorner(s_, t).k >= 0;
    for (uint32_t e = 3 * t; e < 3 * t + 3; ++e) {
      if (split != kNone && (e == split || e == T.opp[split])) continue;
      uint32_t n = T.opp[e] / 3;
      bool rim = T.isFixed(e) || T.isGhost(n) ||
                 std::find(cavity_.begin(), cavity_.end(), n) == cavity_.end();
      if (!rim) continue;
      const double* p[3] = {x, s_.P(T.tri[e]), s_.P(T.tri[next(e)])};
      // A split point at footOf's foot: its corner between a piece of the subsegment and
      // the edge to footOf counts as right (Target::footCorners).
      int foot = 0;
      if (target.feet && footOf != kNone) {
        foot = kNearFoot;
        for (uint32_t end : {T.tri[split], T.tri[next(split)]})
          foot |= int((T.tri[e] == end && T.tri[next(e)] == footOf) ||
                      (T.tri[next(e)] == end && T.tri[e] == footOf));
      }
      change += target.worstCorner(p, foot).k >= 0;
    }
  }
  return change;
}

int Cavity::splitChange(uint32_t e, const double* m, uint32_t footOf) {
  cavity_.clear();
  for (uint32_t side : {e, s_.T.opp[e]}) {
    uint32_t t = side / 3;
    if (s_.T.inDomain(t)) cavity_.push_back(t);
  }
  grow(m);
  return badChange(m, e, footOf);
}

}  // namespace acutemesh::detail
