// report.json, sensors.geojson and diagram.geojson, read back with nlohmann::json and checked
// against the hand-made audit (audit_test_fixture.h), the projection, and brute force.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "report/audit_report.h"
#include "../io/io_test_util.h"
#include "audit_test_fixture.h"

namespace covmap::report {
namespace {

using nlohmann::json;
using testing::AuditFixture;
using testing::audit_fixture;
using testing::context_of;
using testing::kFrameArea;
using testing::ring_area;

json audit_json(const AuditReportContext& c) {
  std::ostringstream out;
  write_audit_json(c, out);
  return json::parse(out.str());
}

json sensors_geojson(const AuditReportContext& c) {
  std::ostringstream out;
  write_sensors_geojson(c, out);
  return json::parse(out.str());
}

json shifts_geojson(const AuditReportContext& c) {
  std::ostringstream out;
  write_shifts_geojson(c, out);
  return json::parse(out.str());
}

json diagram_geojson(const AuditReportContext& c) {
  std::ostringstream out;
  write_diagram_geojson(c, out);
  return json::parse(out.str());
}

// Planar position of a GeoJSON/JSON [lon, lat] through the map's projection (the oracle for the
// writers' inverse projection).
Point forward(const io::CoverageMap& map, double lon, double lat) { return map.frame->forward(lon, lat); }

std::vector<json> features_of_kind(const json& collection, const std::string& kind) {
  std::vector<json> out;
  for (const auto& f : collection["features"]) {
    if (f["properties"]["kind"] == kind) out.push_back(f);
  }
  return out;
}

// ---------------------------------------------------------------------------------- report.json

TEST(AuditJson, TopLevelMembersAndCounts) {
  const AuditFixture f = audit_fixture(true);
  const json j = audit_json(context_of(f));
  EXPECT_EQ(j["format"], "covmap.audit/1");
  EXPECT_EQ(j["map"]["file"], "maps/city.geojson");
  EXPECT_EQ(j["map"]["coordinates"], "lonlat");
  EXPECT_EQ(j["map"]["cells"], 4);
  EXPECT_EQ(j["map"]["projection"]["lon0"], 8.0);
  EXPECT_EQ(j["map"]["projection"]["lat0"], 47.1);
  EXPECT_EQ(j["map"]["projection"]["max_scale_distortion"], 1.25e-8);
  EXPECT_EQ(j["map"]["projection"]["description"], f.map.frame->description());
  EXPECT_EQ(j["sensors_file"], "sensors.csv");
  EXPECT_EQ(j["alpha"], 3.5);
  EXPECT_EQ(j["command_line"], context_of(f).command_line);

  // The fixture has two consistent sensors (a, d), one inconsistent (b), one unreported (c) and one
  // reported sensor absent from the map (e).
  const json& s = j["summary"];
  EXPECT_EQ(s["sensors"], 5);
  EXPECT_EQ(s["in_map"], 4);
  EXPECT_EQ(s["reported"], 4);
  EXPECT_EQ(s["consistent"], 2);
  EXPECT_EQ(s["inconsistent"], 1);
  EXPECT_EQ(s["not_in_map"], 1);
  EXPECT_EQ(s["unreported"], 1);

  const json& k = j["cleaning"];
  EXPECT_EQ(k["junctions_merged"], 2);
  EXPECT_EQ(k["gaps_closed"], 3);
  EXPECT_EQ(k["overlaps_resolved"], 5);
  EXPECT_EQ(k["short_chains_dropped"], 7);
  EXPECT_EQ(k["nodes_snapped"], 11);
  EXPECT_EQ(k["repairs"], 2 + 3 + 5 + 7 + 11);
  EXPECT_EQ(k["snap_distance_m"], 15.0);
  EXPECT_EQ(k["chains"], 9);

  EXPECT_EQ(j["bin_size_m"], 10.0);
  EXPECT_EQ(j["boundary_samples"], 1234);
  EXPECT_EQ(j["refinement"], "converged after 12 iterations");
  EXPECT_EQ(j["agreement"]["refined"]["mean_iou"], 0.975);
  EXPECT_EQ(j["agreement"]["refined"]["hausdorff_m"], 12.5);
  EXPECT_EQ(j["agreement"]["refined"]["appeared"], json::array({"ghost"}));
  EXPECT_EQ(j["agreement"]["refined"]["vanished"], json::array());
  EXPECT_EQ(j["agreement"]["reported"]["mean_iou"], 0.91);
  EXPECT_EQ(j["agreement"]["reported"]["vanished"], json::array({"c"}));
  EXPECT_EQ(j["thresholds"]["inconsistency_chi2"], 16.27);
  EXPECT_EQ(j["thresholds"]["position_floor_m"], 5.0);
  EXPECT_EQ(j["thresholds"]["power_floor_db"], 0.5);
  EXPECT_EQ(j["messages"].size(), 2u);
  EXPECT_EQ(j["timings"]["seconds"], 0.75);
  ASSERT_EQ(j["timings"]["stages"].size(), f.result.timings.size());
  EXPECT_EQ(j["timings"]["stages"][0]["stage"], f.result.timings[0].stage);
  EXPECT_EQ(j["timings"]["stages"][0]["seconds"], f.result.timings[0].seconds);
}

TEST(AuditJson, SensorsCarryReconstructionReportAndComparison) {
  const AuditFixture f = audit_fixture(true);
  const json j = audit_json(context_of(f));
  ASSERT_EQ(j["sensors"].size(), f.result.sensors.size());
  for (std::size_t i = 0; i < f.result.sensors.size(); ++i) {
    const auto& want = f.result.sensors[i];
    const json& got = j["sensors"][i];
    SCOPED_TRACE(want.id);
    EXPECT_EQ(got["id"], want.id);
    EXPECT_EQ(got["in_map"], want.in_map);
    if (want.in_map) {
      EXPECT_EQ(got["x"].get<double>(), want.position.x);
      EXPECT_EQ(got["y"].get<double>(), want.position.y);
      const Point back = forward(f.map, got["lon"], got["lat"]);
      EXPECT_NEAR(back.x, want.position.x, 1e-6);
      EXPECT_NEAR(back.y, want.position.y, 1e-6);
      EXPECT_EQ(got["weight"].get<double>(), want.weight);
    } else {
      EXPECT_TRUE(got["x"].is_null() && got["lon"].is_null() && got["weight"].is_null());
    }
    if (want.reported) {
      const json& r = got["reported"];
      EXPECT_EQ(r["x"].get<double>(), want.reported->position.x);
      const Point back = forward(f.map, r["lon"], r["lat"]);
      EXPECT_NEAR(back.x, want.reported->position.x, 1e-6);
      EXPECT_NEAR(back.y, want.reported->position.y, 1e-6);
      EXPECT_EQ(r["weight"].get<double>(), *want.reported->weight);
      EXPECT_EQ(got["verdict"], audit::to_string(want.verdict));
      EXPECT_EQ(got["reason"], want.reason);
    } else {
      EXPECT_TRUE(got["reported"].is_null());
      EXPECT_TRUE(got["verdict"].is_null());
      EXPECT_TRUE(got["chi2"].is_null());
      EXPECT_TRUE(got["position_error_m"].is_null());
    }
  }
  const json& a = j["sensors"][0];
  EXPECT_EQ(a["tx_power_dbm"], 30.0);
  EXPECT_EQ(a["sigma_position_m"], 4.5);
  EXPECT_EQ(a["sigma_x_m"], 3.0);
  EXPECT_EQ(a["cov_xy_m2"], 1.5);
  EXPECT_EQ(a["sigma_log_weight"], 0.05);
  EXPECT_EQ(a["reported"]["tx_power_dbm"], 30.5);
  EXPECT_EQ(a["reported"]["position_sigma_m"], 10.0);
  EXPECT_EQ(a["reported"]["power_sigma_db"], 1.0);
  EXPECT_EQ(a["position_error_m"], 5.0);
  EXPECT_EQ(a["power_error_db"], 0.5);
  EXPECT_EQ(a["weight_ratio"], 1.08);
  EXPECT_EQ(a["chi2"], 1.25);
  EXPECT_EQ(a["iou_refined"], 0.98);
  EXPECT_EQ(a["iou_reported"], 0.95);
  const json& b = j["sensors"][1];
  EXPECT_EQ(b["verdict"], "inconsistent");
  EXPECT_EQ(b["chi2"], 412.0);
  EXPECT_TRUE(b["reported"]["position_sigma_m"].is_null());
  const json& c = j["sensors"][2];  // unreported, no uncertainty
  EXPECT_FALSE(c["uncertainty_available"].get<bool>());
  EXPECT_TRUE(c["sigma_position_m"].is_null());
  EXPECT_TRUE(c["tx_power_dbm"].is_null());
  EXPECT_TRUE(c["iou_reported"].is_null());
  const json& e = j["sensors"][4];  // reported only: no comparison
  EXPECT_EQ(e["verdict"], "not_in_map");
  EXPECT_TRUE(e["chi2"].is_null());
  EXPECT_EQ(e["reported"]["x"], 50.0);
}

TEST(AuditJson, NamesAreWrittenAsGivenAndNullWhenEmpty) {
  AuditFixture f = audit_fixture(false);
  ASSERT_TRUE(f.result.sensors[0].reported.has_value());
  f.result.sensors[0].name = "Zollikofen";
  f.result.sensors[0].reported->name = "Zollikofen";
  f.result.sensors[2].name = "Münsingen";  // e.g. a name from the map only (c is unreported)
  const json j = audit_json(context_of(f));
  const json g = sensors_geojson(context_of(f));
  const auto points = features_of_kind(g, "sensor");
  ASSERT_EQ(j["sensors"].size(), f.result.sensors.size());
  ASSERT_EQ(points.size(), f.result.sensors.size());
  for (std::size_t i = 0; i < f.result.sensors.size(); ++i) {
    SCOPED_TRACE(f.result.sensors[i].id);
    const json want = i == 0 ? json("Zollikofen") : i == 2 ? json("Münsingen") : json();
    EXPECT_EQ(j["sensors"][i]["name"], want);
    EXPECT_EQ(points[i]["properties"]["name"], want);
    const json& reported = j["sensors"][i]["reported"];
    if (!reported.is_null()) {
      EXPECT_EQ(reported["name"], i == 0 ? json("Zollikofen") : json());
    }
  }
}

// The summary counts every verdict, undetermined sensors included (not lumped as "other"), so its
// verdict counts add up. Every verdict of the enumeration is a member, counted here by hand.
TEST(AuditJson, SummaryCountsEveryVerdictAndAddsUp) {
  const AuditFixture f = testing::audit_fixture_with_undetermined(true);
  const json s = audit_json(context_of(f))["summary"];
  EXPECT_FALSE(s.contains("other"));
  std::size_t total = 0;
  for (const audit::SensorVerdict v : audit::kAllSensorVerdicts) {
    const std::string name(audit::to_string(v));
    ASSERT_TRUE(s.contains(name)) << name;
    const auto want = std::count_if(f.result.sensors.begin(), f.result.sensors.end(),
                                    [&](const audit::SensorAudit& a) { return a.verdict == v; });
    EXPECT_EQ(s[name].get<std::size_t>(), static_cast<std::size_t>(want)) << name;
    total += s[name].get<std::size_t>();
  }
  EXPECT_EQ(s["undetermined"], 1);
  EXPECT_EQ(s["sensors"], 6);
  EXPECT_EQ(total, s["sensors"].get<std::size_t>());
  EXPECT_EQ(s["in_map"], 5);
  EXPECT_EQ(s["reported"], 5);
}

// An undetermined sensor's χ² is never computed, so it is null, not 0.0, in
// report.json and sensors.geojson alike, while the other numbers of its comparison are written.
TEST(AuditJson, ChiSquareOfAnUndeterminedSensorIsNull) {
  const AuditFixture f = testing::audit_fixture_with_undetermined(true);
  const json u = audit_json(context_of(f))["sensors"][4];
  ASSERT_EQ(u["id"], "u");
  EXPECT_EQ(u["verdict"], "undetermined");
  EXPECT_TRUE(u["chi2"].is_null());
  EXPECT_EQ(u["position_error_m"].get<double>(), std::hypot(10.0, 10.0));
  bool found = false;
  for (const auto& feature : features_of_kind(sensors_geojson(context_of(f)), "sensor")) {
    const json& p = feature["properties"];
    if (p["id"] == "u") {
      found = true;
      EXPECT_TRUE(p["chi2"].is_null());
      EXPECT_EQ(p["verdict"], "undetermined");
    } else if (p["id"] == "b") {
      EXPECT_EQ(p["chi2"], 412.0);  // judged: its χ² is written
    }
  }
  EXPECT_TRUE(found);
}

TEST(AuditCounts, EverySensorCountedOnceUnderItsVerdict) {
  const AuditFixture f = testing::audit_fixture_with_undetermined(false);
  const AuditVerdictCounts n = count_verdicts(f.result.sensors);
  std::size_t total = 0;
  for (const std::size_t k : n.by_verdict) total += k;
  EXPECT_EQ(total, f.result.sensors.size());
  EXPECT_EQ(n.of(audit::SensorVerdict::kConsistent), 2u);
  EXPECT_EQ(n.of(audit::SensorVerdict::kInconsistent), 1u);
  EXPECT_EQ(n.of(audit::SensorVerdict::kUndetermined), 1u);
  EXPECT_EQ(n.of(audit::SensorVerdict::kNotInMap), 1u);
  EXPECT_EQ(n.of(audit::SensorVerdict::kUnreported), 1u);
  // The text for people names every verdict with its count, zero counts included.
  const std::string text = verdict_counts_text(n);
  for (const audit::SensorVerdict v : audit::kAllSensorVerdicts)
    EXPECT_NE(text.find(std::to_string(n.of(v)) + " " + std::string(verdict_words(v))), std::string::npos) << text;
  const std::string none = verdict_counts_text(count_verdicts({}));
  for (const audit::SensorVerdict v : audit::kAllSensorVerdicts)
    EXPECT_NE(none.find("0 " + std::string(verdict_words(v))), std::string::npos) << none;
}

// Plain, distinct words for every verdict: no generic "other", none naming two verdicts.
TEST(AuditCounts, EveryVerdictHasItsOwnWords) {
  std::set<std::string> seen;
  for (const audit::SensorVerdict v : audit::kAllSensorVerdicts) {
    const std::string words(verdict_words(v));
    EXPECT_FALSE(words.empty());
    EXPECT_EQ(words.find("other"), std::string::npos) << words;
    EXPECT_TRUE(seen.insert(words).second) << words;
  }
}

TEST(AuditJson, PlanarMapHasNullLonLatAndProjection) {
  const AuditFixture f = audit_fixture(false);
  const json j = audit_json(context_of(f));
  EXPECT_EQ(j["map"]["coordinates"], "planar");
  EXPECT_TRUE(j["map"]["projection"].is_null());
  for (const auto& s : j["sensors"]) {
    EXPECT_TRUE(s["lon"].is_null());
    EXPECT_TRUE(s["lat"].is_null());
    if (!s["reported"].is_null()) {
      EXPECT_TRUE(s["reported"]["lon"].is_null());
    }
  }
}

TEST(AuditJson, DoublesRoundTripBitForBit) {
  AuditFixture f = audit_fixture(false);
  // Values with 17 significant digits, and ones needing every bit.
  f.result.sensors[0].position = {0.1 + 0.2, std::nextafter(1.0 / 3.0, 1.0)};
  f.result.sensors[0].weight = std::numeric_limits<double>::denorm_min();
  f.result.sensors[1].chi2 = 1e300 * 1.7;
  const json j = audit_json(context_of(f));
  EXPECT_EQ(std::bit_cast<std::uint64_t>(j["sensors"][0]["x"].get<double>()), std::bit_cast<std::uint64_t>(0.1 + 0.2));
  EXPECT_EQ(j["sensors"][0]["y"].get<double>(), std::nextafter(1.0 / 3.0, 1.0));
  EXPECT_EQ(j["sensors"][0]["weight"].get<double>(), std::numeric_limits<double>::denorm_min());
  EXPECT_EQ(j["sensors"][1]["chi2"].get<double>(), 1e300 * 1.7);
}

TEST(AuditJson, NonFiniteNumbersBecomeNull) {
  AuditFixture f = audit_fixture(true);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  f.result.sensors[0].sigma_position_m = nan;
  f.result.sensors[0].chi2 = inf;
  f.result.sensors[1].position = {nan, 3.0};
  f.result.sensors[1].power_error_db = -inf;
  f.result.seconds = nan;
  f.result.refined_agreement.hausdorff_m = inf;
  std::ostringstream out;
  write_audit_json(context_of(f), out);
  const std::string text = out.str();
  for (const char* bad : {"nan", "NaN", "inf", "Inf"}) EXPECT_EQ(text.find(bad), std::string::npos) << bad;
  const json j = json::parse(text);
  EXPECT_TRUE(j["sensors"][0]["sigma_position_m"].is_null());
  EXPECT_TRUE(j["sensors"][0]["chi2"].is_null());
  EXPECT_TRUE(j["sensors"][1]["x"].is_null());
  EXPECT_TRUE(j["sensors"][1]["lon"].is_null());  // no position, no geography
  EXPECT_EQ(j["sensors"][1]["y"], 3.0);
  EXPECT_TRUE(j["sensors"][1]["power_error_db"].is_null());
  EXPECT_TRUE(j["timings"]["seconds"].is_null());
  EXPECT_TRUE(j["agreement"]["refined"]["hausdorff_m"].is_null());
}

TEST(AuditJson, ThresholdsAreNullWithoutOptionsAndAlphaNullWithoutAlpha) {
  const AuditFixture f = audit_fixture(false);
  AuditReportContext c = context_of(f);
  c.options = nullptr;
  c.alpha.reset();
  c.sensors_file.clear();
  const json j = audit_json(c);
  EXPECT_TRUE(j["thresholds"].is_null());
  EXPECT_TRUE(j["alpha"].is_null());
  EXPECT_TRUE(j["sensors_file"].is_null());
}

TEST(AuditJson, IdsThatAreNotUtf8StillGiveValidJson) {
  AuditFixture f = audit_fixture(false);
  f.result.sensors[2].id = std::string("bad\xff\xfe id \"quoted\"\n");
  const json j = audit_json(context_of(f));
  EXPECT_EQ(j["sensors"][2]["id"], "bad\xEF\xBF\xBD\xEF\xBF\xBD id \"quoted\"\n");
}

TEST(AuditJson, InvalidRenderOptionsThrowBeforeWriting) {
  const AuditFixture f = audit_fixture(false);
  AuditReportContext c = context_of(f);
  c.render.arc_step_degrees = 0.0;
  std::ostringstream out;
  EXPECT_THROW(write_audit_json(c, out), std::invalid_argument);
  EXPECT_THROW(write_diagram_geojson(c, out), std::invalid_argument);
  EXPECT_TRUE(out.str().empty());
  std::string why;
  EXPECT_FALSE(c.render.is_valid(&why));
  EXPECT_NE(why.find("arc_step_degrees"), std::string::npos);
  EXPECT_TRUE(AuditRenderOptions{}.is_valid());
}

// ------------------------------------------------------------------------------ sensors.geojson

TEST(AuditSensorsGeoJson, PointsAtReconstructedPositionsInLonLat) {
  const AuditFixture f = audit_fixture(true);
  const json g = sensors_geojson(context_of(f));
  EXPECT_EQ(g["type"], "FeatureCollection");
  const auto points = features_of_kind(g, "sensor");
  ASSERT_EQ(points.size(), f.result.sensors.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto& want = f.result.sensors[i];
    const json& p = points[i];
    SCOPED_TRACE(want.id);
    EXPECT_EQ(p["type"], "Feature");
    EXPECT_EQ(p["geometry"]["type"], "Point");
    EXPECT_EQ(p["properties"]["id"], want.id);
    const double lon = p["geometry"]["coordinates"][0], lat = p["geometry"]["coordinates"][1];
    EXPECT_GE(lon, -180.0);
    EXPECT_LE(lon, 180.0);
    const Point at = want.in_map ? want.position : want.reported->position;
    const Point back = forward(f.map, lon, lat);
    EXPECT_NEAR(back.x, at.x, 1e-6);
    EXPECT_NEAR(back.y, at.y, 1e-6);
    EXPECT_EQ(p["properties"]["position_source"], want.in_map ? "reconstructed" : "reported");
    if (want.reported) {
      const Point reported = forward(f.map, p["properties"]["reported_lon"], p["properties"]["reported_lat"]);
      EXPECT_NEAR(reported.x, want.reported->position.x, 1e-6);
      EXPECT_NEAR(reported.y, want.reported->position.y, 1e-6);
      EXPECT_EQ(p["properties"]["verdict"], audit::to_string(want.verdict));
    } else {
      EXPECT_TRUE(p["properties"]["reported_lon"].is_null());
      EXPECT_TRUE(p["properties"]["verdict"].is_null());
    }
  }
  EXPECT_EQ(points[0]["properties"]["weight"], 0.25);
  EXPECT_EQ(points[0]["properties"]["tx_power_dbm"], 30.0);
  EXPECT_EQ(points[0]["properties"]["sigma_position_m"], 4.5);
  EXPECT_EQ(points[0]["properties"]["position_error_m"], 5.0);
  EXPECT_EQ(points[1]["properties"]["power_error_db"], 6.5);
  EXPECT_EQ(points[1]["properties"]["reason"], "moved 100 m where 2 m is expected");
}

TEST(AuditShiftsGeoJson, ShiftLinesRunFromReportedToReconstructed) {
  const AuditFixture f = audit_fixture(false);
  const json g = shifts_geojson(context_of(f));
  const auto shifts = features_of_kind(g, "shift");
  EXPECT_EQ(shifts.size(), g["features"].size());  // nothing else in the file
  // Reported and in the map: a, b, d.
  ASSERT_EQ(shifts.size(), 3u);
  std::map<std::string, const audit::SensorAudit*> by_id;
  for (const auto& s : f.result.sensors) by_id[s.id] = &s;
  for (const auto& line : shifts) {
    const auto& s = *by_id.at(line["properties"]["id"]);
    ASSERT_EQ(line["geometry"]["type"], "LineString");
    const json& xy = line["geometry"]["coordinates"];
    ASSERT_EQ(xy.size(), 2u);
    EXPECT_EQ(xy[0][0].get<double>(), s.reported->position.x);
    EXPECT_EQ(xy[0][1].get<double>(), s.reported->position.y);
    EXPECT_EQ(xy[1][0].get<double>(), s.position.x);
    EXPECT_EQ(xy[1][1].get<double>(), s.position.y);
    EXPECT_EQ(line["properties"]["verdict"], audit::to_string(s.verdict));
  }
  // sensors.geojson holds one geometry type (Points), so every GIS format takes it.
  for (const json& feature : sensors_geojson(context_of(f))["features"])
    EXPECT_TRUE(feature["geometry"].is_null() || feature["geometry"]["type"] == "Point") << feature.dump();
}

TEST(AuditSensorsGeoJson, PlanarMapsWritePlanarCoordinates) {
  const AuditFixture f = audit_fixture(false);
  const json g = sensors_geojson(context_of(f));
  const auto points = features_of_kind(g, "sensor");
  EXPECT_EQ(points[1]["geometry"]["coordinates"], json::array({600.0, 400.0}));
  EXPECT_EQ(points[1]["properties"]["reported_x"], 680.0);
  EXPECT_EQ(points[1]["properties"]["reported_y"], 340.0);
  EXPECT_FALSE(points[1]["properties"].contains("reported_lon"));
}

TEST(AuditSensorsGeoJson, NonFinitePositionGivesNullGeometry) {
  AuditFixture f = audit_fixture(true);
  f.result.sensors[0].position = {std::numeric_limits<double>::quiet_NaN(), 0.0};
  const json g = sensors_geojson(context_of(f));
  EXPECT_TRUE(features_of_kind(g, "sensor")[0]["geometry"].is_null());
  EXPECT_EQ(features_of_kind(shifts_geojson(context_of(f)), "shift").size(), 2u);  // a's shift has no end any more
}

// ------------------------------------------------------------------------------ diagram.geojson

// Every polygon of a feature, as GeoJSON Polygon coordinates.
std::vector<json> polygons_of(const json& feature) {
  const json& geometry = feature["geometry"];
  if (geometry["type"] == "Polygon") return {geometry["coordinates"]};
  EXPECT_EQ(geometry["type"], "MultiPolygon");
  return std::vector<json>(geometry["coordinates"].begin(), geometry["coordinates"].end());
}

// Checks RFC 7946's ring rules; returns the area (outer minus holes) of the feature.
double check_rings(const json& feature) {
  double area = 0.0;
  for (const json& polygon : polygons_of(feature)) {
    for (std::size_t r = 0; r < polygon.size(); ++r) {
      const json& ring = polygon[r];
      EXPECT_GE(ring.size(), 4u);
      EXPECT_EQ(ring.front(), ring.back()) << "ring not closed";
      const double a = ring_area(ring);
      if (r == 0) {
        EXPECT_GT(a, 0.0) << "outer ring not counter-clockwise";
      } else {
        EXPECT_LT(a, 0.0) << "hole not clockwise";
      }
      area += a;
    }
  }
  return area;
}

TEST(AuditDiagramGeoJson, OneFeaturePerSensorWithHolesAndAreasSummingToTheFrame) {
  const AuditFixture f = audit_fixture(false);
  const json g = diagram_geojson(context_of(f));
  EXPECT_EQ(g["type"], "FeatureCollection");
  EXPECT_EQ(g["omitted_unbounded_faces"], 0);
  std::set<std::string> sensors;
  double total = 0.0;
  std::size_t holes_of_b = 0;
  for (const auto& feature : g["features"]) {
    const std::string id = feature["properties"]["sensor"];
    EXPECT_TRUE(sensors.insert(id).second) << "two features for " << id;
    const double area = check_rings(feature);
    EXPECT_NEAR(feature["properties"]["area_m2"].get<double>(), area, 1e-6 * kFrameArea);
    total += area;
    if (id == "b") {
      for (const json& polygon : polygons_of(feature)) holes_of_b += polygon.size() - 1;
    }
  }
  EXPECT_EQ(sensors, (std::set<std::string>{"a", "b", "c", "d"}));
  EXPECT_EQ(holes_of_b, 2u) << "the disks of a and d are holes in b";
  // Chords lose at most arc_deviation (1e-5 of the extent) times the arcs' length in area.
  EXPECT_NEAR(total, kFrameArea, 1e-4 * kFrameArea);
}

TEST(AuditDiagramGeoJson, DisconnectedRegionIsOneMultiPolygon) {
  AuditFixture f = audit_fixture(false);
  f.result.refined_diagram = testing::clipped_diagram(testing::pieces_sites());
  const json g = diagram_geojson(context_of(f));
  ASSERT_EQ(g["features"].size(), 2u);
  double total = 0.0;
  for (const auto& feature : g["features"]) {
    total += check_rings(feature);
    if (feature["properties"]["sensor"] == "b") {
      EXPECT_EQ(feature["geometry"]["type"], "MultiPolygon");
      EXPECT_EQ(polygons_of(feature).size(), 3u);
      EXPECT_EQ(feature["properties"]["faces"], 3);
    }
  }
  EXPECT_NEAR(total, kFrameArea, 1e-4 * kFrameArea);
}

// Every vertex of a site's polygons is a point of that site's region (no site is strictly nearer,
// by brute force over all sites) on its boundary (another site as near, or the frame).
TEST(AuditDiagramGeoJson, VerticesLieOnTheirSitesRegionBoundary) {
  const AuditFixture f = audit_fixture(false);
  const auto sites = testing::holes_sites();
  const json g = diagram_geojson(context_of(f));
  constexpr double kRelative = 1e-9;  // rounding of nodes and of cos/sin along the arcs
  std::size_t checked = 0;
  for (const auto& feature : g["features"]) {
    const std::string id = feature["properties"]["sensor"];
    const auto& own = *std::find_if(sites.begin(), sites.end(), [&](const auto& s) { return s.id == id; });
    for (const json& polygon : polygons_of(feature)) {
      for (const json& ring : polygon) {
        for (const json& position : ring) {
          const Point p{position[0], position[1]};
          const double mine = testing::weighted_distance(p, own);
          double nearest_other = std::numeric_limits<double>::infinity();
          for (const auto& s : sites) {
            if (s.id != id) nearest_other = std::min(nearest_other, testing::weighted_distance(p, s));
          }
          EXPECT_LE(mine, nearest_other * (1 + kRelative)) << id << " at " << p.x << ", " << p.y;
          const bool on_frame = std::min({std::abs(p.x), std::abs(p.x - 1000), std::abs(p.y), std::abs(p.y - 800)}) < 1e-9;
          EXPECT_TRUE(on_frame || std::abs(mine - nearest_other) <= kRelative * mine) << id << " at " << p.x << ", " << p.y;
          ++checked;
        }
      }
    }
  }
  EXPECT_GT(checked, 100u);
}

// Areas against a brute-force raster of the diagram: a missing hole or a face given to the wrong
// sensor moves an area by several percent of the frame.
TEST(AuditDiagramGeoJson, AreasMatchBruteForceOwnership) {
  const AuditFixture f = audit_fixture(false);
  const auto sites = testing::holes_sites();
  constexpr int kNx = 250, kNy = 200;
  std::map<std::string, double> raster;
  for (int i = 0; i < kNx; ++i) {
    for (int j = 0; j < kNy; ++j) {
      const Point p{(i + 0.5) * 1000.0 / kNx, (j + 0.5) * 800.0 / kNy};
      const auto best = std::min_element(sites.begin(), sites.end(), [&](const auto& s, const auto& t) {
        return testing::weighted_distance(p, s) < testing::weighted_distance(p, t);
      });
      raster[best->id] += kFrameArea / (kNx * kNy);
    }
  }
  const json g = diagram_geojson(context_of(f));
  for (const auto& feature : g["features"]) {
    const std::string id = feature["properties"]["sensor"];
    double area = 0.0;
    for (const json& polygon : polygons_of(feature))
      for (const json& ring : polygon) area += ring_area(ring);
    // Raster error: about half a cell along each boundary (perimeters here are below 5 km).
    EXPECT_NEAR(area, raster[id], 0.005 * kFrameArea) << id;
  }
}

double segment_distance(Point p, Point a, Point b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double len2 = dx * dx + dy * dy;
  const double t = len2 == 0 ? 0 : std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0, 1.0);
  return std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy);
}

// The lon/lat rings, projected back, run along the planar rings (they have more vertices: straight
// edges are subdivided) and enclose the same areas.
TEST(AuditDiagramGeoJson, GeographicRingsAreTheProjectedPlanarRings) {
  const AuditFixture planar = audit_fixture(false);
  const AuditFixture geographic = audit_fixture(true);
  const json p = diagram_geojson(context_of(planar));
  const json g = diagram_geojson(context_of(geographic));
  ASSERT_EQ(p["features"].size(), g["features"].size());
  std::size_t vertices = 0;
  for (std::size_t i = 0; i < p["features"].size(); ++i) {
    check_rings(g["features"][i]);  // orientation and closure hold in lon/lat too
    EXPECT_EQ(p["features"][i]["properties"]["sensor"], g["features"][i]["properties"]["sensor"]);
    const auto pp = polygons_of(p["features"][i]);
    const auto gp = polygons_of(g["features"][i]);
    ASSERT_EQ(pp.size(), gp.size());
    for (std::size_t k = 0; k < pp.size(); ++k) {
      ASSERT_EQ(pp[k].size(), gp[k].size());
      for (std::size_t r = 0; r < pp[k].size(); ++r) {
        const json& planar_ring = pp[k][r];
        json projected = json::array();
        for (const json& position : gp[k][r]) {
          const Point back = forward(geographic.map, position[0], position[1]);
          projected.push_back({back.x, back.y});
          double nearest = std::numeric_limits<double>::infinity();
          for (std::size_t v = 0; v + 1 < planar_ring.size(); ++v) {
            nearest = std::min(nearest, segment_distance(back, {planar_ring[v][0], planar_ring[v][1]},
                                                         {planar_ring[v + 1][0], planar_ring[v + 1][1]}));
          }
          EXPECT_LT(nearest, 1e-6);
          ++vertices;
        }
        EXPECT_NEAR(ring_area(projected), ring_area(planar_ring), 1e-9 * kFrameArea);
      }
    }
  }
  EXPECT_GT(vertices, 100u);
}

TEST(AuditDiagramGeoJson, GeographicStraightEdgesAreSubdivided) {
  // The frame's straight sides become several vertices in lon/lat (a projected straight line is
  // curved there), but stay single segments in the plane.
  const AuditFixture planar = audit_fixture(false);
  const AuditFixture geographic = audit_fixture(true);
  const json p = diagram_geojson(context_of(planar));
  const json g = diagram_geojson(context_of(geographic));
  std::size_t planar_vertices = 0, geographic_vertices = 0;
  for (const auto& feature : p["features"])
    for (const json& polygon : polygons_of(feature))
      for (const json& ring : polygon) planar_vertices += ring.size();
  for (const auto& feature : g["features"])
    for (const json& polygon : polygons_of(feature))
      for (const json& ring : polygon) geographic_vertices += ring.size();
  // The frame is 3600 m around; pieces of at most 1 % of the 1281 m diagonal: 290 or more.
  EXPECT_GE(geographic_vertices, planar_vertices + 250);
}

TEST(AuditDiagramGeoJson, UnboundedFacesAreCountedNotWritten) {
  AuditFixture f = audit_fixture(false);
  f.result.refined_diagram = voronoi::build_diagram(testing::holes_sites());  // not clipped
  std::size_t unbounded = 0;
  for (const auto& face : f.result.refined_diagram.faces) unbounded += face.bounded ? 0 : 1;
  ASSERT_GT(unbounded, 0u);
  const json g = diagram_geojson(context_of(f));
  EXPECT_EQ(g["omitted_unbounded_faces"], unbounded);
  for (const auto& feature : g["features"]) check_rings(feature);
}

}  // namespace
}  // namespace covmap::report

namespace covmap::report {
namespace {

// Coordinates at the precision the data carry: each is the double nearest a multiple of
// 1e-8 degrees or of a millimetre, within half a step of the full-precision coordinate. (Written
// by nlohmann's Grisu2, a few such doubles come out with 16 digits instead of their shortest form;
// the file still shrinks by half: checked below.)
bool on_the_grid(double v, double steps) { return std::round(v * steps) / steps == v; }

void expect_rounded(const json& rounded, const json& full, double step, std::size_t& compared) {
  if (rounded.is_array() && !rounded.empty() && rounded[0].is_number()) {
    ASSERT_EQ(rounded.size(), full.size());
    for (std::size_t i = 0; i < rounded.size(); ++i) {
      EXPECT_LE(std::abs(rounded[i].get<double>() - full[i].get<double>()), 0.5 * step * (1 + 1e-6));
      EXPECT_TRUE(on_the_grid(rounded[i].get<double>(), 1 / step)) << rounded[i].dump();
      ++compared;
    }
    return;
  }
  if (rounded.is_array() || rounded.is_object()) {
    ASSERT_EQ(rounded.size(), full.size());
    auto a = rounded.begin();
    auto b = full.begin();
    for (; a != rounded.end(); ++a, ++b) expect_rounded(*a, *b, step, compared);
  }
}

TEST(AuditGeoJsonPrecision, CoordinatesRoundedToWhatTheDataCarry) {
  for (const bool geographic : {true, false}) {
    const AuditFixture f = audit_fixture(geographic);
    AuditReportContext full = context_of(f), rounded = context_of(f);
    rounded.render.full_precision = false;
    const double step = geographic ? 1e-8 : 1e-3;
    for (const auto write : {&write_diagram_geojson, &write_sensors_geojson, &write_shifts_geojson}) {
      std::ostringstream a, b;
      write(rounded, a);
      write(full, b);
      const json r = json::parse(a.str()), g = json::parse(b.str());
      std::size_t compared = 0;
      for (std::size_t i = 0; i < g["features"].size(); ++i)
        expect_rounded(r["features"][i]["geometry"]["coordinates"], g["features"][i]["geometry"]["coordinates"], step,
                       compared);
      EXPECT_GE(compared, 6u);  // the fixture's 5 sensors or 3 shifts, or the diagram's many vertices
      // Geographic coordinates get shorter; the fixture's planar positions sit on whole metres.
      if (geographic) EXPECT_LT(a.str().size(), b.str().size());
      else EXPECT_LE(a.str().size(), b.str().size());
    }
  }
}

}  // namespace
}  // namespace covmap::report
