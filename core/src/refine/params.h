// Every tuning constant of refinement, each with one line of why. How each value was chosen,
// and what the others tried gave, is in docs/TUNING.md.
#pragma once

#include <cstddef>
#include <cstdint>

#include "../portable_math.h"

namespace acutemesh::detail {

constexpr double kDegree = M_PI / 180.0;

// --- The target ---------------------------------------------------------------------------
// Quality refinement aims this many degrees over the minimum angle, so that rounding cannot
// leave a new triangle just under it.
constexpr double kQualityRoom = 0.5;
// Exact feet: an angle at a foot vertex within this (as a cosine) of 90 degrees counts as
// right; the double nearest a tilted segment's exact foot can be hundreds of ulps from it.
constexpr double kFootSlack = 1e-7;
// No edge shorter than 2^-kMinEdgeBits of the input's extent, nor than 2^-kMinEdgeUlpBits of
// its largest coordinate: past that, refinement would spiral into rounding noise.
constexpr int kMinEdgeBits = 36, kMinEdgeUlpBits = 42;
// Minimum angles above this need not terminate; a run that wanders is made again to it.
constexpr double kSureMinAngle = 40;

// --- Parts --------------------------------------------------------------------------------
// A domain of several parts with at least this many triangles is meshed part by part
// (parts.h); below it a whole run is quick, and its meshes stay as they were.
constexpr size_t kPartsFrom = 4096;
// Below 90 degrees the parts' acute meshes come first (parts.cpp runParts): the share of the
// progress bar they stand for (a descent takes ten to a hundred times as long).
constexpr double kPartsAcuteShare = 0.1;

// A domain (a part) of this many vertices or more runs its first strategy alone, the others
// only should it miss: from here on it won on every country's part (strategies.cpp).
constexpr uint32_t kFirstStrategyAloneFrom = 3000;

// --- Budgets --------------------------------------------------------------------------------
// The default Steiner budget: this many per input vertex, at least kSteinerAtLeast.
constexpr double kSteinerPerInputVertex = 50, kSteinerAtLeast = 20000;
// An area bound reserves room for the vertices it expects, but never more than this up front.
constexpr uint32_t kReservedVerticesAtMost = 1u << 21;

// --- Steiner points (seed 2.1) --------------------------------------------------------------
// A cavity examined for encroachment stops growing past this many triangles.
constexpr size_t kCavityExamined = 256;
// The best few candidate points are weighed; later ones rarely win.
constexpr size_t kSliceTries = 3;
// The Voronoi walk for candidates visits at most this many triangles.
constexpr size_t kVoronoiWalk = 64;

// --- Boundary -----------------------------------------------------------------------------
// Non-obtuse: passes of cutting slivers at altitude feet before the fans.
constexpr int kCutAtFeetPasses = 4;

// A boundary edge whose split is blocked by slivers outside the domain (collinear segments)
// gets at most this many of them flipped away.
constexpr int kOuterSliverFlips = 4;

// --- Corner fans --------------------------------------------------------------------------
// Input corners with a domain sector under this get a fan (non-obtuse: a right triangle
// settles a wider tip).
constexpr double kSmallAngle = 60 * kDegree, kSmallAngleNonObtuse = 30 * kDegree;
// A fan's isosceles triangles have apex angles of at most this.
constexpr double kFanAngle = 80 * kDegree;
// Fans at every corner (the descent below 90 degrees) cut it into sectors near this.
constexpr double kEvenFanAngle = 60 * kDegree;
// A fan's radius, as a fraction of its corner's distance to its link: under half keeps fans
// apart and their triangles Delaunay.
constexpr double kFanFactor = 0.49;
// Wide fans (Strategy::wideFans) grow to this fraction of the distance to the link ...
constexpr double kWideFan = 0.8;
// ... keeping the disks of two fans this fraction of their distance apart ...
constexpr double kFanGap = 0.98;
// ... and a fan at a corner over kYieldRatio times as wide yields 1 - kYield of its radius to
// the smaller one, whose room saves more points.
constexpr double kYieldRatio = 4, kYield = 0.2;

// --- Polish -------------------------------------------------------------------------------
// Improvement rounds at most, and removal passes per removal step at most.
constexpr int kPolishRounds = 12, kRemovalPasses = 12;
// Options::optimize's search (Polish::search): the share of tries that ruin rather than kick;
// a kick's share of free Steiner points, and how far each goes toward a random neighbour (a
// share of the edge, from and to); a ruin's share of free Steiner points taken out, and the
// chance each of their free neighbours goes with them; the rounds after either.
constexpr double kSearchRuin = 0.75;
constexpr double kSearchKick = 0.3;
constexpr double kSearchStep[2] = {0.05, 0.45};
constexpr double kRuinShare = 0.02, kRuinNeighbour = 0.5;
constexpr int kSearchRounds = 3;
// A round must take out this fraction of the Steiner points for another to run ...
constexpr double kPolishGain = 0.005;
// ... except below this many points, where rounds are cheap: they go on until two in a row
// gain nothing (non-obtuse: all kPolishRounds). From here on rounds run in two halves at once.
constexpr size_t kSmallPolish = 400;
// Rounds in halves gain for longer: from kHalvesGainFrom points a round must take out
// kHalvesGain, and from kLargeRoundFrom points kLargeGain, to go on.
constexpr size_t kHalvesGainFrom = 700;
constexpr double kHalvesGain = 0.02;
constexpr size_t kLargeRoundFrom = 1000;
constexpr double kLargeGain = 0.03;
// A pair whose joint link has this many edges or more is merged only where one point fits
// without moving its neighbours: such tries almost never succeed.
constexpr size_t kMergeLinkEdges = 11;
// From this many live Steiner points on, the improvement passes visit them in the order of a
// Hilbert curve rather than by age (RefineState::visitOrder, curve_order.h).
constexpr size_t kSpatialOrderFrom = 50000;

// --- Bounds below 90 degrees (descent.h, below90.h) ---------------------------------------
// The descent starts from a quality mesh with this minimum angle: every bound down to 75
// degrees needs angles of at least 30.
constexpr double kDescentMinAngle = 30;
// The pattern search's first step, as a fraction of the distance to the nearest link vertex
// (along a segment: of the stretch between the neighbours), and its finest.
constexpr double kDescentStep = 0.25, kDescentFinestStep = 1e-3;
// Steps of one pattern search at most.
constexpr int kDescentSearchSteps = 32;
// A point on a segment keeps this fraction of its stretch from either neighbour.
constexpr double kDescentSegmentRoom = 0.05;
// Smoothing sweeps per round at most; rounds in a row that do not lower the violation by
// kDescentGain before the descent gives up.
constexpr int kDescentSweeps = 4, kDescentStaleRounds = 5;
// A round must lower the violation by this fraction, or the next looks two moves ahead.
constexpr double kDescentGain = 0.02;
// Smoothing leaves a star alone whose every triangle is this far within the bound (as the
// cosine of its largest angle less the bound's).
constexpr double kDescentSlack = 0.03;
// Smoothing sweeps around a move at most.
constexpr int kDescentLocalSweeps = 2;
// Moves one descent may try, over all its bounds: this many, and this many per vertex.
constexpr double kDescentMoves = 6000, kDescentMovesPerVertex = 16;
// Of those, the first bound may take this many and this many per vertex of the acute mesh.
constexpr double kDescentFirstMoves = 2000, kDescentFirstMovesPerVertex = 8;
// Where a descent stalls, the edges of the triangles still missing its bound are split and it
// runs again, this many times at most.
constexpr int kDescentSplitRetries = 5;
// The moves a descent may try grow by this many for each point the splits add.
constexpr double kDescentMovesPerSplit = 64;
// At the bound a descent reached, passes over its Steiner points that take out those the bound
// does not need (AngleDescent::thin): this many at most, until one takes out under this share.
constexpr int kThinPasses = 3;
constexpr double kThinGain = 0.01;
// The deepest look-ahead: moves in a row, each at the worst triangle near the last.
constexpr int kDescentDepth = 3;
// Joint smoothing (joint_smooth.h), where the descent's moves stop paying: it aims this many
// degrees below the bound and takes at most kJointSteps steps, the first kJointFirstStep times
// the gradient (scaled by each point's shortest edge squared), halved up to kJointTries times
// until the penalty drops; no point moves further than kJointFarthest of its shortest edge in
// one step.
constexpr double kJointRoom = 0.5;
constexpr int kJointSteps = 30;
constexpr double kJointFirstStep = 0.5, kJointFarthest = 0.3;
constexpr int kJointTries = 12;
// Rounds per bound at most.
constexpr int kDescentRounds = 24;

// The direct refinement toward a bound below 90 (refine's repairs with the bound as target)
// aims no lower than this: below, it does not end before its Steiner cap.
constexpr double kDirectFrom = 85;
// The descents below 90 degrees may use this many times the acute mesh's Steiner points
// (plus 200).
constexpr double kBelow90Points = 8;
// From this many vertices in the acute mesh (a country's mainland) the direct start runs
// alone first, and the others only if it misses the bound: where it meets it, their descents
// took ten to twenty times as long for a few percent fewer points (--optimize spends the time
// where that is wanted).
constexpr uint32_t kDirectAloneFrom = 10000;
// A graded descent refines away, before each bound L, the angles under 180 - 2 L + this.
constexpr double kGradedRoom = 4;
// Of two meshes that miss a bound below 90, the one with fewer points is kept unless the
// other's largest angle is smaller by this many degrees or more.
constexpr double kCandidateEven = 0.1;
// --max-angle auto aims for the domain's floor plus this.
constexpr double kAutoMargin = 0.5;
// Auto tries no further start once its best mesh is within this many degrees of the floor (a
// floor near 90: a quarter of the way from it to 90).
constexpr double kAutoEnough = 2;

static_assert(kHalvesGainFrom >= kSmallPolish && kLargeRoundFrom >= kHalvesGainFrom,
              "the rounds in halves start at kSmallPolish and run the larger meshes' round");

}  // namespace acutemesh::detail
