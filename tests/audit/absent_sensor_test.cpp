// Sensors reported but absent from the map are judged by prediction: put among the
// refined sensors at their reported position and power, would they serve part of the map? Oracle:
// the generator's truth — a sensor dominated by a strong neighbour really has no bin, so its
// correct report must agree with the map; a sensor whose cell is cut out of the map really serves
// its bins, so the map contradicts its report.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "generated_map_audit.h"

namespace covmap {
namespace {

using namespace covmap::testing;

const audit::SensorAudit& audited(const audit::AuditResult& r, const std::string& id) {
  const auto it = std::find_if(r.sensors.begin(), r.sensors.end(), [&](const auto& s) { return s.id == id; });
  if (it == r.sensors.end()) throw std::runtime_error("no audit of " + id);
  return *it;
}

TEST(AbsentSensor, DominatedSensorAgreesAndUndrawnSensorContradicts) {
  std::vector<Site> sites = sensors(40, 21);
  // A weak sensor 300 m from a strong one: the strong one's bisector circle around it has a radius
  // of about 300 · 0.05 / (1 − 0.05²) ≈ 15 m, far below a 100 m bin: no bin is its.
  const Site& strong = *std::max_element(sites.begin(), sites.end(), [](const Site& a, const Site& b) { return a.weight < b.weight; });
  sites.push_back({"weak", strong.x + 300.0, strong.y, 0.05 * strong.weight});
  // A sensor the map's maker did not know (the map was drawn without it), reported with its true
  // position and power: it would serve its own cell, which the map gives to its neighbours.
  const Site undrawn = sites[7];
  std::vector<Site> drawn = sites;
  drawn.erase(drawn.begin() + 7);
  mapgen::CoverageMapOptions options = base_options(4);
  options.errors.gross_fraction = 0.0;
  std::vector<ReportedSensor> reported;
  AuditRun r = generate_and_read(options, drawn, 3.5, reported);
  const auto weak = std::find_if(r.generated.truth.begin(), r.generated.truth.end(), [](const auto& t) { return t.id == "weak"; });
  ASSERT_EQ(weak->bins, 0u) << "the weak sensor should be dominated";
  // Its reported power in the map's scale: the generator's weights are scaled so the strongest is 1,
  // with tx_power = 10·α·log10(weight) + 43 dBm.
  double top = 0.0;
  for (const Site& s : drawn) top = std::max(top, s.weight);
  ReportedSensor extra;
  extra.id = undrawn.id;
  extra.position = {undrawn.x, undrawn.y};
  extra.tx_power_dbm = 43.0 + 35.0 * std::log10(undrawn.weight / top);
  reported.push_back(extra);
  audit::AuditOptions ao;
  ao.alpha = 3.5;
  const audit::AuditResult result = audit::audit(r.map.cells, reported, ao);

  const audit::SensorAudit& w = audited(result, "weak");
  EXPECT_FALSE(w.in_map);
  EXPECT_EQ(w.verdict, audit::SensorVerdict::kConsistent) << w.reason;
  EXPECT_EQ(w.basis, audit::VerdictBasis::kPrediction);
  const audit::SensorAudit& u = audited(result, undrawn.id);
  EXPECT_FALSE(u.in_map);
  EXPECT_EQ(u.verdict, audit::SensorVerdict::kInconsistent) << u.reason;
  EXPECT_FALSE(result.model_fit.misfit);
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
