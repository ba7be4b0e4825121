// Sensors reported but absent from the map are judged by prediction (issue 12): put among the
// refined sensors at their reported position and power, would they serve part of the map? Oracle:
// the generator's truth — a sensor dominated by a strong neighbour really has no bin, so its
// correct report must agree with the map; a sensor whose cell is cut out of the map really serves
// its bins, so the map contradicts its report.
#include <gtest/gtest.h>

#include <algorithm>

#include "generated_map_audit.h"

namespace covmap {
namespace {

using namespace covmap::testing;

const audit::SensorAudit& audited(const audit::AuditResult& r, const std::string& id) {
  const auto it = std::find_if(r.sensors.begin(), r.sensors.end(), [&](const auto& s) { return s.id == id; });
  if (it == r.sensors.end()) throw std::runtime_error("no audit of " + id);
  return *it;
}

TEST(AbsentSensor, DominatedSensorAgreesAndMissingCellContradicts) {
  std::vector<Site> sites = sensors(40, 21);
  // A weak sensor 300 m from a strong one: the strong one's bisector circle around it has a radius
  // of about 300 · 0.05 / (1 − 0.05²) ≈ 15 m, far below a 100 m bin: no bin is its.
  const Site& strong = *std::max_element(sites.begin(), sites.end(), [](const Site& a, const Site& b) { return a.weight < b.weight; });
  sites.push_back({"weak", strong.x + 300.0, strong.y, 0.05 * strong.weight});
  mapgen::CoverageMapOptions options = base_options(4);
  options.errors.gross_fraction = 0.0;
  std::vector<ReportedSensor> reported;
  AuditRun r = generate_and_read(options, sites, 3.5, reported);
  const auto weak = std::find_if(r.generated.truth.begin(), r.generated.truth.end(), [](const auto& t) { return t.id == "weak"; });
  ASSERT_EQ(weak->bins, 0u) << "the weak sensor should be dominated";

  // Cut a sensor with a large cell out of the map: it is reported, serves its bins, but has no cell.
  const auto cut = std::max_element(r.generated.truth.begin(), r.generated.truth.end() - 1,
                                    [](const auto& a, const auto& b) { return a.bins < b.bins; });
  std::erase_if(r.map.cells, [&](const CoverageCell& c) { return c.sensor == cut->id; });
  audit::AuditOptions ao;
  ao.alpha = 3.5;
  const audit::AuditResult result = audit::audit(r.map.cells, reported, ao);

  const audit::SensorAudit& w = audited(result, "weak");
  EXPECT_FALSE(w.in_map);
  EXPECT_EQ(w.verdict, audit::SensorVerdict::kConsistent) << w.reason;
  const audit::SensorAudit& c = audited(result, cut->id);
  EXPECT_FALSE(c.in_map);
  EXPECT_EQ(c.verdict, audit::SensorVerdict::kInconsistent) << c.reason;
}

TEST(AbsentSensor, WithoutAPowerTheCellCannotBePredicted) {
  const std::vector<Site> sites = sensors(20, 22);
  std::vector<ReportedSensor> reported;
  mapgen::CoverageMapOptions options = base_options(5);
  options.errors.gross_fraction = 0.0;
  AuditRun r = generate_and_read(options, sites, 3.5, reported);
  ReportedSensor extra;
  extra.id = "extra";
  extra.position = reported.front().position;
  reported.push_back(extra);
  audit::AuditOptions ao;
  ao.alpha = 3.5;
  const audit::AuditResult result = audit::audit(r.map.cells, reported, ao);
  EXPECT_EQ(audited(result, "extra").verdict, audit::SensorVerdict::kNotInMap);
}

}  // namespace
}  // namespace covmap
