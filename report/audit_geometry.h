// Polylines and polygons of a Diagram for the audit reports (internal to io/, declared
// here so tests can check them): circle arcs sampled into polylines, face boundaries into rings,
// and lon/lat for geographic output.
//
// Sampling: a circle arc gets n equal angular steps, n the smallest count with at most
// ArcSampling::max_step_radians per step and a chord no farther than max_deviation from the arc
// (the sagitta r (1 - cos(step / 2))); a line arc gets pieces of at most max_line_step (one piece
// when that is infinite). The end points of a sampled arc are its nodes' coordinates exactly, so
// consecutive arcs of a cycle join without gaps. Arcs with an end at infinity cannot be sampled.
#pragma once

#include <cstddef>
#include <vector>

#include "report/audit_report.h"
#include "io/map_frame.h"
#include "core/diagram.h"

namespace covmap::report::detail {

struct ArcSampling {
  double max_step_radians = 0.0;
  double max_deviation = 0.0;  // map units
  double max_line_step = 0.0;  // map units; infinity: straight arcs stay one segment
};

// The diagonal of the bounding box of the diagram's clip polygon, else of its nodes and sites;
// 1 when that is empty or a single point (so that relative tolerances stay positive).
double diagram_extent(const Diagram& d);

// The sampling `options` ask for, for a diagram of this extent; geographic output also cuts
// straight arcs (AuditRenderOptions::geographic_line_step).
ArcSampling arc_sampling(const AuditRenderOptions& options, double extent, bool geographic);

// The points of a half-arc from its start to its end, both included. Empty for an arc with an end
// at infinity.
std::vector<Point> sample_half_arc(const Diagram& d, HalfArc h, const ArcSampling& s);

// A boundary cycle as an implicitly closed ring (no repeated last point, no two consecutive points
// equal), in the cycle's direction. Empty when the cycle passes through infinity, has a non-finite
// point or has fewer than three distinct points.
Ring sample_cycle(const Diagram& d, std::span<const HalfArc> cycle, const ArcSampling& s);

// The signed area of an implicitly closed ring (shoelace), positive counter-clockwise.
double signed_area(const Ring& ring);

// All bounded faces of one site, each as a polygon: outer ring counter-clockwise, holes clockwise
// (reversed if sampling ever turned one around). A face whose outer ring is empty is left out.
struct SiteRegion {
  int site = kNone;
  std::vector<io::MapPolygon> polygons;
  std::size_t orphan_faces = 0;  // faces not containing their site (still part of its region)
  double area = 0.0;             // of the polygons, holes subtracted, map units squared
};

struct DiagramRegions {
  std::vector<SiteRegion> regions;   // in site order; sites without a bounded face are absent
  std::size_t unbounded_faces = 0;   // left out (an unclipped diagram)
  std::size_t degenerate_faces = 0;  // left out: outer ring empty (see sample_cycle)
};

DiagramRegions diagram_regions(const Diagram& d, const ArcSampling& s);

// Geographic position of a planar point for points (lon in [-180, 180]).
io::LonLat to_lonlat(const io::MapFrame& projection, Point p);
// The same, for vertices of lines and rings: lon is taken within 180 degrees of the central
// meridian, so a ring across the antimeridian stays one ring (lon may then exceed +-180).
io::LonLat to_lonlat_continuous(const io::MapFrame& projection, Point p);

}  // namespace covmap::report::detail
