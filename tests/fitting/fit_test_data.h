// Exact boundary data for the fitting tests: random weighted sites, their diagram from the engine
// (clipped to a frame so every arc is bounded), and points along the bisector arcs.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "fitting/refine.h"
#include "voronoi/arc_path.h"
#include "voronoi/clip.h"
#include "voronoi/engine.h"

namespace covmap::fitting::testing {

struct MapData {
  std::vector<Site> sites;     // the truth
  std::vector<BoundarySample> samples;  // exact points on its bisector arcs, sigma 1, chain = arc index
};

// n sites in the unit square, at least `separation` apart, weights uniform in [w_min, w_max].
inline std::vector<Site> random_sites(int n, std::uint64_t seed, double w_min, double w_max,
                                               double separation = 0.15) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Site> sites;
  while (static_cast<int>(sites.size()) < n) {
    const double x = unit(rng), y = unit(rng), w = w_min + (w_max - w_min) * unit(rng);
    bool far = true;
    for (const auto& s : sites) far = far && std::hypot(s.x - x, s.y - y) >= separation;
    if (!far) continue;
    std::string id = "s";  // (not "s" + to_string: GCC 12 warns falsely, -Wrestrict)
    id += std::to_string(sites.size());
    sites.push_back({id, x, y, w});
  }
  return sites;
}

// per_arc points evenly spread (midpoints of equal parameter steps) along every bisector arc of the
// sites' diagram inside the square [-0.5, 1.5]²; frame arcs are skipped.
inline std::vector<BoundarySample> boundary_samples(const std::vector<Site>& sites, int per_arc) {
  const Diagram full = voronoi::build_diagram(sites);
  const Diagram d = voronoi::clip_diagram(full, {{-0.5, -0.5}, {1.5, -0.5}, {1.5, 1.5}, {-0.5, 1.5}});
  std::vector<BoundarySample> samples;
  for (std::size_t i = 0; i < d.arcs.size(); ++i) {
    const Arc& arc = d.arcs[i];
    if (arc.frame || arc.left_site == kNone || arc.right_site == kNone) continue;
    const voronoi::ArcPathView path = voronoi::arc_path(arc, d.nodes);
    if (!std::isfinite(path.s0) || !std::isfinite(path.s1)) continue;
    for (int j = 0; j < per_arc; ++j) {
      const double s = path.s0 + (j + 0.5) / per_arc * (path.s1 - path.s0);
      samples.push_back({path.at(s), arc.left_site, arc.right_site, 1.0, static_cast<int>(i)});
    }
  }
  return samples;
}

inline MapData make_map(int n, std::uint64_t seed, double w_min, double w_max, int per_arc) {
  MapData map;
  map.sites = random_sites(n, seed, w_min, w_max);
  map.samples = boundary_samples(map.sites, per_arc);
  return map;
}

// The truth moved by up to ±shift in x and y and its weights scaled by up to e^±log_shift.
inline std::vector<Site> perturbed(std::vector<Site> sites, std::uint64_t seed, double shift,
                                            double log_shift) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (auto& s : sites) {
    s.x += shift * unit(rng);
    s.y += shift * unit(rng);
    s.weight *= std::exp(log_shift * unit(rng));
  }
  return sites;
}

// Every sample moved by independent N(0, sigma) in x and y; sample sigma set to `nominal`.
inline std::vector<BoundarySample> noisy(std::vector<BoundarySample> samples, std::mt19937_64& rng, double sigma,
                                         double nominal) {
  std::normal_distribution<double> noise(0.0, sigma);
  for (auto& s : samples) {
    s.p.x += noise(rng);
    s.p.y += noise(rng);
    s.sigma = nominal;
  }
  return samples;
}

// Samples touching site k.
inline int samples_of(const std::vector<BoundarySample>& samples, int k) {
  int n = 0;
  for (const auto& s : samples) n += (s.site_a == k || s.site_b == k) ? 1 : 0;
  return n;
}

}  // namespace covmap::fitting::testing
