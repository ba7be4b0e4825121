// A sensor's human name flows from the files to report.json: the generator writes each town's name
// into map.geojson and sensors.geojson, io reads both back, the audit prefers the operator's name
// to the map's, and report.json carries it (null when neither file names the sensor). Oracle: the
// names this test gave the towns and then changed or removed in the reported list.
#include <gtest/gtest.h>

#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "generated_map_audit.h"
#include "report/audit_report.h"

namespace covmap {
namespace {

using namespace covmap::testing;

std::string town_name(const std::string& id) { return "Städtli " + id; }  // not ASCII on purpose

TEST(SensorNames, ReportJsonGivesTheReportedNameElseTheMapsNameElseNull) {
  // Random sensors put on the ground about Bern, each named after its id.
  const io::LocalProjection plane = io::LocalProjection::about(7.45, 46.95);
  std::vector<mapgen::LonLatSite> towns;
  for (const Site& s : sensors(12, 31)) {
    const io::LonLat g = plane.inverse({s.x, s.y});
    towns.push_back({.id = s.id, .lon = g.lon, .lat = g.lat, .weight = s.weight, .name = town_name(s.id)});
  }
  mapgen::CoverageMapOptions options = base_options(7);
  options.frame = mapgen::OutputFrame::kLonLat;
  options.coordinate_digits.reset();  // degrees to 6 decimals, not base_options' decimetres
  options.errors.gross_fraction = 0.0;
  std::vector<ReportedSensor> reported;
  AuditRun r = generate_and_read(options, towns, 3.5, reported);
  ASSERT_EQ(reported.size(), towns.size());
  for (const ReportedSensor& s : reported) EXPECT_EQ(s.name, town_name(s.id));
  std::map<std::string, bool> in_map;
  for (const CoverageCell& c : r.map.cells) {
    EXPECT_EQ(c.name, town_name(c.sensor));
    in_map[c.sensor] = true;
  }

  // The operator renames every third sensor and leaves every third unnamed; one more sensor is
  // reported far outside the map with a name of its own.
  std::map<std::string, std::optional<std::string>> expected;
  for (std::size_t k = 0; k < reported.size(); ++k) {
    ReportedSensor& s = reported[k];
    if (k % 3 == 0) s.name = "Operator " + s.id;
    if (k % 3 == 1) s.name.clear();
    expected[s.id] = !s.name.empty() ? std::optional(s.name) : in_map[s.id] ? std::optional(town_name(s.id)) : std::nullopt;
  }
  ReportedSensor outside = reported.front();
  outside.id = "outside";
  outside.name = "Hinterland";
  outside.position = {outside.position.x + 200'000.0, outside.position.y};
  reported.push_back(outside);
  expected["outside"] = "Hinterland";

  audit::AuditOptions ao;
  ao.alpha = 3.5;
  const audit::AuditResult result = audit::audit(r.map.cells, reported, ao);
  std::ostringstream text;
  report::write_audit_json({.result = result, .map = r.map, .map_file = "map.geojson", .sensors_file = "sensors.geojson",
                            .alpha = 3.5, .command_line = "covmap audit", .options = &ao},
                           text);
  const nlohmann::json report = nlohmann::json::parse(text.str());
  ASSERT_EQ(report["sensors"].size(), expected.size());
  int from_map = 0;
  for (const auto& s : report["sensors"]) {
    const std::string id = s["id"];
    const auto& want = expected.at(id);
    EXPECT_EQ(s["name"], want ? nlohmann::json(*want) : nlohmann::json()) << id;
    if (want && *want == town_name(id) && s["reported"]["name"].is_null()) ++from_map;
  }
  EXPECT_GE(from_map, 3) << "too few sensors named by the map alone to test it";
}

}  // namespace
}  // namespace covmap
