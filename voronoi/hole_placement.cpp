// Hole placement for trace_faces(): each hole into the face its ray found (hole_rays.cpp), or
// else by containment tests against the outer cycles of its site's faces near it.
#include <algorithm>
#include <cmath>
#include <optional>
#include <unordered_map>
#include <vector>

#include "voronoi/arc_path.h"
#include "voronoi/box_grid.h"
#include "voronoi/face_tracing.h"
#include "core/parallel.h"

namespace covmap::voronoi::tracing {
namespace {

constexpr double kOffCentre = 0.38196601125010515;  // 1/φ²

// Paths for the containment tests of holes the ray cannot place (every hole when tracing by
// sites): computed on first use and kept, since one large face's outer cycle is tested against
// many holes. A map, not an array over all arcs: only the arcs of the candidate faces are ever
// asked for (an array would be a large block of fresh memory on large diagrams).
class PathCache {
 public:
  explicit PathCache(const Diagram& d) : d_(d) {}
  const ArcPathView& operator()(int arc) {
    auto [it, added] = paths_.try_emplace(arc);
    if (added) it->second = arc_path(d_.arcs[arc], d_.nodes);
    return it->second;
  }

 private:
  const Diagram& d_;
  std::unordered_map<int, ArcPathView> paths_;  // node-based: references stay valid
};

// Candidate outer cycles for a point, through a grid over their bounding boxes (made by build(),
// called only when some hole needs a containment test: most graphs have none). Without it, tracing
// by geometry (one label for all faces) would test every hole against every face. Tracing by sites, a hole
// only goes into a face of its own site, so only those faces get a box (the others are left out
// of the grid, which keeps its cells and the candidates' order): the holes' own sites' boxes are a
// small fraction of the cost of the boxes of all the arcs.
class FaceGrid {
 public:
  FaceGrid(const Diagram& d, bool by_sites, const CycleSet& cs, const FaceAssembly& fa)
      : d_(d), by_sites_(by_sites), cs_(cs), fa_(fa) {}
  void build() {
    std::vector<char> hole_site(by_sites_ ? d_.sites.size() : 0, 0);
    for (int c : fa_.holes)
      if (by_sites_) hole_site[cs_.cycles[c].site] = 1;
    LargeVector<Box> boxes(fa_.outer_area.size(), Box{});
    for (std::size_t f = 0; f < fa_.outer_area.size(); ++f) {
      if (by_sites_ && !hole_site[d_.faces[f].site]) continue;
      for (const HalfArc& h : outer_cycle_of(d_, fa_, static_cast<int>(f))) {
        const Box b = arc_bounds(d_.arcs[h.arc], d_.nodes);
        boxes[f].add_box(b);
      }
    }
    // Over the central nodes: a few faces reaching far out would otherwise stretch the cells
    // until every face shares one.
    face_grid_ = make_grid(boxes.size(), [&](std::size_t f) { return boxes[f]; }, central_box(d_.nodes), fa_.outer_area.size(),
                           /*max_cells=*/64);
  }
  // After build(); read only, so any number of threads may ask.
  std::vector<int> candidates(Point p) const {
    std::vector<int> out(face_grid_->always.begin(), face_grid_->always.end());
    if (face_grid_->nx > 0) {  // clamped like the boxes: a point beyond the grid meets the border cells
      const auto c = face_grid_->cell(face_grid_->column(p.x), face_grid_->row(p.y));
      out.insert(out.end(), c.begin(), c.end());
    }
    return out;
  }

 private:
  const Diagram& d_;
  const bool by_sites_;
  const CycleSet& cs_;
  const FaceAssembly& fa_;
  std::optional<BoxGrid> face_grid_;
};

// The face whose outer cycle runs along each half-arc (-1 on holes): the face across a hole's own
// arcs is the one on the hole's other side, never the face containing it.
int outer_face_of_half(const LargeVector<int>& cycle_of_half, const FaceAssembly& fa, int h) {
  const int c = cycle_of_half[h];
  return c < 0 || fa.hole_of_cycle[c] >= 0 ? -1 : fa.face_of_cycle[c];
}

// What every hole's containment test reads: the diagram, its cycles and faces so far.
struct HoleSearch {
  const Diagram& d;
  bool by_sites = false;
  const CycleSet& cs;
  const LargeVector<int>& cycle_of_half;
  const FaceAssembly& fa;
  const FaceGrid& grid;
};

// The innermost outer cycle of the hole's site that contains a point of the hole, among faces not
// across the hole's own arcs; -1 when none does.
int containing_face(const HoleSearch& search, const Cycle& hole, PathCache& cached_path) {
  const Diagram& d = search.d;
  const CycleSet& cs = search.cs;
  const FaceAssembly& fa = search.fa;
  const HalfArc first = half_of(cs.cycle_halves[hole.begin]);
  const ArcPathView path = arc_path(d.arcs[first.arc], d.nodes);
  // Not the middle of the arc: degenerate inputs (grids) make a hole tangent to another arc at its
  // axis-extreme and middle points, where the point would lie on the candidate face's boundary and
  // its containment is noise. 1/φ² of the way along is no such point.
  const double mid = std::isfinite(path.s0) && std::isfinite(path.s1) ? path.s0 + kOffCentre * (path.s1 - path.s0)
                     : std::isfinite(path.s0)                          ? path.s0 + 1.0
                     : std::isfinite(path.s1)                          ? path.s1 - 1.0
                                                                       : 0.0;
  const Point p = path.at(mid);
  int target = -1;
  std::vector<int> across;
  for (int h : cs.halves_of(hole)) across.push_back(outer_face_of_half(search.cycle_of_half, fa, h ^ 1));
  for (int f : search.grid.candidates(p)) {
    if (d.faces[f].site != (search.by_sites ? hole.site : kNone)) continue;
    if (f >= static_cast<int>(fa.outer_area.size())) continue;  // hole-only faces have no outer
    if (std::find(across.begin(), across.end(), f) != across.end()) continue;
    // Innermost containing outer cycle (smallest area) wins.
    if (contains_with(d, outer_cycle_of(d, fa, f), p, cached_path) && (target < 0 || fa.outer_area[f] < fa.outer_area[target]))
      target = f;
  }
  return target;
}

}  // namespace

void place_holes(Diagram& d, bool by_sites, const CycleSet& cs, const LargeVector<int>& cycle_of_half,
                 const std::vector<int>& ray_face, FaceAssembly& fa) {
  const std::size_t n = fa.holes.size();
  std::vector<int> target(ray_face.begin(), ray_face.begin() + static_cast<std::ptrdiff_t>(n));
  FaceGrid grid(d, by_sites, cs, fa);
  if (std::find(target.begin(), target.end(), -2) != target.end()) grid.build();
  // Each hole's containment tests depend on that hole alone (each worker caches its own paths), so
  // they run on all cores, each worker over a contiguous range of holes; a few thousand holes are
  // worth it (each test walks whole outer cycles). The faces created for holes no face contains are
  // added afterwards, in hole order, as one pass did.
  constexpr std::size_t kHolesPerWorker = 512;
  const int workers = n >= 2 * kHolesPerWorker ? hardware_workers() : 1;
  const HoleSearch search{
      .d = d, .by_sites = by_sites, .cs = cs, .cycle_of_half = cycle_of_half, .fa = fa, .grid = grid};
  parallel_chunks(n, workers, [&](std::size_t begin, std::size_t end, int) {
    PathCache cached_path(d);
    for (std::size_t hk = begin; hk < end; ++hk)
      if (target[hk] == -2)
        target[hk] = containing_face(search, cs.cycles[fa.holes[hk]], cached_path);
  });
  for (std::size_t hk = 0; hk < n; ++hk) {
    const int hole = fa.holes[hk];
    fa.face_of_cycle[hole] = target[hk] >= 0 ? target[hk] : implicit_face_of(d, by_sites, fa, cs.cycles[hole].site);
  }
}

}  // namespace covmap::voronoi::tracing
