// mwvd_check_bench: the false-"no" rate of recognize()'s MWVD check (docs/RECOGNITION.md, "The
// MWVD check"). Each instance is the engine's MWVD of random sites, its sites and labels taken off,
// recognized with the check: every "no" is false. Instances whose reconstruction is not accurate
// (a site off by more than --accurate relative to the sites' box, or a normalised weight off by more
// than that relatively) are counted apart: their "no" may be the reconstruction's fault. Measures
// only; nothing asserts here. Sets the engine refuses (it fails loudly rather than write a diagram
// its own self-check rejects) are counted as engine_failed, and answers "unknown" (the engine
// refused the reconstructed sites) as undecided, each with its seed on stderr.
//
//   mwvd_check_bench --n 100,1000,10000,100000 --count 500,200,20,2 --dist uniform12,uniform01 --grids 15 --json
//
// --grids G adds G integer grids (25 sites at integer positions in [0, 7)², weights 1 or 2: nodes of
// degree four and more, tangencies; tests/voronoi/site_families.h, family Grid, seeds 1..G).
// --first-seed S draws the random instances from seeds S, S+1, ... (default 1), so that a second
// run measures other instances. Every false "no" is listed by its seed (false_no_seeds): with --n,
// --dist and that seed (--count 1) it is reproduced.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bench/reconstruction_error.h"
#include "bench/site_distributions.h"
#include "recognition/recognize.h"
#include "tests/voronoi/site_families.h"
#include "voronoi/engine.h"

namespace {

struct Row {
  std::string dist;
  std::size_t n = 0;
  int instances = 0, accurate = 0, no_accurate = 0, no_inaccurate = 0, not_bisector = 0;
  int engine_failed = 0;  // sets the engine refuses (voronoi::EngineFailure): no diagram to recognize
  int undecided = 0;      // answered "unknown": the engine refused the reconstructed sites
  double seconds = 0.0;
  std::string first_no;  // the first difference of the first false "no"
  std::vector<int> no_seeds;  // the seeds of the false "no"s
};

// One instance: recognized with the check, classified into the row.
void run(const std::vector<covmap::Site>& sites, int seed, double accurate_limit, Row& row) {
  covmap::Diagram d;
  try {
    d = covmap::voronoi::build_diagram(sites);
  } catch (const covmap::voronoi::EngineFailure& e) {
    ++row.engine_failed;
    std::cerr << "mwvd_check_bench: seed " << seed << ": " << e.what() << "\n";
    return;
  }
  d.sites.clear();
  clear_faces(d);
  for (auto& a : d.arcs) a.left_site = a.right_site = covmap::kNone;
  const auto t0 = std::chrono::steady_clock::now();
  const covmap::recognition::Reconstruction r = covmap::recognition::recognize(std::move(d));
  row.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ++row.instances;
  if (!r.bisector_graph) {
    ++row.not_bisector;
    std::cerr << "mwvd_check_bench: seed " << seed << ": not a bisector graph: " << r.reason << "\n";
    return;
  }
  const auto [position, weight] = covmap::bench::reconstruction_error(sites, r);
  const bool accurate = position <= accurate_limit && weight <= accurate_limit;
  row.accurate += accurate;
  if (r.voronoi == covmap::recognition::MwvdAnswer::kUnknown) {
    ++row.undecided;
    std::cerr << "mwvd_check_bench: seed " << seed << ": " << r.reason << "\n";
  }
  if (r.voronoi != covmap::recognition::MwvdAnswer::kNo) return;
  (accurate ? row.no_accurate : row.no_inaccurate) += 1;
  row.no_seeds.push_back(seed);
  if (row.first_no.empty() && !r.voronoi_differences.empty()) row.first_no = r.voronoi_differences.front().message;
}

void print(const Row& row, bool json_out) {
  if (json_out) {
    std::cout << nlohmann::json{{"dist", row.dist},
                                {"n", row.n},
                                {"instances", row.instances},
                                {"accurate", row.accurate},
                                {"false_no_accurate", row.no_accurate},
                                {"false_no_inaccurate", row.no_inaccurate},
                                {"not_bisector_graph", row.not_bisector},
                                {"engine_failed", row.engine_failed},
                                {"undecided", row.undecided},
                                {"recognize_s", row.seconds},
                                {"first_false_no", row.first_no},
                                {"false_no_seeds", row.no_seeds}}
                     .dump()
              << "\n";
  } else {
    std::printf("%-10s %8zu %9d %9d %9d %9d %9d %9d %9d %10.2f  %s\n", row.dist.c_str(), row.n, row.instances,
                row.accurate, row.no_accurate, row.no_inaccurate, row.not_bisector, row.engine_failed, row.undecided,
                row.seconds, row.first_no.c_str());
  }
  std::cout.flush();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"false-\"no\" rate of the MWVD check on exact MWVDs"};
  std::vector<std::string> sizes = {"100", "1000"}, counts = {"100", "20"}, dists = {"uniform12", "uniform01"};
  int grids = 15, first_seed = 1;
  double accurate_limit = 1e-8;
  bool json_out = false;
  app.add_option("--n", sizes, "numbers of sites (comma separated)")->delimiter(',');
  app.add_option("--count", counts, "instances per size (comma separated, one per --n)")->delimiter(',');
  app.add_option("--dist", dists, "weight distributions (see mwvd_bench)")->delimiter(',');
  app.add_option("--grids", grids, "integer-weight grids to add (seeds 1..G)");
  app.add_option("--first-seed", first_seed, "the random instances' first seed (then S+1, ...)");
  app.add_option("--accurate", accurate_limit, "reconstruction error below which an instance counts as accurate");
  app.add_flag("--json", json_out, "one JSON object per row");
  CLI11_PARSE(app, argc, argv);
  if (counts.size() != sizes.size()) {
    std::cerr << "mwvd_check_bench: --count needs one number per --n\n";
    return 2;
  }
  if (!json_out)
    std::printf("%-10s %8s %9s %9s %9s %9s %9s %9s %9s %10s  %s\n", "dist", "n", "instances", "accurate", "no(acc)",
                "no(inacc)", "not_bisec", "eng_fail", "undecided", "recog_s", "first false no");
  for (const std::string& name : dists) {
    std::string error;
    const auto dist = covmap::bench::parse_distribution(name, &error);
    if (!dist) {
      std::cerr << "mwvd_check_bench: " << error << "\n";
      return 2;
    }
    for (std::size_t k = 0; k < sizes.size(); ++k) {
      Row row;
      row.dist = dist->name();
      row.n = static_cast<std::size_t>(std::stod(sizes[k]));
      const int count = std::stoi(counts[k]);
      for (int seed = first_seed; seed < first_seed + count; ++seed)
        run(covmap::bench::make_sites(row.n, *dist, seed), seed, accurate_limit, row);
      print(row, json_out);
    }
  }
  if (grids > 0) {
    Row row;
    row.dist = "grid";
    row.n = 25;
    for (int seed = 1; seed <= grids; ++seed)
      run(covmap::voronoi::testing::make_sites(covmap::voronoi::testing::Family::Grid, 25, seed), seed, accurate_limit,
          row);
    print(row, json_out);
  }
  return 0;
}
