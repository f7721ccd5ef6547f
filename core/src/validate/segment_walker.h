// The walk behind walkSegments(), shared by its two files: segment_walk.cpp walks one
// segment, segment_list.cpp matches the walks against Mesh::segments.
//
// A walk goes from a toward b. A step goes along a mesh edge to a vertex exactly on the
// segment and strictly closer to b, or else along a listed segment edge (Mesh::segments) to
// a vertex within rounding reach of the segment (a rounded crossing or split point) not
// visited before. Where no step continues, the segment must leave the meshed domain there
// and may re-enter only at a boundary vertex on it (within rounding reach). Segments a
// rounding apart can make two chains side by side, so the walk is depth first; only if no
// walk gets through is the segment reported, along the walk of first choices.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "../rounding.h"
#include "check.h"
#include "query_grid.h"
#include "segment_walk.h"
#include "topology.h"
#include "vertices.h"

namespace acutemesh::validation {

class SegmentWalker {
 public:
  SegmentWalker(const Check& c, const Topology& topo, const VertexMap& vertices, SegmentEdges& out)
      : c_(c),
        topo_(topo),
        vertices_(vertices),
        marked_(out.marked),
        listed_(out.listed),
        segCount_(out.segCount),
        onSegment_(out.onSegment) {}

  void walkAll();               // walks every input segment once (segment_walk.cpp)
  void rerouteToListedEdges();  // retries walks that miss listed edges (segment_list.cpp)

 private:
  // A walk along input segment s (a->b).
  struct SegmentWalk {
    uint32_t s, a, b;
    const double *A, *B;
    int axis = 0;
    double dir = 1;
    std::vector<uint32_t> entries;  // boundary vertices on the segment, in order; built lazily
    bool haveEntries = false;
    // Whether a depth-first walk may also leave the domain where an edge goes on, and skip
    // boundary vertices; tried only when no walk gets through without (see walkSteps).
    bool leaveAnywhere = false;
    // rerouteToListedEdges: listed edges only, those no walk has taken first; with
    // mustTakeLeftOver only a walk that takes one of those (leftOver_) gets through.
    bool preferListed = false, mustTakeLeftOver = false;
    SegmentWalk(uint32_t s_, uint32_t a_, uint32_t b_, const double* A_, const double* B_)
        : s(s_), a(a_), b(b_), A(A_), B(B_) {
      reach = detail::roundingReach(A, B, A);
      // Position along the segment: the coordinate on its dominant axis, signed to grow toward b.
      axis = std::fabs(B[0] - A[0]) >= std::fabs(B[1] - A[1]) ? 0 : 1;
      dir = B[axis] > A[axis] ? 1 : -1;
    }
    double key(const double* p) const { return dir * p[axis]; }
    double reach = 0;  // roundingReach() about the segment (it takes both ends into account)
  };

  // One step of a walk: to vertex `to` along mesh half-edge `he`, or (he == kNone) past a
  // stretch outside the domain to boundary vertex `to` (kNone: the segment ends outside).
  struct WalkStep {
    uint32_t to, he;
  };
  struct WalkFrame {
    uint32_t vertex, he;          // the vertex, and the half-edge that led to it (or kNone)
    uint32_t previousOnSegment;   // onSegment_[vertex] before the walk came
    std::vector<WalkStep> steps;  // the steps from it, best first
    size_t nextStep = 0;
  };
  // A segment's walk as found: its steps along mesh edges, and the vertices it went through.
  struct Chain {
    std::vector<std::array<uint32_t, 2>> steps;  // half-edge, and the vertex it was taken from
    std::vector<uint32_t> vertices;
  };

  // segment_walk.cpp: one walk.
  void walkSegment(uint32_t s);
  size_t entriesAfter(SegmentWalk& w, double k);
  void walkSteps(SegmentWalk& w, uint32_t cur, bool backtrack, std::vector<WalkStep>& out);
  void entrySteps(SegmentWalk& w, double k, bool backtrack, std::vector<WalkStep>& out);
  bool walkDepthFirst(SegmentWalk& w, bool backtrack);
  bool walkFrom(SegmentWalk& w, bool backtrack, uint32_t cur);
  void keepChain(const SegmentWalk& w, const std::vector<WalkFrame>& stack, uint32_t via,
                 bool reached);
  void markWalked(uint32_t h, uint32_t from, int w = 1);
  const QueryGrid& boundaryGrid();
  bool enteredThroughTriangle(uint32_t v, const SegmentWalk& w);
  uint32_t enteringTriangle(uint32_t v, const double* A) const;

  // segment_list.cpp: matching the walks against Mesh::segments.
  bool stillLeftOver(uint32_t h) const;
  bool rerouteSegment(uint32_t s, bool nearLeftOver);
  void applyChain(const Chain& chain, uint32_t s, int w);
  size_t wrongAmong(const Chain& x, const Chain& y);
  bool wrong(uint32_t e) const { return listed_[e] ? marked_[e] == 0 : marked_[e] > 0; }
  bool takesUnlisted(const Chain& chain) const;

  // What logs why segment w is not a chain of mesh edges (report), or nothing (a depth-first
  // walk trying its ways).
  auto reporter(const SegmentWalk& w, bool report) {
    return [this, &w, report](auto&&... parts) {
      if (report) c_.log.add("input segment ", w.s, " (", w.a, "->", w.b, ") ", parts...);
    };
  }

  const double* P(uint32_t v) const { return topo_.P(v); }
  uint32_t canon(uint32_t h) const { return topo_.canon(h); }

  const Check& c_;
  const Topology& topo_;
  const VertexMap& vertices_;
  std::vector<uint32_t>& marked_;     // SegmentEdges::marked
  std::vector<uint8_t>& listed_;      // SegmentEdges::listed
  std::vector<int32_t>& segCount_;    // SegmentEdges::segCount
  std::vector<uint32_t>& onSegment_;  // SegmentEdges::onSegment
  std::vector<uint32_t> deadEnd_;     // per vertex: the walk (walkId_) that got stuck past it
  uint32_t walkId_ = 0;
  std::vector<WalkFrame> walkStack_;
  std::vector<WalkStep> preferred_;  // walkSteps' scratch
  std::vector<Chain> chains_;        // per input segment: its walk
  std::vector<uint8_t> leftOver_;    // per canonical half-edge: listed, and on no first walk
  std::vector<uint32_t> edges_;      // wrongAmong's scratch
  std::unique_ptr<QueryGrid> boundaryGrid_;  // boundary vertices, built when a walk needs it
};

}  // namespace acutemesh::validation
