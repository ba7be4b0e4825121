// One audit job from files to report folder: the typed result against what the files say, the
// typed failures (with the input they are about, and nothing written), and the outcome record a
// job's process leaves for the service, read back equal.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <set>

#include "io/input_error.h"
#include "job/audit_job.h"
#include "job/audit_outcome.h"
#include "tools/mapgen/coverage_map_files.h"
#include "tools/mapgen/coverage_map_generator.h"
#include "tools/mapgen/site_layouts.h"
#include "tests/support/temp_dir.h"

namespace covmap::job {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

using Folder = testing::TempDir;

// A planar map of 12 sensors with gross errors, written as covmap-make-map writes it.
mapgen::CoverageMap write_map(const fs::path& dir, mapgen::OutputFrame frame = mapgen::OutputFrame::kPlanar) {
  mapgen::RandomSitesOptions layout;
  layout.count = 12;
  layout.width_m = 4000;
  layout.height_m = 4000;
  layout.seed = 3;
  mapgen::CoverageMapOptions o;
  o.bin_size_m = 50;
  o.errors.gross_fraction = 0.2;
  o.seed = 3;
  o.frame = frame;
  if (frame == mapgen::OutputFrame::kLonLat) o.centre = io::LonLat{7.4, 46.9};
  const std::vector<Site> sites = mapgen::random_sites(layout);
  mapgen::CoverageMap map = mapgen::generate_coverage_map(sites, o);
  mapgen::write_coverage_map(map, dir);
  return map;
}

AuditRequest planar_request(const fs::path& dir) {
  AuditRequest r;
  r.inputs.map = dir / mapgen::kMapFileName;
  r.inputs.sensors = dir / mapgen::kSensorsFileName;
  r.inputs.planar = true;
  r.outputs.folder = dir / "out";
  r.settings.threads = 1;
  return r;
}

Json read_json(const fs::path& file) {
  std::ifstream in(file);
  return Json::parse(in);
}

TEST(AuditJob, ResultAgreesWithTheReportsItWrote) {
  Folder dir;
  write_map(dir.path());
  std::vector<std::string> said;
  AuditJobHooks hooks;
  hooks.progress = [&](const std::string& what) { said.push_back(what); };
  const AuditedMap audited = run_audit_job(planar_request(dir.path()), hooks);
  // Every report of the format, and nothing else but covmap's marker.
  std::set<std::string> files;
  for (const auto& e : fs::directory_iterator(dir.path() / "out")) files.insert(e.path().filename().string());
  for (const std::string& name : report::audit_report_file_names(report::GisFormat::kGeoJson))
    EXPECT_TRUE(files.count(name)) << name;
  // The counts returned are report.json's, and they account for every sensor of the truth file.
  const Json report = read_json(dir.path() / "out" / "report.json");
  EXPECT_EQ(Json::parse(report::verdict_counts_json(audited.counts)), report["summary"]);
  // ... and to the generator's truth: every sensor with bins has a cell, every one is reported.
  const Json truth = read_json(dir.path() / mapgen::kTruthFileName);
  std::size_t with_bins = 0, reported = 0;
  for (const Json& s : truth["sensors"]) with_bins += s["bins"].get<int>() > 0, reported += !s["reported"].is_null();
  EXPECT_EQ(audited.counts.in_map, with_bins);
  EXPECT_EQ(audited.counts.reported, reported);
  EXPECT_EQ(audited.counts.sensors, report["sensors"].size());
  EXPECT_FALSE(said.empty());
  EXPECT_EQ(said.front().rfind("reading the map", 0), 0u);
  EXPECT_EQ(said.back(), "moving the reports into place");
  // The outcome record a job's process leaves reads back equal, summary included.
  const AuditOutcome done = done_outcome(audited);
  EXPECT_EQ(outcome_from_json(outcome_json(done)), done);
  EXPECT_EQ(Json::parse(done.summary_json), report["summary"]);
}

// Runs the job, which must fail, and says how.
AuditFailure failure_of(const AuditRequest& r) {
  try {
    run_audit_job(r);
  } catch (const std::exception&) {
    return describe_current_failure(&r);
  }
  ADD_FAILURE() << "the job did not fail";
  return {};
}

TEST(AuditJob, FailuresAreTypedAndNameTheirInput) {
  Folder dir;
  write_map(dir.path());
  AuditRequest r = planar_request(dir.path());
  // The validator speaks before anything is read or written.
  AuditRequest bad = r;
  bad.settings.alpha = 0;
  bad.inputs.map = dir.path() / "missing.geojson";
  AuditFailure f = failure_of(bad);
  EXPECT_EQ(f.kind, FailureKind::kBadInput);
  EXPECT_EQ(f.message, "alpha: must be a positive number (got '0')");
  EXPECT_FALSE(fs::exists(r.outputs.folder));
  // A map that is not there.
  bad = r;
  bad.inputs.map = dir.path() / "missing.geojson";
  f = failure_of(bad);
  EXPECT_EQ(f.kind, FailureKind::kBadInput);
  EXPECT_EQ(f.input, AuditInputKind::kMap);
  EXPECT_NE(f.message.find("missing.geojson"), std::string::npos);
  // Sensors that are not sensors.
  std::ofstream(dir.path() / "broken.csv") << "id,x,y,power\na,1,2,not-a-number\n";
  bad = r;
  bad.inputs.sensors = dir.path() / "broken.csv";
  f = failure_of(bad);
  EXPECT_EQ(f.kind, FailureKind::kBadInput);
  EXPECT_EQ(f.input, AuditInputKind::kSensors);
  // An output folder holding someone else's file: refused before reading, the file untouched.
  fs::create_directories(r.outputs.folder);
  std::ofstream(r.outputs.folder / "mine.txt") << "keep";
  f = failure_of(r);
  EXPECT_EQ(f.kind, FailureKind::kBadInput);
  EXPECT_EQ(fs::file_size(r.outputs.folder / "mine.txt"), 4u);
  EXPECT_FALSE(fs::exists(r.outputs.folder / "report.json"));
  // Each failure's outcome record reads back equal.
  const AuditOutcome failed = failed_outcome(f);
  EXPECT_EQ(outcome_from_json(outcome_json(failed)), failed);
  EXPECT_THROW(outcome_from_json(""), std::invalid_argument);
  EXPECT_THROW(outcome_from_json(R"({"format": "covmap.audit-outcome/1", "status": "maybe"})"), std::invalid_argument);
}

TEST(AuditJob, ImplausibleInputStopsTheJobUnlessForced) {
  Folder dir;
  write_map(dir.path(), mapgen::OutputFrame::kLonLat);
  AuditRequest r = planar_request(dir.path());  // degrees read as metres: the map looks like lon/lat
  const AuditInputsRead in = read_audit_inputs(r);
  ASSERT_FALSE(in.implausible.empty());
  EXPECT_EQ(in.implausible.front().input, AuditInputKind::kMap);
  try {
    run_audit_job(r);
    FAIL() << "an implausible map was audited";
  } catch (const ImplausibleInputError& e) {
    EXPECT_EQ(e.input, AuditInputKind::kMap);
    EXPECT_EQ(e.file, r.inputs.map);
    EXPECT_EQ(e.finding, in.implausible.front().finding);
  }
  EXPECT_FALSE(fs::exists(r.outputs.folder / "report.json"));
}

}  // namespace
}  // namespace covmap::job
