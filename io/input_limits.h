// covmap::io input limits: the most any one input may hold, so that no file, however hostile,
// makes covmap run out of memory or time without a word. Each limit is far above what real data
// needs (the figures after each say how far) and is enforced by the readers with an InputError
// that names the limit. docs/RELIABILITY.md lists them with the measured cost at the limit.
#pragma once

#include <cstddef>

namespace covmap::io {

// Bytes in one input file. Reading holds the text and its parsed form in memory at once (about
// 10x the file for GeoJSON); a national coverage map with 10^5 cells is ~100 MB.
inline constexpr std::size_t kMaxInputFileBytes = std::size_t{1} << 30;

// Nesting of JSON arrays and objects. covmap's formats nest at most 6 deep (a MultiPolygon's
// coordinates inside a feature inside a collection); deeper nesting is never data, and the JSON
// library's printing recurses once per level, so a bound here keeps every later step bounded.
inline constexpr int kMaxJsonDepth = 32;

// Features of a coverage map, and vertices over all its rings. 10^6 one-sensor cells is already a
// map of every cell site of a large country; the vertex bound keeps cleaning's memory under ~8 GB.
inline constexpr std::size_t kMaxMapFeatures = 1'000'000;
inline constexpr std::size_t kMaxMapVertices = 50'000'000;

// Sites of a site file, reported sensors of a sensors file, and nodes plus arcs of an arc graph.
// The engine builds the diagram of 10^6 sites in well under a minute. Every reported sensor gets
// a row in each of the audit's reports, whose time and memory grow with them (docs/RELIABILITY.md
// has the cost at 10^5), so twice that is the limit; an audit itself takes at most 10^5
// sensors in the map (audit/tolerances.h).
inline constexpr std::size_t kMaxSites = 2'000'000;
inline constexpr std::size_t kMaxReportedSensors = 200'000;
inline constexpr std::size_t kMaxGraphItems = 20'000'000;

// Coordinates of planar inputs (metres): beyond 10^8 m (2.5 times round the Earth) no projected
// coordinate reference system has values, so such a number is a typo or a unit mistake.
inline constexpr double kMaxPlanarCoordinate = 1e8;
// How every reader words a coordinate beyond it (after naming where it is).
inline constexpr const char* kBeyondPlanarLimit =
    "lies beyond ±1e8 m (100 000 km), where no projected coordinate system has values; is a coordinate "
    "mistyped or in the wrong unit?";

}  // namespace covmap::io
