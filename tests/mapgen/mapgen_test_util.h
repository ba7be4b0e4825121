// Oracles and helpers shared by the map generator tests: brute-force ownership, ring geometry,
// 4-connected components by flood fill, a scratch directory.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "core/diagram.h"
#include "tests/support/temp_dir.h"

namespace covmap::mapgen::testing {


// The owner of p by brute force over all sites: smallest sqrt(dx² + dy²) / w, lowest index on ties,
// kNone when beyond max_range (negative: unlimited). Also returns the smallest distance.
inline int brute_force_owner(const std::vector<Site>& sites, double px, double py, double max_range = -1.0,
                             double* best_out = nullptr) {
  int best = kNone;
  double best_d = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < sites.size(); ++k) {
    const double dx = px - sites[k].x, dy = py - sites[k].y;
    const double d = std::sqrt(dx * dx + dy * dy) / sites[k].weight;
    if (d < best_d) {
      best_d = d;
      best = static_cast<int>(k);
    }
  }
  if (best_out) *best_out = best_d;
  if (max_range >= 0.0 && best_d > max_range) return kNone;
  return best;
}

// Shoelace over a closed ring (front == back): positive when counter-clockwise.
inline double signed_area(const std::vector<Point>& ring) {
  double twice = 0.0;
  for (std::size_t k = 0; k + 1 < ring.size(); ++k) twice += ring[k].x * ring[k + 1].y - ring[k + 1].x * ring[k].y;
  return 0.5 * twice;
}

// Per label (>= 0), the number of 4-connected components, by an independent flood fill.
inline std::vector<int> components_per_label(const std::vector<int>& labels, int nx, int ny, int label_count) {
  std::vector<int> count(static_cast<std::size_t>(label_count), 0);
  std::vector<bool> seen(labels.size(), false);
  for (int j0 = 0; j0 < ny; ++j0) {
    for (int i0 = 0; i0 < nx; ++i0) {
      const std::size_t start = static_cast<std::size_t>(j0) * nx + i0;
      if (labels[start] < 0 || seen[start]) continue;
      ++count[static_cast<std::size_t>(labels[start])];
      std::vector<std::pair<int, int>> queue = {{i0, j0}};
      seen[start] = true;
      for (std::size_t q = 0; q < queue.size(); ++q) {
        const auto [i, j] = queue[q];
        const int di[4] = {1, -1, 0, 0}, dj[4] = {0, 0, 1, -1};
        for (int d = 0; d < 4; ++d) {
          const int a = i + di[d], b = j + dj[d];
          if (a < 0 || b < 0 || a >= nx || b >= ny) continue;
          const std::size_t n = static_cast<std::size_t>(b) * nx + a;
          if (!seen[n] && labels[n] == labels[start]) {
            seen[n] = true;
            queue.emplace_back(a, b);
          }
        }
      }
    }
  }
  return count;
}

// prefix followed by k. (Built by appending: GCC 12 gives a false -Wrestrict for
// "literal" + std::string, PR 105651.)
inline std::string numbered(const char* prefix, long k) {
  std::string out = prefix;
  out += std::to_string(k);
  return out;
}

// Random sites in [0, size]², weights log-uniform in [1/ratio, 1].
inline std::vector<Site> random_test_sites(int n, double size, double ratio, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Site> sites;
  for (int k = 0; k < n; ++k)
    sites.push_back(Site{numbered("s", k), size * unit(rng), size * unit(rng), std::exp(-std::log(ratio) * unit(rng))});
  return sites;
}

using covmap::testing::read_text;
using covmap::testing::TempDir;

}  // namespace covmap::mapgen::testing
