// The stages of audit() (audit.cpp) and the plain data they pass between them. Internal to the
// audit library: not a public header (audit/CMakeLists.txt).
//
// In the order audit() runs them, after cleaning the map (cleaning/map_cleaning.h):
//   map cells              map_cells.cpp               cell areas, centroids, the map's box, its raster
//   start values           starting_sites.cpp          tolerant estimates checked against the cells
//   refinement             two_phase_refinement.cpp    boundary samples, priors, one refinement
//   multi-start            multi_start_refinement.cpp  several starts, restarts of escaped sensors
//   local re-solves        local_resolve.cpp           sensors in local minima, solved with their neighbourhoods
//   verdicts per sensor    sensor_audits.cpp           weight scale, uncertainty and verdict per sensor
//   recomputed diagrams    recomputed_diagrams.cpp     diagrams of the sensors and their agreement
#pragma once

#include <functional>

#include <cstddef>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "audit/audit.h"
#include "audit/map_agreement.h"
#include "audit/start_values.h"
#include "audit/tolerances.h"
#include "core/box.h"
#include "fitting/refine.h"
#include "voronoi/best_server_raster.h"

namespace covmap::audit::stages {

// The pipeline's fixed numbers (sizes that switch strategies, iteration caps) are in
// audit/tolerances.h.

double median(std::vector<double> v);

// What a stage says for the report (AuditResult::messages), in the order it says it. Stages return
// theirs; audit() appends them in stage order.
using Messages = std::vector<std::string>;
inline void append(Messages& to, const Messages& from) { to.insert(to.end(), from.begin(), from.end()); }

// ---- Map cells (map_cells.cpp) ----

// The map's cells per cleaned sensor.
struct MapCells {
  std::unordered_map<std::string, int> index;  // sensor name -> index in cleaned.sensors
  std::vector<double> area, cx, cy;            // per sensor: signed area, area-weighted x and y sums
  std::vector<Point> centroids;                // per sensor: its cells' centroid (box centre if none)
  std::vector<std::string> names;              // per sensor: the first non-empty name its cells give
  std::vector<int> cell_sensor;                // per cell of the map: its sensor (kNone if unknown)
  Box box;                                     // of every cell's outer rings
};

MapCells map_cells(std::span<const CoverageCell> map, const cleaning::CleanedMap& cleaned);

// The bin size of the map: the cleaning's estimate, else its snapping distance.
double bin_size(const cleaning::CleanedMap& cleaned, const Box& box);

// The map rasterised: its own bins where it has them, at most ~4·10⁶.
struct MapRaster {
  voronoi::RasterGrid grid;
  LabelRaster raster;
  // The sensor of the bin holding (x, y); kNone outside the raster.
  int label_at(double x, double y) const;
};

MapRaster map_raster(std::span<const CoverageCell> map, const MapCells& cells, double bin_size);

// ---- Start values (starting_sites.cpp) ----

// The reported sensor of each map sensor that was reported.
using ReportedOf = std::map<int, const ReportedSensor*>;
ReportedOf reported_in_map(std::span<const ReportedSensor> reported, const MapCells& cells);

// The tolerant estimates, each inside its own cell (else at the cell's centroid), and reported
// positions where the estimate had nothing better than a centroid.
struct StartingSites {
  std::vector<Site> sites;
  Messages messages;  // the estimates moved, the reported positions taken
};

StartingSites starting_sites(const SiteEstimates& estimates, const MapCells& cells, const MapRaster& raster,
                             const ReportedOf& reported_of);

// ---- Refinement (two_phase_refinement.cpp, multi_start_refinement.cpp) ----

// What every refinement of one audit shares.
struct RefinementSetup {
  std::size_t n = 0;  // sensors
  double bin_size_m = 0.0;
  std::vector<fitting::BoundarySample> samples;
  fitting::RefineOptions options;
  double spacing = 0.0;               // mean sensor spacing
  double prior_position_sigma = 0.0;  // of the weak position priors
};

RefinementSetup refinement_setup(const cleaning::CleanedMap& cleaned, const Box& box, double bin_size_m, int threads);

// A refinement and what it said: each phase's summary, a failure, restarts.
struct Refinement {
  fitting::RefineResult refined;
  Messages messages;
};

// One two-phase refinement from `from` (the starting values kept, and said, when it cannot run).
Refinement refine_from(const RefinementSetup& setup, std::vector<Site> from, const std::vector<Point>& centroids);

// The refinement from several starts (on maps small enough), then the restarts of sensors that
// escaped their cells, then the local re-solves (resolve_misplaced). `lap`, if set, hears the name
// of each of these three parts as it ends (the audit's stage times).
Refinement multi_start_refinement(const RefinementSetup& setup, const SiteEstimates& estimates,
                                  const std::vector<Site>& start, const MapCells& cells, const MapRaster& raster,
                                  const ReportedOf& reported_of,
                                  const std::function<void(const std::string& part)>& lap = {});

// ---- Range edges the fit does not bear out (range_edge_check.cpp) ----

// A sensor's outside boundary that cleaning took for a range edge (a circle about the sensor that
// holds its cell) may be another circle of that shape: the edge of a hole where a cell is missing
// is a weaker sensor's Apollonius circle against the missing one. Taken for a reach, it pulls the
// sensor toward the circle's centre, and the sensor's boundaries no longer fit. Where sensors with
// a range edge have a model-fit ratio (model_fit.h) above kRangeEdgeMisfitRatio, the refinement is
// tried again without their range edges; the trial is kept (setup.samples, refined and
// cleaned.range_edges updated, said in the messages returned) only if it then fits every one of
// them: a sensor held in a bad minimum by something else keeps its true range edge.
Messages check_range_edges(RefinementSetup& setup, fitting::RefineResult& refined, const MapCells& cells,
                           const AuditOptions& options, cleaning::CleanedMap& cleaned);

// Local re-solves (local_resolve.cpp): every sensor suspected of a local minimum (outside its own
// cell, a weight far from its neighbours', a merged neighbour, an island cell it hosts, a poorly
// fitted boundary) is solved again with its neighbourhood (the ring around it held) from several
// starts; of the solutions that keep every site in its own cell, apart and with a plausible
// weight, the lowest cost wins. Updates refined.sites only (not its summary or residuals); returns
// what it says of the re-solves.
Messages resolve_misplaced(const RefinementSetup& setup, const SiteEstimates& estimates, const MapCells& cells,
                           const MapRaster& raster, const ReportedOf& reported_of, fitting::RefineResult& refined);

// ---- Verdicts per sensor (sensor_audits.cpp) ----

// Reported and reconstructed weights are each known only up to a factor.
struct WeightScale {
  double log_factor = 0.0;     // median of log(reported / reconstructed weight)
  std::optional<double> p0;    // power of weight 1 (dBm), when powers were reported
  double logw_per_db = 0.0;
};

WeightScale weight_scale(const fitting::RefineResult& refined, const ReportedOf& reported_of,
                         const AuditOptions& options);

// What the stages after the refinement read: the cleaned map, its cells and raster, the refinement
// and the reports. Views of audit()'s own values.
struct VerificationInputs {
  const cleaning::CleanedMap& cleaned;
  const MapCells& cells;
  const MapRaster& raster;
  const RefinementSetup& setup;
  const fitting::RefineResult& refined;
  const ReportedOf& reported_of;
  std::span<const ReportedSensor> reported;
  const WeightScale& scale;
  const AuditOptions& options;
};

// Per map sensor its reconstruction and verdict, then the reported sensors absent from the map.
std::vector<SensorAudit> sensor_audits(const VerificationInputs& in);

// ---- Recomputed diagrams and agreement (recomputed_diagrams.cpp) ----

// Sets out.refined_diagram, out.reported_diagram and their agreements with the map, and each
// sensor's iou_refined and iou_reported; returns what went wrong drawing them.
Messages recomputed_diagrams(const VerificationInputs& in, AuditResult& out);

}  // namespace covmap::audit::stages
