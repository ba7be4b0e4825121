// recognition_accuracy_bench: round trips sites → engine → arc graph → recognize → sites on
// near-degenerate families, similarity-transformed copies and graphs rounded to a few significant
// digits (docs/RECOGNITION.md, "Accuracy"). Measures only; nothing asserts.
//
//   recognition_accuracy_bench --family random,collinear --n 300 --perturb 0,ulp,1e-12 \
//       [--offset 1e7] [--scale 1] [--rotate 0.3] [--digits 12,9,6] [--tolerance 1e-7 | --tolerance-units 10]
//       [--seeds 10] [--no-check] [--json]
//
// One row per (family, perturbation, digits): how many of the seeds' diagrams the engine drew
// validly (check::check_diagram; the others are skipped and counted), how many graphs were accepted
// as bisector graphs, unique (not a family), with two surviving solutions (Lemma 6; the answer is
// the first), how many answered "voronoi: yes", and the worst position error (relative to the
// sites' extent) and weight error (relative) over the unique single-solution ones.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "../tests/recognition/recognition_families.h"
#include "check/check.h"
#include "io/diagram_json.h"
#include "recognition/recognize.h"
#include "voronoi/engine.h"

namespace {

namespace rt = covmap::recognition::testing;

struct Row {
  int seeds = 0, engine_invalid = 0, accepted = 0, unique = 0, two_solutions = 0, voronoi_yes = 0;
  std::size_t most_differences = 0;  // over the graphs answered "voronoi: no"
  std::string first_difference;
  double position = 0.0, weight = 0.0, seconds = 0.0;
  std::string first_rejection;
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"round-trip accuracy of recognition on near-degenerate, transformed and rounded graphs"};
  std::vector<std::string> families = {"random"}, perturbations = {"0"};
  std::vector<int> digits_list = {0};
  int n = 300, seeds = 10;
  double offset = 0.0, scale = 1.0, rotate = 0.0, tolerance = 1e-7, digit_units = 0.0;
  bool json_out = false, no_check = false;
  std::string dump_dir;
  app.add_option("--family", families, "random, equal, collinear, cocircular, grid")->delimiter(',');
  app.add_option("--perturb", perturbations, "relative perturbations: 0, ulp, 1e-15, ...")->delimiter(',');
  app.add_option("--digits", digits_list, "round the graph to this many significant digits (0: exact)")->delimiter(',');
  app.add_option("--n", n, "sites per diagram");
  app.add_option("--seeds", seeds, "diagrams per row");
  app.add_option("--offset", offset, "added to both coordinates of every site");
  app.add_option("--scale", scale, "multiplies every site position");
  app.add_option("--rotate", rotate, "rotation of the site set (radians)");
  app.add_option("--tolerance", tolerance, "RecognitionOptions::relative_tolerance");
  app.add_option("--tolerance-units", digit_units,
                 "for rounded graphs: the tolerance is this many units of the last written digit (F·10^-d)");
  app.add_flag("--no-check", no_check, "skip the MWVD check");
  app.add_flag("--json", json_out, "one JSON object per row");
  app.add_option("--dump", dump_dir, "write each rejected graph here as FAMILY-PERTURB-dDIGITS-sSEED.json (for covmap recognize)");
  CLI11_PARSE(app, argc, argv);
  const rt::Similarity similarity{scale, rotate, offset, offset};
  if (!json_out)
    std::cout << "family      perturb  digits seeds invalid accepted unique two voronoi_yes  position_err  weight_err\n";
  for (const std::string& family_name : families) {
    const auto family = rt::recognition_family_from_string(family_name);
    if (!family) {
      std::cerr << "recognition_accuracy_bench: unknown family " << family_name << "\n";
      return 2;
    }
    for (const std::string& perturb_name : perturbations) {
      const auto perturbation = rt::perturbation_from_string(perturb_name);
      if (!perturbation) {
        std::cerr << "recognition_accuracy_bench: bad perturbation " << perturb_name << "\n";
        return 2;
      }
      for (const int digits : digits_list) {
        Row row;
        for (int seed = 1; seed <= seeds; ++seed) {
          const auto sites = rt::recognition_sites(*family, n, seed, *perturbation, similarity);
          covmap::Diagram drawn;
          try {
            drawn = covmap::voronoi::build_diagram(sites);
          } catch (const std::exception&) {
            ++row.engine_invalid;
            continue;
          }
          if (!covmap::check::check_diagram(drawn).ok()) {
            ++row.engine_invalid;
            continue;
          }
          ++row.seeds;
          covmap::Diagram graph = drawn;
          if (digits > 0) rt::round_graph(graph, digits);
          covmap::recognition::RecognitionOptions options;
          options.relative_tolerance = digits > 0 && digit_units > 0 ? digit_units * std::pow(10.0, -digits) : tolerance;
          options.voronoi_check = !no_check;
          const auto t0 = std::chrono::steady_clock::now();
          const auto r = covmap::recognition::recognize(std::move(graph), options);
          row.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
          if (!r.bisector_graph || r.voronoi != covmap::recognition::MwvdAnswer::kYes) {
            if (!dump_dir.empty()) {
              covmap::Diagram shown = drawn;
              if (digits > 0) rt::round_graph(shown, digits);
              std::filesystem::create_directories(dump_dir);
              std::ofstream out(std::filesystem::path(dump_dir) / (family_name + "-" + perturbation->name() + "-d" +
                                                                   std::to_string(digits) + "-s" + std::to_string(seed) + ".json"));
              covmap::io::write_diagram_json(shown, out);
            }
          }
          if (!r.bisector_graph) {
            if (row.first_rejection.empty()) row.first_rejection = "seed " + std::to_string(seed) + ": " + r.reason;
            continue;
          }
          ++row.accepted;
          row.unique += r.unique ? 1 : 0;
          row.two_solutions += r.unique && r.candidates.size() > 1 ? 1 : 0;
          row.voronoi_yes += r.voronoi == covmap::recognition::MwvdAnswer::kYes ? 1 : 0;
          row.most_differences = std::max(row.most_differences, r.voronoi_differences.size());
          if (row.first_difference.empty() && !r.voronoi_differences.empty())
            row.first_difference = "seed " + std::to_string(seed) + ": " + r.voronoi_differences.front().message;
          // A family member, or the first of two surviving solutions (Lemma 6), need not be the
          // drawing sites.
          if (!r.unique || r.candidates.size() > 1) continue;
          const auto e = rt::round_trip_error(sites, drawn, r);
          row.position = std::max(row.position, e.position);
          row.weight = std::max(row.weight, e.weight);
        }
        if (json_out) {
          nlohmann::json j = {{"family", family_name}, {"perturbation", perturbation->name()}, {"digits", digits},
                              {"n", n}, {"offset", offset}, {"scale", scale}, {"rotate", rotate},
                              {"tolerance", digits > 0 && digit_units > 0 ? digit_units * std::pow(10.0, -digits) : tolerance}, {"seeds", row.seeds}, {"engine_invalid", row.engine_invalid},
                              {"accepted", row.accepted}, {"unique", row.unique}, {"two_solutions", row.two_solutions}, {"voronoi_yes", row.voronoi_yes},
                              {"worst_position_error", row.position}, {"worst_weight_error", row.weight},
                              {"recognize_s", row.seconds}, {"first_rejection", row.first_rejection},
                              {"most_voronoi_differences", row.most_differences}, {"first_difference", row.first_difference}};
          std::cout << j.dump() << "\n";
        } else {
          std::printf("%-11s %-8s %6d %5d %7d %8d %6d %3d %11d  %12.2e  %10.2e\n", family_name.c_str(),
                      perturbation->name().c_str(), digits, row.seeds, row.engine_invalid, row.accepted, row.unique,
                      row.two_solutions, row.voronoi_yes, row.position, row.weight);
          if (!row.first_rejection.empty()) std::printf("            first rejection: %s\n", row.first_rejection.c_str());
          if (!row.first_difference.empty())
            std::printf("            most differences %zu; first: %s\n", row.most_differences, row.first_difference.c_str());
        }
        std::cout.flush();
      }
    }
  }
  return 0;
}
