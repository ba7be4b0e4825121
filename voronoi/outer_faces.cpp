// Outer faces for trace_faces(): the cycles' half-arcs into the diagram, one face per outer cycle
// (counter-clockwise, or through infinity), the clockwise cycles listed as holes; the unbounded
// face of a site that has only holes; and, once the holes are placed, each face's cycles.
#include <algorithm>
#include <cmath>

#include "core/parallel.h"
#include "voronoi/face_tracing.h"

namespace covmap::voronoi::tracing {

FaceAssembly outer_faces(Diagram& d, bool by_sites, const CycleSet& cs) {
  const LargeVector<Cycle>& cycles = cs.cycles;
  const LargeVector<int>& cycle_halves = cs.cycle_halves;
  FaceAssembly fa;
  // All cycles as half-arcs, in the order of cycle_halves: no allocation per face. Advised as huge
  // pages before the first touch, filled in parallel.
  std::vector<HalfArc>& pool = d.half_arcs;
  pool.reserve(cycle_halves.size());
  advise_huge_pages(pool.data(), pool.capacity() * sizeof(HalfArc));
  pool.resize(cycle_halves.size());
  parallel_chunks(cycle_halves.size(), worker_count(cycle_halves.size()), [&](std::size_t b, std::size_t e, int) {
    for (std::size_t k = b; k < e; ++k) pool[k] = half_of(cycle_halves[k]);
  });

  // Outer cycles make faces; clockwise cycles are holes of the face of their site containing them.
  fa.face_of_cycle.assign(cycles.size(), -1);
  fa.hole_of_cycle.assign(cycles.size(), -1);
  // Faces: one per outer cycle, plus at most one per hole (a site's unbounded face made for its
  // holes), so no reallocation of a million faces when the first of those appears.
  d.faces.reserve(cycles.size() + 1);
  fa.faces_of_site = FacesOfSite(std::max<std::size_t>(d.sites.size(), 1));
  advise_huge_pages(d.faces.data(), d.faces.capacity() * sizeof(Face));
  for (std::size_t c = 0; c < cycles.size(); ++c) {
    const Cycle& cyc = cycles[c];
    if (cyc.through_infinity || cyc.area2 > 0) {
      fa.outer_area.push_back(cyc.through_infinity ? INFINITY : cyc.area2);
      fa.outer_cycle.push_back({cyc.begin, cyc.end});
      fa.face_of_cycle[c] = static_cast<int>(d.faces.size());
      fa.faces_of_site.add(cyc.site, static_cast<int>(d.faces.size()));
      d.faces.push_back(Face{by_sites ? cyc.site : kNone, !cyc.through_infinity, false});
    } else {
      fa.hole_of_cycle[c] = static_cast<int>(fa.holes.size());
      fa.holes.push_back(static_cast<int>(c));
    }
  }
  fa.has_outer.assign(d.faces.size(), 1);
  return fa;
}

int implicit_face_of(Diagram& d, bool by_sites, FaceAssembly& fa, int site) {
  auto it = fa.implicit_face.find(site);
  if (it == fa.implicit_face.end()) {
    Face f;
    f.site = by_sites ? site : kNone;
    f.bounded = false;
    fa.faces_of_site.add(site, static_cast<int>(d.faces.size()));
    d.faces.push_back(f);
    it = fa.implicit_face.emplace(site, static_cast<int>(d.faces.size()) - 1).first;
  }
  return it->second;
}

void store_face_cycles(Diagram& d, const CycleSet& cs, const FaceAssembly& fa) {
  // A counting sort of the cycles by face; every cycle has a face once the holes are placed.
  const std::size_t n_faces = d.faces.size();
  LargeVector<int> at(n_faces + 1, 0);
  for (std::size_t c = 0; c < cs.cycles.size(); ++c) ++at[fa.face_of_cycle[c] + 1];
  for (std::size_t f = 0; f < n_faces; ++f) at[f + 1] += at[f];
  for (std::size_t f = 0; f < n_faces; ++f) d.faces[f].cycles_begin = at[f], d.faces[f].cycles_end = at[f + 1];
  d.cycles.resize(cs.cycles.size());
  for (std::size_t f = 0; f < fa.outer_cycle.size(); ++f) d.cycles[at[f]++] = fa.outer_cycle[f];
  for (int c : fa.holes) d.cycles[at[fa.face_of_cycle[c]]++] = {cs.cycles[c].begin, cs.cycles[c].end};
}

}  // namespace covmap::voronoi::tracing
