// polygon_check_bench: times the two simplicity checks of covmap::io on large polygons (bounded
// work on hostile input): polygon_defect (every --clip polygon, every arc graph's "clip")
// and detail::find_crossing (every ring set of a coverage map). See docs/PERFORMANCE.md. Measures
// only; nothing asserts a time.
//
//   polygon_check_bench --n 10000,100000,1e6 --shape spiral,circle,comb --check defect,crossing [--json]
//
// Shapes (all simple polygons, so each check has to look at the whole input):
//   spiral  a thick spiral strip: an inner and an outer Archimedean spiral of n/2 vertices each,
//           about sqrt(n)/8 turns, joined at both ends; a vertical line meets ~4 edges per turn, so
//           the sweep's status holds hundreds of edges at 10^6.
//   circle  a regular n-gon of radius 1.
//   comb    m = (n-3)/4 teeth of width 1 and height 2m on integer coordinates, closed by a long
//           excursion along y = 0 and y = -1 to x = 64 m^2: many short edges next to a few very
//           long ones, the worst case of the grid the crossing finder used before the sweep.
// For each (n, shape, check) row: the vertices, the seconds of one call (steady_clock), the answer
// (a defect message or a crossing, "none" when simple) and the process's peak RSS so far (ru_maxrss;
// run one row per process under /usr/bin/time -v for the row's own peak).
#include <sys/resource.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "bench/count_argument.h"
#include "io/coverage_map_crossings.h"
#include "io/polygon_check.h"

namespace {

using covmap::Point;

std::size_t parse_size(const std::string& text) {
  return covmap::bench::parse_count(text, 8.0, "--n", "a vertex count (at least 8)");
}

std::vector<Point> spiral(std::size_t n) {
  const std::size_t m = n / 2;
  const double turns = std::max(2.0, std::round(std::sqrt(static_cast<double>(n)) / 8));
  const double total = 2 * std::numbers::pi * turns;
  std::vector<Point> out(2 * m);
  for (std::size_t k = 0; k < m; ++k) {
    const double t = total * static_cast<double>(k) / static_cast<double>(m - 1);
    const double r = 1 + t / (2 * std::numbers::pi);  // pitch 1; the outer spiral is 0.5 further out
    out[k] = {r * std::cos(t), r * std::sin(t)};
    out[2 * m - 1 - k] = {(r + 0.5) * std::cos(t), (r + 0.5) * std::sin(t)};
  }
  return out;
}

std::vector<Point> circle(std::size_t n) {
  std::vector<Point> out(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double t = 2 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(n);
    out[k] = {std::cos(t), std::sin(t)};
  }
  return out;
}

std::vector<Point> comb(std::size_t n) {
  const std::size_t m = (n - 3) / 4;
  const double height = 2.0 * static_cast<double>(m);
  std::vector<Point> out;
  out.reserve(4 * m + 3);
  for (std::size_t k = 0; k < m; ++k) {
    const double x = 2.0 * static_cast<double>(k);
    out.push_back({x, 0});
    out.push_back({x, height});
    out.push_back({x + 1, height});
    out.push_back({x + 1, 0});
  }
  const double far = 64.0 * static_cast<double>(m) * static_cast<double>(m);
  out.push_back({far, 0});
  out.push_back({far, -1});
  out.push_back({0, -1});
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"time covmap's polygon simplicity checks on large simple polygons"};
  std::vector<std::string> sizes = {"10000", "100000"};
  std::vector<std::string> shapes = {"spiral", "circle", "comb"};
  std::vector<std::string> checks = {"defect", "crossing"};
  bool json_out = false;
  app.add_option("--n", sizes, "vertex counts (comma separated, 1e6 accepted)")->delimiter(',');
  app.add_option("--shape", shapes, "spiral, circle, comb")->delimiter(',')->check(CLI::IsMember({"spiral", "circle", "comb"}));
  app.add_option("--check", checks, "defect (io::polygon_defect), crossing (io::detail::find_crossing)")
      ->delimiter(',')
      ->check(CLI::IsMember({"defect", "crossing"}));
  app.add_flag("--json", json_out, "one JSON object per row (JSON Lines)");
  CLI11_PARSE(app, argc, argv);
  std::vector<std::size_t> counts;
  try {
    for (const auto& s : sizes) counts.push_back(parse_size(s));
  } catch (const CLI::ValidationError& e) {
    std::cerr << "polygon_check_bench: " << e.what() << "\n";
    return 2;
  }
  using Clock = std::chrono::steady_clock;
  if (!json_out) std::printf("%10s %7s %9s %10s %10s  answer\n", "vertices", "shape", "check", "seconds", "peak_MiB");
  for (const std::size_t n : counts) {
    for (const auto& shape : shapes) {
      const std::vector<Point> ring = shape == "spiral" ? spiral(n) : shape == "circle" ? circle(n) : comb(n);
      for (const auto& check : checks) {
        std::string answer;
        const auto t0 = Clock::now();
        if (check == "defect") {
          const auto defect = covmap::io::polygon_defect(ring);
          answer = defect ? *defect : "none";
        } else {
          const std::vector<std::vector<Point>> rings{ring};
          const auto crossing = covmap::io::detail::find_crossing(rings);
          answer = crossing ? "edges " + std::to_string(crossing->first.edge) + " and " + std::to_string(crossing->second.edge)
                            : "none";
        }
        const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
        rusage usage{};
        getrusage(RUSAGE_SELF, &usage);
        if (json_out) {
          const nlohmann::json row = {{"vertices", ring.size()}, {"shape", shape},   {"check", check},
                                      {"seconds", seconds},      {"answer", answer}, {"peak_rss_kib", usage.ru_maxrss}};
          std::cout << row.dump() << "\n";
        } else {
          std::printf("%10zu %7s %9s %10.3f %10.1f  %s\n", ring.size(), shape.c_str(), check.c_str(), seconds,
                      static_cast<double>(usage.ru_maxrss) / 1024.0, answer.c_str());
        }
        std::cout.flush();
      }
    }
  }
  return 0;
}
