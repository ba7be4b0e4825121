// The 3D regular triangulation of the lifted sites (see lifted_traits.h), with integer ids on
// cells so per-cell and per-facet data can live in plain arrays.
//
// SpatialTriangulation, in every dimension. No lifted site is ever hidden (each owns a
// neighbourhood of itself, so it has a power cell among any subset of the sites), so cells keep no
// list of hidden points: CGAL's default std::list costs 24 bytes in each of the ~6.5 million cells
// of 10^6 sites. With Discard_hidden_points the container is only asked for an empty range, and
// cells are 72 bytes (4 vertex and 4 neighbour handles, the id, the empty member) instead of 96: a
// quarter less memory to fault in and to walk through, the same triangulation in the same order
// (the planar extractor reads cells in CGAL's container order, which the layout does not change;
// tests/voronoi/spatial_triangulation_test.cpp compares the cells in every dimension). Coplanar
// lifted sites (dimension ≤ 2: equal weights, w² affine in position, fewer than four sites) use
// them too: the planar extractor does not take edges from CGAL's edge iterator, which picks the
// cell reporting an edge by comparing cell addresses, so the cells' layout changes no output.
//
// RegularTriangulation, CGAL's default cells, is the reference the tests compare against.
#pragma once

#include <CGAL/Hidden_point_memory_policy.h>
#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Regular_triangulation_cell_base_3.h>
#include <CGAL/Regular_triangulation_vertex_base_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>

#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/spatial_sort.h>
#include <boost/property_map/function_property_map.hpp>

#include <memory>
#include <type_traits>
#include <vector>

#include "voronoi/engine/cell_arena.h"
#include "voronoi/engine/lifted_traits.h"

namespace covmap::voronoi::engine {

// The hidden-point container of SpatialTriangulation's cells: always empty.
struct NoHiddenPoints {
  using value_type = RawWeightedPoint;
  using iterator = RawWeightedPoint*;
  using const_iterator = const RawWeightedPoint*;
  iterator begin() { return nullptr; }
  iterator end() { return nullptr; }
  const_iterator begin() const { return nullptr; }
  const_iterator end() const { return nullptr; }
};

using VertexBase = CGAL::Regular_triangulation_vertex_base_3<LiftedTraits>;
using CellBase = CGAL::Triangulation_cell_base_with_info_3<
    int, LiftedTraits, CGAL::Regular_triangulation_cell_base_3<LiftedTraits>>;
using Tds = CGAL::Triangulation_data_structure_3<VertexBase, CellBase>;
using RegularTriangulation = CGAL::Regular_triangulation_3<LiftedTraits, Tds>;

using LeanCellBase = CGAL::Regular_triangulation_cell_base_3<
    LiftedTraits, CGAL::Triangulation_cell_base_with_info_3<int, LiftedTraits>, CGAL::Discard_hidden_points,
    NoHiddenPoints>;
using SpatialTds = CGAL::Triangulation_data_structure_3<VertexBase, LeanCellBase>;
// SpatialTds's cell and vertex types, named without instantiating it (its containers would
// instantiate std::allocator of them before the specializations below).
using SpatialCell = LeanCellBase::Rebind_TDS<SpatialTds>::Other;
using SpatialVertex = VertexBase::Rebind_TDS<SpatialTds>::Other;

}  // namespace covmap::voronoi::engine

// SpatialTriangulation's cells and vertices live in CGAL's Compact_container, whose blocks come
// from CGAL_ALLOCATOR(T), i.e. std::allocator<T>, with no other way in: for these two types it is
// the huge-page arena of engine/cell_arena.h. (A program may specialize std::allocator for its own
// types; these depend on LiftedTraits. Nothing else allocates them.)
namespace std {
template <>
struct allocator<covmap::voronoi::engine::SpatialCell>
    : covmap::voronoi::engine::ArenaAllocator<covmap::voronoi::engine::SpatialCell> {
  allocator() noexcept = default;
  template <class U>
  allocator(const allocator<U>&) noexcept {}
  friend bool operator==(const allocator&, const allocator&) noexcept { return true; }
};
template <>
struct allocator<covmap::voronoi::engine::SpatialVertex>
    : covmap::voronoi::engine::ArenaAllocator<covmap::voronoi::engine::SpatialVertex> {
  allocator() noexcept = default;
  template <class U>
  allocator(const allocator<U>&) noexcept {}
  friend bool operator==(const allocator&, const allocator&) noexcept { return true; }
};
}  // namespace std

namespace covmap::voronoi::engine {

static_assert(std::is_same_v<SpatialTds::Cell, SpatialCell> && std::is_same_v<SpatialTds::Vertex, SpatialVertex>);
using SpatialTriangulation = CGAL::Regular_triangulation_3<LiftedTraits, SpatialTds>;

// Inserts `points` (sorted in place) into the empty triangulation `rt` one by one, each located
// from the cell of the one before, after sorting them along a space-filling curve: the loop of
// CGAL's Regular_triangulation_3::insert(first, last), sequential branch, with CGAL's spatial
// sort (its BRIO rounds, with CGAL's fixed-seed shuffle). The triangulation is the same complex
// in every order (CGAL's symbolic perturbation does not depend on it, and no lifted site is ever
// hidden); only where CGAL stores its cells and in which order it lists their vertices differ.
//   kSpatial3: the sort CGAL's range insertion does, on the raw (x, y, w) — the same cells in the
//     same container order as SpatialTriangulation's range constructor
//     (tests/voronoi/spatial_triangulation_test.cpp); the order the planar extractor (dimension
//     2), which reads CGAL's order, is defined by.
//   kHilbert2: the same sort on (x, y) only. Consecutive sites are then near in the plane whatever
//     their weights, and each insertion starts nearer its conflict zone, so insertion takes less
//     time on large inputs (docs/PERFORMANCE.md). The spatial extractor's output
//     does not depend on the order (flat_triangulation.h): build_diagram is free to choose it.
//   kAsGiven: no sort, the input order (tests: a second, unrelated insertion order).
// Where CGAL sorts a copy of the points, they are sorted here in place: the copy would be tens of
// MB of fresh pages on large inputs.
enum class InsertionOrder { kSpatial3, kHilbert2, kAsGiven };

namespace detail {

// The site's position (x, y), as CGAL's 2D spatial sort reads it.
struct PlanarPosition {
  using result_type = BaseKernel::Point_2;
  BaseKernel::Point_2 operator()(const RawWeightedPoint& p) const { return {p.x(), p.y()}; }
};

inline void sort_for_insertion(SpatialTriangulation& rt, std::vector<RawWeightedPoint>& points, InsertionOrder order) {
  using WeightedPoint = SpatialTriangulation::Weighted_point;
  if (order == InsertionOrder::kSpatial3) {
    using Gt = SpatialTriangulation::Geom_traits;
    using ConstructPoint = Gt::Construct_point_3;
    using Ret = typename boost::result_of<const ConstructPoint(const WeightedPoint&)>::type;
    using PointMap = boost::function_property_map<ConstructPoint, WeightedPoint, Ret>;
    using SortTraits = CGAL::Spatial_sort_traits_adapter_3<Gt, PointMap>;
    CGAL::spatial_sort(points.begin(), points.end(),
                       SortTraits(boost::make_function_property_map<WeightedPoint, Ret, ConstructPoint>(
                                      rt.geom_traits().construct_point_3_object()),
                                  rt.geom_traits()));
  } else if (order == InsertionOrder::kHilbert2) {
    using PointMap = boost::function_property_map<PlanarPosition, WeightedPoint, BaseKernel::Point_2>;
    using SortTraits = CGAL::Spatial_sort_traits_adapter_2<BaseKernel, PointMap>;
    CGAL::spatial_sort(points.begin(), points.end(), SortTraits(PointMap(PlanarPosition())));
  }
}

}  // namespace detail

inline void insert_spatially_sorted(SpatialTriangulation& rt, std::vector<RawWeightedPoint>& points,
                                    InsertionOrder order = InsertionOrder::kSpatial3) {
  detail::sort_for_insertion(rt, points, order);
  SpatialTriangulation::Cell_handle hint;
  for (const SpatialTriangulation::Weighted_point& p : points) {
    SpatialTriangulation::Locate_type lt;
    int li, lj;
    const SpatialTriangulation::Cell_handle c = rt.locate(p, lt, li, lj, hint);
    const SpatialTriangulation::Vertex_handle v = rt.insert(p, lt, c, li, lj);
    hint = v == SpatialTriangulation::Vertex_handle() ? c : v->cell();
  }
}

template <class VertexHandle>
int site_of(VertexHandle v) {
  return static_cast<int>(v->point().weight());
}

}  // namespace covmap::voronoi::engine
