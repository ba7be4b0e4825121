// Outputs never destroy what the user did not ask to replace: the rules of
// io/output_plan.h, each on the file system as a user would meet it.
#include "io/output_plan.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include "io_test_util.h"

namespace covmap::io {
namespace {

using testing::read_text;
using testing::TempDir;
namespace fs = std::filesystem;

const NamedTexts kReports = {{"report.json", "{}"}, {"report.html", "<html>"}};

OutputPlan folder_plan(const fs::path& folder, std::vector<fs::path> inputs = {}) {
  OutputPlan plan;
  plan.folder = folder;
  plan.folder_files = {"report.json", "report.html"};
  plan.inputs = std::move(inputs);
  return plan;
}

TEST(OutputPlan, AFolderWithTheUsersFilesIsRefusedUnlessForced) {
  TempDir dir;
  dir.write("d/mydata.txt", "precious");
  EXPECT_THROW(check_output_plan(folder_plan(dir / "d")), OutputError);
  EXPECT_THROW(write_report_folder(dir / "d", kReports, false), OutputError);
  EXPECT_EQ(read_text(dir / "d" / "mydata.txt"), "precious");
  OutputPlan forced = folder_plan(dir / "d");
  forced.force = true;
  EXPECT_NO_THROW(check_output_plan(forced));
  write_report_folder(dir / "d", kReports, true);
  EXPECT_EQ(read_text(dir / "d" / "mydata.txt"), "precious");
  EXPECT_EQ(read_text(dir / "d" / "report.json"), "{}");
}

TEST(OutputPlan, CovmapsOwnFolderIsReplacedAndStaleReportsGo) {
  TempDir dir;
  write_report_folder(dir / "out", {{"report.json", "1"}, {"old.geojson", "x"}}, false);
  EXPECT_NO_THROW(check_output_plan(folder_plan(dir / "out")));
  write_report_folder(dir / "out", kReports, false);
  EXPECT_EQ(read_text(dir / "out" / "report.json"), "{}");
  EXPECT_FALSE(fs::exists(dir / "out" / "old.geojson"));  // written by covmap before, not now
  EXPECT_TRUE(fs::exists(dir / "out" / kFolderMarker));
}

TEST(OutputPlan, AFileIsNeverReplacedByAFolderNorAFolderByAFile) {
  TempDir dir;
  dir.write("f.txt", "mine");
  EXPECT_THROW(check_output_plan(folder_plan(dir / "f.txt")), OutputError);
  EXPECT_THROW(write_report_folder(dir / "f.txt", kReports, true), OutputError);
  EXPECT_EQ(read_text(dir / "f.txt"), "mine");
  dir.write("folder/x", "");
  OutputPlan plan;
  plan.files = {dir / "folder"};
  EXPECT_THROW(check_output_plan(plan), OutputError);
}

TEST(OutputPlan, AnInputIsNeverAnOutputHoweverSpelled) {
  TempDir dir;
  const fs::path input = dir.write("s.json", "{}");
  OutputPlan plan;
  plan.inputs = {input};
  plan.files = {dir.path() / "." / "s.json"};
  EXPECT_THROW(check_output_plan(plan), OutputError);
  fs::create_hard_link(input, dir / "link.json");
  plan.files = {dir / "link.json"};
  EXPECT_THROW(check_output_plan(plan), OutputError);
  EXPECT_THROW(check_output_plan(folder_plan(input, {input})), OutputError);
  // The map inside a folder the report would write into: report.json is not it, so allowed...
  dir.write("out/.covmap-output", "covmap report folder; covmap wrote the files listed below\n");
  const fs::path map = dir.write("out/map.geojson", "{}");
  EXPECT_NO_THROW(check_output_plan(folder_plan(dir / "out", {map})));
  // ...but an input named like a report file would be overwritten: refused.
  const fs::path named = dir.write("out/report.json", "{}");
  EXPECT_THROW(check_output_plan(folder_plan(dir / "out", {named})), OutputError);
}

TEST(OutputPlan, TrailingSlashesAndDotsAreTheFolderItself) {
  EXPECT_EQ(normalized_output_path("out/"), fs::path("out"));
  EXPECT_EQ(normalized_output_path("./a//b/"), fs::path("a/b"));
  EXPECT_EQ(normalized_output_path("."), fs::path("."));
  EXPECT_EQ(normalized_output_path("./"), fs::path("."));
  TempDir dir;
  write_report_folder((dir / "r").string() + "/", kReports, false);
  EXPECT_EQ(read_text(dir / "r" / "report.html"), "<html>");
}

TEST(OutputPlan, LeftoversOfKilledRunsAreRemovedAndNothingElse) {
  TempDir dir;
  dir.write(".covmap-tmp-2147483646-3-out/report.json", "dead process");
  dir.write(std::string(".covmap-tmp-") + std::to_string(::getpid()) + "-9-x", "a live process (this one)");
  dir.write("out.tmp-12/report.json", "old version");
  dir.write("out.old-13/report.html", "old version");
  dir.write("notes.tmp-1/mine.txt", "the user's");
  dir.write("data.old-2", "a file, not covmap's");
  EXPECT_EQ(remove_stale_temporaries(dir.path()), 3);
  EXPECT_TRUE(fs::exists(dir / (".covmap-tmp-" + std::to_string(::getpid()) + "-9-x")));
  EXPECT_TRUE(fs::exists(dir / "notes.tmp-1" / "mine.txt"));
  EXPECT_TRUE(fs::exists(dir / "data.old-2"));
  EXPECT_FALSE(fs::exists(dir / "out.tmp-12"));
}

// Files written as they are produced: nothing shows until commit(); a failure half-way (a writer
// throwing after part of its file) leaves no trace in a new folder and the old version in an
// existing one.
TEST(ReportFolderWriter, StreamedFilesAppearOnlyOnCommit) {
  TempDir dir;
  {
    ReportFolderWriter writer(dir / "out", false);
    writer.add("big.geojson", [](std::ostream& out) {
      for (int i = 0; i < 100000; ++i) out << i << ",";
    });
    writer.add("report.json", std::string("{}"));
    EXPECT_FALSE(fs::exists(dir / "out"));
    writer.commit();
  }
  const std::string big = read_text(dir / "out" / "big.geojson");
  EXPECT_EQ(big.substr(0, 6), "0,1,2,");
  EXPECT_EQ(big.substr(big.size() - 6), "99999,");
  // The marker lists both, so a later run may replace them.
  const std::string marker = read_text(dir / "out" / kFolderMarker);
  EXPECT_NE(marker.find("big.geojson\n"), std::string::npos);
  EXPECT_NE(marker.find("report.json\n"), std::string::npos);
}

TEST(ReportFolderWriter, AWriterFailingHalfWayLeavesNothingInANewFolder) {
  TempDir dir;
  EXPECT_THROW(
      {
        ReportFolderWriter writer(dir / "out", false);
        writer.add("report.json", std::string("{}"));
        writer.add("diagram.geojson", [](std::ostream& out) {
          out << "{\"type\":";
          throw std::runtime_error("renderer failed");
        });
        writer.commit();
      },
      std::runtime_error);
  EXPECT_TRUE(fs::is_empty(dir.path()));  // no folder, no temporaries
}

TEST(ReportFolderWriter, AWriterFailingHalfWayKeepsTheEarlierReports) {
  TempDir dir;
  write_report_folder(dir / "out", kReports, false);
  dir.write("out/mine.txt", "the user's");
  EXPECT_THROW(
      {
        ReportFolderWriter writer(dir / "out", true);
        writer.add("report.json", std::string("{\"new\":1}"));
        writer.add("report.html", [](std::ostream&) { throw std::runtime_error("renderer failed"); });
        writer.commit();
      },
      std::runtime_error);
  EXPECT_EQ(read_text(dir / "out" / "report.json"), "{}");
  EXPECT_EQ(read_text(dir / "out" / "report.html"), "<html>");
  EXPECT_EQ(read_text(dir / "out" / "mine.txt"), "the user's");
  size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir / "out")) ++entries;
  EXPECT_EQ(entries, 4u);  // report.json, report.html, the marker, mine.txt: no temporaries
}

}  // namespace
}  // namespace covmap::io
