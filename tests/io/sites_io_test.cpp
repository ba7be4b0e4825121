#include "io/sites_io.h"

#include <gtest/gtest.h>

#include <bit>
#include <cfloat>
#include <cmath>
#include <sstream>

#include "io_test_util.h"

namespace covmap::io {
namespace {

using testing::input_error_from;
using testing::TempDir;

SiteTable csv(const std::string& text) { return parse_sites(text, "sites.csv"); }
SiteTable json(const std::string& text) { return parse_sites(text, "sites.json"); }
InputError csv_error(const std::string& text) { return input_error_from([&] { csv(text); }); }
InputError json_error(const std::string& text) { return input_error_from([&] { json(text); }); }

std::string json_sites(const std::string& entries) {
  return R"({"format":"covmap.sites/1","sites":[)" + entries + "]}";
}

// ---- CSV ----

TEST(SitesCsv, ReadsRowsWithCommentsBlankLinesAndSpaces) {
  const auto t = csv("# sensors\n"
                     "id, x, y, weight\n"
                     "\n"
                     "a, 0, 0, 1\n"
                     "  # disabled: z,9,9,1\n"
                     "b,1.5,-2,2.5\r\n");
  ASSERT_EQ(t.sites.size(), 2u);
  EXPECT_EQ(t.sites[1].id, "b");
  EXPECT_EQ(t.sites[1].x, 1.5);
  EXPECT_EQ(t.sites[1].y, -2);
  EXPECT_EQ(t.sites[1].weight, 2.5);
  EXPECT_EQ(t.origin[0], "line 4");
  EXPECT_EQ(t.origin[1], "line 6");
}

TEST(SitesCsv, ColumnsInAnyOrderWithExtraColumns) {
  const auto t = csv("Weight,ID,note,y,x\n2,a,hello,5,7\n");
  ASSERT_EQ(t.sites.size(), 1u);
  EXPECT_EQ(t.sites[0].id, "a");
  EXPECT_EQ(t.sites[0].x, 7);
  EXPECT_EQ(t.sites[0].y, 5);
  EXPECT_EQ(t.sites[0].weight, 2);
}

TEST(SitesCsv, QuotedIdsMayHoldCommasAndQuotes) {
  const auto t = csv("id,x,y,weight\n\"north, \"\"big\"\" one\",0,0,+1e0\n");
  EXPECT_EQ(t.sites[0].id, "north, \"big\" one");
  EXPECT_EQ(t.sites[0].weight, 1);
}

TEST(SitesCsv, NegativeWeightNamesFileLineAndSite) {
  const auto e = csv_error("id,x,y,weight\na,0,0,1\n\nb,1,1,-1\n");
  EXPECT_STREQ(e.what(), "sites.csv:4: site 'b': weight must be positive (got -1)");
}

TEST(SitesCsv, ZeroWeight) {
  EXPECT_EQ(csv_error("id,x,y,weight\na,0,0,0\n").message(), "weight must be positive (got 0)");
}

TEST(SitesCsv, NonFiniteValues) {
  EXPECT_EQ(csv_error("id,x,y,weight\na,0,0,nan\n").message(), "weight must be finite (got nan)");
  EXPECT_EQ(csv_error("id,x,y,weight\na,inf,0,1\n").message(), "x must be finite (got inf)");
  EXPECT_EQ(csv_error("id,x,y,weight\na,0,1e999,1\n").message(), "y is out of the range of a double (got '1e999')");
}

TEST(SitesCsv, NonNumericField) {
  const auto e = csv_error("id,x,y,weight\na,0,0,1\nq,zero,0,1\n");
  EXPECT_EQ(e.line(), 3);
  EXPECT_EQ(e.item(), "site 'q'");
  EXPECT_EQ(e.message(), "x is not a number (got 'zero')");
}

TEST(SitesCsv, MissingFieldAndEmptyId) {
  const auto e = csv_error("id,x,y,weight\na,0,0\n,1,1,1\n");
  ASSERT_EQ(e.problems.size(), 2u);
  EXPECT_EQ(e.problems[0].line, 2);
  EXPECT_EQ(e.problems[0].message, "missing weight (the row has 3 fields)");
  EXPECT_EQ(e.problems[1].line, 3);
  EXPECT_EQ(e.problems[1].item, "row");
  EXPECT_EQ(e.problems[1].message, "id is empty");
}

TEST(SitesCsv, HeaderProblems) {
  const auto missing = csv_error("id,x,y\na,0,0\n");
  EXPECT_EQ(missing.line(), 1);
  EXPECT_EQ(missing.item(), "header");
  EXPECT_NE(missing.message().find("missing column 'weight'"), std::string::npos);
  EXPECT_NE(csv_error("id,x,x,y,weight\n").message().find("repeated column 'x'"), std::string::npos);
  EXPECT_NE(csv_error("").message().find("no header line"), std::string::npos);
  EXPECT_EQ(csv_error("id,x,y,weight\n# nothing\n").message(), "no sites");
}

TEST(SitesCsv, DuplicateIdNamesBothLines) {
  const auto e = csv_error("id,x,y,weight\na,0,0,1\nb,1,0,1\na,2,0,1\n");
  EXPECT_STREQ(e.what(), "sites.csv:4: site 'a': duplicate id; first used by site 'a' (line 2)");
}

TEST(SitesCsv, DuplicatePositionNamesBothSitesAndLines) {
  const auto e = csv_error("id,x,y,weight\na,1,2,1\nb,5,5,1\nc,1.0,2e0,3\n");
  EXPECT_STREQ(e.what(), "sites.csv:4: site 'c': same position (1, 2) as site 'a' (line 2)");
}

TEST(SitesCsv, NegativeZeroIsTheSamePosition) {
  EXPECT_NE(csv_error("id,x,y,weight\na,0,0,1\nb,-0,0,2\n").message().find("same position"), std::string::npos);
}

TEST(SitesCsv, AllProblemsReportedTogetherInFileOrder) {
  const auto e = csv_error("id,x,y,weight\n"
                           "a,0,0,-1\n"   // 2
                           "b,0,1,1\n"    // 3
                           "b,0,2,1\n"    // 4 duplicate id
                           "c,x,0,1\n"    // 5
                           "d,0,1,1\n");  // 6 same position as b
  ASSERT_EQ(e.problems.size(), 4u) << e.what();
  EXPECT_EQ(e.problems[0].line, 2);
  EXPECT_EQ(e.problems[1].line, 4);
  EXPECT_EQ(e.problems[2].line, 5);
  EXPECT_EQ(e.problems[3].line, 6);
  EXPECT_NE(std::string(e.what()).find("sites.csv: 4 problems"), std::string::npos);
}

// The same mistake on 30 rows is one line with a count in the message; every row stays in problems.
TEST(SitesCsv, RepeatedMistakesAreOneLineButAllKeptInProblems) {
  std::string text = "id,x,y,weight\n";
  for (int i = 0; i < 30; ++i) {
    const std::string n = std::to_string(i);
    text.append("s").append(n).append(",").append(n).append(",0,-1\n");
  }
  const auto e = csv_error(text);
  EXPECT_EQ(e.problems.size(), 30u);
  EXPECT_NE(std::string(e.what()).find("(and 29 more like it)"), std::string::npos) << e.what();
}

TEST(SitesCsv, IdMustBeUtf8SoItCanBeWrittenAsJsonAndSvg) {
  const auto e = csv_error("id,x,y,weight\n\xff\xfe,0,0,1\n");
  EXPECT_EQ(e.line(), 2);
  EXPECT_EQ(e.message(), "id is not valid UTF-8");
}

TEST(SitesCsv, ByteOrderMarkIsSkipped) {
  EXPECT_EQ(csv("\xEF\xBB\xBFid,x,y,weight\na,0,0,1\n").sites[0].id, "a");
}

TEST(SitesCsv, OptionalNameColumnIsKept) {
  const auto t = csv("id,x,y,weight,Name,note\n"
                     "a,0,0,1,North mast,x\n"
                     "b,1,0,1,\"Gate, west\",y\n"
                     "c,2,0,1,,z\n"
                     "d,3,0,1\n");  // a short row: the name is optional, so no name
  ASSERT_EQ(t.sites.size(), 4u);
  EXPECT_EQ(t.sites[0].name, "North mast");
  EXPECT_EQ(t.sites[1].name, "Gate, west");
  EXPECT_EQ(t.sites[2].name, "");
  EXPECT_EQ(t.sites[3].name, "");
  EXPECT_EQ(t.sites[0].id, "a");  // the name does not replace the id
}

TEST(SitesCsv, WithoutNameColumnNamesAreEmpty) {
  const auto t = csv("id,x,y,weight,note\na,0,0,1,North mast\n");
  ASSERT_EQ(t.sites.size(), 1u);
  EXPECT_EQ(t.sites[0].name, "");
}

TEST(SitesCsv, NameProblems) {
  const auto repeated = csv_error("id,x,y,weight,name,NAME\na,0,0,1,p,q\n");
  EXPECT_EQ(repeated.line(), 1);
  EXPECT_NE(std::string(repeated.what()).find("repeated column 'name'"), std::string::npos) << repeated.what();
  const auto bad = csv_error("id,x,y,weight,name\na,0,0,1,\xff\n");
  EXPECT_EQ(bad.line(), 2);
  EXPECT_EQ(bad.message(), "name is not valid UTF-8");
}

// ---- JSON ----

TEST(SitesJson, ReadsStringAndIntegerIds) {
  const auto t = json(json_sites(R"({"id":"a","x":0,"y":0,"weight":1},{"id":7,"x":1.25,"y":-3,"weight":0.5})"));
  ASSERT_EQ(t.sites.size(), 2u);
  EXPECT_EQ(t.sites[1].id, "7");
  EXPECT_EQ(t.sites[1].x, 1.25);
  EXPECT_EQ(t.sites[1].weight, 0.5);
  EXPECT_EQ(t.origin[1], "sites[1]");
}

TEST(SitesJson, ByteOrderMarkIsSkipped) {
  EXPECT_EQ(parse_sites("\xEF\xBB\xBF" + json_sites(R"({"id":"a","x":0,"y":0,"weight":1})"), "s.txt").sites.size(), 1u);
}

TEST(SitesJson, SyntaxErrorGivesBytePositionAndLine) {
  const auto e = json_error("{\"format\":\"covmap.sites/1\",\n\"sites\":[ {\"id\":\"a\", x} ]}");
  EXPECT_EQ(e.line(), 2);
  EXPECT_NE(e.message().find("invalid JSON at byte"), std::string::npos) << e.what();
  EXPECT_EQ(e.message().find("[json.exception"), std::string::npos) << e.what();
}

TEST(SitesJson, FormatTag) {
  EXPECT_STREQ(json_error(R"({"sites":[]})").what(), "sites.json: format: missing; expected \"covmap.sites/1\"");
  EXPECT_STREQ(json_error(R"({"format":"covmap.sites/2","sites":[]})").what(),
               "sites.json: format: expected \"covmap.sites/1\" (got string \"covmap.sites/2\")");
  EXPECT_EQ(json_error(R"({"format":"covmap.sites/1"})").item(), "sites");
  EXPECT_EQ(json_error(json_sites("")).message(), "no sites");
}

TEST(SitesJson, MissingAndMistypedFieldsNameIndexAndId) {
  const auto e = json_error(json_sites(R"({"id":"a","x":0,"y":0,"weight":1},)"
                                       R"({"id":"b","x":0,"y":1},)"
                                       R"({"id":"c","x":"2","y":1,"weight":1},)"
                                       R"({"id":1.5,"x":9,"y":1,"weight":1},)"
                                       R"({"x":3,"y":3,"weight":1},)"
                                       R"(42)"));
  ASSERT_EQ(e.problems.size(), 5u) << e.what();
  EXPECT_EQ(format_problem(e.file, e.problems[0]), "sites.json: sites[1] (site 'b'): missing weight");
  EXPECT_EQ(format_problem(e.file, e.problems[1]), "sites.json: sites[2] (site 'c'): x must be a number (got string \"2\")");
  EXPECT_EQ(format_problem(e.file, e.problems[2]), "sites.json: sites[3]: id must be a string or an integer (got number 1.5)");
  EXPECT_EQ(format_problem(e.file, e.problems[3]), "sites.json: sites[4]: missing id");
  EXPECT_EQ(format_problem(e.file, e.problems[4]), "sites.json: sites[5]: must be an object (got number 42)");
}

TEST(SitesJson, OptionalNameIsKept) {
  const auto t = json(json_sites(R"({"id":"a","x":0,"y":0,"weight":1,"name":"North \u00e9"},)"
                                 R"({"id":"b","x":1,"y":0,"weight":1},)"
                                 R"({"id":"c","x":2,"y":0,"weight":1,"name":""})"));
  ASSERT_EQ(t.sites.size(), 3u);
  EXPECT_EQ(t.sites[0].name, "North \xC3\xA9");
  EXPECT_EQ(t.sites[1].name, "");
  EXPECT_EQ(t.sites[2].name, "");
}

TEST(SitesJson, NameThatIsNotAStringIsAnErrorNamingTheSite) {
  const auto e = json_error(json_sites(R"({"id":"a","x":0,"y":0,"weight":1,"name":17},)"
                                       R"({"id":"b","x":1,"y":0,"weight":1,"name":null})"));
  ASSERT_EQ(e.problems.size(), 2u) << e.what();
  EXPECT_EQ(format_problem(e.file, e.problems[0]),
            "sites.json: sites[0] (site 'a'): name must be a string (got number 17; leave it out for no name)");
  EXPECT_EQ(format_problem(e.file, e.problems[1]),
            "sites.json: sites[1] (site 'b'): name must be a string (got null; leave it out for no name)");
}

TEST(SitesJson, ValueProblems) {
  const auto e = json_error(json_sites(R"({"id":"a","x":0,"y":0,"weight":0},)"
                                       R"({"id":"b","x":1,"y":0,"weight":-2})"));
  ASSERT_EQ(e.problems.size(), 2u);
  EXPECT_EQ(format_problem(e.file, e.problems[0]), "sites.json: sites[0] (site 'a'): weight must be positive (got 0)");
  EXPECT_EQ(format_problem(e.file, e.problems[1]), "sites.json: sites[1] (site 'b'): weight must be positive (got -2)");
}

TEST(SitesJson, OverflowingNumberIsAnErrorWithItsLine) {
  const auto e = json_error("{\"format\":\"covmap.sites/1\",\"sites\":[\n{\"id\":\"a\",\"x\":1e999,\"y\":0,\"weight\":1}]}");
  EXPECT_STREQ(e.what(), "sites.json:2: invalid JSON: number overflow parsing '1e999'");
}

TEST(SitesJson, DuplicatesNameBothSites) {
  const auto e = json_error(json_sites(R"({"id":"a","x":1,"y":2,"weight":1},)"
                                       R"({"id":"b","x":1,"y":2,"weight":2},)"
                                       R"({"id":"a","x":3,"y":2,"weight":2})"));
  ASSERT_EQ(e.problems.size(), 2u);
  EXPECT_EQ(format_problem(e.file, e.problems[0]), "sites.json: sites[1] (site 'b'): same position (1, 2) as site 'a' (sites[0])");
  EXPECT_EQ(format_problem(e.file, e.problems[1]), "sites.json: sites[2] (site 'a'): duplicate id; first used by site 'a' (sites[0])");
}

// ---- files and detection ----

TEST(ReadSites, DetectsFormatByExtensionThenContent) {
  TempDir dir;
  EXPECT_EQ(read_sites(dir.write("a.csv", "id,x,y,weight\na,0,0,1\n")).sites.size(), 1u);
  EXPECT_EQ(read_sites(dir.write("b.json", json_sites(R"({"id":"a","x":0,"y":0,"weight":1})"))).sites.size(), 1u);
  EXPECT_EQ(read_sites(dir.write("c.txt", "  " + json_sites(R"({"id":"a","x":0,"y":0,"weight":1})"))).sites.size(), 1u);
  EXPECT_EQ(read_sites(dir.write("d.txt", "id,x,y,weight\na,0,0,1\n")).sites.size(), 1u);
  EXPECT_EQ(read_sites(dir.write("e.dat", "id,x,y,weight\na,0,0,1\n"), SitesFormat::kCsv).sites.size(), 1u);
}

TEST(ReadSites, ErrorsCarryThePathAsGiven) {
  TempDir dir;
  const auto file = dir.write("s.csv", "id,x,y,weight\na,0,0,-3\n");
  EXPECT_EQ(std::string(input_error_from([&] { read_sites(file); }).what()),
            file.string() + ":2: site 'a': weight must be positive (got -3)");
}

TEST(ReadSites, UnreadableFile) {
  TempDir dir;
  const auto missing = dir / "nope.csv";
  const auto e = input_error_from([&] { read_sites(missing); });
  EXPECT_EQ(e.file, missing.string());
  EXPECT_NE(e.message().find("cannot open file"), std::string::npos);
  EXPECT_NE(input_error_from([&] { read_sites(dir.path()); }).message().find("directory"), std::string::npos);
}

// ---- writing ----

TEST(WriteSitesJson, RoundTripsBitExactly) {
  const std::vector<Site> sites = {{"a", 0.1, -0.0, 1.0 / 3.0},
                                            {"b \"quoted\" \xC3\xA9", 5e-324, DBL_MAX, std::nextafter(1.0, 2.0)},
                                            {"7", -123456789.123456789, 1e-300, 1e300}};
  std::ostringstream out;
  write_sites_json(sites, out);
  const auto back = json(out.str()).sites;
  ASSERT_EQ(back.size(), sites.size());
  for (std::size_t i = 0; i < sites.size(); ++i) {
    EXPECT_EQ(back[i].id, sites[i].id);
    EXPECT_EQ(std::bit_cast<std::uint64_t>(back[i].x), std::bit_cast<std::uint64_t>(sites[i].x)) << i;
    EXPECT_EQ(std::bit_cast<std::uint64_t>(back[i].y), std::bit_cast<std::uint64_t>(sites[i].y)) << i;
    EXPECT_EQ(std::bit_cast<std::uint64_t>(back[i].weight), std::bit_cast<std::uint64_t>(sites[i].weight)) << i;
  }
}

TEST(WriteSitesJson, NamesRoundTripAndEmptyNamesAreLeftOut) {
  std::vector<Site> sites = {{"a", 0, 0, 1}, {"b", 1, 0, 1}};
  sites[0].name = "North \"mast\" \xC3\xA9";
  std::ostringstream out;
  write_sites_json(sites, out);
  EXPECT_EQ(out.str().find("\"name\":\"\""), std::string::npos) << out.str();
  const auto back = json(out.str()).sites;
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[0].name, sites[0].name);
  EXPECT_EQ(back[1].name, "");
}

TEST(WriteSitesJson, RefusesNonFiniteValues) {
  std::ostringstream out;
  EXPECT_THROW(write_sites_json({{"a", NAN, 0, 1}}, out), std::invalid_argument);
}

}  // namespace
}  // namespace covmap::io
