// recognition_bench: times covmap::recognition::recognize on MWVDs of random weighted sites (the
// engine's output with its sites stripped), without and with the MWVD check. See
// docs/PERFORMANCE.md. Measures only; nothing asserts a time.
//
//   recognition_bench --n 1000,10000,100000 [--dist uniform12] [--seed 1] [--json]
//   recognition_bench --n 1000000 --no-check          (the MWVD check at 10^6 takes minutes)
#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

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
  app.add_option("--n", sizes, "numbers of sites (comma separated)")->delimiter(',');
  app.add_option("--dist", dist_name, "weight distribution (see mwvd_bench)");
  app.add_option("--seed", seed, "random seed");
  app.add_flag("--json", json_out, "one JSON object per row");
  app.add_flag("--no-check", no_check, "time recognize() without the MWVD check only (for 10^6)");
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
    std::cout << "       n    faces    arcs  recognize_s  with_check_s  check   bisector  ns/arc\n";
  for (const std::string& text : sizes) {
    const auto n = static_cast<std::size_t>(std::stod(text));
    const auto sites = covmap::bench::make_sites(n, *dist, seed);
    covmap::voronoi::Diagram d = covmap::voronoi::build_diagram(sites);
    d.sites.clear();
    d.faces.clear();
    covmap::recognition::RecognitionOptions plain;
    plain.voronoi_check = false;
    const auto t0 = Clock::now();
    const auto r1 = covmap::recognition::recognize(d, plain);
    const auto t1 = Clock::now();
    covmap::recognition::Reconstruction r2;
    if (!no_check) r2 = covmap::recognition::recognize(d);
    const auto t2 = Clock::now();
    const double s1 = seconds(t0, t1), s2 = seconds(t1, t2);
    if (json_out) {
      nlohmann::json row = {{"n", n},          {"dist", dist->name()},
                            {"faces", r1.graph.faces.size()}, {"arcs", d.arcs.size()},
                            {"recognize_s", s1}, {"with_check_s", s2},
                            {"bisector_graph", r1.bisector_graph}, {"voronoi", r2.voronoi},
                            {"voronoi_differences", r2.voronoi_differences.size()}};
      std::cout << row.dump() << "\n";
    } else {
      std::printf("%8zu %8zu %8zu %12.3f %13.3f %6s %10s %7.0f\n", n, r1.graph.faces.size(),
                  d.arcs.size(), s1, s2, r2.voronoi.c_str(), r1.bisector_graph ? "yes" : "no",
                  1e9 * s1 / static_cast<double>(d.arcs.size()));
    }
    std::cout.flush();
  }
  return 0;
}
