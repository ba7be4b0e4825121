// io_bench: the file I/O of `covmap diagram` and of the commands that read arc graphs, timed apart
// from the engine (the aim: reading and writing within 20 % of the engine's time). Each row, in a
// child process of its own (bench/isolated_run.h):
//   1. n sites from bench/site_distributions.h (the same sites as mwvd_bench for the same --n,
//      --dist and --seed), written as covmap.sites/1 JSON (not timed);
//   2. read_sites            (the public reader: fast path, reference on a miss; and the same
//                            sites as CSV, read_sites_csv)
//   3. engine                (voronoi::build_diagram)
//   4. write_diagram_json    (to a file through std::ofstream; then as `covmap diagram` writes it,
//                            streamed into an io::StagedFiles temporary and renamed into place),
//                            and diagram_json_text (the whole text in memory)
//   5. read_diagram_json     (the public reader, ArcLabels::kRequired)
//   and, for comparison on the same text in memory: the public readers again, the reference
//   (nlohmann DOM) readers of both files, and nlohmann's SAX parser with a handler that does
//   nothing (the floor for any SAX-based reader).
// Each phase's time and peak RSS (VmHWM reset before it) are reported; nothing is asserted.
//   io_bench --n 1e4,1e5,1e6 --json [--keep DIR]   (--keep leaves sites_N.json there, for
//   `/usr/bin/time -v covmap diagram DIR/sites_N.json -o ...` end to end on the same sites)
// With --map FILE (GeoJSON coverage maps, e.g. from covmap-make-map; --planar for x/y maps) the rows
// are those maps instead: the public reader on the text in memory, its two first passes apart
// (fast, reference) and the rest of the reader on one worker and on the machine's cores
// (io/coverage_map_drafts.h; `covmap audit`'s stage "reading map and sensors" is mostly this), and
// the reported sensors of a sensors.geojson beside the map.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <ctime>
#include <unistd.h>

#include "bench/count_argument.h"
#include "bench/isolated_run.h"
#include "bench/site_distributions.h"
#include "core/round_trip_numbers.h"
#include "io/atomic_file.h"
#include "io/coverage_map.h"
#include "io/coverage_map_drafts.h"
#include "io/reported_sensors.h"
#include "io/diagram_json.h"
#include "io/fast_readers.h"
#include "io/site_parsers.h"
#include "io/sites_io.h"
#include "io/text_util.h"
#include "voronoi/engine.h"

namespace {

namespace bench = covmap::bench;
namespace io = covmap::io;
namespace fs = std::filesystem;
using json = nlohmann::json;
using Clock = std::chrono::steady_clock;

struct Options {
  std::vector<std::string> sizes = {"1e4", "1e5"};
  std::string distribution = "uniform12";
  std::uint64_t seed = 1;
  std::string keep;  // directory for the sites files; empty: a temporary one, removed
  bool reference = true;
  bool json = false;
  std::vector<std::string> maps;  // coverage maps to time instead of the site rows
  bool planar = false;            // the maps are planar (covmap audit --planar)
};

json optional_kib(std::optional<long> kib) { return kib ? json(*kib) : json(nullptr); }

// CPU time of this process (user + system: page faults count), steadier than wall time on a
// shared machine; the engine and the graph writers use both cores, so their CPU time is the sum.
double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// Runs `body` as phase `name`: its wall and CPU time and the peak RSS while it ran go into the row.
template <class Body>
auto phase(json& row, const std::string& name, Body&& body) {
  bench::reset_peak_rss();
  const double cpu_start = process_cpu_seconds();
  const auto start = Clock::now();
  auto result = body();
  row[name + "_seconds"] = std::chrono::duration<double>(Clock::now() - start).count();
  row[name + "_cpu_seconds"] = process_cpu_seconds() - cpu_start;
  row[name + "_peak_rss_kib"] = optional_kib(bench::peak_rss_kib());
  return result;
}

// nlohmann's SAX interface with every event ignored: what a SAX reader costs before doing anything.
struct NullSax : nlohmann::json_sax<json> {
  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t) override { return true; }
  bool number_unsigned(number_unsigned_t) override { return true; }
  bool number_float(number_float_t, const string_t&) override { return true; }
  bool string(string_t&) override { return true; }
  bool binary(binary_t&) override { return true; }
  bool start_object(std::size_t) override { return true; }
  bool key(string_t&) override { return true; }
  bool end_object() override { return true; }
  bool start_array(std::size_t) override { return true; }
  bool end_array() override { return true; }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override { return false; }
};

// The readers alone, on text already in memory (no file reading), each after the others have warmed
// the allocator: the public (fast path) readers, the reference readers, and the SAX floor.
void parser_phases(json& row, const fs::path& sites_file, const fs::path& graph_file) {
  const std::string sites_text = io::detail::read_text_file(sites_file);
  const std::string graph_text = io::detail::read_text_file(graph_file);
  phase(row, "reference_parse_sites", [&] { return io::detail::parse_sites_json(sites_text, "s").sites.size(); });
  phase(row, "parse_sites", [&] { return io::parse_sites(sites_text, "s.json").sites.size(); });
  phase(row, "reference_parse_graph", [&] {
    return io::detail::parse_diagram_json_reference(graph_text, "g", io::ArcLabels::kRequired).arcs.size();
  });
  phase(row, "parse_graph", [&] { return io::parse_diagram_json(graph_text, "g").arcs.size(); });
  phase(row, "sax_null_parse_graph", [&] {
    NullSax sax;
    return json::sax_parse(graph_text, &sax);
  });
}

// The same sites as CSV (id,x,y,weight), numbers as in the JSON file.
void write_sites_csv(const std::vector<covmap::Site>& sites, const fs::path& file) {
  std::string text = "id,x,y,weight\n";
  for (const auto& s : sites) {
    text += s.id;
    for (const double v : {s.x, s.y, s.weight}) {
      text += ',';
      covmap::append_json_number(text, v);
    }
    text += '\n';
  }
  std::ofstream(file, std::ios::binary) << text;
}

std::string measure_row(std::size_t n, const bench::Distribution& dist, const Options& options, const fs::path& dir) {
  json row = {{"n", n}, {"dist", dist.name()}, {"seed", options.seed}};
  const fs::path sites_file = dir / ("sites_" + std::to_string(n) + ".json");
  const fs::path graph_file = dir / ("graph_" + std::to_string(n) + ".json");
  const fs::path csv_file = dir / ("sites_" + std::to_string(n) + ".csv");
  {
    const auto sites = bench::make_sites(n, dist, options.seed);
    std::ofstream out(sites_file, std::ios::binary);
    io::write_sites_json(sites, out);
    write_sites_csv(sites, csv_file);
  }
  phase(row, "read_sites_csv", [&] { return io::read_sites(csv_file).sites.size(); });
  const auto table = phase(row, "read_sites", [&] { return io::read_sites(sites_file); });
  const auto diagram = phase(row, "engine", [&] { return covmap::voronoi::build_diagram(table.sites); });
  phase(row, "write_graph", [&] {
    std::ofstream out(graph_file, std::ios::binary);
    io::write_diagram_json(diagram, out);
    out.close();
    return out.good();
  });
  // As `covmap diagram` writes it: streamed into the temporary of an all-or-nothing write, which is
  // then renamed into place (io/atomic_file.h).
  const fs::path staged_file = dir / ("staged_graph_" + std::to_string(n) + ".json");
  phase(row, "write_graph_staged", [&] {
    io::StagedFiles outputs;
    outputs.stage(staged_file, [&diagram](std::ostream& out) { io::write_diagram_json(diagram, out); });
    outputs.commit();
    return true;
  });
  if (fs::file_size(staged_file) != fs::file_size(graph_file)) throw std::runtime_error("the staged graph differs");
  fs::remove(staged_file);
  // The whole text in memory (diagram_json_text), for callers that need it as one string.
  phase(row, "render_graph_text", [&] { return io::diagram_json_text(diagram).size(); });
  const auto back = phase(row, "read_graph", [&] { return io::read_diagram_json(graph_file); });
  if (back.arcs.size() != diagram.arcs.size()) throw std::runtime_error("the graph read back differs");
  row["sites_bytes"] = fs::file_size(sites_file);
  row["graph_bytes"] = fs::file_size(graph_file);
  row["arcs"] = diagram.arcs.size();
  const auto seconds = [&](const char* key) { return row[std::string(key) + "_seconds"].get<double>(); };
  // What `covmap diagram` adds to the engine, as a fraction of the engine's time: reading the sites
  // and writing the graph as it does (streamed into the atomic write's temporary).
  row["cli_io_over_engine"] = (seconds("read_sites") + seconds("write_graph_staged")) / seconds("engine");
  // The same with the text rendered in memory instead (how this ratio was defined before the CLI
  // streamed its output; kept so that rows stay comparable with earlier ones).
  row["diagram_io_over_engine"] = (seconds("read_sites") + seconds("render_graph_text")) / seconds("engine");
  if (options.reference) parser_phases(row, sites_file, graph_file);
  fs::remove(graph_file);
  if (options.keep.empty()) {
    fs::remove(sites_file);
    fs::remove(csv_file);
  }
  return row.dump();
}

// One coverage map: the public reader, then its parts on the same text (each first pass's drafts
// are used by the following phase, so nothing is read twice from the file).
std::string measure_map_row(const fs::path& file, bool planar) {
  json row = {{"map", file.string()}, {"map_bytes", fs::file_size(file)}};
  const std::string text = io::detail::read_text_file(file);
  io::CoverageMapOptions options;
  options.planar = planar;
  const auto map = phase(row, "parse_map", [&] { return io::parse_coverage_map(text, "m", options); });
  row["cells"] = map.cells.size();
  row["vertices"] = map.vertex_count;
  auto fast = phase(row, "map_first_pass_fast", [&] { return io::detail::read_features_fast(text, options); });
  if (!fast) throw std::runtime_error("the fast path missed " + file.string());
  auto reference = phase(row, "map_first_pass_reference", [&] { return io::detail::read_features_reference(text, "m", options); });
  phase(row, "map_rest_one_worker", [&] { return io::detail::finish_coverage_map(std::move(reference), "m", options, 1).cells.size(); });
  phase(row, "map_rest", [&] { return io::detail::finish_coverage_map(std::move(*fast), "m", options).cells.size(); });
  // The reported sensors beside the map (covmap-make-map writes them there), placed through its frame.
  if (const fs::path sensors_file = file.parent_path() / "sensors.geojson"; fs::exists(sensors_file)) {
    const std::string sensors_text = io::detail::read_text_file(sensors_file);
    io::ReportedSensorOptions so;
    so.planar = planar;
    so.frame = map.frame.get();
    so.alpha = 3.5;
    phase(row, "parse_sensors", [&] {
      return io::parse_reported_sensors(sensors_text, "s", so, io::SensorsFormat::kGeoJson).size();
    });
  }
  return row.dump();
}

void print_map_row(const json& row) {
  const auto s = [&](const char* key) { return row.contains(key) ? row[key].get<double>() : -1.0; };
  std::printf("%s  parse map %.3f s  first pass fast %.3f s (reference %.3f s)  rest %.3f s (one worker %.3f s)"
              "  parse sensors %.3f s\n",
              row["map"].get<std::string>().c_str(), s("parse_map_seconds"), s("map_first_pass_fast_seconds"),
              s("map_first_pass_reference_seconds"), s("map_rest_seconds"), s("map_rest_one_worker_seconds"),
              s("parse_sensors_seconds"));
}

int run_maps(const Options& options) {
  int failures = 0;
  for (const auto& file : options.maps) {
    const auto result = bench::run_isolated([&] { return measure_map_row(file, options.planar); });
    json row = result.ok ? json::parse(result.output) : json{{"map", file}, {"error", result.failure}};
    row["process_peak_rss_kib"] = result.peak_rss_kib;
    failures += result.ok ? 0 : 1;
    if (options.json) std::cout << row.dump() << std::endl;
    else if (result.ok) print_map_row(row);
    else std::printf("%s FAILED: %s\n", file.c_str(), result.failure.c_str());
  }
  return failures == 0 ? 0 : 1;
}

void print_row(const json& row) {
  const auto s = [&](const char* key) { return row.contains(key) ? row[key].get<double>() : -1.0; };
  std::printf("%8zu  read sites %.3f s  engine %.3f s  write graph %.3f s (staged %.3f s)  text %.3f s  read graph %.3f s"
              "  (io/engine %.2f, text %.2f)  read sites CSV %.3f s\n"
              "          in memory: parse sites %.3f s (reference %.3f s)  parse graph %.3f s (reference %.3f s,"
              " SAX no-op %.3f s)\n",
              row["n"].get<std::size_t>(), s("read_sites_seconds"), s("engine_seconds"), s("write_graph_seconds"),
              s("write_graph_staged_seconds"), s("render_graph_text_seconds"), s("read_graph_seconds"),
              s("cli_io_over_engine"), s("diagram_io_over_engine"),
              s("read_sites_csv_seconds"), s("parse_sites_seconds"), s("reference_parse_sites_seconds"),
              s("parse_graph_seconds"), s("reference_parse_graph_seconds"), s("sax_null_parse_graph_seconds"));
}

int run(const Options& options) {
  if (!options.maps.empty()) return run_maps(options);
  std::string error;
  const auto dist = bench::parse_distribution(options.distribution, &error);
  if (!dist) throw CLI::ValidationError("--dist", error);
  const fs::path dir = options.keep.empty() ? fs::temp_directory_path() / ("io_bench_" + std::to_string(getpid()))
                                            : fs::path(options.keep);
  fs::create_directories(dir);
  int failures = 0;
  for (const auto& size : options.sizes) {
    const std::size_t n = bench::parse_count(size, 3, "--n", "a site count");
    const auto result = bench::run_isolated([&] { return measure_row(n, *dist, options, dir); });
    json row = result.ok ? json::parse(result.output) : json{{"n", n}, {"error", result.failure}};
    row["process_peak_rss_kib"] = result.peak_rss_kib;
    failures += result.ok ? 0 : 1;
    if (options.json) std::cout << row.dump() << std::endl;
    else if (result.ok) print_row(row);
    else std::printf("%8zu FAILED: %s\n", n, result.failure.c_str());
  }
  if (options.keep.empty()) fs::remove_all(dir);
  return failures == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"io_bench: time reading sites, the engine, writing and reading the arc graph"};
  Options options;
  app.add_option("--n", options.sizes, "site counts, comma separated (1e4,1e5,1e6)")->delimiter(',')->capture_default_str();
  app.add_option("--dist", options.distribution, "weight distribution (as mwvd_bench)")->capture_default_str();
  app.add_option("--seed", options.seed, "random seed (as mwvd_bench)")->capture_default_str();
  app.add_option("--keep", options.keep, "keep the sites files in this directory");
  app.add_flag("!--no-reference", options.reference, "skip the reference readers and the SAX floor");
  app.add_option("--map", options.maps, "time reading these GeoJSON coverage maps instead of the site rows (comma separated)")
      ->delimiter(',');
  app.add_flag("--planar", options.planar, "the --map files are planar (as covmap audit --planar)");
  app.add_flag("--json", options.json, "one JSON object per row (JSON Lines) instead of a table");
  CLI11_PARSE(app, argc, argv);
  try {
    return run(options);
  } catch (const CLI::Error& e) {
    return app.exit(e);
  }
}
