// covmap::io arc graphs: a Diagram as covmap.arcgraph/1 JSON, both directions.
//
// Layout (docs/FORMATS.md is the reference):
//   {"format":"covmap.arcgraph/1",
//    "sites":[{"id":"a","x":0,"y":0,"weight":1}, ...],
//    "nodes":[{"x":..,"y":..}, ...],
//    "arcs":[{"from":i|null,"to":j|null,
//             "circle":{"cx":..,"cy":..,"r":..,"ccw":true} | "line":{"x":..,"y":..,"dx":..,"dy":..},
//             "sites":[left|null, right|null], "frame":true (only on frame arcs)}, ...],
//    "faces":[{"site":i,"bounded":b,"orphan":b,"boundaries":[[[arc,forward], ...], ...]}, ...],
//    "clip":[[x,y], ...]}
// null stands for kNone. Orientation conventions are those of core/diagram.h.
//
// Writing: every double is written in the shortest form that reads back to the same bits
// (core/round_trip_numbers.h: always with a fraction or an exponent, "10.0", "1e+16"), so
// write -> read reproduces the Diagram exactly. A non-finite number cannot be written (JSON has
// none) and makes write_diagram_json throw std::invalid_argument naming the JSON path.
//
// Reading: a one-pass reader takes well-formed files; anything else, and every error, goes to the
// reference reader built on nlohmann's DOM (io/fast_readers.h), so the messages are the same.
// "faces" and "clip" are optional (graphs from other tools often have neither); unknown
// members are ignored. The reader checks what a consumer would otherwise crash on or misread, and
// throws InputError with the JSON path ("arcs[12].to: node index 99 out of range (41 nodes)"):
//   the format tag; sites as in read_sites (ids unique, positions distinct, weights > 0);
//   finite numbers; circle radius > 0; line direction non-zero; every index in range;
//   circle arcs have both ends or neither; bisector arcs name two different sites; frame arcs name
//   exactly one; boundary cycles are non-empty; a clip polygon is simple and counter-clockwise.
// It does not check geometry (nodes on their arcs, cycles closing up): that is covmap_check's job.
#pragma once

#include <filesystem>
#include <iosfwd>
#include <string>
#include <string_view>

#include "core/diagram.h"

namespace covmap::io {

// Large graphs are rendered in pieces on the machine's cores and written to `out` in order, from the
// calling thread only (io/ordered_pieces.h); the text is the same whatever the number of cores.
void write_diagram_json(const Diagram& diagram, std::ostream& out);

// The same text as a string, for callers that need it whole (`covmap diagram` streams into its
// atomic write's temporary instead). Its capacity is reserved once from an upper bound on the
// length, in huge pages where the system has them, so a large graph costs no reallocation and few
// page faults: growing a string by doubling would cost more than formatting it.
// Throws as write_diagram_json.
std::string diagram_json_text(const Diagram& diagram);

// kRequired: a diagram, sites and labels checked as above. kIgnored: an arc graph whose sites are
// unknown (the input of recognition and comparison): "sites", the arcs' "sites" and "faces" may be
// absent and are ignored; the result has no sites, no faces and kNone labels.
// kOptional: an arc graph that may carry sites (the input of recognition, which compares them with
// its reconstruction): without "sites" (or with an empty list) as kIgnored; with sites, their labels
// are read and checked as for kRequired, but "faces" are ignored.
enum class ArcLabels { kRequired, kIgnored, kOptional };

Diagram read_diagram_json(const std::filesystem::path& path, ArcLabels labels = ArcLabels::kRequired);

// Parses text already in memory; `file` is only used in error messages.
Diagram parse_diagram_json(std::string_view text, const std::string& file,
                                    ArcLabels labels = ArcLabels::kRequired);

}  // namespace covmap::io
