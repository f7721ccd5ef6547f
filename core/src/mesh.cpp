// mesh(): the one entry point. Input checks, then the construction steps of build.h in order,
// then the output mesh and its figures.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <memory>
#include <new>
#include <stdexcept>

#include "acutemesh/acutemesh.h"
#include "acutemesh/predicates.h"
#include "acutemesh/vocabulary.h"
#include "angle_bound.h"
#include "build.h"
#include "domain_angles.h"
#include "labels.h"
#include "parts.h"
#include "portable_math.h"
#include "size_field.h"

namespace acutemesh {
namespace {

using detail::Budget;
using detail::kNone;
using detail::StepResult;
using detail::Triangulation;

// Messages about thin corners and missed triangles name this many of them at most.
constexpr size_t kCornersNamed = 3;

std::string checkInput(const Pslg& in) {
  if (in.points.size() % 2) return "points array has odd length " + std::to_string(in.points.size());
  if (in.segments.size() % 2)
    return "segments array has odd length " + std::to_string(in.segments.size());
  if (in.holes.size() % 2) return "holes array has odd length " + std::to_string(in.holes.size());
  size_t n = in.vertexCount();
  if (n > detail::kMaxVertices)
    return "too many vertices (" + std::to_string(n) + "; at most " +
           std::to_string(detail::kMaxVertices) + ")";
  for (size_t i = 0; i < n; ++i)
    if (!std::isfinite(in.points[2 * i]) || !std::isfinite(in.points[2 * i + 1]))
      return "vertex " + std::to_string(i) + " has a non-finite coordinate";
  for (size_t s = 0; s < in.segmentCount(); ++s)
    for (int k = 0; k < 2; ++k)
      if (in.segments[2 * s + k] >= n)
        return "segment " + std::to_string(s) + " refers to vertex " +
               std::to_string(in.segments[2 * s + k]) + ", but there are only " +
               std::to_string(n) + " vertices";
  for (size_t h = 0; h < in.holes.size(); ++h)
    if (!std::isfinite(in.holes[h])) return "hole " + std::to_string(h / 2) + " is not finite";
  if (!in.vertexMarkers.empty() && in.vertexMarkers.size() != n)
    return "vertexMarkers has " + std::to_string(in.vertexMarkers.size()) +
           " markers; expected one per vertex (" + std::to_string(n) + ") or none";
  if (!in.segmentMarkers.empty() && in.segmentMarkers.size() != in.segmentCount())
    return "segmentMarkers has " + std::to_string(in.segmentMarkers.size()) +
           " markers; expected one per segment (" + std::to_string(in.segmentCount()) +
           ") or none";
  for (size_t r = 0; r < in.regions.size(); ++r) {
    const Region& g = in.regions[r];
    const std::string region = "region " + std::to_string(r);
    if (!std::isfinite(g.x) || !std::isfinite(g.y)) return region + " has a non-finite coordinate";
    if (!std::isfinite(g.attribute)) return region + " has a non-finite attribute";
    if (!(g.maxArea >= 0) || !std::isfinite(g.maxArea))
      return region + " has maxArea " + detail::shortestText(g.maxArea) +
             "; expected a finite number >= 0";
  }
  return {};
}

// Copies the domain's triangles out, keeping input vertices at their indices and numbering
// the Steiner points that are used after them.
void extractMesh(const Triangulation& T, const std::vector<uint8_t>& inside,
                 const Pslg& input, const std::vector<uint32_t>& inputOf,
                 const std::vector<uint8_t>& freeVertex,
                 const std::vector<detail::ExactVertex>& exact, Mesh& mesh,
                 std::vector<const detail::RationalPoint*>& exactAt) {
  uint32_t slots = T.triangleSlots(), total = T.vertexCount();
  uint32_t inputCount = uint32_t(inputOf.size());
  // index: store vertex -> output vertex. Input vertices keep their input index.
  std::vector<uint32_t> index(total, kNone);
  std::copy(inputOf.begin(), inputOf.end(), index.begin());
  std::vector<uint8_t> used(total, 0);
  uint32_t nextIndex = inputCount, triangles = 0;
  for (uint32_t t = 0; t < slots; ++t) {
    if (!inside[t]) continue;
    ++triangles;
    for (int k = 0; k < 3; ++k) {
      uint32_t v = T.tri[3 * t + k];
      used[v] = 1;
      if (index[v] == kNone) index[v] = nextIndex++;
    }
  }
  // Input coordinates are copied as they came (the store holds the same values, reordered).
  mesh.points.resize(2 * size_t(nextIndex));
  std::copy(input.points.begin(), input.points.end(), mesh.points.begin());
  mesh.vertexKind.assign(nextIndex, kSegmentVertex);
  for (uint32_t v = 0; v < inputCount; ++v)
    mesh.vertexKind[index[v]] = used[v] ? kInputVertex : kUnusedVertex;
  for (uint32_t v = inputCount; v < total; ++v) {
    if (index[v] == kNone) continue;
    mesh.points[2 * size_t(index[v])] = T.pts[2 * size_t(v)];
    mesh.points[2 * size_t(index[v]) + 1] = T.pts[2 * size_t(v) + 1];
    if (v < freeVertex.size() && freeVertex[v]) mesh.vertexKind[index[v]] = kFreeVertex;
  }
  mesh.exactPoints.clear();
  exactAt.assign(exact.empty() ? 0 : nextIndex, nullptr);
  for (const detail::ExactVertex& x : exact) {
    if (index[x.vertex] == kNone) continue;
    mesh.exactPoints.push_back({index[x.vertex], detail::rationalText(x.at.x, x.at.w),
                                detail::rationalText(x.at.y, x.at.w)});
    exactAt[index[x.vertex]] = &x.at;
  }
  std::sort(mesh.exactPoints.begin(), mesh.exactPoints.end(),
            [](const ExactPoint& a, const ExactPoint& b) { return a.vertex < b.vertex; });
  mesh.triangles.resize(3 * size_t(triangles));
  mesh.segments.clear();
  mesh.segmentInput.clear();
  // The twins come from the store's (the output keeps each triangle's corners in order), for
  // the output labels (labels.h): far cheaper than finding them again.
  std::vector<uint32_t> outputOf(slots, kNone);
  for (uint32_t t = 0, i = 0; t < slots; ++t)
    if (inside[t]) outputOf[t] = i++;
  std::vector<int32_t>& twin = mesh.adjacency.halfedges;
  twin.assign(3 * size_t(triangles), -1);
  uint32_t* out = mesh.triangles.data();
  for (uint32_t t = 0; t < slots; ++t) {
    if (!inside[t]) continue;
    for (uint32_t e = 3 * t; e < 3 * t + 3; ++e) {
      const uint32_t o = T.opp[e];
      if (inside[o / 3]) twin[size_t(out - mesh.triangles.data())] = int32_t(3 * outputOf[o / 3] + o % 3);
      *out++ = index[T.tri[e]];
      // A fixed edge on an input segment is reported once, from an inside triangle. (Hull
      // edges fixed for refinement lie on no segment.)
      bool onSegment = T.fixed[e] && (T.segment.empty() || T.segment[e] != kNone);
      if (onSegment && (!inside[T.opp[e] / 3] || e < T.opp[e])) {
        mesh.segments.push_back(index[T.tri[e]]);
        mesh.segments.push_back(index[T.tri[detail::next(e)]]);
        mesh.segmentInput.push_back(T.segment.empty() ? 0 : T.segment[e]);
      }
    }
  }
}

// Smallest and largest angle in floating point (via cosines: the smallest angle is opposite
// the shortest edge, the largest opposite the longest), and the exact count of triangles with
// a right or obtuse corner (dot-product signs).
// Runs on the store (vertices in insertion order) where there is one, rather than on the
// output, whose input numbering scatters neighbours across memory: `slots` triangles of
// `tri` over `points` (x, y per vertex), those `inside` says (every one without it).
// Also returns the largest triangle area (floating point, as refinement measures it).
// Triangles at a vertex in `exact` are counted with its exact position.
double measureAngles(const std::vector<double>& points, const std::vector<uint32_t>& tri,
                     uint32_t slots, const std::vector<uint8_t>* inside,
                     const std::vector<detail::ExactVertex>& exact, Stats& stats) {
  double cosSmallest = -1, cosLargest = 1;  // of the smallest and the largest angle seen
  double largestArea = 0;
  uint32_t nonAcute = 0, obtuse = 0, count = 0;
  std::vector<const detail::RationalPoint*> exactAt(exact.empty() ? 0 : points.size() / 2, nullptr);
  for (const detail::ExactVertex& x : exact) exactAt[x.vertex] = &x.at;
  for (uint32_t t = 0; t < slots; ++t) {
    if (inside && !(*inside)[t]) continue;
    ++count;
    const uint32_t* v = &tri[3 * size_t(t)];
    const double* p[3];
    for (int k = 0; k < 3; ++k) p[k] = &points[2 * size_t(v[k])];
    double len2[3];  // squared length of the edge opposite corner k
    bool right = false, blunt = false;
    const bool atExact = !exactAt.empty() && (exactAt[v[0]] || exactAt[v[1]] || exactAt[v[2]]);
    int dots[3];
    if (atExact) {
      const detail::RationalPoint* at[3] = {exactAt[v[0]], exactAt[v[1]], exactAt[v[2]]};
      detail::triangleSigns(p, at, dots);
    }
    for (int k = 0; k < 3; ++k) {
      const double *a = p[k], *b = p[(k + 1) % 3], *c = p[(k + 2) % 3];
      len2[k] = (b[0] - c[0]) * (b[0] - c[0]) + (b[1] - c[1]) * (b[1] - c[1]);
      const int d = atExact ? dots[k] : sign(dot2d(a, b, c));
      right |= d <= 0;
      blunt |= d < 0;
    }
    nonAcute += right;
    obtuse += blunt;
    largestArea = std::max(largestArea, 0.5 * std::fabs(orient2d(p[0], p[1], p[2])));
    int lo = 0, hi = 0;
    for (int k = 1; k < 3; ++k) {
      if (len2[k] < len2[lo]) lo = k;
      if (len2[k] > len2[hi]) hi = k;
    }
    auto cosAt = [&](int k) {
      const double *a = p[k], *b = p[(k + 1) % 3], *c = p[(k + 2) % 3];
      double dot = (b[0] - a[0]) * (c[0] - a[0]) + (b[1] - a[1]) * (c[1] - a[1]);
      return dot / std::sqrt(len2[(k + 1) % 3] * len2[(k + 2) % 3]);
    };
    cosSmallest = std::max(cosSmallest, cosAt(lo));
    // (At an exact foot the double's angle may be a hair over the exact right angle.)
    cosLargest = std::min(cosLargest, atExact && !blunt ? std::max(0.0, cosAt(hi)) : cosAt(hi));
  }
  auto degrees = [](double c) { return std::acos(std::max(-1.0, std::min(1.0, c))) * (180.0 / M_PI); };
  stats.minAngle = count ? degrees(cosSmallest) : 0;
  stats.maxAngle = count ? degrees(cosLargest) : 0;
  stats.nonAcute = nonAcute;
  stats.obtuse = obtuse;
  return largestArea;
}

// Smallest angle between two segments at a shared end (degrees), from the directions of the
// segments at each vertex sorted by angle; 180 when no two segments meet.
double smallestInputAngle(const Pslg& in) {
  // The directions of the segments from each vertex, grouped by vertex (counting sort).
  const size_t n = in.vertexCount();
  std::vector<uint32_t> first(n + 1, 0);
  auto each = [&](auto visit) {
    for (size_t s = 0; s < in.segmentCount(); ++s) {
      const uint32_t a = in.segments[2 * s], b = in.segments[2 * s + 1];
      const double dx = in.points[2 * b] - in.points[2 * a];
      const double dy = in.points[2 * b + 1] - in.points[2 * a + 1];
      if (dx != 0 || dy != 0) visit(a, b, dx, dy);
    }
  };
  each([&](uint32_t a, uint32_t b, double, double) { ++first[a + 1], ++first[b + 1]; });
  for (size_t v = 0; v < n; ++v) first[v + 1] += first[v];
  std::vector<double> directions(first[n]);
  std::vector<uint32_t> fill(first.begin(), first.end() - 1);
  each([&](uint32_t a, uint32_t b, double dx, double dy) {
    directions[fill[a]++] = detail::portableAtan2(dy, dx);
    directions[fill[b]++] = detail::portableAtan2(-dy, -dx);
  });
  double smallest = M_PI;
  for (size_t v = 0; v < n; ++v) {
    double* const from = directions.data() + first[v];
    double* const to = directions.data() + first[v + 1];
    if (to - from < 2) continue;
    std::sort(from, to);
    for (const double* d = from; d + 1 < to; ++d)
      if (d[1] > d[0]) smallest = std::min(smallest, d[1] - d[0]);  // 0: the same segment twice
    const double wrap = *from + 2 * M_PI - to[-1];
    if (wrap > 0) smallest = std::min(smallest, wrap);
  }
  return smallest * (180.0 / M_PI);
}

// Whether a maximum angle of `bound` is at or below the floor: never at 90 (every corner is
// wider than 0, so its floor is below 90, however thin); below 90 the floor is measured in
// floating point, and a bound within a hair of it counts as at it.
bool atOrBelowFloor(double bound, const Stats& stats) {
  return bound != kAutoMaxAngle && bound < 90 && bound <= stats.angleFloor + 1e-9;
}

// The corners whose floor (angleFloor of each) is at or above `bound`.
double cornersUnder(double bound) { return 2 * (90 - bound) + 2e-9; }

// Says when the domain's corners make a target
// unreachable: a minimum angle above the smallest corner, or a maximum angle at or below the
// floor (Stats::angleFloor), naming the input vertices of those corners. True for the
// latter: refinement then aims for the lowest bound it can reach instead of spending the
// budget on the impossible.
bool warnAboutInputAngles(const Options& target, const detail::NamedCorners& corners,
                          Stats& stats) {
  using detail::degreesText;
  const std::string corner = degreesText(stats.smallestDomainAngle);
  if (target.minAngle > stats.smallestDomainAngle)
    stats.warnings.push_back("the domain's smallest corner (" + corner + ") is below the minimum "
                             "angle asked for (" + degreesText(target.minAngle) +
                             "): triangles there cannot meet it (" +
                             corners.below(target.minAngle, kCornersNamed) + ")");
  if (target.mode != Mode::Acute || !atOrBelowFloor(target.maxAngle, stats)) return false;
  const std::string floor = degreesText(stats.angleFloor);
  const double under = cornersUnder(target.maxAngle);
  const std::string which = " (the corners of " + degreesText(under) +
                            " or less: " + corners.below(under, kCornersNamed) + ")";
  // Above 72 the floor is sharp (the corner's own triangles); at 72 it is Bishop's bound for
  // every domain, below which some domains can go, but not by any plan acutemesh has.
  stats.warnings.push_back(
      stats.angleFloor > 72
          ? "the domain's smallest corner (" + corner + ") sets a floor of " + floor +
                ": no mesh has every angle below it; aiming for the lowest bound reachable "
                "instead of " + degreesText(target.maxAngle) + which
          : "a maximum angle of " + degreesText(target.maxAngle) + " is at or below the floor "
                "of " + floor + " that every domain reaches (its smallest corner is " + corner +
                "), and acutemesh does not aim below it; aiming for the lowest bound reachable "
                "instead");
  return true;
}

// The output triangles that miss the refinement target (the first kMaxMissedListed), for
// Stats::missedTriangles: exact for angle bounds (per output vertex, exactAt: the exact place
// of the mesh's exact points, extractMesh's), floating point for the minimum angle.
void listMissedTriangles(const Options& options, const Mesh& mesh,
                         const std::vector<const detail::RationalPoint*>& exactAt, Stats& stats) {
  const detail::AngleCheck below(options.maxAngle == kAutoMaxAngle ? 90 : options.maxAngle);
  const double cosMin = detail::portableCos(options.minAngle * M_PI / 180);
  const detail::Sizes sizes(options);
  stats.missedTriangles.clear();
  for (size_t t = 0; t < mesh.triangleCount() && stats.missedTriangles.size() < kMaxMissedListed; ++t) {
    const uint32_t* v = &mesh.triangles[3 * t];
    const double* p[3];
    for (int k = 0; k < 3; ++k) p[k] = &mesh.points[2 * size_t(v[k])];
    const bool atExact = !exactAt.empty() && (exactAt[v[0]] || exactAt[v[1]] || exactAt[v[2]]);
    int dots[3];
    if (atExact) {
      const detail::RationalPoint* at[3] = {exactAt[v[0]], exactAt[v[1]], exactAt[v[2]]};
      detail::triangleSigns(p, at, dots);
    }
    bool miss = false;
    for (int k = 0; k < 3 && !miss; ++k) {
      const double *a = p[k], *b = p[(k + 1) % 3], *c = p[(k + 2) % 3];
      const int d = atExact ? dots[k] : sign(dot2d(a, b, c));
      double ux = b[0] - a[0], uy = b[1] - a[1], vx = c[0] - a[0], vy = c[1] - a[1];
      double cosine = (ux * vx + uy * vy) / std::sqrt((ux * ux + uy * uy) * (vx * vx + vy * vy));
      if (options.mode == Mode::Acute) miss = d <= 0 || !below.cornerBelow(a, b, c);
      if (options.mode == Mode::NonObtuse) miss = d < 0;
      if (options.minAngle > 0 && cosine > cosMin * (1 + 1e-12)) miss = true;
    }
    if (options.maxArea > 0 && 0.5 * std::fabs(orient2d(p[0], p[1], p[2])) > options.maxArea) miss = true;
    if (sizes.any() && sizes.ratio(p[0], p[1], p[2]) > 1) miss = true;
    if (miss) stats.missedTriangles.push_back(uint32_t(t));
  }
}

// Where the first missed triangles are (their centroids), and the thin input corners nearest
// them: where a user would look to fix the data. Empty when nothing is missed.
std::string missedPlaces(const Mesh& mesh, const std::vector<uint32_t>& missed,
                         const detail::NamedCorners& corners) {
  std::vector<double> at;
  std::string text;
  for (size_t i = 0; i < missed.size() && i < kCornersNamed; ++i) {
    const uint32_t* v = &mesh.triangles[3 * size_t(missed[i])];
    auto mean = [&](int d) {
      const double* p = mesh.points.data() + d;
      const double sum = p[2 * size_t(v[0])] + p[2 * size_t(v[1])] + p[2 * size_t(v[2])];
      return corners.reported(sum / 3);
    };
    const double c[2] = {mean(0), mean(1)};
    at.insert(at.end(), c, c + 2);
    char place[64];
    std::snprintf(place, sizeof place, "(%.9g, %.9g)", c[0], c[1]);
    text += (text.empty() ? "" : ", ") + std::string(place);
  }
  if (text.empty()) return text;
  if (missed.size() > kCornersNamed) text += " (of " + std::to_string(missed.size()) + " listed)";
  text = "; missed triangles at " + text;
  const std::string near = corners.nearest(at);
  return near.empty() ? text : text + "; the input corners nearest them: " + near;
}

// Acute: the bound every angle of the mesh is certified below (Stats::angleBound).
double certifiedAngleBound(const Options& options, const Mesh& mesh, const Stats& stats) {
  if (stats.nonAcute > 0 || stats.triangles == 0) return 0;
  if (options.maxAngle >= 90) return 90;  // the dot-product signs of nonAcute say so
  if (options.maxAngle != kAutoMaxAngle && detail::meshBelow(mesh, detail::AngleCheck(options.maxAngle)))
    return options.maxAngle;
  return detail::tenthBound(stats.maxAngle, [&](double bound) {
    return detail::meshBelow(mesh, detail::AngleCheck(bound));
  });
}

// Whether the refined mesh meets the target, certified exactly for the angle bounds (acute:
// every angle below Stats::angleBound; non-obtuse: none above 90), in floating point for the
// minimum angle (to a relative 1e-9) and the area. `asked` is the maximum angle asked for,
// `options.maxAngle` what was aimed at (kAutoMaxAngle for a bound below the floor).
void certify(const Options& options, double asked, double largestArea,
             const std::vector<const detail::RationalPoint*>& exactAt,
             const detail::NamedCorners& corners, Stats& stats, Result& result) {
  bool met = true;
  if (options.mode == Mode::Acute) {
    stats.angleBound = certifiedAngleBound(options, result.mesh, stats);
    stats.certified = stats.angleBound > 0;
    met = stats.certified && (asked == kAutoMaxAngle || stats.angleBound <= asked);
  } else if (options.mode == Mode::NonObtuse) {
    met = stats.obtuse == 0;
    stats.certified = met;
  }
  if (options.minAngle > 0 && stats.triangles > 0 && stats.minAngle < options.minAngle * (1 - 1e-9))
    met = false;
  // An area bound counts too: a quality run stopped by its time limit has triangles above it.
  if (options.maxArea > 0 && largestArea > options.maxArea) met = false;
  const detail::Sizes sizes(options);
  if (sizes.any()) {
    const Mesh& m = result.mesh;
    for (size_t t = 0; t < m.triangleCount(); ++t) {
      const uint32_t* v = &m.triangles[3 * t];
      stats.sizeRatio = std::max(stats.sizeRatio, sizes.ratio(&m.points[2 * size_t(v[0])],
                                                              &m.points[2 * size_t(v[1])],
                                                              &m.points[2 * size_t(v[2])]));
    }
    if (stats.sizeRatio > 1) met = false;
  }
  stats.targetMet = met;
  if (!met) {
    Options missed = options;
    missed.maxAngle = asked;
    listMissedTriangles(missed, result.mesh, exactAt, stats);
  }
  if (!met && result.status == Status::Ok) {
    result.status = Status::TargetNotMet;
    uint32_t missing = options.mode == Mode::Acute       ? stats.nonAcute
                       : options.mode == Mode::NonObtuse ? stats.obtuse
                                                         : 0;
    result.message = missing ? std::to_string(missing) + " triangles still miss the target"
                             : "some triangles still miss the target";
  }
  // (Auto cut short has no bound to miss, but says what it certified too.)
  if ((!met || asked == kAutoMaxAngle) && stats.certified && result.status == Status::TargetNotMet)
    result.message += "; every angle is below " + detail::degreesText(stats.angleBound) + " (certified)";
  if (!met && result.status == Status::TargetNotMet)
    result.message += missedPlaces(result.mesh, stats.missedTriangles, corners);
}

// The result of a run whose maximum angle was below the floor (warnAboutInputAngles): not met,
// saying what was asked, the floor and the corners that set it, and what the mesh reached.
void reportBelowFloor(double asked, const detail::NamedCorners& corners, Result& result) {
  using detail::degreesText;
  Stats& stats = result.stats;
  stats.targetMet = false;
  if (result.status == Status::Cancelled) return;
  std::string reached = stats.certified
                            ? "the mesh has every angle below " + degreesText(stats.angleBound) +
                                  " (certified)"
                            : "the mesh is not acute" +
                                  (result.message.empty() ? "" : " (" + result.message + ")");
  // (At Bishop's 72 the floor is every domain's, and no corner need be under the bound's.)
  std::string which = corners.below(cornersUnder(asked), kCornersNamed);
  if (which.empty()) which = degreesText(stats.smallestDomainAngle);
  result.status = Status::TargetNotMet;
  result.message = "a maximum angle of " + degreesText(asked) + " is at or below the floor of " +
                   degreesText(stats.angleFloor) + " set by the domain's smallest corner (" +
                   which + "); " + reached;
}

}  // namespace

const char* version() { return "0.1.0"; }

namespace detail {
void CoordinateRange::add(const std::vector<double>& xy) {
  for (double x : xy) {
    if (x == 0) continue;
    if (!std::isfinite(x)) {
      finite = false;
      continue;
    }
    int e;
    std::frexp(x, &e);
    if (empty) largest = smallest = e, empty = false;
    largest = std::max(largest, e);
    smallest = std::min(smallest, e);
  }
}

namespace {
// Binary exponents the predicates handle exactly once scaled (see build.h): the largest
// magnitude is left alone within 2^+-kNear, the smallest non-zero one must stay above
// 2^kLowest, and a wide spread may push the largest up to 2^kNear.
constexpr int kNear = 64, kLowest = -166;
}  // namespace

bool exactScale(const CoordinateRange& r, int& exponent) {
  exponent = 0;
  if (r.empty || !r.finite) return true;  // non-finite input is refused elsewhere
  if (r.largest > kNear || r.largest < -kNear) exponent = r.largest;
  if (r.smallest - exponent >= kLowest) return true;
  // Tiny features next to large ones (1e-60 beside 1): lift the smallest as far as the
  // largest allows.
  exponent = r.largest - kNear;
  return r.smallest - exponent >= kLowest;
}

std::string degreesText(double degrees) {
  char text[40];
  std::snprintf(text, sizeof text, "%g", degrees);
  if (degrees < 90 && std::strtod(text, nullptr) >= 90) return shortestText(degrees) + " degrees";
  return std::string(text) + " degrees";
}

std::string shortestText(double x) {
  char text[32];
  for (int digits = 6; digits <= 17; ++digits) {  // (from 6: "10", not "1e+01")
    std::snprintf(text, sizeof text, "%.*g", digits, x);
    if (std::strtod(text, nullptr) == x) break;
  }
  return text;
}

std::string rangeMessage(const CoordinateRange& r) {
  return "coordinates span too many orders of magnitude to be meshed exactly (the largest "
         "about 2^" + std::to_string(r.largest) + ", the smallest non-zero about 2^" +
         std::to_string(r.smallest) + "; at most 2^" + std::to_string(kNear - kLowest) +
         " apart)";
}

bool scaleExactly(std::vector<double>& xy, int exponent) {
  bool exact = true;
  for (double& x : xy) {
    double y = std::ldexp(x, exponent);
    if (std::ldexp(y, -exponent) != x) exact = false;
    x = y;
  }
  return exact;
}
}  // namespace detail

namespace {

// mesh() for coordinates within range of the predicates (see below).
// An option out of range, or empty.
std::string checkOptions(const Options& options) {
  if (options.maxAngle == kAutoMaxAngle) {
    if (options.mode != Mode::Acute) return "maxAngle auto needs mode acute";
  } else if (!(options.maxAngle > 60 && options.maxAngle <= 90)) {
    return "maxAngle must be above 60 and at most 90 degrees, or auto";
  }
  if (!(options.minAngle >= 0 && options.minAngle < 60))
    return "minAngle must be at least 0 and below 60 degrees";
  if (!(options.maxArea >= 0) || !std::isfinite(options.maxArea))
    return "maxArea must be a finite number >= 0";
  if (!(options.optimize >= 0) || !std::isfinite(options.optimize))
    return "optimize must be a finite number of seconds >= 0";
  return detail::checkSizes(options);
}

// Why Options::optimize's search does not run (null: it does).
const char* searchLeftOut(const Options& options, const Options& target, bool refining) {
  if (!detail::searchAsked(options)) return nullptr;
  if (!refining) return "in a mode that does not refine";
  if (target.mode == Mode::Quality && target.minAngle == 0)
    return "on quality meshes without a minimum angle";
  return nullptr;
}

// Times each phase into Stats::phases and reports its end to Options::progress; the phase
// that follows (`next`) is what the reports until its end name.
class PhaseClock {
 public:
  PhaseClock(const Budget& budget, const Options& options, Stats& stats)
      : budget_(budget), options_(options), stats_(stats) {
    if (budget_.progress()) budget_.progress()->note("delaunay", -1, 0);
  }
  void end(const char* name, const char* next = nullptr) {
    double now = budget_.elapsed();
    stats_.phases.push_back({name, now - start_});
    start_ = now;
    if (options_.progress) options_.progress({name, 1.0, 0});
    if (next && budget_.progress()) budget_.progress()->note(next, -1, 0);
  }

 private:
  const Budget& budget_;
  const Options& options_;
  Stats& stats_;
  double start_ = 0;
};

// Why no triangle is inside (T's domain, classified with `options`, is empty): what the fill
// rule removed, and what would keep some.
std::string emptyDomainMessage(const Triangulation& T, const Pslg& input, const Options& options,
                               bool keepHull) {
  const std::string start = "the domain is empty: ";
  if (options.fill != FillRule::Triangle) {
    const bool evenOdd = options.fill == FillRule::EvenOdd;
    return start + "no region " +
           (evenOdd ? "lies inside an odd number of rings (fill 'evenodd')"
                    : "has a non-zero winding number (fill 'nonzero')") +
           "; the segments enclose no area";
  }
  // Without the hole points, is anything left? Then they removed it.
  std::vector<std::string> ignored;
  Pslg noHoles = input;
  noHoles.holes.clear();
  const std::vector<uint8_t> kept = detail::classifyDomain(T, noHoles, options, keepHull, ignored);
  if (std::find(kept.begin(), kept.end(), uint8_t(1)) != kept.end())
    return start + (input.holes.size() == 2 ? "the hole point's region is"
                                            : "the hole points' regions are") +
           " all of it (a hole point in the wrong place?)";
  return start + "fill 'triangle' removes every triangle reachable from outside the convex hull "
                 "without crossing a segment, and the segments enclose no area (close the "
                 "boundary with segments, or keep the hull with convexHull / --convex-hull)";
}

// The Delaunay triangulation of the input's vertices (inputOf: T's vertex k is input vertex
// inputOf[k]), its segments inserted unless the mode is Delaunay, and the domain's triangles
// marked in `inside`. With nearEnds.snap, segment ends within rounding reach of another
// segment are taken onto it, unless that leaves no domain: a needle that thin may be all
// there is (then nearEnds.snap is cleared and the input is taken as given).
StepResult triangulateDomain(const Pslg& input, const Options& options, const Budget& budget,
                             PhaseClock& clock, Triangulation& T, std::vector<uint32_t>& inputOf,
                             std::vector<uint8_t>& inside, Stats& stats, detail::NearEnds& nearEnds) {
  const size_t warningsBefore = stats.warnings.size(), phasesBefore = stats.phases.size();
  const bool constrained = options.mode != Mode::Delaunay;
  const uint32_t n = uint32_t(input.vertexCount());
  auto freshStore = [&] {
    T = Triangulation{};
    T.trackSegments = T.trackWinding = constrained;
    // Each vertex makes about two triangles (ghosts included): room up front avoids copies as
    // the arrays grow (only room: a duplicate vertex makes none, and untouched room costs no
    // memory).
    T.reserveCapacity(n, 2 * size_t(n) + 16);
  };
  freshStore();
  std::vector<uint32_t> canonical;
  auto countDuplicates = [&] {
    for (uint32_t i = 0; i < n; ++i) stats.duplicates += inputOf[canonical[i]] != i;
    if (stats.duplicates)
      stats.warnings.push_back(std::to_string(stats.duplicates) +
                               " duplicate vertices merged into earlier equal ones");
  };
  bool declined = true;
  StepResult step;
  if (constrained && detail::alongSegmentsPays(input)) {
    // One pass, timed as the segments' phase (the Delaunay phase is then empty).
    clock.end("delaunay", "segments");
    step = detail::triangulateAlongSegments(T, input, canonical, inputOf, stats, budget, nearEnds,
                                            declined);
    if (declined) {
      stats.warnings.resize(warningsBefore);
      freshStore();
    } else {
      if (!step.ok()) return step;
      countDuplicates();
    }
  }
  if (declined) {
    step = detail::buildDelaunay(T, input.points, canonical, inputOf, budget);
    if (!step.ok()) return step;
    countDuplicates();
    if (stats.phases.size() == phasesBefore)
      clock.end("delaunay", constrained ? "segments" : "domain");
    if (constrained) step = detail::insertSegments(T, input, canonical, stats, budget, nearEnds);
    if (!step.ok()) return step;
  }
  if (constrained) clock.end("segments", "domain");
  Options domainOptions = options;
  if (!constrained) domainOptions.fill = FillRule::Triangle;
  const bool keepHull = !constrained || options.convexHull || input.segments.empty();
  inside = detail::classifyDomain(T, constrained ? input : Pslg{}, domainOptions, keepHull,
                                  stats.warnings);
  const bool refining = options.mode == Mode::Quality || options.mode == Mode::NonObtuse ||
                        options.mode == Mode::Acute;
  clock.end("domain", refining ? "refine" : "output");
  if (std::find(inside.begin(), inside.end(), uint8_t(1)) == inside.end()) {
    if (nearEnds.snap && !nearEnds.found.empty()) {
      stats.warnings.resize(warningsBefore);
      stats.phases.resize(phasesBefore);
      stats.duplicates = 0;
      nearEnds.snap = false;
      T = Triangulation{};
      return triangulateDomain(input, options, budget, clock, T, inputOf, inside, stats, nearEnds);
    }
    return {Status::BadInput, emptyDomainMessage(T, input, domainOptions, keepHull)};
  }
  T.dropWinding();
  return {};
}

// What folding the slivers of segment ends near segments (detail::NearEnds) says: how many,
// the first of them and how far off its segment it was.
std::string snappedEndsWarning(const Triangulation& T, const Pslg& input,
                               const detail::NearEnds& nearEnds, int exponent) {
  std::vector<uint32_t> ends;
  for (const auto& found : nearEnds.found) ends.push_back(found.first);
  std::sort(ends.begin(), ends.end());
  const size_t count = size_t(std::unique(ends.begin(), ends.end()) - ends.begin());
  const auto [v, seg] = nearEnds.found.front();
  const double* p = T.point(v);
  const double off = detail::offSegment(input, seg, p);
  char text[320];
  std::snprintf(text, sizeof text,
                "%zu segment end%s within rounding reach of another segment taken onto it (the "
                "first at (%.9g, %.9g), %.2g off it): the slivers there are too thin to refine; "
                "the mesh follows the input within that reach",
                count, count == 1 ? "" : "s", std::ldexp(p[0], exponent),
                std::ldexp(p[1], exponent), std::ldexp(off, exponent));
  return text;
}

}  // namespace

namespace detail {

// `exponent`: the input was scaled by 2^-exponent for meshing (meshScaled); messages give
// coordinates as the caller did. byParts: false for a part's own run (parts.h).
Result meshInRange(const Pslg& input, const Options& asked, int exponent, bool byParts) {
  Result result;
  Stats& stats = result.stats;
  // The steps report through the relay (progress.h), which the budget's polls let report too.
  Options options = asked;
  std::unique_ptr<detail::ProgressRelay> relay;
  if (asked.progress) {
    relay = std::make_unique<detail::ProgressRelay>(asked.progress);
    options.progress = [r = relay.get()](const Progress& p) { r->report(p); };
  }
  Budget budget(options, relay.get());
  stats.inputVertices = uint32_t(input.vertexCount());
  stats.inputSegments = uint32_t(input.segmentCount());
  stats.inputHoles = uint32_t(input.holes.size() / 2);
  auto fail = [&](Status status, std::string message) {
    result.status = status;
    result.message = std::move(message);
    stats.seconds = budget.elapsed();
    return result;
  };
  std::string bad = checkInput(input);
  if (bad.empty()) bad = checkOptions(options);
  if (!bad.empty()) return fail(Status::BadInput, bad);

  PhaseClock clock(budget, options, stats);
  Triangulation T;
  std::vector<uint32_t> inputOf;
  std::vector<uint8_t> inside;
  // Refinement cannot resolve the slivers a segment end within rounding reach of another
  // segment makes: they are folded (NearEnds). A part's own run takes its part as given: a
  // sliver may lie between two parts, which must agree on it.
  detail::NearEnds nearEnds;
  nearEnds.snap = byParts && (options.mode == Mode::Quality || options.mode == Mode::NonObtuse ||
                              options.mode == Mode::Acute);
  StepResult step =
      triangulateDomain(input, options, budget, clock, T, inputOf, inside, stats, nearEnds);
  if (!step.ok()) return fail(step.status, step.message);
  if (nearEnds.snap && !nearEnds.found.empty())
    stats.warnings.push_back(snappedEndsWarning(T, input, nearEnds, exponent));

  bool refining = options.mode == Mode::Quality || options.mode == Mode::NonObtuse ||
                  options.mode == Mode::Acute;
  Options target = options;
  if (refining) detail::compileSizes(T, inside, input, target);
  // (Asked for in the options: the input's regional area bounds keep the default.)
  if (target.mode == Mode::Quality && target.minAngle == 0 && target.maxArea == 0 &&
      target.maxEdge == 0 && options.size.empty())
    target.minAngle = kQualityDefaultMinAngle;
  std::vector<uint8_t> freeVertex;
  std::vector<detail::ExactVertex> exact;
  bool belowFloor = false;
  T.inside = std::move(inside);
  T.inside.resize(T.tri.size() / 3, 0);
  const detail::NamedCorners corners(refining
                                         ? detail::NamedCorners(T, inputOf, exponent, input,
                                                                nearEnds.close)
                                         : detail::NamedCorners());
  // (The domain's corners for every constrained mode, so that a CDT's --stats says what a
  // refinement could reach; Delaunay ignores the segments.)
  if (options.mode != Mode::Delaunay) {
    stats.smallestDomainAngle = detail::smallestDomainAngle(T);
    stats.angleFloor = detail::angleFloor(stats.smallestDomainAngle);
    stats.smallestInputAngle = smallestInputAngle(input);
  }
  inside = std::move(T.inside);
  if (refining) belowFloor = warnAboutInputAngles(target, corners, stats);
  if (!refining && (options.minAngle > 0 || options.maxArea > 0 || options.maxAngle != 90 ||
                    options.maxEdge > 0 || !options.size.empty() || options.grading > 0))
    stats.warnings.push_back(std::string("minAngle, maxAngle, maxArea and sizes have no effect in mode ") +
                             nameOf(options.mode) +
                             ", which does not refine (modes quality, nonobtuse, acute do)");
  if (refining && options.grading > 0 && !(options.maxEdge > 0) && !options.size.function &&
      options.size.grid.h.empty() && options.size.sizes.empty())
    stats.warnings.push_back("grading has no effect without maxEdge or a size: it limits how fast "
                             "those grow");
  if (belowFloor) target.maxAngle = kAutoMaxAngle;
  if (const char* why = searchLeftOut(options, target, refining))
    stats.warnings.push_back(std::string("optimize has no effect ") + why);
  const bool inParts = refining && byParts &&
                       detail::meshByParts(T, inside, input, inputOf, target, budget, result);
  if (refining && !inParts && T.vertexCount() == 0) {
    // The parts released T, then one refused its input (a fault): the domain again, whole.
    Stats again;
    Options quiet = options;
    quiet.progress = nullptr;
    PhaseClock quietClock(budget, quiet, again);
    detail::NearEnds ends;
    ends.snap = nearEnds.snap;
    step = triangulateDomain(input, options, budget, quietClock, T, inputOf, inside, again, ends);
    if (!step.ok()) return fail(step.status, step.message);
  }
  if (inParts) {
    clock.end("refine", "output");
  } else if (refining) {
    T.inside = std::move(inside);
    step = detail::refine(T, input, target, budget, freeVertex, exact);
    inside = std::move(T.inside);
    clock.end("refine", "output");
    if (step.status == Status::Cancelled || step.status == Status::TargetNotMet) {
      result.status = step.status;
      result.message = step.message;
    }
  }

  std::vector<const detail::RationalPoint*> exactAt;  // per output vertex (into exact)
  if (!inParts) extractMesh(T, inside, input, inputOf, freeVertex, exact, result.mesh, exactAt);
  const Mesh& mesh = result.mesh;
  stats.vertices = uint32_t(mesh.vertexCount());
  stats.triangles = uint32_t(mesh.triangleCount());
  stats.segments = uint32_t(mesh.segments.size() / 2);
  stats.steiner = stats.vertices - stats.inputVertices;
  const double largestArea =
      inParts ? measureAngles(mesh.points, mesh.triangles, stats.triangles, nullptr, exact, stats)
              : measureAngles(T.pts, T.tri, T.triangleSlots(), &inside, exact, stats);
  if (refining) certify(target, options.maxAngle, largestArea, exactAt, corners, stats, result);
  if (belowFloor) reportBelowFloor(options.maxAngle, corners, result);
  clock.end("output");
  stats.seconds = budget.elapsed();
  return result;
}

}  // namespace detail

namespace {

// The predicates are exact while products of coordinate differences neither overflow nor
// underflow. Inputs far from 1 in magnitude (1e300, 1e-300), or with tiny features beside
// large ones, are scaled by a power of two, meshed, and scaled back: exact, since only
// exponents change. Inputs no power of two brings into range are refused.
// The output labels (labels.h) and the adjacency asked for, on the mesh as made (`made`: the
// input at the mesh's scale; `input` as the caller gave it, which warnings quote). Timed
// with the output phase.
void labelOutput(const Pslg& made, const Pslg& input, const Options& options, Result& r) {
  if (r.status == Status::BadInput) return;
  const auto start = std::chrono::steady_clock::now();
  detail::HalfEdges h = detail::labelMesh(made, input, r.mesh, r.stats.warnings);
  if (options.adjacency) r.mesh.adjacency = detail::adjacency(r.mesh, std::move(h));
  const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!r.stats.phases.empty()) r.stats.phases.back().seconds += took;
  r.stats.seconds += took;
}

// Region points (x, y) as interleaved coordinates, for the range and the scaling.
std::vector<double> regionPoints(const Pslg& input) {
  std::vector<double> xy;
  xy.reserve(2 * input.regions.size());
  for (const Region& g : input.regions) xy.insert(xy.end(), {g.x, g.y});
  return xy;
}

// An area bound scaled by 2^(2 * exponent): one beyond the double range bounds nothing, one
// below it is as small as can be asked for.
double scaledArea(double area, int exponent) {
  if (!(area > 0) || !std::isfinite(area)) return area;
  const double scaled = std::ldexp(area, 2 * exponent);
  return std::isinf(scaled) ? 0 : std::max(scaled, std::numeric_limits<double>::denorm_min());
}

Result meshScaled(const Pslg& input, const Options& options) {
  detail::CoordinateRange range;
  range.add(input.points);
  range.add(input.holes);
  std::vector<double> regions = regionPoints(input);
  range.add(regions);
  int exponent = 0;
  if (input.points.size() % 2 == 0 && !detail::exactScale(range, exponent)) {
    Result r;
    r.status = Status::BadInput;
    r.message = detail::rangeMessage(range);
    r.stats.inputVertices = uint32_t(input.vertexCount());
    r.stats.inputSegments = uint32_t(input.segmentCount());
    r.stats.inputHoles = uint32_t(input.holes.size() / 2);
    return r;
  }
  if (exponent == 0) {
    Result r = detail::meshInRange(input, options, 0, true);
    labelOutput(input, input, options, r);
    return r;
  }
  Pslg scaled = input;
  detail::scaleExactly(scaled.points, -exponent);
  detail::scaleExactly(scaled.holes, -exponent);
  detail::scaleExactly(regions, -exponent);
  for (size_t i = 0; i < scaled.regions.size(); ++i) {
    scaled.regions[i].x = regions[2 * i];
    scaled.regions[i].y = regions[2 * i + 1];
    scaled.regions[i].maxArea = scaledArea(input.regions[i].maxArea, -exponent);
  }
  Options scaledOptions = options;
  scaledOptions.exactFeet = false;  // their rationals would have to be scaled back too
  scaledOptions.maxArea = scaledArea(options.maxArea, -exponent);
  detail::scaleSizes(scaledOptions, exponent);
  Result r = detail::meshInRange(scaled, scaledOptions, exponent, true);
  labelOutput(scaled, input, options, r);
  // Steiner points below 2^-1022 once scaled back would lose bits (subnormal doubles), and
  // the mesh could fold: refused rather than returned inexact.
  if (!detail::scaleExactly(r.mesh.points, exponent)) {
    Result bad;
    bad.status = Status::BadInput;
    bad.message = "the mesh needs points too close to zero to be represented exactly at this "
                  "scale (below 2^-1022); scale the input up";
    bad.stats = std::move(r.stats);
    bad.stats.vertices = bad.stats.triangles = bad.stats.segments = bad.stats.steiner = 0;
    return bad;
  }
  return r;
}

// A size or area function's bad value (SizeFunctionGuard) makes the whole run BadInput.
Result meshGuarded(const Pslg& input, const Options& options) {
  if (!options.size.function && !options.size.maxArea) return meshScaled(input, options);
  Options guarded = options;
  const detail::SizeFunctionGuard guard(guarded);
  Result r = meshScaled(input, guarded);
  const std::string bad = guard.message();
  if (bad.empty() || r.status == Status::BadInput) return r;
  Result failed;
  failed.status = Status::BadInput;
  failed.message = bad;
  failed.stats.inputVertices = r.stats.inputVertices;
  failed.stats.inputSegments = r.stats.inputSegments;
  failed.stats.inputHoles = r.stats.inputHoles;
  return failed;
}

}  // namespace

// Nothing throws, as promised in acutemesh.h: memory running out (an area bound or a Steiner
// budget far beyond what fits, a huge input) ends the call with a message instead. Builds
// without exceptions (Emscripten's default) abort on it instead.
Result mesh(const Pslg& input, const Options& options) {
#if defined(__cpp_exceptions) || defined(__EXCEPTIONS)
  try {
    return meshGuarded(input, options);
  } catch (const std::bad_alloc&) {
  } catch (const std::length_error&) {
  }
  Result r;
  r.status = Status::BadInput;
  r.message = "out of memory: the input, or the refinement asked for, needs more memory than "
              "is available (a Steiner budget or a time limit bounds refinement)";
  r.stats.inputVertices = uint32_t(input.vertexCount());
  r.stats.inputSegments = uint32_t(input.segmentCount());
  r.stats.inputHoles = uint32_t(input.holes.size() / 2);
  return r;
#else
  return meshGuarded(input, options);
#endif
}

}  // namespace acutemesh
