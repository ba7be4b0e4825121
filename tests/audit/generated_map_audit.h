// Generated maps (tools/mapgen) audited through the same files and readers as a user's: the
// generator writes GeoJSON, io reads it back, audit() judges it. Shared by the audit tests.
#pragma once

#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "audit/audit.h"
#include "io/coverage_map.h"
#include "io/reported_sensors.h"
#include "tools/mapgen/coverage_map_files.h"
#include "tools/mapgen/coverage_map_generator.h"
#include "tests/support/temp_dir.h"
#include "tools/mapgen/site_layouts.h"

namespace covmap::testing {


struct AuditRun {
  mapgen::CoverageMap generated;
  io::CoverageMap map;
  audit::AuditResult result;
};

// Generates a map, writes it and reads it back like `covmap audit` does (r.result left empty).
// Sites: std::vector<Site> (planar) or std::vector<mapgen::LonLatSite>.
template <class Sites>
AuditRun generate_and_read(const mapgen::CoverageMapOptions& options, const Sites& sites, double alpha,
                           std::vector<ReportedSensor>& reported) {
  AuditRun r;
  r.generated = mapgen::generate_coverage_map(sites, options);
  TempDir dir;
  mapgen::write_coverage_map(r.generated, dir.path());
  io::CoverageMapOptions mo;
  mo.planar = options.frame == mapgen::OutputFrame::kPlanar;
  r.map = io::read_coverage_map(dir.path() / mapgen::kMapFileName, mo);
  io::ReportedSensorOptions so;
  so.alpha = alpha;
  so.planar = mo.planar;
  so.frame = r.map.frame ? &*r.map.frame : nullptr;
  reported = io::read_reported_sensors(dir.path() / mapgen::kSensorsFileName, so);
  return r;
}

// ... and audits it.
template <class Sites>
AuditRun run(const mapgen::CoverageMapOptions& options, const Sites& sites, double alpha) {
  std::vector<ReportedSensor> reported;
  AuditRun r = generate_and_read(options, sites, alpha, reported);
  audit::AuditOptions ao;
  ao.alpha = alpha;
  r.result = audit::audit(r.map.cells, reported, ao);
  return r;
}

inline mapgen::CoverageMapOptions base_options(std::uint64_t seed) {
  mapgen::CoverageMapOptions o;
  o.bin_size_m = 100.0;
  o.coordinate_digits = 1;  // decimetres
  o.vertex_jitter_m = 5.0;
  o.errors.gross_fraction = 0.1;
  o.seed = seed;
  return o;
}

inline std::vector<Site> sensors(int n, std::uint64_t seed) {
  mapgen::RandomSitesOptions ro;
  ro.count = n;
  ro.width_m = 20'000.0;
  ro.height_m = 20'000.0;
  ro.weight_ratio = 3.0;
  ro.seed = seed;
  return mapgen::random_sites(ro);
}

}  // namespace covmap::testing
