// Local re-solves of the sensors that the joint refinement left badly placed (audit_stages.h).
//
// Why: one descent of the whole map can leave a sensor in a local minimum that the sensors around
// it hold it in: two neighbours merged at one point with nearly equal weights (their bisector
// circle fits their common boundary whatever the pair does elsewhere, docs/NUMERICS.md, 'Apollonius
// centre'), a heavy sensor at the wrong inverse point of its island's circle, or the ring around
// either distorted by it. A solve of the neighbourhood alone, from a few starts its own cell
// suggests, can leave such a minimum; it is small, so cheap, and every start sees the same samples
// and held sensors, so their costs compare fairly. The functions below say which sensors are
// suspects, what a neighbourhood and a start are, and why the result does not depend on threads.
#include <algorithm>
#include <cmath>
#include <exception>
#include <functional>
#include <map>
#include <utility>

#include "audit/audit_stages.h"
#include "audit/tolerances.h"
#include "core/parallel.h"
#include "fitting/local_uncertainty.h"

namespace covmap::audit::stages {
namespace {

// Per sensor: the indices of its samples and its neighbours (sorted, unique).
struct Adjacency {
  std::vector<std::vector<int>> samples;
  std::vector<std::vector<int>> neighbours;
};

Adjacency adjacency(const RefinementSetup& setup) {
  Adjacency adj;
  adj.samples.resize(setup.n);
  adj.neighbours.resize(setup.n);
  for (std::size_t k = 0; k < setup.samples.size(); ++k) {
    const fitting::BoundarySample& s = setup.samples[k];
    adj.samples[s.site_a].push_back(static_cast<int>(k));
    if (s.site_b == kNone) continue;  // a range edge: the sensor's own sample, no neighbour
    adj.samples[s.site_b].push_back(static_cast<int>(k));
    adj.neighbours[s.site_a].push_back(s.site_b);
    adj.neighbours[s.site_b].push_back(s.site_a);
  }
  for (auto& v : adj.neighbours) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
  }
  return adj;
}

// The site lies inside its own cell (up to the raster's resolution: the bin holding it or one of
// the eight around it is the cell's), or outside the map not far from its cell.
bool inside_own_cell(const RefinementSetup& setup, const MapCells& cells, const MapRaster& raster, const Site& site,
                     std::size_t i) {
  const double step = tolerance::kLocalCellSlackBins * raster.grid.bin;
  bool outside_map = false;
  for (int dx = -1; dx <= 1; ++dx)
    for (int dy = -1; dy <= 1; ++dy) {
      const int at = raster.label_at(site.x + dx * step, site.y + dy * step);
      if (at == static_cast<int>(i)) return true;
      outside_map = outside_map || (dx == 0 && dy == 0 && at == kNone);
    }
  return outside_map && std::hypot(site.x - cells.centroids[i].x, site.y - cells.centroids[i].y) <=
                            tolerance::kLocalOutsideMapSpacings * setup.spacing;
}

// How well sensor i's boundaries fit: per neighbour, the median |residual| / σ over their common
// samples (at least kLocalMinBoundarySamples of them); the worst boundary's. A median over all its
// samples would hide one boundary fitted several bins off behind the others (a heavy sensor with a
// small island cell inside it fits the island's circle whatever its own position).
double worst_boundary_fit(const RefinementSetup& setup, const fitting::RefineResult& refined, const std::vector<int>& own,
                          std::size_t i) {
  if (refined.sample_residual.size() != setup.samples.size()) return 0.0;
  std::map<int, std::vector<double>> per_neighbour;
  for (int k : own) {
    const fitting::BoundarySample& s = setup.samples[k];
    per_neighbour[s.site_a == static_cast<int>(i) ? s.site_b : s.site_a].push_back(std::abs(refined.sample_residual[k]) / s.sigma);
  }
  double worst = 0.0;
  for (auto& [j, r] : per_neighbour)
    if (r.size() >= tolerance::kLocalMinBoundarySamples) worst = std::max(worst, median(std::move(r)));
  return worst;
}

// The log weight that puts sensor i, at p, on the right side of its boundaries: on the bisector
// |q − p| / w_i = |q − s_j| / w_j for every sample q between i and j.
double boundary_log_weight(const RefinementSetup& setup, const std::vector<Site>& sites, const std::vector<int>& own,
                           std::size_t i, Point p) {
  std::vector<double> v;
  v.reserve(own.size());
  for (int k : own) {
    const fitting::BoundarySample& s = setup.samples[k];
    const int j = s.site_a == static_cast<int>(i) ? s.site_b : s.site_a;
    if (j == kNone) continue;  // a range edge says nothing of the weight ratio to a neighbour
    const double di = std::hypot(s.p.x - p.x, s.p.y - p.y), dj = std::hypot(s.p.x - sites[j].x, s.p.y - sites[j].y);
    if (di > 0 && dj > 0) v.push_back(std::log(di / dj) + std::log(sites[j].weight));
  }
  return v.empty() ? std::log(sites[i].weight) : median(std::move(v));
}

// One neighbourhood: its sensors (free ones first), samples and priors.
struct Neighbourhood {
  std::vector<int> sensors;  // global indices, the first `free` free, the rest held
  std::size_t free = 0;
  std::vector<fitting::BoundarySample> samples;  // site indices local
  std::vector<fitting::SitePrior> priors;
};

Neighbourhood neighbourhood(const RefinementSetup& setup, const Adjacency& adj, const std::vector<Site>& sites,
                            std::size_t i, std::vector<int>& local_of) {
  Neighbourhood nb;
  // Free: the sensors within kLocalFreeRings steps of i (breadth first, i first).
  nb.sensors.push_back(static_cast<int>(i));
  local_of[i] = 0;
  for (std::size_t ring = 0, begin = 0; ring < tolerance::kLocalFreeRings; ++ring) {
    const std::size_t end = nb.sensors.size();
    for (std::size_t f = begin; f < end; ++f)
      for (int j : adj.neighbours[nb.sensors[f]])
        if (local_of[j] < 0) local_of[j] = static_cast<int>(nb.sensors.size()), nb.sensors.push_back(j);
    begin = end;
  }
  nb.free = nb.sensors.size();
  std::vector<int> sample_ids;
  for (std::size_t f = 0; f < nb.free; ++f)
    sample_ids.insert(sample_ids.end(), adj.samples[nb.sensors[f]].begin(), adj.samples[nb.sensors[f]].end());
  std::sort(sample_ids.begin(), sample_ids.end());  // a sample between two free sensors once
  sample_ids.erase(std::unique(sample_ids.begin(), sample_ids.end()), sample_ids.end());
  for (int k : sample_ids)
    for (int j : {setup.samples[k].site_a, setup.samples[k].site_b})
      if (j != kNone && local_of[j] < 0) local_of[j] = static_cast<int>(nb.sensors.size()), nb.sensors.push_back(j);
  for (int k : sample_ids) {
    fitting::BoundarySample s = setup.samples[k];
    s.site_a = local_of[s.site_a], s.site_b = s.site_b == kNone ? kNone : local_of[s.site_b];
    nb.samples.push_back(s);
  }
  for (std::size_t l = 0; l < nb.sensors.size(); ++l) {
    const Site& site = sites[nb.sensors[l]];
    const bool held = l >= nb.free;
    nb.priors.push_back({static_cast<int>(l), {site.x, site.y},
                         held ? tolerance::kLocalHeldPositionBins * setup.bin_size_m : setup.prior_position_sigma,
                         std::log(site.weight), held ? tolerance::kLocalHeldLogWeight : tolerance::kAuditLogWeightPrior});
  }
  for (int j : nb.sensors) local_of[j] = -1;
  return nb;
}

struct LocalResult {
  double cost = INFINITY;
  bool admissible = false;  // every free site inside its own cell, none merged with a neighbour
  std::vector<Site> sites;  // the neighbourhood's, weights in the global solution's units
};

// The neighbourhood solved from `start` (its sites, in nb.sensors' order).
// range: the whole map's R (its range edges' reach is held: a neighbourhood's few edges would
// otherwise set their own).
LocalResult solve_from(const RefinementSetup& setup, const Neighbourhood& nb, const std::vector<Site>& start,
                       std::optional<double> range) {
  fitting::RefineOptions o = setup.options;
  o.held_range = range;
  o.compute_covariance = false;
  o.inner_iterations = false;
  o.on_iteration = nullptr;
  o.max_iterations = tolerance::kLocalMaxIterations;
  LocalResult out;
  try {
    fitting::RefineResult r = fitting::refine_sites(start, nb.samples, nb.priors, o);
    // Back into the global solution's weight units: the held sensors keep theirs (the whole
    // neighbourhood's, when nothing is held).
    const std::size_t from = nb.free < nb.sensors.size() ? nb.free : 0;
    double shift = 0.0;
    if (range && r.range) {
      // The map's R was held: weights are absolute through it (R·w is invariant under the
      // normalisation), whether or not any sensor was held.
      shift = std::log(*r.range / *range);
    } else {
      for (std::size_t l = from; l < start.size(); ++l) shift += std::log(start[l].weight) - std::log(r.sites[l].weight);
      shift /= static_cast<double>(start.size() - from);
    }
    for (Site& site : r.sites) site.weight *= std::exp(shift);
    out.cost = r.summary.final_cost;
    out.sites = std::move(r.sites);
  } catch (const std::exception&) {
    return {};  // a start the refinement refuses (two sites at one point) is no candidate
  }
  return out;
}

// A site lies inside its own region, two sites at one point are no diagram, and neighbours'
// weights differ by modest factors: a solution that breaks any of these is a degenerate minimum,
// however low its cost (two merged sensors fit their common boundary with a circle of any radius;
// a weight that only one short boundary bounds runs off to 10¹³).
bool admissible(const RefinementSetup& setup, const MapCells& cells, const MapRaster& raster, const Adjacency& adj,
                const Neighbourhood& nb, const std::vector<Site>& local) {
  const double coincident = tolerance::kLocalCoincidentBins * setup.bin_size_m;
  std::map<int, std::size_t> local_of;
  for (std::size_t l = 0; l < local.size(); ++l) local_of[nb.sensors[l]] = l;
  for (std::size_t l = 0; l < nb.free; ++l) {
    const int i = nb.sensors[l];
    if (!inside_own_cell(setup, cells, raster, local[l], static_cast<std::size_t>(i))) return false;
    for (std::size_t m = 0; m < local.size(); ++m)
      if (m != l && std::hypot(local[m].x - local[l].x, local[m].y - local[l].y) < coincident) return false;
    // A weight that ran away from its neighbours' (a boundary that bounds it only weakly) diverged.
    std::vector<double> neighbour_logw;
    for (int j : adj.neighbours[i]) neighbour_logw.push_back(std::log(local[local_of.at(j)].weight));
    if (std::abs(std::log(local[l].weight) - median(std::move(neighbour_logw))) > tolerance::kAuditMaxLogWeightJump)
      return false;
  }
  return true;
}

// Admissible before inadmissible, then the lower cost; ties keep the earlier start.
bool better(const LocalResult& a, const LocalResult& b) {
  if (a.sites.empty()) return false;
  if (b.sites.empty()) return true;
  if (a.admissible != b.admissible) return a.admissible;
  return a.cost < b.cost;
}

// Where the starts of a re-solve come from: the map's cells, the tolerant estimates, the reports.
struct StartSources {
  const SiteEstimates& estimates;
  const MapCells& cells;
  const MapRaster& raster;
  const ReportedOf& reported_of;
};

// The candidate positions of sensor i: its cell's centroid, its tolerant estimate (inside its own
// cell), its reported position; one within kLocalSameStartBins of the current site or of an earlier
// candidate would repeat that start's descent and is left out.
std::vector<Point> candidate_positions(const RefinementSetup& setup, const StartSources& from, const Site& current,
                                       std::size_t i) {
  const SiteEstimates& estimates = from.estimates;
  const MapRaster& raster = from.raster;
  const ReportedOf& reported_of = from.reported_of;
  std::vector<Point> all{from.cells.centroids[i]};
  const Site& e = estimates.sites[i];
  if (estimates.how[i] != EstimateSource::kCentroid && raster.label_at(e.x, e.y) == static_cast<int>(i))
    all.push_back({e.x, e.y});
  if (auto it = reported_of.find(static_cast<int>(i)); it != reported_of.end()) all.push_back(it->second->position);
  std::vector<Point> out;
  const double same = tolerance::kLocalSameStartBins * setup.bin_size_m;
  auto near = [same](Point a, Point b) { return std::hypot(a.x - b.x, a.y - b.y) < same; };
  for (Point p : all)
    if (!near(p, {current.x, current.y}) && std::none_of(out.begin(), out.end(), [&](Point q) { return near(p, q); }))
      out.push_back(p);
  return out;
}

// The starts of a neighbourhood (its sites in nb.sensors' order): the current solution; sensor i
// (first) at each candidate position; every free sensor at its cell's centroid. At a new position a
// sensor's weight is the one its boundaries imply (two sweeps over the free sensors for the last).
std::vector<std::vector<Site>> local_starts(const RefinementSetup& setup, const StartSources& from,
                                            const Adjacency& adj, const std::vector<Site>& sites,
                                            const Neighbourhood& nb) {
  const MapCells& cells = from.cells;
  std::vector<Site> current;
  for (int j : nb.sensors) current.push_back(sites[j]);
  std::vector<std::vector<Site>> starts{current};
  const std::size_t i = static_cast<std::size_t>(nb.sensors[0]);
  for (Point p : candidate_positions(setup, from, sites[i], i)) {
    starts.push_back(current);
    starts.back()[0] = {sites[i].id, p.x, p.y, std::exp(boundary_log_weight(setup, sites, adj.samples[i], i, p))};
  }
  std::vector<Site> fresh = sites;
  for (std::size_t l = 0; l < nb.free; ++l) {
    const int j = nb.sensors[l];
    fresh[j].x = cells.centroids[j].x, fresh[j].y = cells.centroids[j].y;
  }
  for (int sweep = 0; sweep < 2; ++sweep)
    for (std::size_t l = 0; l < nb.free; ++l) {
      const int j = nb.sensors[l];
      fresh[j].weight = std::exp(boundary_log_weight(setup, fresh, adj.samples[j], j, {fresh[j].x, fresh[j].y}));
    }
  starts.emplace_back();
  for (int j : nb.sensors) starts.back().push_back(fresh[j]);
  return starts;
}

// Why sensor i may sit in a local minimum (the file's comment says why each test).
enum class Suspicion {
  kNone,
  kIslandHost,  // only that it hosts an island: every boundary of it fits
  kMisfit,      // outside its own cell, a weight far from its neighbours', merged or a poor boundary
};

Suspicion suspicion(const RefinementSetup& setup, const MapCells& cells, const MapRaster& raster, const Adjacency& adj,
                    const fitting::RefineResult& refined, std::size_t i) {
  if (adj.samples[i].empty()) return Suspicion::kNone;
  const std::vector<Site>& sites = refined.sites;
  std::vector<double> neighbour_logw;
  bool merged = false, island = false;
  for (int j : adj.neighbours[i]) {
    neighbour_logw.push_back(std::log(sites[j].weight));
    merged = merged || std::hypot(sites[j].x - sites[i].x, sites[j].y - sites[i].y) < tolerance::kLocalMergedBins * setup.bin_size_m;
    island = island || adj.neighbours[j].size() == 1;
  }
  const bool weight_ok =
      std::abs(std::log(sites[i].weight) - median(std::move(neighbour_logw))) <= tolerance::kAuditMaxLogWeightJump;
  if (!inside_own_cell(setup, cells, raster, sites[i], i) || !weight_ok || merged ||
      worst_boundary_fit(setup, refined, adj.samples[i], i) > tolerance::kLocalPoorFitSigma)
    return Suspicion::kMisfit;
  return island ? Suspicion::kIslandHost : Suspicion::kNone;
}

// An island host whose other boundaries pin its position cannot sit at the wrong inverse point of
// its island's circle, which moves it by bins: they would show the move. What they can hide is a
// move that shifts each of their n samples by no more than its noise: about σ·√n, with σ the
// host's conditional position 1-σ from them (fitting/local_uncertainty.h, neighbours held). Below
// kLocalIslandHostHiddenBins the host is no suspect: such re-solves cost time and find nothing.
void drop_pinned_island_hosts(const RefinementSetup& setup, const Adjacency& adj, const fitting::RefineResult& refined,
                              std::vector<Suspicion>& suspect) {
  if (std::none_of(suspect.begin(), suspect.end(), [](Suspicion s) { return s == Suspicion::kIslandHost; })) return;
  auto island = [&adj](int j) { return j != kNone && adj.neighbours[j].size() == 1; };
  std::vector<fitting::BoundarySample> other;  // every sample but those of an island's boundary
  std::vector<int> count(suspect.size(), 0);   // per sensor, its samples among them
  for (const fitting::BoundarySample& s : setup.samples) {
    if (island(s.site_a) || island(s.site_b)) continue;
    other.push_back(s);
    ++count[s.site_a];
    if (s.site_b != kNone) ++count[s.site_b];
  }
  const std::vector<fitting::LocalUncertainty> u =
      fitting::local_uncertainty(refined.sites, other, setup.options.loss_scale, refined.range);
  const double hidden = tolerance::kLocalIslandHostHiddenBins * setup.bin_size_m;
  for (std::size_t i = 0; i < suspect.size(); ++i)
    if (suspect[i] == Suspicion::kIslandHost && u[i].available &&
        std::max(u[i].sigma_x, u[i].sigma_y) * std::sqrt(static_cast<double>(count[i])) < hidden)
      suspect[i] = Suspicion::kNone;
}

// The re-solves of `suspects` (in index order), each seeing the ones before, run wave by wave: a
// wave takes, in index order, every remaining suspect whose neighbourhood (free and held sensors)
// shares no sensor with that of any earlier remaining suspect. Such a re-solve reads nothing an
// earlier one writes, and writes nothing a later one reads (nor marks it done), so the wave's
// re-solves may run at once and the result is the one of the plain sequence, bit for bit. On a
// large map nearly all suspects are far apart: most go in the first wave, on every thread.
// still_suspect(i): false for a suspect an earlier one's re-solve settled. starts_of(nb): the
// starts of a neighbourhood. take(i, nb, best, which): the best solution of suspect i (which: its
// start), in index order; it may write the free sensors of nb and settle others.
struct WaveSteps {
  std::function<bool(std::size_t i)> still_suspect;
  std::function<std::vector<std::vector<Site>>(const Neighbourhood& nb)> starts_of;
  std::function<void(std::size_t i, const Neighbourhood& nb, LocalResult& best, int which)> take;
};

void solve_in_waves(const RefinementSetup& setup, const MapCells& cells, const MapRaster& raster,
                    const Adjacency& adj, const fitting::RefineResult& refined, std::vector<std::size_t> remaining,
                    const WaveSteps& steps) {
  const std::size_t n = setup.n;
  const std::vector<Site>& sites = refined.sites;
  std::vector<int> local_of(n, -1);
  std::vector<char> claimed(n, 0);
  while (!remaining.empty()) {
    std::vector<std::size_t> wave, deferred;
    std::vector<Neighbourhood> hoods;
    std::vector<int> touched;
    for (std::size_t i : remaining) {
      if (!steps.still_suspect(i)) continue;
      Neighbourhood nb = neighbourhood(setup, adj, sites, i, local_of);
      const bool free_of_earlier = std::none_of(nb.sensors.begin(), nb.sensors.end(), [&](int j) { return claimed[j] != 0; });
      for (int j : nb.sensors)
        if (!claimed[j]) claimed[j] = 1, touched.push_back(j);
      if (!free_of_earlier) {
        deferred.push_back(i);
        continue;
      }
      wave.push_back(i);
      hoods.push_back(std::move(nb));
    }
    for (int j : touched) claimed[j] = 0;
    // Every start of every re-solve of the wave is an independent solve: on the refinement's
    // threads, each compared with its own suspect's other starts in start order.
    std::vector<std::vector<std::vector<Site>>> starts;
    std::vector<std::pair<std::size_t, std::size_t>> items;  // (wave member, start)
    for (std::size_t w = 0; w < wave.size(); ++w) {
      starts.push_back(steps.starts_of(hoods[w]));
      for (std::size_t k = 0; k < starts.back().size(); ++k) items.emplace_back(w, k);
    }
    std::vector<LocalResult> solved(items.size());
    parallel_items(items.size(), setup.options.threads, [&](std::size_t t) {
      const auto [w, k] = items[t];
      solved[t] = solve_from(setup, hoods[w], starts[w][k], refined.range);
      solved[t].admissible = !solved[t].sites.empty() && admissible(setup, cells, raster, adj, hoods[w], solved[t].sites);
    });
    for (std::size_t w = 0, t = 0; w < wave.size(); ++w) {
      LocalResult best;
      int which = -1;
      for (std::size_t k = 0; k < starts[w].size(); ++k, ++t)
        if (better(solved[t], best)) best = std::move(solved[t]), which = static_cast<int>(k);
      steps.take(wave[w], hoods[w], best, which);
    }
    remaining = std::move(deferred);
  }
}

}  // namespace

Messages resolve_misplaced(const RefinementSetup& setup, const SiteEstimates& estimates, const MapCells& cells,
                           const MapRaster& raster, const ReportedOf& reported_of, fitting::RefineResult& refined) {
  const std::size_t n = setup.n;
  if (n < 2 || refined.sites.size() != n) return {};
  const Adjacency adj = adjacency(setup);
  std::vector<Site>& sites = refined.sites;
  std::vector<Suspicion> suspect(n, Suspicion::kNone);
  for (std::size_t i = 0; i < n; ++i) suspect[i] = suspicion(setup, cells, raster, adj, refined, i);
  drop_pinned_island_hosts(setup, adj, refined, suspect);
  // Local minima are local: when a large share of the map looks stuck, the cause is global (the map
  // does not follow the model, which the model fit will report), and re-solves would only chase it
  // at great cost.
  const std::size_t suspects = n - static_cast<std::size_t>(std::count(suspect.begin(), suspect.end(), Suspicion::kNone));
  if (static_cast<double>(suspects) > tolerance::kLocalMaxSuspectShare * static_cast<double>(n)) {
    return {std::to_string(suspects) + " of " + std::to_string(n) +
            " sensors looked stuck in local minima: too many for local causes; not solved again locally"};
  }
  int resolved = 0, moved = 0;
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < n; ++i)
    if (suspect[i] != Suspicion::kNone) order.push_back(i);
  WaveSteps steps;
  steps.still_suspect = [&](std::size_t i) { return suspect[i] != Suspicion::kNone; };
  const StartSources from{.estimates = estimates, .cells = cells, .raster = raster, .reported_of = reported_of};
  steps.starts_of = [&](const Neighbourhood& nb) { return local_starts(setup, from, adj, sites, nb); };
  steps.take = [&](std::size_t i, const Neighbourhood& nb, LocalResult& best, int which) {
    ++resolved;
    if (best.sites.empty() || !best.admissible) return;  // nothing better than a degenerate minimum
    for (std::size_t l = 0; l < nb.free; ++l) sites[nb.sensors[l]] = best.sites[l];
    // Its neighbours were solved with it, from the same starts: a later suspect among them is
    // done. So is an island host anywhere in the free set (it was solved from its centroid with
    // its island); a misfit two rings away needs starts of its own (the shared ones can leave it
    // bins off).
    for (int j : adj.neighbours[i]) suspect[j] = Suspicion::kNone;
    for (std::size_t l = 0; l < nb.free; ++l)
      if (suspect[nb.sensors[l]] == Suspicion::kIslandHost) suspect[nb.sensors[l]] = Suspicion::kNone;
    moved += which > 0;
  };
  solve_in_waves(setup, cells, raster, adj, refined, std::move(order), steps);
  if (!resolved) return {};
  return {std::to_string(resolved) +
          " sensor(s) outside their own cell, with a weight far from their neighbours', merged with a "
          "neighbour, hosting an island or with a poorly fitted boundary were solved again with their "
          "neighbourhoods from several starts; " +
          std::to_string(moved) + " moved to a lower minimum"};
}

}  // namespace covmap::audit::stages
