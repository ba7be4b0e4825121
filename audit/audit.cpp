#include "audit/audit.h"

#include "core/box.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cmath>
#include <map>
#include <stdexcept>
#include <unordered_map>

#include "fitting/refine.h"
#include "audit/verdict.h"
#include "audit/boundary_samples.h"
#include "fitting/local_uncertainty.h"
#include "audit/map_agreement.h"
#include "audit/start_values.h"
#include "audit/tolerances.h"
#include "voronoi/best_server_raster.h"
#include "voronoi/clip.h"
#include "voronoi/engine.h"

namespace covmap::audit {
namespace {


// Maps up to this many sensors are refined from several starts (the tolerant estimate, the cells'
// centroids, the reported sensors); larger ones from one, to bound the time.
constexpr std::size_t kMultiStartSensors = 300;
// Maps up to this many sensors get one boundary sample per bin, larger ones one per two bins.
constexpr std::size_t kDenseSamplingSensors = 3000;
// Iterations of the second refinement phase (see refine below).
constexpr int kPhase2Iterations = 60;
// Rounds of restarting sensors that ended outside their own cell. A second round was measured on
// a 10⁴-sensor map: mean IoU 0.942 -> 0.953 for twice the refinement time (55 s end to end).
constexpr int kRestartRounds = 1;

// Signed area and area-weighted centroid of a ring (shoelace).
void accumulate_ring(const Ring& ring, double& area, double& cx, double& cy) {
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const Point& a = ring[k];
    const Point& b = ring[(k + 1) % ring.size()];
    const double cross = a.x * b.y - b.x * a.y;
    area += 0.5 * cross;
    cx += (a.x + b.x) * cross / 6.0;
    cy += (a.y + b.y) * cross / 6.0;
  }
}


// The map's frame as a simple counter-clockwise polygon, for clipping recomputed diagrams: the
// longest closed walk along frame arcs; the bounding box when there is none.
std::vector<Point> frame_polygon(const Diagram& g, const Box& box) {
  std::vector<int> next(g.nodes.size(), kNone);
  std::vector<int> starts;
  for (std::size_t a = 0; a < g.arcs.size(); ++a) {
    const auto& arc = g.arcs[a];
    if (!arc.frame || arc.from == kNone || arc.to == kNone) continue;
    // The inside is on the left of a frame arc; walk so that the inside stays on the left.
    const bool inside_left = arc.left_site != kNone;
    const int from = inside_left ? arc.from : arc.to, to = inside_left ? arc.to : arc.from;
    next[from] = to;
    starts.push_back(from);
  }
  std::vector<Point> best;
  std::vector<char> seen(g.nodes.size(), 0);
  for (int s : starts) {
    if (seen[s]) continue;
    std::vector<Point> ring;
    int v = s;
    while (v != kNone && !seen[v]) {
      seen[v] = 1;
      ring.push_back({g.nodes[v].x, g.nodes[v].y});
      v = next[v];
    }
    if (v == s && ring.size() > best.size()) best = std::move(ring);
  }
  if (best.size() >= 3) return best;
  return {{box.xmin, box.ymin}, {box.xmax, box.ymin}, {box.xmax, box.ymax}, {box.xmin, box.ymax}};
}

Diagram recomputed_diagram(const std::vector<Site>& sites, const std::vector<Point>& frame,
                                    const Box& box, std::vector<std::string>& messages, const char* what) {
  try {
    const Diagram d = voronoi::build_diagram(sites);
    try {
      return voronoi::clip_diagram(d, frame);
    } catch (const std::exception& e) {
      messages.push_back(std::string(what) + ": clipping to the map's frame failed (" + e.what() + "); clipped to its bounding box");
      return voronoi::clip_diagram(d, {{box.xmin, box.ymin}, {box.xmax, box.ymin}, {box.xmax, box.ymax}, {box.xmin, box.ymax}});
    }
  } catch (const std::exception& e) {
    messages.push_back(std::string(what) + ": no diagram (" + e.what() + ")");
    return {};
  }
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

}  // namespace

AuditResult audit(std::span<const CoverageCell> map, std::span<const ReportedSensorValues> reported,
                  const AuditOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  if (map.empty()) throw std::invalid_argument("audit: the map has no cells");
  auto progress = [&](const std::string& stage, double f) {
    if (options.progress) options.progress(stage, f);
  };
  AuditResult out;

  // 1. Clean the map into chains, junctions and fitted bisectors.
  progress("cleaning", 0.0);
  out.cleaned = cleaning::clean_coverage_map(map, options.cleaning);
  const cleaning::CleanedMap& cleaned = out.cleaned;
  const std::size_t n = cleaned.sensors.size();
  std::unordered_map<std::string, int> index;
  for (std::size_t i = 0; i < n; ++i) index[cleaned.sensors[i]] = static_cast<int>(i);

  // Cell areas and centroids per sensor; the map's box.
  std::vector<double> area(n, 0.0), cx(n, 0.0), cy(n, 0.0);
  std::vector<int> cell_sensor;
  Box box;
  for (const CoverageCell& cell : map) {
    const int s = index.count(cell.sensor) ? index[cell.sensor] : kNone;
    cell_sensor.push_back(s);
    for (const CellPolygon& p : cell.polygons) {
      for (const Point& q : p.outer) box.add(q);
      if (s == kNone) continue;
      accumulate_ring(p.outer, area[s], cx[s], cy[s]);
      for (const Ring& h : p.holes) accumulate_ring(h, area[s], cx[s], cy[s]);
    }
  }
  std::vector<Point> centroids(n);
  for (std::size_t i = 0; i < n; ++i)
    centroids[i] = area[i] != 0 ? Point{cx[i] / area[i], cy[i] / area[i]} : Point{0.5 * (box.xmin + box.xmax), 0.5 * (box.ymin + box.ymax)};
  const double extent = std::hypot(box.xmax - box.xmin, box.ymax - box.ymin);
  out.bin_size_m = cleaned.report.bin_size_estimate > 0 ? cleaned.report.bin_size_estimate
                                                        : std::max(cleaned.report.snap_distance, 1e-6 * extent);

  // 2. Starting values: tolerant recognition; reported values where it found nothing better.
  progress("recognition", 0.2);
  const SiteEstimates estimates = estimate_sites(cleaned, centroids);
  std::map<int, const ReportedSensorValues*> reported_of;
  for (const ReportedSensorValues& r : reported)
    if (auto it = index.find(r.id); it != index.end()) reported_of[it->second] = &r;
  // A site lies in its own region (or outside the map, for a sensor beyond the map's edge): an
  // estimate inside another sensor's cell is noise from short, poorly fitted arcs, and the cell's
  // centroid is the better start.
  const double extent_box = std::max(box.xmax - box.xmin, box.ymax - box.ymin);
  double res = out.bin_size_m;
  const double bw = box.xmax - box.xmin, bh = box.ymax - box.ymin;
  if (bw * bh / (res * res) > 4e6) res = std::sqrt(bw * bh / 4e6);
  const voronoi::RasterGrid grid{box.xmin, box.ymin, res, std::max(1, static_cast<int>(std::ceil(bw / res))),
                                 std::max(1, static_cast<int>(std::ceil(bh / res)))};
  const LabelRaster map_raster = rasterize_cells(map, cell_sensor, grid);
  auto label_at = [&](double x, double y) {
    const int i = static_cast<int>(std::floor((x - grid.x0) / grid.bin));
    const int j = static_cast<int>(std::floor((y - grid.y0) / grid.bin));
    if (i < 0 || j < 0 || i >= grid.nx || j >= grid.ny) return kNone;
    return map_raster.labels[grid.index(i, j)];
  };
  std::vector<Site> start = estimates.sites;
  int moved_to_centroid = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const int at = label_at(start[i].x, start[i].y);
    const bool far = std::hypot(start[i].x - centroids[i].x, start[i].y - centroids[i].y) > extent_box;
    if ((at != kNone && at != static_cast<int>(i)) || far || !std::isfinite(start[i].x) || !std::isfinite(start[i].y)) {
      start[i].x = centroids[i].x, start[i].y = centroids[i].y;
      ++moved_to_centroid;
    }
  }
  if (moved_to_centroid)
    out.messages.push_back(std::to_string(moved_to_centroid) +
                           " tolerant estimates lay in another sensor's cell; those sensors start from their cell's centroid");
  for (auto [i, r] : reported_of)
    if (estimates.how[i] == EstimateSource::kCentroid) {
      start[i].x = r->position.x, start[i].y = r->position.y;
      out.messages.push_back("sensor '" + r->id + "': no junction or located neighbour; started from its reported position");
    }

  // 3. Refinement on boundary samples (one per bin along each shared boundary).
  progress("refinement", 0.3);
  const double sigma = out.bin_size_m / std::sqrt(12.0);
  // One sample per bin; on maps too large for that to stay fast, one per two bins (each chain
  // still has about ten, against its curve's three parameters).
  const double sample_spacing = n > kDenseSamplingSensors ? 2.0 * out.bin_size_m : out.bin_size_m;
  const auto samples = sample_boundaries(cleaned, sample_spacing, sigma);
  out.boundary_samples = samples.size();
  fitting::RefineOptions ro;
  ro.loss_scale = 3.0;  // in sample σ: staircase noise is bounded by ±bin/2 ≈ 1.7 σ
  ro.threads = options.threads;
  ro.max_iterations = 500;
  ro.function_tolerance = tolerance::kAuditFunctionTolerance;
  // Weak priors keep sites that the map barely constrains (one short boundary, a sliver) from
  // drifting off while leaving every determined site to the data: a position prior of twice the
  // mean sensor spacing about the start. (No prior on weights: it would also fix their common
  // factor, which the boundaries leave free and every comparison removes; a weight's excursion
  // is bounded in fitting/ instead.) A site whose posterior σ stays above half its prior σ is
  // reported as undetermined.
  const double spacing = std::sqrt(std::max(bw * bh, 1e-300) / static_cast<double>(std::max<std::size_t>(n, 1)));
  const double prior_position_sigma = 2.0 * spacing;
  // Phase 1 also holds every log weight loosely (±kAuditLogWeightPrior about its start): from a
  // poor start a weakly bounded weight can otherwise run off and take a whole neighbourhood with
  // it, and with weights held this way Ceres' inner iterations (per-site block descent) may run,
  // which cut its iterations several-fold. Phase 2 drops the weight priors and polishes from
  // phase 1's optimum (its gauge: one reference weight held); on maps above
  // kDenseSamplingSensors it is skipped for time — the uncertainties come from
  // local_uncertainty.h either way, and the loose priors move no determined weight measurably.
  auto priors_for = [&](const std::vector<Site>& from, bool weights) {
    std::vector<fitting::SitePrior> priors;
    for (std::size_t i = 0; i < n; ++i)
      priors.push_back({static_cast<int>(i), {from[i].x, from[i].y}, prior_position_sigma,
                        std::log(from[i].weight), weights ? tolerance::kAuditLogWeightPrior : 0.0});
    return priors;
  };
  // Two sensors may not start at one point (their bisector would be undefined): a later one moves
  // to its cell's centroid, or a tenth of a bin aside.
  auto separate = [&](std::vector<Site>& sites) {
    std::map<std::pair<double, double>, int> taken;
    for (std::size_t i = 0; i < n; ++i) {
      for (int attempt = 0; taken.count({sites[i].x, sites[i].y}); ++attempt) {
        if (attempt == 0) sites[i].x = centroids[i].x, sites[i].y = centroids[i].y;
        else sites[i].x += 0.1 * out.bin_size_m * attempt;
      }
      taken[{sites[i].x, sites[i].y}] = static_cast<int>(i);
    }
  };
  auto refine = [&](std::vector<Site> from) {
    separate(from);
    fitting::RefineOptions quick = ro;
    quick.compute_covariance = false;
    fitting::RefineOptions first = quick;
    first.inner_iterations = true;  // phase 1 has weight priors, no held reference: allowed
    quick.nonmonotonic_steps = true;
    // Phase 2 starts at phase 1's optimum and only releases the weights' priors: a few dozen
    // iterations settle it; its long tail (cost changes of parts in 10⁵) is cut off.
    quick.max_iterations = kPhase2Iterations;
    try {
      fitting::RefineResult phase1 = fitting::refine_sites(from, samples, priors_for(from, true), first);
      out.messages.push_back("refinement phase 1: " + phase1.summary.brief());
      separate(phase1.sites);
      if (n > kDenseSamplingSensors) return phase1;  // large maps: time (docs/PERFORMANCE.md)
      fitting::RefineResult phase2 = fitting::refine_sites(phase1.sites, samples, priors_for(from, false), quick);
      out.messages.push_back("refinement phase 2: " + phase2.summary.brief());
      return phase2;
    } catch (const std::exception& e) {
      // A refinement that cannot run leaves the starting values, said in the report.
      out.messages.push_back(std::string("refinement failed (") + e.what() + "); kept the starting values");
      fitting::RefineResult kept;
      kept.sites = from;
      double top = 0;
      for (const Site& site : kept.sites) top = std::max(top, site.weight);
      for (Site& site : kept.sites) site.weight /= top;
      kept.summary.final_cost = INFINITY;
      kept.summary.message = "not run";
      return kept;
    }
  };
  auto lap = [&, last = t0](const std::string& what) mutable {
    const auto now = std::chrono::steady_clock::now();
    char text[64];
    std::snprintf(text, sizeof text, " took %.2f s", std::chrono::duration<double>(now - last).count());
    out.messages.push_back(what + text);
    last = now;
  };
  lap("cleaning and starting values");
  const bool multi_start = n <= kMultiStartSensors;
  // The first start: every sensor at its cell's centroid, with the tolerant weights. Measured on
  // generated maps (docs/ACCURACY.md), it converges in about half the iterations of the junction
  // positions, whose solution circles come from short, noisy arcs; those positions are a second
  // start on maps small enough for several.
  std::vector<Site> centroid_start = estimates.sites;
  for (std::size_t i = 0; i < n; ++i) centroid_start[i].x = centroids[i].x, centroid_start[i].y = centroids[i].y;
  fitting::RefineResult refined = refine(centroid_start);
  if (multi_start) {
    // A second start from the tolerant estimates themselves (outside their own cell: centroid).
    fitting::RefineResult second = refine(start);
    if (second.summary.final_cost < refined.summary.final_cost) refined = std::move(second);
  }
  if (multi_start && !reported_of.empty()) {
    // A further start from the reported sensors (where they exist): the lower cost wins.
    std::vector<Site> alt = start;
    for (auto [i, r] : reported_of) {
      alt[i].x = r->position.x, alt[i].y = r->position.y;
      if (r->weight) alt[i].weight = *r->weight;
    }
    fitting::RefineResult second = refine(alt);
    if (second.summary.final_cost < refined.summary.final_cost) {
      out.messages.push_back("refinement: the start from the reported sensors reached a lower cost (" +
                             std::to_string(second.summary.final_cost) + " < " + std::to_string(refined.summary.final_cost) + ")");
      refined = std::move(second);
    }
  }
  // A site lies in its own region. One that the refinement left inside another sensor's cell (or
  // far outside the map) was dragged off by a poor start or a bad neighbour (and, with its weight,
  // distorts the cells around it): it restarts from its cell's centroid with its neighbours'
  // typical weight, and the refinement runs again (kRestartRounds times; a restart can free a
  // neighbour that the escaped sensor held off, but another round costs a whole refinement).
  for (int round = 0; round < kRestartRounds; ++round) {
    std::vector<Site> repaired = refined.sites;
    std::vector<std::vector<double>> neighbour_logw(n);
    for (const auto& sample : samples) {
      neighbour_logw[sample.site_a].push_back(std::log(refined.sites[sample.site_b].weight));
      neighbour_logw[sample.site_b].push_back(std::log(refined.sites[sample.site_a].weight));
    }
    int escaped = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const int at = label_at(repaired[i].x, repaired[i].y);
      // Outside the map is possible for a sensor beyond its edge, but not far beyond.
      const bool placed = at == static_cast<int>(i) ||
                          (at == kNone && std::hypot(repaired[i].x - centroids[i].x, repaired[i].y - centroids[i].y) <= 3.0 * spacing);
      // Neighbouring sensors' weights differ by modest factors; a weight that ran off to its bound
      // (e.g. 1e13 times its neighbours') is a divergence even where the position looks fine.
      const bool weight_ok = neighbour_logw[i].empty() ||
                             std::abs(std::log(repaired[i].weight) - median(neighbour_logw[i])) <= tolerance::kAuditMaxLogWeightJump;
      if (placed && weight_ok) continue;
      ++escaped;
      repaired[i].x = centroids[i].x, repaired[i].y = centroids[i].y;
      if (!neighbour_logw[i].empty()) repaired[i].weight = std::exp(median(neighbour_logw[i]));
    }
    if (escaped == 0) break;
    fitting::RefineResult again = refine(repaired);
    out.messages.push_back(std::to_string(escaped) + " sensor(s) ended outside their own cell (or with a weight far from their neighbours') and were refined again from their cell's centroid");
    if (!std::isfinite(again.summary.final_cost)) break;
    refined = std::move(again);
  }
  out.refinement_summary = refined.summary.brief();
  lap(multi_start ? "refinement (several starts)" : "refinement");
  progress("verification", 0.7);

  // 4. Powers and the common factor of weights: reported and reconstructed weights are each known
  //    only up to a factor; the factor between them is the median of their log ratios.
  const double ln10 = std::log(10.0);
  std::vector<double> log_ratios, power_offsets;
  for (auto [i, r] : reported_of) {
    std::optional<double> w = r->weight;
    if (!w && r->tx_power_dbm && options.alpha) w = std::pow(10.0, *r->tx_power_dbm / (10.0 * *options.alpha));
    if (w && *w > 0) log_ratios.push_back(std::log(*w) - std::log(refined.sites[i].weight));
    if (r->tx_power_dbm && options.alpha)
      power_offsets.push_back(*r->tx_power_dbm - 10.0 * *options.alpha * std::log10(refined.sites[i].weight));
  }
  const double log_factor = median(log_ratios);
  const std::optional<double> p0 = power_offsets.empty() ? std::nullopt : std::optional<double>(median(power_offsets));
  const double logw_per_db = options.alpha ? ln10 / (10.0 * *options.alpha) : ln10 / (10.0 * 3.5);

  // 5. Per sensor: reconstruction, uncertainty (local_uncertainty.h says why conditional), verdict.
  const std::vector<fitting::LocalUncertainty> local = fitting::local_uncertainty(refined.sites, samples, ro.loss_scale);
  for (std::size_t i = 0; i < n; ++i) {
    SensorAudit s;
    s.id = cleaned.sensors[i];
    s.position = {refined.sites[i].x, refined.sites[i].y};
    s.weight = refined.sites[i].weight;
    if (p0 && options.alpha) s.tx_power_dbm = *p0 + 10.0 * *options.alpha * std::log10(s.weight);
    if (options.alpha) s.relative_power_db = 10.0 * *options.alpha * std::log10(s.weight);
    const fitting::LocalUncertainty& u = local[i];
    s.uncertainty_available = u.available;
    s.sigma_x = u.sigma_x, s.sigma_y = u.sigma_y, s.cov_xy = u.cov_xy, s.sigma_log_weight = u.sigma_log_weight;
    {
      const double a = u.sigma_x * u.sigma_x, b = u.sigma_y * u.sigma_y, c = u.cov_xy;
      s.sigma_position_m = std::sqrt(0.5 * (a + b) + std::sqrt(0.25 * (a - b) * (a - b) + c * c));
    }
    if (auto it = reported_of.find(static_cast<int>(i)); it != reported_of.end()) {
      const ReportedSensorValues& r = *it->second;
      s.reported = r;
      const double dx = r.position.x - s.position.x, dy = r.position.y - s.position.y;
      s.position_error_m = std::hypot(dx, dy);
      VerdictInput vi;
      vi.dx = dx, vi.dy = dy;
      std::optional<double> w = r.weight;
      if (!w && r.tx_power_dbm && options.alpha) w = std::pow(10.0, *r.tx_power_dbm / (10.0 * *options.alpha));
      if (w && *w > 0) {
        vi.dlogw = std::log(*w) - std::log(s.weight) - log_factor;
        s.weight_ratio = std::exp(*vi.dlogw);
        if (options.alpha) s.power_error_db = *vi.dlogw / logw_per_db;
      }
      vi.var_x = u.sigma_x * u.sigma_x, vi.var_y = u.sigma_y * u.sigma_y, vi.cov_xy = u.cov_xy;
      vi.var_logw = u.sigma_log_weight * u.sigma_log_weight;
      vi.reported_position_sigma = r.position_sigma_m.value_or(0.0);
      if (r.power_sigma_db) vi.reported_logw_sigma = *r.power_sigma_db * logw_per_db;
      vi.position_floor = options.position_floor_bins * out.bin_size_m;
      vi.logw_floor = options.power_floor_db * logw_per_db;
      vi.alpha = options.alpha;
      if (!u.available || s.sigma_position_m > 0.5 * prior_position_sigma) {
        s.verdict = SensorVerdict::kUndetermined;
        s.reason = "the map does not determine this sensor (too few boundary points); not judged";
      } else {
        const Judgement v = judge(vi, options.inconsistency_chi2);
        s.chi2 = v.chi2;
        s.verdict = v.inconsistent ? SensorVerdict::kInconsistent : SensorVerdict::kConsistent;
        s.reason = v.reason;
      }
    }
    out.sensors.push_back(std::move(s));
  }
  for (const ReportedSensorValues& r : reported) {
    if (index.count(r.id)) continue;
    SensorAudit s;
    s.id = r.id;
    s.in_map = false;
    s.position = r.position;
    s.reported = r;
    s.verdict = SensorVerdict::kNotInMap;
    s.reason = "reported, but no cell of the map names it";
    out.sensors.push_back(std::move(s));
  }

  // 6. Recompute the diagrams and compare them with the map on a raster.
  const std::vector<Point> frame = frame_polygon(cleaned.graph, box);
  std::vector<Site> refined_sites = refined.sites;
  out.refined_diagram = recomputed_diagram(refined_sites, frame, box, out.messages, "refined sensors");
  // The raster of the map (made above): its own bins where it has them, at most ~4·10⁶.
  auto agreement_of = [&](const std::vector<Site>& sites, int count) {
    const voronoi::BestServerRaster labels = voronoi::best_server_raster(sites, grid);
    LabelAgreement a = compare_labels(map_raster, labels.labels, count);
    DiagramAgreement d;
    d.mean_iou = a.mean_iou;
    d.hausdorff_m = a.hausdorff;
    for (int v : a.vanished) d.vanished.push_back(v < static_cast<int>(n) ? cleaned.sensors[v] : std::to_string(v));
    for (int v : a.appeared) d.appeared.push_back(v < static_cast<int>(n) ? cleaned.sensors[v] : std::to_string(v));
    return std::make_pair(d, a.iou);
  };
  {
    auto [d, iou] = agreement_of(refined_sites, static_cast<int>(n));
    out.refined_agreement = d;
    for (std::size_t i = 0; i < n; ++i)
      if (std::isfinite(iou[i])) out.sensors[i].iou_refined = iou[i];
  }
  if (!reported.empty()) {
    // The reported sensors' own diagram: map sensors at their reported values (reconstructed ones
    // where a sensor was not reported), then sensors reported but absent from the map.
    std::vector<Site> rs = refined_sites;
    for (auto [i, r] : reported_of) {
      rs[i].x = r->position.x, rs[i].y = r->position.y;
      std::optional<double> wr = r->weight;
      if (!wr && r->tx_power_dbm && options.alpha) wr = std::pow(10.0, *r->tx_power_dbm / (10.0 * *options.alpha));
      rs[i].weight = wr ? *wr / std::exp(log_factor) : refined_sites[i].weight;
    }
    for (const ReportedSensorValues& r : reported) {
      if (index.count(r.id)) continue;
      std::optional<double> wr = r.weight;
      if (!wr && r.tx_power_dbm && options.alpha) wr = std::pow(10.0, *r.tx_power_dbm / (10.0 * *options.alpha));
      rs.push_back({r.id, r.position.x, r.position.y, wr ? *wr / std::exp(log_factor) : 1.0});
    }
    out.reported_diagram = recomputed_diagram(rs, frame, box, out.messages, "reported sensors");
    auto [d, iou] = agreement_of(rs, static_cast<int>(rs.size()));
    // Names of appeared reported-only sensors.
    for (auto& name : d.appeared) {
      const int k = std::atoi(name.c_str());
      if (k >= static_cast<int>(n) && k < static_cast<int>(rs.size())) name = rs[k].id;
    }
    out.reported_agreement = d;
    for (std::size_t i = 0; i < n; ++i)
      if (std::isfinite(iou[i])) out.sensors[i].iou_reported = iou[i];
  }
  lap("recomputed diagrams and comparison");
  progress("done", 1.0);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace covmap::audit
