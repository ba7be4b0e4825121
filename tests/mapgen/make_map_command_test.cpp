#include "tools/mapgen/make_map_command.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>

#include "tools/mapgen/coverage_map_files.h"
#include "make_map_run.h"
#include "mapgen_test_util.h"

namespace covmap::mapgen {
namespace {

using nlohmann::json;
using testing::read_text;
using testing::TempDir;

int run(std::vector<std::string> args, std::string* error = nullptr) { return testing::run_make_map_args(std::move(args), error); }

TEST(MakeMapCommand, SwissTownsInKilometresToLonLat) {
  TempDir dir;
  const std::string sites = std::string(COVMAP_SOURCE_DIR) + "/datasets/swiss_towns.csv";
  ASSERT_EQ(run({"--sites", sites, "--bin", "2000", "--lonlat", "8.0084,47.1044", "--jitter", "2", "--gross-fraction",
                 "0.1", "--seed", "1", "-o", dir.path().string()}),
            0);
  const json truth = json::parse(read_text(dir.path() / kTruthFileName));
  EXPECT_EQ(truth["generator"]["frame"], "lonlat");
  EXPECT_EQ(truth["generator"]["bin_size_m"].get<double>(), 2000.0);
  EXPECT_EQ(truth["counts"]["sensors"].get<int>(), 151);
  EXPECT_EQ(truth["counts"]["gross_errors"].get<int>(), 15);
  // Zürich: (40.990, 29.168) km in the file.
  EXPECT_EQ(truth["sensors"][0]["id"], "2657896");
  EXPECT_EQ(truth["sensors"][0]["x"].get<double>(), 40990.0);
  EXPECT_EQ(truth["sensors"][0]["y"].get<double>(), 29168.0);
  EXPECT_NEAR(truth["sensors"][0]["lon"].get<double>(), 8.55, 0.01);
  EXPECT_NEAR(truth["sensors"][0]["lat"].get<double>(), 47.37, 0.01);
  const json map = json::parse(read_text(dir.path() / kMapFileName));
  EXPECT_FALSE(map.contains("crs"));
  EXPECT_EQ(map["features"].size(), 151u - truth["counts"]["sensors_without_bins"].get<std::size_t>());
}

TEST(MakeMapCommand, LonLatSitesRandomSitesAndUnits) {
  TempDir dir;
  const auto csv = dir.path() / "towns.csv";
  std::ofstream(csv) << "id,lon,lat,weight\na,7.40,46.90,1\nb,7.50,46.95,2\nc,7.45,47.00,1.5\n";
  const auto out = dir.path() / "lonlat";
  ASSERT_EQ(run({"--lonlat-sites", csv.string(), "--bin", "250", "-o", out.string()}), 0);
  EXPECT_EQ(json::parse(read_text(out / kTruthFileName))["generator"]["frame"], "lonlat");
  ASSERT_EQ(run({"--lonlat-sites", csv.string(), "--bin", "250", "--planar", "-o", out.string()}), 0);
  EXPECT_EQ(json::parse(read_text(out / kTruthFileName))["generator"]["frame"], "planar");

  const auto random = dir.path() / "random";
  ASSERT_EQ(run({"--random", "20", "--area", "10,5", "--weight-ratio", "3", "-o", random.string()}), 0);
  const json truth = json::parse(read_text(random / kTruthFileName));
  ASSERT_EQ(truth["sensors"].size(), 20u);
  for (const auto& s : truth["sensors"]) {
    EXPECT_LE(std::abs(s["x"].get<double>()), 5000.0);
    EXPECT_LE(std::abs(s["y"].get<double>()), 2500.0);
    EXPECT_GE(s["weight"].get<double>(), 1.0 / 3.0);
  }

  const auto metres = dir.path() / "m.csv";
  std::ofstream(metres) << "id,x,y,weight\na,0,0,1\nb,3000,0,1\n";
  ASSERT_EQ(run({"--sites", metres.string(), "--unit", "m", "--bin", "100", "-o", (dir.path() / "m").string()}), 0);
  EXPECT_EQ(json::parse(read_text(dir.path() / "m" / kTruthFileName))["sensors"][1]["x"].get<double>(), 3000.0);
}

TEST(MakeMapCommand, BadInputNamesTheProblemAndWritesNothing) {
  TempDir dir;
  const auto csv = dir.path() / "bad.csv";
  std::ofstream(csv) << "id,lon,lat,weight\na,7.4,46.9,1\nb,7.5,95,1\n";
  std::string error;
  const auto out = dir.path() / "out";
  EXPECT_EQ(run({"--lonlat-sites", csv.string(), "-o", out.string()}, &error), 2);
  EXPECT_NE(error.find("bad.csv:3: sensor 'b': lat must be in (-90, 90) (got 95)"), std::string::npos) << error;
  EXPECT_FALSE(std::filesystem::exists(out));

  const auto sites = dir.path() / "sites.csv";
  std::ofstream(sites) << "id,x,y,weight\na,0,0,1\nb,1,1,-2\n";
  EXPECT_EQ(run({"--sites", sites.string(), "-o", out.string()}, &error), 2);
  EXPECT_NE(error.find("sites.csv:3"), std::string::npos) << error;

  const auto good = dir.path() / "good.csv";
  std::ofstream(good) << "id,x,y,weight\na,0,0,1\nb,1,1,2\n";
  EXPECT_EQ(run({"--sites", good.string(), "--bin", "-5", "-o", out.string()}, &error), 2);
  EXPECT_NE(error.find("bin size"), std::string::npos) << error;
  EXPECT_EQ(run({"--sites", good.string(), "--lonlat-sites", csv.string(), "-o", out.string()}, &error), -1)
      << "exactly one input";
  EXPECT_EQ(run({"--sites", good.string()}, &error), -1) << "-o is required";

  std::ofstream(dir.path() / "file") << "x";
  EXPECT_EQ(run({"--sites", good.string(), "--unit", "m", "--bin", "1", "-o", (dir.path() / "file").string()}, &error), 3);
}

TEST(MakeMapCommand, RefusesBadModelsAndTownWindows) {
  TempDir dir;
  const std::string out = (dir.path() / "out").string();
  const std::string iowa = std::string(COVMAP_SOURCE_DIR) + "/datasets/towns/iowa.csv";
  std::string error;
  EXPECT_EQ(run({"--random", "20", "--model", "Shadowing", "-o", out}, &error), -1);
  EXPECT_EQ(run({"--random", "20", "--model", "exponents", "--alpha-spread", "2", "-o", out}, &error), 2);
  EXPECT_NE(error.find("alpha spread"), std::string::npos) << error;
  EXPECT_EQ(run({"--towns", iowa, "--count", "100000", "-o", out}, &error), 2);
  EXPECT_NE(error.find("larger than the list"), std::string::npos) << error;
  EXPECT_EQ(run({"--towns", iowa, "--town-weights", "random", "-o", out}, &error), -1);
  EXPECT_FALSE(std::filesystem::exists(out));
  EXPECT_EQ(run({"--towns", iowa, "--count", "30", "--town-weights", "power-classes", "--planar", "-o", out}, &error), 0)
      << error;
  const json truth = json::parse(read_text(std::filesystem::path(out) / kTruthFileName));
  EXPECT_EQ(truth["generator"]["frame"], "planar");
  EXPECT_EQ(truth["layout"]["power_classes_dbm"], json::array({43.0, 37.0, 31.0}));
}

}  // namespace
}  // namespace covmap::mapgen
