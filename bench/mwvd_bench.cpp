// mwvd_bench: times covmap::voronoi::build_diagram on random weighted sites and, on the same points,
// CGAL's Delaunay_triangulation_2 (Epick) as a reference. See docs/PERFORMANCE.md.
//
// Each (n, distribution) row runs in its own child process, so its peak memory is its own. Within the
// row: generate the sites, run the engine `repeat` times, then the Delaunay triangulation `repeat`
// times; the median run of each is reported. Nothing is asserted about the times.
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/version.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bench/count_argument.h"
#include "bench/isolated_run.h"
#include "bench/site_distributions.h"
#include "voronoi/engine.h"

namespace {

using covmap::bench::Distribution;
using json = nlohmann::json;
using Clock = std::chrono::steady_clock;

struct Options {
  std::vector<std::string> sizes = {"1000", "10000", "100000"};
  std::vector<std::string> distributions = {"uniform12", "uniform01", "correlated"};
  std::uint64_t seed = 1;
  int repeat = 1;
  bool json = false;
};

struct Plan {
  std::vector<std::size_t> sizes;
  std::vector<Distribution> distributions;
};

// "1000", "1e6", "100000" -> a count ≥ 1; throws CLI::ValidationError otherwise.
std::size_t parse_size(const std::string& text) {
  return covmap::bench::parse_count(text, 1.0, "--n", "a site count");
}

Plan make_plan(const Options& options) {
  Plan plan;
  for (const auto& s : options.sizes) plan.sizes.push_back(parse_size(s));
  for (const auto& d : options.distributions) {
    std::string error;
    auto dist = covmap::bench::parse_distribution(d, &error);
    if (!dist) throw CLI::ValidationError("--dist", error);
    plan.distributions.push_back(*dist);
  }
  return plan;
}

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// CPU time of this process (the engine and the reference are single-threaded), to tell a slow run
// from a run that shared its core with other work: wall ≫ cpu means the machine was busy.
double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

template <class T>
std::size_t median_index(const std::vector<T>& runs, double T::*key) {
  std::vector<std::size_t> order(runs.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return runs[a].*key < runs[b].*key; });
  return order[(order.size() - 1) / 2];
}

struct EngineRun {
  double total_seconds = 0.0;
  double cpu_seconds = 0.0;
  covmap::voronoi::BuildStats stats;
};

struct DelaunayRun {
  double seconds = 0.0;
  double cpu_seconds = 0.0;
};

json optional_kib(std::optional<long> kib) { return kib ? json(*kib) : json(nullptr); }

// The body of one row, run in the child process; returns the row as JSON text.
std::string measure_row(std::size_t n, const Distribution& dist, std::uint64_t seed, int repeat) {
  namespace bench = covmap::bench;
  const auto sites = bench::make_sites(n, dist, seed);
  json row;
  row["n"] = n;
  row["dist"] = dist.name();
  row["seed"] = seed;
  row["repeat"] = repeat;
  row["input_rss_kib"] = optional_kib(bench::current_rss_kib());

  // The engine's first step, timed alone to account for part of engine - triangulation - extraction.
  {
    const auto start = Clock::now();
    const auto problems = covmap::voronoi::find_invalid_sites(sites);
    row["validation_seconds"] = seconds_since(start);
    if (!problems.empty()) throw covmap::voronoi::InvalidSites(problems);
  }

  // Peak memory. The engine's peak is VmHWM after resetting it just before the first build (so the
  // input generation's temporaries do not count); the diagram lives until the end of its iteration,
  // so the peak includes the output. The reset also lowers what wait4 later reports as ru_maxrss,
  // so the peak of the input phase is kept here and the parent takes the maximum.
  row["input_phase_peak_rss_kib"] = optional_kib(bench::peak_rss_kib());
  const bool can_reset_peak = bench::reset_peak_rss();
  std::vector<EngineRun> engine_runs;
  std::size_t nodes = 0, arcs = 0, faces = 0;
  for (int r = 0; r < repeat; ++r) {
    EngineRun run;
    const double cpu_start = process_cpu_seconds();
    const auto start = Clock::now();
    const auto diagram = covmap::voronoi::build_diagram(sites, &run.stats);
    run.total_seconds = seconds_since(start);
    run.cpu_seconds = process_cpu_seconds() - cpu_start;
    nodes = diagram.nodes.size();
    arcs = diagram.arcs.size();
    faces = diagram.faces.size();
    engine_runs.push_back(run);
  }
  row["engine_peak_rss_kib"] = can_reset_peak ? optional_kib(bench::peak_rss_kib()) : json(nullptr);
  const auto& engine = engine_runs[median_index(engine_runs, &EngineRun::total_seconds)];
  row["engine_seconds"] = engine.total_seconds;
  row["engine_cpu_seconds"] = engine.cpu_seconds;
  row["engine_other_seconds"] = engine.total_seconds - engine.stats.triangulation_seconds -
                                engine.stats.extraction_seconds - engine.stats.faces_seconds;
  row["triangulation_seconds"] = engine.stats.triangulation_seconds;
  row["extraction_seconds"] = engine.stats.extraction_seconds;
  row["faces_seconds"] = engine.stats.faces_seconds;
  row["engine_seconds_all"] = json::array();
  for (const auto& run : engine_runs) row["engine_seconds_all"].push_back(run.total_seconds);
  row["ns_per_n_log2_n"] =
      n > 1 ? json(engine.total_seconds * 1e9 /
                    (static_cast<double>(n) * std::log2(static_cast<double>(n))))
            : json(nullptr);
  row["exact_fallbacks"] = engine.stats.exact_fallbacks;
  row["exact_nodes"] = engine.stats.exact_nodes;
  row["self_check_seconds"] = engine.stats.self_check_seconds;
  row["triangulation_dimension"] = engine.stats.triangulation_dimension;
  row["nodes"] = nodes;
  row["arcs"] = arcs;
  row["faces"] = faces;

  // The reference: CGAL's 2D Delaunay triangulation of the same points (range insert sorts them
  // spatially first), timed from the construction of the empty triangulation to the last insert.
  using K = CGAL::Epick;
  using Delaunay = CGAL::Delaunay_triangulation_2<K>;
  std::vector<K::Point_2> points;
  points.reserve(sites.size());
  for (const auto& s : sites) points.emplace_back(s.x, s.y);
  std::vector<DelaunayRun> delaunay_runs;
  std::size_t delaunay_vertices = 0;
  for (int r = 0; r < repeat; ++r) {
    DelaunayRun run;
    const double cpu_start = process_cpu_seconds();
    const auto start = Clock::now();
    Delaunay dt;
    dt.insert(points.begin(), points.end());
    run.seconds = seconds_since(start);
    run.cpu_seconds = process_cpu_seconds() - cpu_start;
    delaunay_vertices = dt.number_of_vertices();
    delaunay_runs.push_back(run);
  }
  const auto& delaunay_run = delaunay_runs[median_index(delaunay_runs, &DelaunayRun::seconds)];
  const double delaunay = delaunay_run.seconds;
  row["delaunay2_seconds"] = delaunay;
  row["delaunay2_cpu_seconds"] = delaunay_run.cpu_seconds;
  row["delaunay2_vertices"] = delaunay_vertices;
  row["engine_over_delaunay2"] =
      delaunay > 0 ? json(engine.total_seconds / delaunay) : json(nullptr);
  return row.dump();
}

std::string mib(const json& kib) {
  if (!kib.is_number()) return "-";
  char text[32];
  std::snprintf(text, sizeof text, "%.0f", kib.get<double>() / 1024.0);
  return text;
}

void print_header() {
  std::printf("%8s %-15s %8s %8s %7s %7s %7s %7s %8s %7s %6s %8s %8s %8s %7s %8s %8s\n", "n",
              "dist", "engine_s", "cpu_s", "tri_s", "extr_s", "faces_s", "other_s", "ns/nlg2n",
              "dt2_s", "x_dt2", "nodes", "arcs", "faces", "fallbck", "eng_MiB", "peak_MiB");
}

void print_row(const json& row) {
  auto number = [&](const char* key) {
    return row[key].is_number() ? row[key].get<double>() : 0.0;  // null only for n = 1, dt2 = 0
  };
  auto count = [&](const char* key) { return row[key].get<std::size_t>(); };
  std::printf(
      "%8zu %-15s %8.3f %8.3f %7.3f %7.3f %7.3f %7.3f %8.1f %7.3f %6.1f %8zu %8zu %8zu %7zu %8s "
      "%8s\n",
      count("n"), row["dist"].get<std::string>().c_str(), number("engine_seconds"),
      number("engine_cpu_seconds"), number("triangulation_seconds"), number("extraction_seconds"),
      number("faces_seconds"), number("engine_other_seconds"), number("ns_per_n_log2_n"),
      number("delaunay2_seconds"), number("engine_over_delaunay2"), count("nodes"), count("arcs"),
      count("faces"), count("exact_fallbacks"), mib(row["engine_peak_rss_kib"]).c_str(),
      mib(row["process_peak_rss_kib"]).c_str());
}

int run_bench(const Options& options, const Plan& plan) {
  if (!options.json) {
#ifndef NDEBUG
    std::printf("# WARNING: assertions are on (not a Release build); times are not representative\n");
#endif
    std::printf("# mwvd_bench  CGAL %s  compiler %s  seed %llu  repeat %d (median reported)\n",
                CGAL_VERSION_STR, __VERSION__, static_cast<unsigned long long>(options.seed),
                options.repeat);
    print_header();
    std::fflush(stdout);
  }
  int failures = 0;
  for (const auto n : plan.sizes) {
    for (const auto& dist : plan.distributions) {
      const auto result = covmap::bench::run_isolated(
          [&] { return measure_row(n, dist, options.seed, options.repeat); });
      json row;
      if (result.ok) {
        row = json::parse(result.output);
      } else {
        ++failures;
        row = {{"n", n}, {"dist", dist.name()}, {"seed", options.seed}, {"error", result.failure}};
      }
      // The row's whole-process peak: wait4's ru_maxrss, or the input phase's VmHWM if that was
      // higher (the child reset VmHWM before the engine ran).
      long peak = result.peak_rss_kib;
      if (row.contains("input_phase_peak_rss_kib") && row["input_phase_peak_rss_kib"].is_number())
        peak = std::max(peak, row["input_phase_peak_rss_kib"].get<long>());
      row["process_peak_rss_kib"] = peak;
      if (options.json) {
        std::cout << row.dump() << std::endl;
      } else if (result.ok) {
        print_row(row);
      } else {
        std::printf("%8zu %-15s FAILED: %s (peak %s MiB)\n", n, dist.name().c_str(),
                    result.failure.c_str(), mib(row["process_peak_rss_kib"]).c_str());
      }
      std::fflush(stdout);
    }
  }
  return failures == 0 ? 0 : 1;
}

void setup_options(CLI::App& app, Options& options) {
  app.add_option("--n", options.sizes, "site counts, comma separated (1000,1e4,...)")
      ->delimiter(',')
      ->capture_default_str();
  app.add_option("--dist", options.distributions,
                 "weight distributions: uniform12, uniform01, correlated, correlated:A:B")
      ->delimiter(',')
      ->capture_default_str();
  app.add_option("--seed", options.seed, "random seed")->capture_default_str();
  app.add_option("--repeat", options.repeat, "runs per row; the median is reported")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  app.add_flag("--json", options.json, "one JSON object per row (JSON Lines) instead of a table");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"mwvd_bench: time the MWVD engine against CGAL Delaunay_triangulation_2"};
  Options options;
  setup_options(app, options);
  CLI11_PARSE(app, argc, argv);
  Plan plan;
  try {
    plan = make_plan(options);
  } catch (const CLI::Error& e) {
    return app.exit(e);
  }
  return run_bench(options, plan);
}
