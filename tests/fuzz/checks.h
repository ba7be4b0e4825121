// What the fuzz targets check beyond "no crash": on success, each io/ reader promises properties
// of its result in its header (io/sites_io.h, io/diagram_json.h, io/polygon_io.h,
// io/coverage_map.h, io/reported_sensors.h). These functions check the promises that can be checked
// without redoing the reader's own geometry (simplicity and orientation of rings are left out: the
// only independent oracle would be a second exact orientation test). A broken promise aborts, which
// libFuzzer reports as a crash and saves the input.
//
// Outcomes of a target (tests/fuzz/*.cpp): a result that keeps these promises, or io::InputError.
// Any other exception escapes the target and terminates it, which libFuzzer reports as a crash too:
// the parsers' contracts allow std::invalid_argument only for invalid options, and the targets pass
// valid ones.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "core/diagram.h"
#include "core/reported_sensor.h"
#include "io/coverage_map.h"
#include "io/diagram_json.h"

namespace covmap::fuzz {

// The fuzzer's bytes as text (the readers take any bytes; nothing here assumes UTF-8).
inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// Prints "fuzz: broken promise: <promise>" (or "<what>: <promise>") and aborts unless `holds`.
void require(bool holds, std::string_view promise);
void require(bool holds, std::string_view what, std::string_view promise);

// read_sites: at least one site, finite positions, finite weights > 0, unique non-empty ids, no
// two sites at the same position (-0 == 0).
void check_sites(const std::vector<Site>& sites);

// A normalized ring (clip polygons, coverage-map rings): at least 3 vertices, finite, no two
// consecutive vertices equal, the closing vertex not repeated.
void check_ring(std::span<const Point> ring, std::string_view what);

// parse_clip, parse_polygon_json, an arcgraph's clip: a ring as above that is simple, has non-zero
// area and runs counter-clockwise. Simplicity and orientation are judged again on the ring scaled
// by a power of two into the range where core/orientation.h is exact (products neither overflow
// nor underflow): exact decisions do not change under exact scaling, so the reader's answer for
// huge or tiny coordinates must be the one it gives at a tame size. Rings whose coordinates span
// too many binary orders of magnitude for one scale are left at the ring checks.
void check_clip_polygon(std::span<const Point> ring, std::string_view what);

// read_diagram_json: sites as above (kRequired) or none (kIgnored); finite numbers; radius > 0;
// line direction not zero; every index in range; circle arcs with both ends or neither; bisector
// arcs name two different sites, frame arcs exactly one; faces and cycles in range and non-empty;
// the clip empty or a ring.
void check_diagram(const Diagram& diagram, io::ArcLabels labels);

// read_coverage_map: at least one cell, each with a sensor and at least one polygon, every ring a
// ring as above, outer rings counter-clockwise and holes clockwise (judged, as for clip polygons,
// at a tame scale), vertex_count their total; a projection exactly for lon/lat input.
void check_coverage_map(const io::CoverageMap& map, bool planar);

// read_reported_sensors: at least one sensor, unique non-empty ids, finite positions, weight set,
// finite and > 0, powers finite, sigmas finite and > 0; lon/lat as read (in range) exactly for a
// geographic map; no two sensors at the same position as read.
void check_sensors(const std::vector<ReportedSensor>& sensors, bool geographic);

}  // namespace covmap::fuzz
