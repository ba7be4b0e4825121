// A sweep-line search for a pair of segments with some property (Shamos–Hoey), internal to io/. It
// decides both polygon checks of io/: "does any edge of a clip polygon meet a non-adjacent edge"
// (io/polygon_check.cpp) and "does any edge of a coverage-map polygon properly cross another"
// (io/coverage_map_crossings.cpp). It only ever tests pairs of segments that are neighbours on the
// sweep line; this file proves which pairs that is enough for, and each user applies the proof to
// its own question.
//
// ## The sweep
//
// Points are ordered lexicographically, by x then y. A segment's left end is its smaller end, its
// right end the larger (a vertical segment's left end is its lower end). Events are segment ends,
// sorted by point; at one point, right ends (removals) come before left ends (insertions), ties by
// segment index. The status is the list of segments the sweep line currently meets, bottom to top,
// in a balanced search tree (std::set).
//
// Picture the sweep line as x = t tilted by an infinitesimal angle, so that it meets points of one
// vertical line from bottom to top: the line through an event point p meets exactly the points
// before p (lexicographically) on one side. "Just after p" means the sweep line through p moved on
// by an infinitesimal amount, smaller than the tilt; there, the segments the line meets are those
// with left end <= p < right end, and their order along the line is:
//   - a segment that does not contain p is below or above p according to the side of its line on
//     which p lies (a vertical segment active at p always contains p);
//   - segments through p are ordered by their direction out of p, counter-clockwise from just
//     after straight down to straight up (included): the sign of orientation(p, r1, r2) for their
//     right ends r1, r2 (both directions lie in that half-open half plane, where the sign of the
//     turn is the angular order);
//   - segments through p in the same direction overlap on a line; their order is their index.
// std::set compares only the segment being inserted, which starts at p, with segments already in
// it, so these three rules, each one exact orientation sign (core/orientation.h), are the whole
// comparator; no intersection point is ever computed.
//
// Every insertion tests the new segment against its two neighbours; every removal tests the two
// segments it leaves adjacent. Hence (N) every pair of segments that are ever neighbours in the
// status is tested, at the moment they become neighbours. The search stops at the first pair the
// test accepts.
//
// ## What the sweep maintains
//
// A proper crossing is a point in the relative interior of two non-collinear segments. Between two
// events, the order of the segments the line meets changes only where two of them meet in a point
// that is an end of neither, i.e. at a proper crossing (collinear segments that overlap keep their
// index order). At an event p, the segments that contain p and survive it keep their order unless
// two of them cross properly at p. Touching and overlapping (an end on another segment, shared
// ends, collinear overlaps) never change the order. Removal uses the element's stored position and
// compares nothing; an insertion lands in the right place if the status it searches is in order.
// So, with X the lexicographically first proper crossing (or none):
//   (G) at every event p before X, and at X itself if no two segments of the status cross properly
//       there, the insertions at p search a status in the order just after p, and after p the
//       status is in that order;
//   (C) for any point Y up to X, the segments that contain Y and begin before it form a contiguous
//       run of the status after the last event before Y: a segment between two of them is squeezed
//       towards Y as the line approaches Y and, having no end in between, contains Y. (The tilt
//       makes this hold for vertical segments and events on one vertical line too.)
//
// ## Proper crossings are always found (used by coverage_map_crossings.cpp)
//
// Claim: if every properly crossing pair is accepted, the search accepts some pair whenever a
// proper crossing exists, and it never inserts into a status that is out of order.
// Proof. Let X be the first proper crossing and T the segments through X that begin before X, in
// status order after the last event q before X (T is a contiguous run by (C), and in order by (G)).
// Choose two of them, Ti below Tj, that cross properly at X with the fewest members of T between
// them. Any Tm between them runs into X from inside the angle that Ti and Tj make on the left of X
// (or along one of its sides). If Tm went on past X, then X would be in its relative interior, and
// its direction on the right of X would lie in the opposite angle, so Tm would cross Ti or Tj
// properly at X (if it is collinear with one, then the other), with fewer members of T between: a
// contradiction. So every Tm ends at X. If there is none, Ti and Tj were neighbours after q and were
// tested by (N). Otherwise X is an event; its removals come first and compare nothing, and the last
// of those between Ti and Tj leaves them adjacent, and they are tested. Either way the search stops
// no later than the removals at X, and every insertion before that was made at an event before X,
// into the ordered status of (G). Touching and overlapping pairs need no special case: they do not
// disturb the order, and a pair that is not accepted is simply passed over.
//
// The precondition matters: with an `accept` that misses some proper crossing, the sweep could go on
// past it with the status out of order, which std::set does not allow. Both users accept every
// properly crossing pair.
//
// ## Cost
//
// O(n log n) time for n segments: one sort of 2n events, and per event one tree operation of
// O(log n) comparisons of at most three orientation signs each, plus at most two tests (so at most
// 3n calls of `accept`). O(n) memory. Orientation signs are exact for coordinates whose pairwise
// products neither overflow nor underflow (core/orientation.h).
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

#include "core/diagram.h"

namespace covmap::io::detail {

struct Segment {
  Point a;
  Point b;
};

struct SegmentPair {
  std::size_t first = 0;   // first < second, indices into the segments
  std::size_t second = 0;
};

// The first pair of segments that the sweep above finds adjacent on the sweep line and for which
// accept(first, second) is true (first < second), or nullopt. Precondition: accept(i, j) holds for
// every pair that crosses properly (it may hold for others too). Then the answer is nullopt only if
// no two segments cross properly; that it also rules out other accepted pairs needs its own
// argument (io/polygon_check.cpp has one). Segments of zero length are never inserted, so never
// tested. The answer is deterministic: it depends only on the coordinates and the order of the
// segments. Throws std::length_error for 2^31 segments or more.
// The segments are taken by value (move them in): the sweep puts each one's ends in sweep order in
// place, and `accept` should read the geometry from the caller's own data.
std::optional<SegmentPair> find_adjacent_pair(std::vector<Segment> segments,
                                              const std::function<bool(std::size_t, std::size_t)>& accept);

}  // namespace covmap::io::detail
