// The service's parts that need no network: the API document against the routes the server really
// adds, the options of an audit request, progress lines, upload names, the error shape.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>

#include "service/api_error.h"
#include "service/audit_process.h"
#include "job/audit_request_json.h"
#include "service/audit_request.h"
#include "service/http_server.h"
#include "service/job_files.h"
#include "tests/support/temp_dir.h"

namespace covmap::service {
namespace {

using Json = nlohmann::json;

TEST(OpenApi, DocumentListsExactlyTheRoutesTheServerAdds) {
  covmap::testing::TempDir dir;
  ServeOptions o;
  o.data_dir = dir.path();
  o.port = 0;
  o.workers = 1;
  std::vector<Route> served;
  {
    HttpServer server(o);
    served = server.routes();
  }
  std::ifstream in(std::string(COVMAP_SOURCE_DIR) + "/docs/openapi.json");
  const Json doc = Json::parse(in);
  std::vector<Route> documented;
  for (const auto& [path, operations] : doc["paths"].items())
    for (const auto& [method, operation] : operations.items()) {
      if (method == "parameters") continue;
      std::string upper = method;
      std::transform(upper.begin(), upper.end(), upper.begin(), [](unsigned char c) { return std::toupper(c); });
      documented.push_back({upper, path});
    }
  auto order = [](const Route& a, const Route& b) { return std::tie(a.path, a.method) < std::tie(b.path, b.method); };
  std::sort(served.begin(), served.end(), order);
  std::sort(documented.begin(), documented.end(), order);
  EXPECT_EQ(served, documented);
  // The document's audit options are exactly those parse_audit_request takes.
  for (const auto& [name, schema] : doc["components"]["schemas"]["AuditOptions"]["properties"].items()) {
    Json one;
    if (schema["type"] == "boolean") one[name] = true;
    else if (name == "basemap") one[name] = "https://tiles.example/{z}/{x}/{y}.png";  // the validator checks URLs
    else if (schema["type"] == "string") one[name] = schema.contains("enum") ? schema["enum"][0] : Json("x");
    else if (schema["type"] == "integer") one[name] = 2;
    else one[name] = 1.5;
    EXPECT_NO_THROW(parse_audit_request(one.dump())) << name;
  }
  // ... and every option the service takes is documented.
  for (const job::AuditOption o : job::kServiceOptions)
    EXPECT_TRUE(doc["components"]["schemas"]["AuditOptions"]["properties"].contains(std::string(job::option_name(o))))
        << job::option_name(o);
}

TEST(AuditRequest, OptionsFillTheJobRequest) {
  const job::AuditRequest r =
      parse_audit_request(R"({"alpha": 3.5, "planar": true, "sensor_property": "cell", "format": "gpkg", "band": 2})");
  EXPECT_EQ(r.settings.alpha, 3.5);
  EXPECT_TRUE(r.inputs.planar);
  EXPECT_EQ(r.inputs.sensor_property, "cell");
  EXPECT_EQ(r.inputs.band, 2);
  EXPECT_EQ(r.outputs.format, report::GisFormat::kGeoPackage);
  EXPECT_EQ(report_files(r), (std::vector<std::string>{"report.json", "report.html", "audit.gpkg"}));
  EXPECT_EQ(parse_audit_request("").inputs.sensor_property, "sensor");
}

std::string where_of(const std::string& options) {
  try {
    parse_audit_request(options);
  } catch (const ApiError& e) {
    EXPECT_EQ(e.code, ErrorCode::kBadInput);
    return e.where;
  }
  return "accepted";
}

TEST(AuditRequest, BadOptionsNameTheMember) {
  EXPECT_EQ(where_of("[1]"), "options");
  EXPECT_EQ(where_of("{alpha: 1}"), "options");
  EXPECT_EQ(where_of(R"({"alpha": -1})"), "options.alpha");
  EXPECT_EQ(where_of(R"({"alpha": "3"})"), "options.alpha");
  EXPECT_EQ(where_of(R"({"planar": 1})"), "options.planar");
  EXPECT_EQ(where_of(R"({"band": 0})"), "options.band");
  EXPECT_EQ(where_of(R"({"format": "shp"})"), "options.format");
  EXPECT_EQ(where_of(R"({"--alpha": 3})"), "options.--alpha");
  // The rules themselves are the job library's (tests/job/audit_request_test.cpp); threads are the
  // service's to decide (its limits), not a submitter's.
  EXPECT_EQ(where_of(R"({"threads": 2})"), "options.threads");
}

TEST(AuditProcess, ProgressLinesOfTheCli) {
  ProgressLine p;
  ASSERT_TRUE(parse_progress_line("covmap audit: refining sites, 40 % (1.2 s)", p));
  EXPECT_DOUBLE_EQ(p.fraction, 0.4);
  EXPECT_EQ(p.stage, "refining sites");
  ASSERT_TRUE(parse_progress_line("covmap audit: reading the map (0.3 MB) (< 0.001 s)", p));
  EXPECT_LT(p.fraction, 0);
  EXPECT_EQ(p.stage, "reading the map (0.3 MB)");
  EXPECT_FALSE(parse_progress_line("covmap: map.geojson: features[3]: not closed", p));
  EXPECT_FALSE(parse_progress_line("covmap audit: note: sensors.csv: both pairs", p));
}

TEST(JobFiles, UploadNamesStayInTheirFolder) {
  EXPECT_EQ(safe_upload_name("../../etc/passwd", "map"), "passwd");
  EXPECT_EQ(safe_upload_name("C:\\maps\\bern map.gpkg", "map"), "bern_map.gpkg");
  EXPECT_EQ(safe_upload_name("..", "map"), "map");
  EXPECT_EQ(safe_upload_name(".hidden.geojson", "map"), "hidden.geojson");
  EXPECT_EQ(safe_upload_name("", "sensors"), "sensors");
  EXPECT_EQ(safe_upload_name(std::string(300, 'a') + ".tif", "map").size(), 100u);
  EXPECT_TRUE(safe_upload_name(std::string(300, 'a') + ".tif", "map").ends_with(".tif"));
}

TEST(ApiError, OneJsonShapeWithItsStatus) {
  const Json j = Json::parse(error_json(ErrorCode::kTooLarge, "big \xff", "map"));
  EXPECT_EQ(j["error"]["code"], "too_large");
  EXPECT_EQ(j["error"]["where"], "map");
  EXPECT_EQ(http_status(ErrorCode::kTooLarge), 413);
  EXPECT_EQ(http_status(ErrorCode::kQueueFull), 503);
  EXPECT_EQ(http_status(ErrorCode::kInternal), 500);
}

}  // namespace
}  // namespace covmap::service
