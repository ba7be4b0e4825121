#include "tools/mapgen/lonlat_sites_csv.h"

#include <gtest/gtest.h>

#include "io/input_error.h"

namespace covmap::mapgen {
namespace {

io::InputError error_of(const std::string& text) {
  try {
    parse_lonlat_sites_csv(text, "towns.csv");
  } catch (const io::InputError& e) {
    return e;
  }
  ADD_FAILURE() << "expected an InputError for:\n" << text;
  return io::InputError("", 0, "", "none");
}

TEST(LonLatSitesCsv, ReadsColumnsInAnyOrderAndSkipsComments) {
  const auto table = parse_lonlat_sites_csv(
      "# made by hand\n"
      "name,LAT,lon,weight,id,population\n"
      "\n"
      "Bern, 46.94809 ,7.44744,1.5,2661552,121631\r\n"
      "# a comment\n"
      "Thun,46.75118,7.62166,1.0,2658377,42136\n",
      "towns.csv");
  ASSERT_EQ(table.sites.size(), 2u);
  EXPECT_EQ(table.sites[0].id, "2661552");
  EXPECT_EQ(table.sites[0].lon, 7.44744);
  EXPECT_EQ(table.sites[0].lat, 46.94809);
  EXPECT_EQ(table.sites[0].weight, 1.5);
  EXPECT_EQ(table.line, (std::vector<int>{4, 6}));
  EXPECT_EQ(table.sites[0].name, "Bern");
  EXPECT_EQ(table.sites[1].name, "Thun");
}

TEST(LonLatSitesCsv, NameColumnIsOptional) {
  const auto table = parse_lonlat_sites_csv("id,lon,lat,weight\na,7.4,46.9,1\n", "towns.csv");
  EXPECT_EQ(table.sites[0].name, "");
  const auto empty = parse_lonlat_sites_csv("id,lon,lat,weight,Name\na,7.4,46.9,1,\nb,7.5,46.9,1\n", "towns.csv");
  EXPECT_EQ(empty.sites[0].name, "");
  EXPECT_EQ(empty.sites[1].name, "");  // a short row has no name
}

TEST(LonLatSitesCsv, ReportsEveryBadLineWithFileLineAndId) {
  const auto e = error_of(
      "id,lon,lat,weight\n"
      "a,7.4,46.9,1\n"
      "b,7.4,91,1\n"
      "c,east,46.9,1\n"
      "a,7.5,46.9,1\n"
      "d,7.4,46.9,0\n"
      "e,7.4,46.9,2\n"
      "f,7.4\n");
  ASSERT_EQ(e.problems.size(), 7u) << e.what();
  EXPECT_EQ(format_problem(e.file, e.problems[0]), "towns.csv:3: sensor 'b': lat must be in (-90, 90) (got 91)");
  EXPECT_EQ(format_problem(e.file, e.problems[1]), "towns.csv:4: sensor 'c': lon is not a number (got 'east')");
  EXPECT_EQ(format_problem(e.file, e.problems[2]), "towns.csv:5: sensor 'a': id already used on line 2");
  EXPECT_EQ(format_problem(e.file, e.problems[3]), "towns.csv:6: sensor 'd': weight must be finite and positive (got 0)");
  EXPECT_EQ(format_problem(e.file, e.problems[4]), "towns.csv:7: sensor 'e': same lon/lat as the sensor on line 2");
  EXPECT_EQ(e.problems[5].line, 8);
  EXPECT_NE(e.problems[5].message.find("missing lat"), std::string::npos);
  EXPECT_NE(e.problems[6].message.find("missing weight"), std::string::npos);
}

// The town lists are read like every covmap CSV (io/csv_table.h): a spreadsheet's semicolons with
// decimal commas, tabs, and quoted names give the same sites as the plain comma file.
TEST(LonLatSitesCsv, ReadsAnyDelimiterAndQuotedFieldsLikeTheOtherCsvReaders) {
  const auto want = parse_lonlat_sites_csv("id,lon,lat,weight,name\na,7.44744,46.94809,1.5,Bern\nb,7.5,46.75,1,Thun\n", "t.csv");
  for (const std::string text : {std::string("id;lon;lat;weight;name\na;7,44744;46,94809;1,5;Bern\nb;7,5;46,75;1;Thun\n"),
                                 std::string("id\tlon\tlat\tweight\tname\na\t7.44744\t46.94809\t1.5\tBern\nb\t7.5\t46.75\t1\tThun\n"),
                                 std::string("id|lon|lat|weight|name\n\"a\"|7.44744|46.94809|1.5|\"Bern\"\nb|7.5|46.75|1|Thun\n")}) {
    const auto got = parse_lonlat_sites_csv(text, "t.csv");
    ASSERT_EQ(got.sites.size(), want.sites.size()) << text;
    for (std::size_t i = 0; i < want.sites.size(); ++i) {
      EXPECT_EQ(got.sites[i].id, want.sites[i].id) << text;
      EXPECT_EQ(got.sites[i].name, want.sites[i].name) << text;
      EXPECT_EQ(got.sites[i].lon, want.sites[i].lon) << text;
      EXPECT_EQ(got.sites[i].lat, want.sites[i].lat) << text;
      EXPECT_EQ(got.sites[i].weight, want.sites[i].weight) << text;
    }
    EXPECT_EQ(got.line, want.line);
  }
  const auto quoted = parse_lonlat_sites_csv("id,lon,lat,weight,name\na,7.4,46.9,1,\"Biel, Bienne\"\n", "t.csv");
  EXPECT_EQ(quoted.sites[0].name, "Biel, Bienne");
}

TEST(LonLatSitesCsv, RejectsBadHeadersAndEmptyFiles) {
  EXPECT_NE(error_of("id,x,y,weight\n1,2,3,4\n").message().find("missing column 'lon'"), std::string::npos);
  EXPECT_NE(error_of("id,lon,lat,weight,lon\n").message().find("repeated column 'lon'"), std::string::npos);
  EXPECT_NE(error_of("id,lon,lat,weight,name,NAME\n").message().find("repeated column 'name'"), std::string::npos);
  EXPECT_NE(error_of("# nothing\n").message().find("no header"), std::string::npos);
  EXPECT_NE(error_of("id,lon,lat,weight\n").message().find("no sensors"), std::string::npos);
  EXPECT_NE(error_of("id,lon,lat,weight\n\"a,1,2,3\n").message().find("unterminated quoted field"), std::string::npos);
  try {
    read_lonlat_sites_csv("/nonexistent/towns.csv");
    ADD_FAILURE();
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.file, "/nonexistent/towns.csv");
  }
}

}  // namespace
}  // namespace covmap::mapgen
