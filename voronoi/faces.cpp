#include "voronoi/faces.h"

#include "voronoi/face_tracing.h"
#include "core/parallel.h"

namespace covmap::voronoi {
namespace {

using namespace tracing;

// A diagram of one site (or none with arcs): the whole plane.
void whole_plane_faces(Diagram& d, FaceAssembly& fa) {
  FacesOfSite& faces_of_site = fa.faces_of_site;
  for (std::size_t s = 0; s < d.sites.size(); ++s)
    if (faces_of_site.empty(static_cast<int>(s)) && d.arcs.empty() && d.clip.empty())
      faces_of_site.add(static_cast<int>(s), add_face(d, Face{static_cast<int>(s), false, false}));
}

// Orphans: every face of a site but the one containing the site itself. Faces created for holes
// only (the unbounded component of a site without lines) have no outer cycle. Each site's faces are
// decided by that site alone, so the sites are shared among the workers.
void mark_orphans(Diagram& d, const FaceAssembly& fa) {
  const LargeVector<char>& has_outer = fa.has_outer;
  const std::vector<int>& sites = fa.faces_of_site.sites();
  parallel_chunks(sites.size(), worker_count(sites.size()), [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t k = begin; k < end; ++k) {
      const int site = sites[k];
      const Point s{d.sites[site].x, d.sites[site].y};
      // Unclipped, a site lies in its own region: a single face is its own.
      if (fa.faces_of_site.single(site) && d.clip.empty()) {
        d.faces[fa.faces_of_site.front(site)].orphan = false;
        continue;
      }
      fa.faces_of_site.for_each(site, [&](int f) {
        Face& face = d.faces[f];
        const bool outer = f < static_cast<int>(has_outer.size()) && has_outer[f];
        const FaceCycles cycles = face_cycles(d, face);
        bool inside = !outer || cycle_contains(d, cycles.front(), s);
        for (std::size_t b = outer ? 1 : 0; inside && b < cycles.size(); ++b)
          if (cycle_contains(d, cycles[b], s)) inside = false;
        face.orphan = !inside;
      });
    }
  });
}

}  // namespace

bool cycle_contains(const Diagram& d, std::span<const HalfArc> cycle, Point p) {
  ArcPathView scratch;
  return contains_with(d, cycle, p, [&](int arc) -> const ArcPathView& {
    scratch = arc_path(d.arcs[arc], d.nodes);
    return scratch;
  });
}

void trace_faces(Diagram& d, FaceLabels labels, FaceIndex* index) {
  clear_faces(d);
  const bool by_sites = labels == FaceLabels::kSites;
  const TracingGeometry geometry = tracing_geometry(d, !by_sites);
  LargeVector<int> next_half = continuations(d, by_sites, geometry);
  CycleSet cycles = walk_cycles(d, by_sites, next_half);
  const LargeVector<int> cycle_of_half = orient_cycles(d, geometry, cycles);
  FaceAssembly faces = outer_faces(d, by_sites, cycles);
  const std::vector<int> ray_face = hole_ray_faces(d, by_sites, geometry, cycles, cycle_of_half, faces);
  place_holes(d, by_sites, cycles, cycle_of_half, ray_face, faces);
  store_face_cycles(d, cycles, faces);
  if (index) fill_face_index(*index, std::move(next_half), cycle_of_half, faces.face_of_cycle);
  if (!by_sites) {
    if (d.faces.empty()) add_face(d, Face{kNone, false, false});  // no arcs: the plane
    return;
  }
  whole_plane_faces(d, faces);
  mark_orphans(d, faces);
}

}  // namespace covmap::voronoi
