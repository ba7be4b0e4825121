// Propagation in recognize(): a candidate site of the start face carried to every face breadth
// first, across each arc of a spanning tree by Lemma 1 (bisector_relation.h: exact to a few ulps
// however large the circle, anchored at the arc's point nearest the site). No re-anchoring: pulling
// the sites of faces at degenerate nodes onto their nodes' solution circles and holding them fixed
// would keep them only as good as those circles, which are no better than the arcs they come
// from; the position solve over all arcs does better by orders of magnitude.
#include <algorithm>

#include "mobius/bisector_relation.h"
#include "recognition/recognize_stages.h"

namespace covmap::recognition::stages {

PropagationBuffers::PropagationBuffers(int faces) : site(faces), reached(faces) { queue.reserve(faces); }

void propagate(const TracedGraph& t, int start, mobius::Complex p, PropagationBuffers& buffers) {
  const Diagram& g = t.g;
  const LargeVector<int>& face_of_half = t.face_of_half;
  LargeVector<FaceSite>& site = buffers.site;
  LargeVector<char>& reached = buffers.reached;
  LargeVector<int>& queue = buffers.queue;
  std::fill(site.begin(), site.end(), FaceSite{});
  // A byte per face (1 MB at 10^6 faces, cache-resident) for the test every half-arc makes.
  std::fill(reached.begin(), reached.end(), 0);
  site[start] = {true, p, 1.0};
  reached[start] = 1;
  queue.assign(1, start);
  // Memory latency bound (faces, their cycles, half-arcs and the faces across are scattered at 10^6
  // faces): the data of the faces a few places ahead in the queue is prefetched in stages.
  auto prefetch_face = [&](std::size_t at) {
    if (at < queue.size()) __builtin_prefetch(&g.faces[queue[at]]);
  };
  auto prefetch_cycles = [&](std::size_t at) {
    if (at >= queue.size()) return;
    const Face& face = g.faces[queue[at]];
    if (face.cycles_end > face.cycles_begin) __builtin_prefetch(&g.cycles[face.cycles_begin]);
  };
  auto prefetch_boundary = [&](std::size_t at) {
    if (at >= queue.size()) return;
    const FaceCycles b = face_cycles(g, queue[at]);
    if (!b.empty()) __builtin_prefetch(b.front().data());
  };
  auto prefetch_across = [&](std::size_t at) {
    if (at >= queue.size()) return;
    const FaceCycles b = face_cycles(g, queue[at]);
    if (b.empty()) return;
    for (const HalfArc& h : b.front()) __builtin_prefetch(&face_of_half[half_id({h.arc, !h.forward})]);
  };
  for (std::size_t head = 0; head < queue.size(); ++head) {
    prefetch_face(head + 16);
    prefetch_cycles(head + 12);
    prefetch_boundary(head + 8);
    prefetch_across(head + 4);
    const int f = queue[head];
    const FaceSite here = site[f];
    for (const auto cycle : face_cycles(g, f))
      for (const HalfArc& h : cycle) {
        const int other = face_of_half[half_id({h.arc, !h.forward})];
        if (other == kNone || reached[other] || g.arcs[h.arc].frame) continue;
        reached[other] = 1;
        const mobius::WeightedPoint partner = mobius::partner_across(mobius::arc_bisector(g.arcs[h.arc], g.nodes, here.position), {here.position, here.weight});
        site[other] = {true, partner.position, partner.weight};
        queue.push_back(other);
      }
  }
}

}  // namespace covmap::recognition::stages
