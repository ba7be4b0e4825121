// io/fast_readers.h: the fast paths against the reference (nlohmann DOM) readers as the oracle.
// The contract: whenever a fast path returns a result, the reference accepts the same text and
// returns the identical result, bit for bit; and the writers' own output always takes the fast
// path (otherwise it would not be fast). Mutated texts (every byte deleted, replaced, or preceded
// by a JSON-significant character) probe the first half where it is easiest to get wrong.
#include "io/fast_readers.h"

#include <gtest/gtest.h>

#include <bit>
#include <sstream>

#include "diagram_samples.h"
#include "io/site_parsers.h"
#include "io_test_util.h"

namespace covmap::io {
namespace {

using detail::parse_diagram_json_fast;
using detail::parse_diagram_json_reference;
using detail::parse_sites_json_fast;
using testing::expect_identical;
using testing::mutate_all;
using testing::sample;
using testing::same;

constexpr ArcLabels kAllModes[] = {ArcLabels::kRequired, ArcLabels::kIgnored, ArcLabels::kOptional};

std::string to_json(const Diagram& d) {
  std::ostringstream out;
  write_diagram_json(d, out);
  return out.str();
}

std::string sites_json(const std::vector<Site>& sites) {
  std::ostringstream out;
  write_sites_json(sites, out);
  return out.str();
}

// True when the fast path took the text; then the reference must agree exactly.
bool graph_fast_path_agrees(const std::string& text, ArcLabels labels) {
  const auto fast = parse_diagram_json_fast(text, labels);
  if (!fast) return false;
  Diagram reference;
  EXPECT_NO_THROW(reference = parse_diagram_json_reference(text, "g.json", labels)) << text;
  expect_identical(*fast, reference);
  return true;
}

bool sites_fast_path_agrees(const std::string& text) {
  const auto fast = parse_sites_json_fast(text);
  if (!fast) return false;
  SiteTable reference;
  EXPECT_NO_THROW(reference = detail::parse_sites_json(text, "s.json")) << text;
  EXPECT_EQ(fast->origin, reference.origin);
  EXPECT_EQ(fast->sites.size(), reference.sites.size());
  for (std::size_t i = 0; i < std::min(fast->sites.size(), reference.sites.size()); ++i) {
    const Site &a = fast->sites[i], &b = reference.sites[i];
    EXPECT_TRUE(a.id == b.id && a.name == b.name && same(a.x, b.x) && same(a.y, b.y) && same(a.weight, b.weight))
        << "site " << i << " of " << text;
  }
  return true;
}

TEST(FastReaders, WriterOutputTakesTheFastPathAndAgrees) {
  const std::string text = to_json(sample());
  for (const ArcLabels labels : kAllModes) EXPECT_TRUE(graph_fast_path_agrees(text, labels));
  // The parsed diagram is the written one.
  expect_identical(*parse_diagram_json_fast(text, ArcLabels::kRequired), sample());
  EXPECT_TRUE(sites_fast_path_agrees(sites_json(sample().sites)));
}

// A small graph keeps the number of variants (about 35 per byte, three modes) manageable.
std::string small_graph_text() {
  Diagram d;
  d.sites = {{"a", 0.5, -0.0, 1.0}, {"7", 1e-7, 2.0, 2.5}};
  d.sites[1].name = "b\n\"c\"";
  d.nodes = {{0.1, 1e16}};
  d.arcs = {{0, 0, Circle{1, 2, 3}, false, 0, 1, false}, {kNone, 0, Line{0, 0, 0, 1}, true, 1, kNone, true}};
  add_face(d, {1, true, false}, {{{0, true}, {1, false}}});
  d.clip = {{-10, -10}, {10, -10}, {10, 10}};
  return to_json(d);
}

TEST(FastReaders, MutatedArcGraphsEitherMissOrAgree) {
  const std::string text = small_graph_text();
  for (const ArcLabels labels : kAllModes) {
    const auto [taken, missed] = mutate_all(text, [&](const std::string& t) { return graph_fast_path_agrees(t, labels); });
    EXPECT_GT(taken, 100);  // whitespace, digits and unknown spellings the fast path may take
    EXPECT_GT(missed, 1000);
  }
}

TEST(FastReaders, MutatedSiteListsEitherMissOrAgree) {
  std::vector<Site> sites = {{"a", 0.5, -0.0, 1.0}, {"b", 1e-7, 2.0, 2.5}, {"c", 3, 4, 0.25}};
  sites[2].name = "n\t\\";
  const auto [taken, missed] = mutate_all(sites_json(sites), sites_fast_path_agrees);
  EXPECT_GT(taken, 50);
  EXPECT_GT(missed, 500);
}

Diagram parse_public(const std::string& text, ArcLabels labels = ArcLabels::kRequired) {
  return parse_diagram_json(text, "g.json", labels);
}

const char* const kTwoSites = R"("sites":[{"id":"a","x":0,"y":0,"weight":1},{"id":"b","x":2,"y":0,"weight":1}])";
const char* const kOneLine = R"("arcs":[{"from":null,"to":null,"line":{"x":1,"y":0,"dx":0,"dy":1},"sites":[1,0]}])";

TEST(FastReaders, MembersInAnyOrderThatNeedsNoLookahead) {
  // format last, unknown members anywhere, nodes before sites: all taken.
  const std::string text = std::string("{\"tool\":{\"v\":[1,2.5e3,null,true]},\"nodes\":[],") + kTwoSites + "," +
                           kOneLine + ",\"format\":\"covmap.arcgraph/1\"}";
  EXPECT_TRUE(graph_fast_path_agrees(text, ArcLabels::kRequired));
  // Labels before the sites they index: missed, and the public reader still reads it.
  const std::string late = std::string("{\"format\":\"covmap.arcgraph/1\",\"nodes\":[],") + kOneLine + "," + kTwoSites + "}";
  EXPECT_FALSE(parse_diagram_json_fast(late, ArcLabels::kRequired));
  EXPECT_FALSE(parse_diagram_json_fast(late, ArcLabels::kOptional));
  expect_identical(parse_public(late), parse_diagram_json_reference(late, "g.json", ArcLabels::kRequired));
  expect_identical(parse_public(late, ArcLabels::kOptional),
                   parse_diagram_json_reference(late, "g.json", ArcLabels::kOptional));
  EXPECT_TRUE(graph_fast_path_agrees(late, ArcLabels::kIgnored));
}

TEST(FastReaders, OptionalLabelsFollowTheSites) {
  const std::string empty_sites = std::string("{\"format\":\"covmap.arcgraph/1\",\"sites\":[],\"nodes\":[],") +
                                  R"("arcs":[{"from":null,"to":null,"line":{"x":1,"y":0,"dx":0,"dy":1}}]})";
  ASSERT_TRUE(graph_fast_path_agrees(empty_sites, ArcLabels::kOptional));
  EXPECT_EQ(parse_diagram_json_fast(empty_sites, ArcLabels::kOptional)->arcs[0].left_site, kNone);
  const std::string with_sites = std::string("{\"format\":\"covmap.arcgraph/1\",") + kTwoSites + ",\"nodes\":[]," + kOneLine + "}";
  ASSERT_TRUE(graph_fast_path_agrees(with_sites, ArcLabels::kOptional));
  EXPECT_EQ(parse_diagram_json_fast(with_sites, ArcLabels::kOptional)->arcs[0].left_site, 1);
}

TEST(FastReaders, NumbersAndStringsAsTheReferenceReadsThem) {
  // "-0" is an integer token: the reference reads +0; "-0.0" keeps the sign.
  const auto one_site = [](const std::string& id, const std::string& x) {
    return "{\"format\":\"covmap.sites/1\",\"sites\":[{\"id\":" + id + ",\"x\":" + x + ",\"y\":0.5,\"weight\":1}]}";
  };
  ASSERT_TRUE(sites_fast_path_agrees(one_site("\"a\"", "-0")));
  EXPECT_FALSE(std::signbit(parse_sites_json_fast(one_site("\"a\"", "-0"))->sites[0].x));
  ASSERT_TRUE(sites_fast_path_agrees(one_site("\"a\"", "-0.0")));
  EXPECT_TRUE(std::signbit(parse_sites_json_fast(one_site("\"a\"", "-0.0"))->sites[0].x));
  for (const char* x : {"18446744073709551616", "-9223372036854775809", "123456789012345678901234567890", "1E2", "4.9e-324"})
    EXPECT_TRUE(sites_fast_path_agrees(one_site("\"a\"", x))) << x;
  EXPECT_TRUE(sites_fast_path_agrees(one_site("-12", "1")));
  EXPECT_EQ(parse_sites_json_fast(one_site("-12", "1"))->sites[0].id, "-12");
  EXPECT_TRUE(sites_fast_path_agrees(one_site("\"Z\xC3\xBCrich \\\"\\/\\\\\"", "1")));
  // Missed (the reference decides): \u escapes, invalid UTF-8, overflow, duplicates, "-0" ids.
  for (const auto& text : {one_site("\"\\u00e9\"", "1"), one_site("\"\xC3\"", "1"), one_site("\"a\"", "1e999"),
                           one_site("\"a\"", "1e-400"), one_site("-0", "1"), one_site("12345678901234567890", "1")})
    EXPECT_FALSE(parse_sites_json_fast(text)) << text;
  EXPECT_FALSE(parse_sites_json_fast(R"({"format":"covmap.sites/1","format":"covmap.sites/1","sites":[]})"));
}

TEST(FastReaders, RawUtf8MemberNamesAreTakenInvalidOnesMissed) {
  const std::string site = R"({"id":"a","x":0,"y":0,"weight":1)";
  EXPECT_TRUE(sites_fast_path_agrees("{\"format\":\"covmap.sites/1\",\"Größe\":1,\"sites\":[" + site + ",\"Zürich\":2}]}"));
  EXPECT_FALSE(parse_sites_json_fast("{\"format\":\"covmap.sites/1\",\"\xC3\":1,\"sites\":[" + site + "}]}"));
  EXPECT_FALSE(parse_sites_json_fast("{\"format\":\"covmap.sites/1\",\"\\u00e9\":1,\"sites\":[" + site + "}]}"));
}

TEST(FastReaders, ErrorsComeFromTheReferenceReader) {
  // The public readers' messages are the reference's (tests/io/diagram_json_test and sites_io_test
  // check their wording); here only that a fast-path miss still reaches them.
  const std::string bad = std::string("{\"format\":\"covmap.arcgraph/1\",") + kTwoSites +
                          R"(,"nodes":[],"arcs":[{"from":3,"to":null,"line":{"x":1,"y":0,"dx":0,"dy":1},"sites":[1,0]}]})";
  const auto e = testing::input_error_from([&] { parse_public(bad); });
  EXPECT_NE(std::string(e.what()).find("arcs[0].from: node index 3 out of range (0 nodes)"), std::string::npos) << e.what();
}

}  // namespace
}  // namespace covmap::io
