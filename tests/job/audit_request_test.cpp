// The job library's request: one validator whose words are the command line's, the JSON options a
// service receives, and the whole request's JSON form read back exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "job/audit_request.h"
#include "job/audit_request_json.h"

namespace covmap::job {
namespace {

TEST(AuditOptionNames, EveryOptionHasOneNameThatReadsBack) {
  for (const AuditOption o : kAllAuditOptions) {
    ASSERT_FALSE(option_name(o).empty());
    EXPECT_EQ(option_from_name(option_name(o)), o) << option_name(o);
  }
  EXPECT_FALSE(option_from_name("--alpha"));
  EXPECT_FALSE(option_from_name("Alpha"));
}

TEST(ValueRules, BoundariesOfEveryNumericOption) {
  // Closed forms of each rule: alpha > 0, snap >= 0, threads in 1..64, band in 1..65535.
  EXPECT_EQ(value_problem(AuditOption::kAlpha, "3.5"), "");
  EXPECT_EQ(value_problem(AuditOption::kAlpha, "1e-300"), "");
  EXPECT_EQ(value_problem(AuditOption::kAlpha, "0"), "must be a positive number (got '0')");
  for (const char* bad : {"-1", "nan", "inf", "1e999", "3.5x", ""})
    EXPECT_NE(value_problem(AuditOption::kAlpha, bad), "") << bad;
  EXPECT_EQ(value_problem(AuditOption::kSnap, "0"), "");
  EXPECT_EQ(value_problem(AuditOption::kSnap, "-0.001"), "must be a number ≥ 0 (got '-0.001')");
  EXPECT_EQ(value_problem(AuditOption::kThreads, "1"), "");
  EXPECT_EQ(value_problem(AuditOption::kThreads, "64"), "");
  EXPECT_EQ(value_problem(AuditOption::kThreads, "65"), "must be a whole number in 1–64 (got '65')");
  EXPECT_NE(value_problem(AuditOption::kThreads, "2.5"), "");
  EXPECT_EQ(value_problem(AuditOption::kBand, "65535"), "");
  EXPECT_NE(value_problem(AuditOption::kBand, "0"), "");
  EXPECT_NE(value_problem(AuditOption::kSensorProperty, ""), "");
  EXPECT_EQ(value_problem(AuditOption::kBasemap, "https://t.example/{z}/{x}/{y}.png"), "");
  EXPECT_NE(value_problem(AuditOption::kBasemap, "https://t.example/{z}/{x}.png"), "");
  EXPECT_NE(value_problem(AuditOption::kBasemap, "ftp://t.example/{z}/{x}/{y}.png"), "");
  EXPECT_NE(value_problem(AuditOption::kFormat, "shp"), "");
}

TEST(Validator, RequestProblemsNameTheirOptionAndValidateThrowsTheFirst) {
  AuditRequest r;
  EXPECT_TRUE(request_problems(r).empty());
  r.settings.alpha = -2;
  r.inputs.band = 0;
  const auto problems = request_problems(r);
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_EQ(problems[0].option, AuditOption::kAlpha);
  EXPECT_EQ(problems[1].option, AuditOption::kBand);
  try {
    validate(r);
    FAIL() << "validate accepted alpha -2";
  } catch (const InvalidAuditRequest& e) {
    EXPECT_EQ(e.problem.option, AuditOption::kAlpha);
    EXPECT_EQ(std::string(e.what()), "alpha: must be a positive number (got '-2')");
  }
  AuditRequest planar;
  planar.inputs.planar = true;
  planar.outputs.basemap_url = "https://t.example/{z}/{x}/{y}.png";
  ASSERT_EQ(request_problems(planar).size(), 1u);
  EXPECT_EQ(request_problems(planar)[0].option, AuditOption::kBasemap);
}

TEST(ReadMaps, OneMappingToTheReaders) {
  AuditRequest r;
  r.inputs.sensor_property = "cell";
  r.inputs.planar = true;
  r.inputs.layer = "cells";
  r.inputs.band = 3;
  r.inputs.raster_table = "values.csv";
  r.inputs.sensor_crs = "EPSG:2056";
  r.inputs.sensor_layer = "sites";
  r.settings.alpha = 3.5;
  const gis::MapReadOptions m = map_read_options(r);
  EXPECT_EQ(m.map.sensor_property, "cell");
  EXPECT_TRUE(m.map.planar);
  EXPECT_EQ(m.layer, "cells");
  EXPECT_EQ(m.band, 3);
  EXPECT_EQ(m.raster_table, "values.csv");  // the copy the service used to make dropped it
  const gis::SensorReadOptions s = sensor_read_options(r);
  EXPECT_EQ(s.sensors.alpha, 3.5);
  EXPECT_TRUE(s.sensors.planar);
  EXPECT_EQ(s.sensor_crs, "EPSG:2056");
  EXPECT_EQ(s.layer, "sites");
}

std::string member_of(const std::string& options) {
  try {
    AuditRequest r;
    read_options_json(options, r);
  } catch (const OptionsError& e) {
    return e.member.empty() ? "(whole)" : e.member;
  }
  return "accepted";
}

TEST(OptionsJson, MembersTypesAndValuesRefusedByName) {
  EXPECT_EQ(member_of(""), "accepted");
  EXPECT_EQ(member_of("  \n"), "accepted");
  EXPECT_EQ(member_of("[1]"), "(whole)");
  EXPECT_EQ(member_of("{alpha: 1}"), "(whole)");
  EXPECT_EQ(member_of(R"({"alpha": 0})"), "alpha");
  EXPECT_EQ(member_of(R"({"alpha": "3"})"), "alpha");
  EXPECT_EQ(member_of(R"({"planar": 1})"), "planar");
  EXPECT_EQ(member_of(R"({"band": 2.5})"), "band");
  EXPECT_EQ(member_of(R"({"snap": -1})"), "snap");
  EXPECT_EQ(member_of(R"({"format": "GPKG"})"), "format");
  EXPECT_EQ(member_of(R"({"colour": "red"})"), "colour");
  EXPECT_EQ(member_of(R"({"threads": 4})"), "threads");  // not a service option
  // The same words as the command line's for the same value.
  try {
    AuditRequest r;
    read_options_json(R"({"alpha": -1})", r);
    FAIL();
  } catch (const OptionsError& e) {
    EXPECT_EQ(e.message, value_problem(AuditOption::kAlpha, "-1"));
  }
  // A huge value is not echoed whole.
  try {
    AuditRequest r;
    read_options_json(R"({"planar": ")" + std::string(100000, 'x') + R"("})", r);
    FAIL();
  } catch (const OptionsError& e) {
    EXPECT_LT(std::string(e.what()).size(), 200u);
  }
}

TEST(RequestJson, EveryRequestReadsBackEqual) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> u(1e-6, 10.0);
  for (int k = 0; k < 200; ++k) {
    AuditRequest r;
    r.inputs.map = "maps/m" + std::to_string(k) + ".geojson";
    r.inputs.sensors = k % 2 ? "s.csv" : "";
    r.inputs.raster_table = k % 3 ? "" : "t.csv";
    r.inputs.layer = k % 4 ? "" : "cells";
    r.inputs.band = 1 + k % 7;
    r.inputs.sensor_property = "p\"" + std::to_string(k);
    r.inputs.planar = k % 2 == 0;
    r.inputs.sensor_crs = k % 5 ? "" : "EPSG:2056";
    r.inputs.sensor_layer = k % 6 ? "" : "sites";
    if (k % 3) r.settings.alpha = u(random);
    r.settings.snap = k % 2 ? u(random) : 0.0;
    r.settings.threads = 1 + k % 64;
    r.settings.force = k % 7 == 0;
    r.outputs.folder = "out/" + std::to_string(k);
    r.outputs.format = k % 2 ? report::GisFormat::kGeoPackage : report::GisFormat::kGeoJson;
    r.outputs.full_precision = k % 3 == 1;
    r.outputs.basemap_url = r.inputs.planar ? "" : "https://t.example/{z}/{x}/{y}.png";
    r.command_line = "covmap audit é\n" + std::to_string(k);
    const AuditRequest back = request_from_json(request_json(r));
    EXPECT_EQ(back.inputs.map, r.inputs.map);
    EXPECT_EQ(back.inputs.sensors, r.inputs.sensors);
    EXPECT_EQ(back.inputs.raster_table, r.inputs.raster_table);
    EXPECT_EQ(back.inputs.layer, r.inputs.layer);
    EXPECT_EQ(back.inputs.band, r.inputs.band);
    EXPECT_EQ(back.inputs.sensor_property, r.inputs.sensor_property);
    EXPECT_EQ(back.inputs.planar, r.inputs.planar);
    EXPECT_EQ(back.inputs.sensor_crs, r.inputs.sensor_crs);
    EXPECT_EQ(back.inputs.sensor_layer, r.inputs.sensor_layer);
    EXPECT_EQ(back.settings.alpha, r.settings.alpha);  // bit for bit
    EXPECT_EQ(back.settings.snap, r.settings.snap);
    EXPECT_EQ(back.settings.threads, r.settings.threads);
    EXPECT_EQ(back.settings.force, r.settings.force);
    EXPECT_EQ(back.outputs.folder, r.outputs.folder);
    EXPECT_EQ(back.outputs.format, r.outputs.format);
    EXPECT_EQ(back.outputs.full_precision, r.outputs.full_precision);
    EXPECT_EQ(back.outputs.basemap_url, r.outputs.basemap_url);
    EXPECT_EQ(back.command_line, r.command_line);
  }
  EXPECT_THROW(request_from_json("{}"), OptionsError);
  EXPECT_THROW(request_from_json("not json"), OptionsError);
}

}  // namespace
}  // namespace covmap::job
