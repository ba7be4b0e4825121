// recognition_bench: times covmap::recognition::recognize on MWVDs of random weighted sites (the
// engine's output with its sites stripped), without and with the MWVD check. See
// docs/PERFORMANCE.md. Measures only; nothing asserts a time.
//
//   recognition_bench --n 1000,10000,100000 [--dist uniform12] [--seed 1] [--json]
//   recognition_bench --n 1000000 --no-check          (the MWVD check at 10^6 takes minutes)
//   recognition_bench --n 1000000 --no-check --cache graphs --repeat 3
//       keeps the engine's graph in the folder graphs between runs (building it takes longer than
//       recognizing it) and reports the fastest of three recognitions with its stages
#include <CLI/CLI.hpp>
#include <sys/resource.h>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <optional>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "bench/diagram_cache.h"
#include "bench/reconstruction_error.h"
#include "bench/site_distributions.h"
#include "recognition/recognize.h"
#include "voronoi/engine.h"


int main(int argc, char** argv) {
  CLI::App app{"time recognition of MWVD arc graphs"};
  std::vector<std::string> sizes = {"1000", "10000", "100000"};
  std::string dist_name = "uniform12";
  std::uint64_t seed = 1;
  bool json_out = false;
  bool no_check = false;
  std::string cache_dir;
  int repeat = 1;
  bool verify = false;
  app.add_option("--n", sizes, "numbers of sites (comma separated)")->delimiter(',');
  app.add_option("--dist", dist_name, "weight distribution (see mwvd_bench)");
  app.add_option("--seed", seed, "random seed");
  app.add_flag("--json", json_out, "one JSON object per row");
  app.add_flag("--no-check", no_check, "time recognize() without the MWVD check only (for 10^6)");
  app.add_option("--cache", cache_dir, "directory keeping the engine's graphs between runs");
  app.add_option("--repeat", repeat, "recognitions per size; the fastest is reported")->check(CLI::PositiveNumber);
  app.add_flag("--verify", verify,
               "compare the reconstruction with the sites that drew the graph (largest position error "
               "relative to the unit square, largest relative error of normalised weights)");
  CLI11_PARSE(app, argc, argv);
  std::string error;
  const auto dist = covmap::bench::parse_distribution(dist_name, &error);
  if (!dist) {
    std::cerr << "recognition_bench: " << error << "\n";
    return 2;
  }
  using Clock = std::chrono::steady_clock;
  auto seconds = [](Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
  };
  if (!json_out)
    std::cout << "       n    faces    arcs  recognize_s  with_check_s  check   bisector  ns/arc"
                 "  (faces start propagate sites s)\n";
  for (const std::string& text : sizes) {
    const auto n = static_cast<std::size_t>(std::stod(text));
    const std::string cache_file = cache_dir.empty() ? std::string()
        : cache_dir + "/mwvd-" + dist->name() + "-" + std::to_string(n) + "-" + std::to_string(seed) + ".bin";
    std::optional<covmap::Diagram> cached;
    if (!cache_file.empty()) cached = covmap::bench::load_graph(cache_file);
    covmap::Diagram d;
    if (cached) {
      d = std::move(*cached);
    } else {
      d = covmap::voronoi::build_diagram(covmap::bench::make_sites(n, *dist, seed));
      if (!cache_file.empty()) covmap::bench::save_graph(d, cache_file);
    }
    d.sites.clear();
    clear_faces(d);
    covmap::recognition::RecognitionOptions plain;
    plain.voronoi_check = false;
    covmap::recognition::Reconstruction r1;
    double s1 = INFINITY;
    for (int k = 0; k < repeat; ++k) {
      covmap::Diagram input = d;  // moved in, as a caller done with its graph does
      rusage before{}, after{};
      getrusage(RUSAGE_SELF, &before);
      const auto t0 = Clock::now();
      auto r = covmap::recognition::recognize(std::move(input), plain);
      const double s = seconds(t0, Clock::now());
      getrusage(RUSAGE_SELF, &after);
      if (!json_out) std::fprintf(stderr, "recognize: %.3f s, %ld page faults\n", s, after.ru_minflt - before.ru_minflt);
      if (s < s1) s1 = s, r1 = std::move(r);
    }
    const auto t1 = Clock::now();
    covmap::recognition::Reconstruction r2;
    if (!no_check) r2 = covmap::recognition::recognize(d);
    const double s2 = seconds(t1, Clock::now());
    const auto& st = r1.timings;
    double worst_position = 0.0, worst_weight = 0.0;
    if (verify) std::tie(worst_position, worst_weight) = covmap::bench::reconstruction_error(covmap::bench::make_sites(n, *dist, seed), r1);
    if (json_out) {
      nlohmann::json row = {{"n", n},          {"dist", dist->name()},
                            {"faces", r1.graph.faces.size()}, {"arcs", d.arcs.size()},
                            {"recognize_s", s1}, {"with_check_s", s2},
                            {"bisector_graph", r1.bisector_graph}, {"voronoi", std::string(covmap::recognition::to_string(r2.voronoi))},
                            {"voronoi_differences", r2.voronoi_differences.size()},
                            {"worst_position_error", worst_position}, {"worst_weight_error", worst_weight},
                            {"stages_s", {{"faces", st.faces}, {"start", st.start},
                                          {"propagate", st.propagate}, {"sites", st.sites}}}};
      std::cout << row.dump() << "\n";
    } else {
      std::printf("%8zu %8zu %8zu %12.3f %13.3f %6s %10s %7.0f  (%.3f %.3f %.3f %.3f)\n", n,
                  r1.graph.faces.size(), d.arcs.size(), s1, s2, std::string(covmap::recognition::to_string(r2.voronoi)).c_str(),
                  r1.bisector_graph ? "yes" : "no", 1e9 * s1 / static_cast<double>(d.arcs.size()),
                  st.faces, st.start, st.propagate, st.sites);
      if (verify) std::printf("         worst position error %.2e, worst weight error %.2e\n", worst_position, worst_weight);
      for (std::size_t k = 0; k < std::min<std::size_t>(3, r2.voronoi_differences.size()); ++k)
        std::printf("         difference %zu of %zu: %s\n", k + 1, r2.voronoi_differences.size(),
                    r2.voronoi_differences[k].message.c_str());
    }
    std::cout.flush();
  }
  return 0;
}
