// CSV delimiters (a semicolon-separated CSV must not get a misleading message): the readers
// take comma, semicolon, tab and '|' files, and decimal commas with any delimiter but the comma.
// The oracle is the same table written with commas and points.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "io/csv_fields.h"
#include "io/input_error.h"
#include "io/reported_sensors.h"
#include "io/sites_io.h"

namespace covmap::io {
namespace {

using detail::CsvDelimiter;

TEST(CsvFields, TheDelimiterIsTheOneThatSplitsTheHeaderMost) {
  EXPECT_EQ(detail::detect_delimiter("id,x,y,weight"), CsvDelimiter::kComma);
  EXPECT_EQ(detail::detect_delimiter("id;x;y;weight"), CsvDelimiter::kSemicolon);
  EXPECT_EQ(detail::detect_delimiter("id\tx\ty\tweight"), CsvDelimiter::kTab);
  EXPECT_EQ(detail::detect_delimiter("id|x|y|weight"), CsvDelimiter::kPipe);
  EXPECT_EQ(detail::detect_delimiter("\"a;b;c\",x"), CsvDelimiter::kComma);  // quoted ones do not count
  EXPECT_EQ(detail::detect_delimiter("id"), CsvDelimiter::kComma);           // one column: any will do
}

TEST(CsvFields, SplitsTrimsAndUnquotes) {
  const auto f = detail::split_csv_line(" a ; \"b;c\" ;\"d\"\"e\";", CsvDelimiter::kSemicolon);
  EXPECT_TRUE(f.error.empty());
  EXPECT_EQ(f.values, (std::vector<std::string>{"a", "b;c", "d\"e", ""}));
  const auto t = detail::split_csv_line("a\t b \t\tc", CsvDelimiter::kTab);
  EXPECT_EQ(t.values, (std::vector<std::string>{"a", "b", "", "c"}));  // an empty field between two tabs
  EXPECT_EQ(detail::split_csv_line("\"open;x", CsvDelimiter::kSemicolon).error, "unterminated quoted field");
  EXPECT_EQ(detail::split_csv_line("\"a\"b;x", CsvDelimiter::kSemicolon).error, "unexpected text after a quoted field");
}

TEST(CsvFields, DecimalCommasOnlyWhereTheyCannotBeDelimiters) {
  EXPECT_EQ(detail::number_text("7,4508", CsvDelimiter::kSemicolon), "7.4508");
  EXPECT_EQ(detail::number_text("-0,5e3", CsvDelimiter::kTab), "-0.5e3");
  EXPECT_EQ(detail::number_text("7,4508", CsvDelimiter::kComma), "7,4508");       // not a number: reported as such
  EXPECT_EQ(detail::number_text("1.234,5", CsvDelimiter::kSemicolon), "1.234,5");  // thousands separators: not guessed
  EXPECT_EQ(detail::number_text("a,b", CsvDelimiter::kSemicolon), "a,b");
}

const char* const kSitesComma = "id,x,y,weight,name\na,0.5,1.25,1,Bern\nb,10,-3.5,2.5,\"Thun, Lake\"\nc,4,8,0.75,\n";

TEST(CsvFields, SitesReadAlikeWhateverTheDelimiter) {
  const SiteTable want = parse_sites(kSitesComma, "s.csv", SitesFormat::kCsv);
  for (const std::string text : {std::string("id;x;y;weight;name\na;0,5;1,25;1;Bern\nb;10;-3,5;2,5;Thun, Lake\nc;4;8;0,75;\n"),
                                 std::string("id\tx\ty\tweight\tname\na\t0.5\t1.25\t1\tBern\nb\t10\t-3.5\t2.5\tThun, Lake\nc\t4\t8\t0.75\t\n"),
                                 std::string("id|x|y|weight|name\na|0.5|1.25|1|Bern\nb|10|-3.5|2.5|Thun, Lake\nc|4|8|0.75|\n")}) {
    const SiteTable got = parse_sites(text, "s.csv", SitesFormat::kCsv);
    ASSERT_EQ(got.sites.size(), want.sites.size()) << text;
    for (std::size_t i = 0; i < want.sites.size(); ++i) {
      EXPECT_EQ(got.sites[i].id, want.sites[i].id);
      EXPECT_EQ(got.sites[i].name, want.sites[i].name);
      EXPECT_EQ(got.sites[i].x, want.sites[i].x);
      EXPECT_EQ(got.sites[i].y, want.sites[i].y);
      EXPECT_EQ(got.sites[i].weight, want.sites[i].weight);
    }
  }
}

TEST(CsvFields, ReportedSensorsReadAlikeWhateverTheDelimiter) {
  ReportedSensorOptions planar;
  planar.alpha = 3.5;
  const auto want = parse_reported_sensors("id,x,y,tx_power_dbm\ns1,100.5,200,43\ns2,-50,75.25,37.5\n", "r.csv", planar,
                                           SensorsFormat::kCsv);
  const auto got = parse_reported_sensors("id;x;y;tx_power_dbm\ns1;100,5;200;43\ns2;-50;75,25;37,5\n", "r.csv", planar,
                                          SensorsFormat::kCsv);
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) {
    EXPECT_EQ(got[i].id, want[i].id);
    EXPECT_EQ(got[i].position.x, want[i].position.x);
    EXPECT_EQ(got[i].position.y, want[i].position.y);
    EXPECT_EQ(got[i].tx_power_dbm, want[i].tx_power_dbm);
    EXPECT_EQ(got[i].weight, want[i].weight);
  }
}

// Before: "id;x;y;weight" was one column named "id;x;y;weight", and the message said the columns
// were missing. A comma file with a decimal comma still says what is wrong with the number.
TEST(CsvFields, ACommaFileWithADecimalCommaIsNotGuessed) {
  try {
    parse_sites("id,x,y,weight\na,\"0,5\",1,1\n", "s.csv", SitesFormat::kCsv);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("x is not a number"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace covmap::io
