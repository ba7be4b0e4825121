#include "io/diagram_json.h"

#include <gtest/gtest.h>

#include <bit>
#include <cfloat>
#include <cmath>
#include <nlohmann/json.hpp>
#include <functional>
#include <sstream>

#include "diagram_samples.h"
#include "io/diagram_json_write.h"
#include "io_test_util.h"

namespace covmap::io {
namespace {

using testing::expect_identical;
using testing::input_error_from;
using testing::sample;

std::string to_json(const Diagram& d) {
  std::ostringstream out;
  write_diagram_json(d, out);
  return out.str();
}

TEST(DiagramJson, RoundTripIsIdenticalDownToTheBits) {
  const auto d = sample();
  const std::string text = to_json(d);
  expect_identical(d, parse_diagram_json(text, "g.json"));
  EXPECT_EQ(to_json(parse_diagram_json(text, "g.json")), text);  // and writing is deterministic
}

TEST(DiagramJson, TextInMemoryIsTheStreamedTextWithinItsReservedBound) {
  // The longest spellings everywhere: 24-character numbers, control characters (six-byte escapes).
  Diagram worst = sample();
  const double longest = -2.2250738585072014e-308;
  for (auto& s : worst.sites) s.x = s.y = longest, s.id += "\x01\x02", s.name = "\x1f\x1f";
  for (auto& n : worst.nodes) n.x = n.y = longest;
  for (auto& p : worst.clip) p.x = longest;
  for (const Diagram& d : {sample(), worst}) {
    const std::string text = diagram_json_text(d);
    EXPECT_EQ(text, to_json(d));
    EXPECT_LE(text.size(), detail::diagram_json_size_bound(d));
  }
  // The bound is not wildly above the text either (it is reserved, though never touched beyond it).
  const std::string text = diagram_json_text(sample());
  EXPECT_LT(detail::diagram_json_size_bound(sample()), 8 * text.size());
}

TEST(DiagramJson, WritesNullsFrameFlagAndShortestDoubles) {
  const auto j = nlohmann::json::parse(to_json(sample()));
  EXPECT_EQ(j["format"], "covmap.arcgraph/1");
  EXPECT_TRUE(j["arcs"][0]["from"].is_null());
  EXPECT_TRUE(j["arcs"][0]["to"].is_null());
  EXPECT_EQ(j["arcs"][0]["circle"]["ccw"], true);
  EXPECT_EQ(j["arcs"][1]["circle"]["ccw"], false);
  EXPECT_TRUE(j["arcs"][2].contains("line"));
  EXPECT_FALSE(j["arcs"][0].contains("frame"));
  EXPECT_EQ(j["arcs"][5]["frame"], true);
  EXPECT_TRUE(j["arcs"][5]["sites"][1].is_null());
  EXPECT_EQ(j["faces"][1]["boundaries"][1][0], nlohmann::json::array({3, false}));
  // The shortest representation, not 17 digits.
  EXPECT_NE(to_json(sample()).find("\"x\":0.1,"), std::string::npos);
}

TEST(DiagramJson, FacesAndClipAreOptional) {
  auto j = nlohmann::json::parse(to_json(sample()));
  j.erase("faces");
  j.erase("clip");
  const auto d = parse_diagram_json(j.dump(), "other-tool.json");
  EXPECT_TRUE(d.faces.empty());
  EXPECT_TRUE(d.clip.empty());
  EXPECT_EQ(d.arcs.size(), 6u);
}

// kOptional (recognition's input): a graph with sites keeps them and its arcs' labels (checked as
// for a diagram) but not its faces; without sites, or with an empty list, it reads as kIgnored.
TEST(DiagramJson, OptionalLabelsAreReadWhenSitesAreCarried) {
  const Diagram full = sample();
  const Diagram carried = parse_diagram_json(to_json(full), "g.json", ArcLabels::kOptional);
  EXPECT_EQ(carried.sites.size(), full.sites.size());
  for (std::size_t a = 0; a < full.arcs.size(); ++a) {
    EXPECT_EQ(carried.arcs[a].left_site, full.arcs[a].left_site) << "arc " << a;
    EXPECT_EQ(carried.arcs[a].right_site, full.arcs[a].right_site) << "arc " << a;
  }
  EXPECT_TRUE(carried.faces.empty());
  auto j = nlohmann::json::parse(to_json(full));
  for (auto& arc : j["arcs"]) arc.erase("sites");
  j["sites"] = nlohmann::json::array();
  const Diagram bare = parse_diagram_json(j.dump(), "g.json", ArcLabels::kOptional);
  EXPECT_TRUE(bare.sites.empty());
  for (const Arc& a : bare.arcs) EXPECT_TRUE(a.left_site == kNone && a.right_site == kNone);
  j.erase("sites");
  EXPECT_EQ(parse_diagram_json(j.dump(), "g.json", ArcLabels::kOptional).arcs.size(), full.arcs.size());
  // Sites carried but an arc without its labels: the reader says where.
  auto half = nlohmann::json::parse(to_json(full));
  half["arcs"][2].erase("sites");
  const auto e = input_error_from([&] { parse_diagram_json(half.dump(), "g.json", ArcLabels::kOptional); });
  EXPECT_NE(std::string(e.what()).find("arcs[2]"), std::string::npos) << e.what();
}

TEST(DiagramJson, UnknownMembersAreIgnored) {
  auto j = nlohmann::json::parse(to_json(sample()));
  j["generator"] = "elsewhere";
  j["arcs"][0]["colour"] = "red";
  EXPECT_NO_THROW(parse_diagram_json(j.dump(), "g.json"));
}

// Applies `edit` to the JSON of sample() and returns the reader's complaint.
InputError error_after(const std::function<void(nlohmann::json&)>& edit) {
  auto j = nlohmann::json::parse(to_json(sample()));
  edit(j);
  return input_error_from([&] { parse_diagram_json(j.dump(), "g.json"); });
}

TEST(DiagramJson, IndexOutOfRangeNamesThePath) {
  EXPECT_STREQ(error_after([](auto& j) { j["arcs"][1]["to"] = 99; }).what(),
               "g.json: arcs[1].to: node index 99 out of range (3 nodes)");
  EXPECT_STREQ(error_after([](auto& j) { j["arcs"][1]["from"] = -1; }).what(),
               "g.json: arcs[1].from: node index -1 out of range (3 nodes)");
  EXPECT_STREQ(error_after([](auto& j) { j["arcs"][2]["sites"][0] = 3; }).what(),
               "g.json: arcs[2].sites[0]: site index 3 out of range (3 sites)");
  EXPECT_STREQ(error_after([](auto& j) { j["faces"][2]["boundaries"][0][1][0] = 6; }).what(),
               "g.json: faces[2].boundaries[0][1][0]: arc index 6 out of range (6 arcs)");
  EXPECT_STREQ(error_after([](auto& j) { j["faces"][0]["site"] = nullptr; }).what(),
               "g.json: faces[0].site: must be a site index (got null)");
  EXPECT_STREQ(error_after([](auto& j) { j["arcs"][1]["to"] = 1.0; }).what(),
               "g.json: arcs[1].to: must be a node index (got number 1.0)");
}

TEST(DiagramJson, StructuralErrors) {
  const auto message = [](const std::function<void(nlohmann::json&)>& edit) { return std::string(error_after(edit).what()); };
  EXPECT_EQ(message([](auto& j) { j["format"] = "covmap.sites/1"; }),
            "g.json: format: expected \"covmap.arcgraph/1\" (got string \"covmap.sites/1\")");
  EXPECT_EQ(message([](auto& j) { j.erase("nodes"); }), "g.json: nodes: missing");
  EXPECT_EQ(message([](auto& j) { j["arcs"][0]["line"] = {{"x", 0}, {"y", 0}, {"dx", 1}, {"dy", 0}}; }),
            "g.json: arcs[0]: has both \"circle\" and \"line\"; an arc lies on exactly one curve");
  EXPECT_EQ(message([](auto& j) { j["arcs"][0].erase("circle"); }), "g.json: arcs[0]: needs a \"circle\" or a \"line\"");
  EXPECT_EQ(message([](auto& j) { j["arcs"][1]["circle"]["r"] = -2; }), "g.json: arcs[1].circle.r: radius must be positive (got -2)");
  EXPECT_EQ(message([](auto& j) { j["arcs"][1]["circle"].erase("ccw"); }), "g.json: arcs[1].circle.ccw: missing");
  EXPECT_EQ(message([](auto& j) { j["arcs"][2]["line"]["dx"] = 0; j["arcs"][2]["line"]["dy"] = 0; }),
            "g.json: arcs[2].line: direction (dx, dy) must not be zero");
  EXPECT_EQ(message([](auto& j) { j["nodes"][2]["y"] = "0"; }), "g.json: nodes[2].y: must be a number (got string \"0\")");
  EXPECT_EQ(message([](auto& j) { j["nodes"][2]["y"] = 1e308 * 10; }), "g.json: nodes[2].y: must be a number (got null)");
  EXPECT_NE(message([](auto& j) { j["arcs"][1]["to"] = nullptr; }).find("arcs[1]: a circle arc has both ends or neither"),
            std::string::npos);
  EXPECT_NE(message([](auto& j) { j["arcs"][2]["sites"][1] = nullptr; }).find("arcs[2].sites: a bisector arc separates two"),
            std::string::npos);
  EXPECT_NE(message([](auto& j) { j["arcs"][5].erase("frame"); }).find("arcs[5].sites"), std::string::npos);
  EXPECT_NE(message([](auto& j) { j["arcs"][5]["sites"] = {2, 1}; }).find("a frame arc names the site inside"), std::string::npos);
  EXPECT_EQ(message([](auto& j) { j["faces"][0]["boundaries"][0] = nlohmann::json::array(); }),
            "g.json: faces[0].boundaries[0]: a boundary cycle must not be empty");
  EXPECT_EQ(message([](auto& j) { j["clip"] = {{0, 0}, {0, 1}, {1, 1}, {1, 0}}; }), "g.json: clip: must be counter-clockwise");
  EXPECT_NE(message([](auto& j) { j["clip"] = {{0, 0}, {1, 1}, {1, 0}, {0, 1}}; }).find("not simple"), std::string::npos);
  EXPECT_EQ(message([](auto& j) { j["sites"][1]["weight"] = 0; }), "g.json: sites[1] (site 'b'): weight must be positive (got 0)");
}

TEST(DiagramJson, OverflowingLiteralIsRejected) {
  auto text = to_json(sample());
  const auto at = text.find("\"r\":2.0");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 7, "\"r\":-1e999");
  const auto e = input_error_from([&] { parse_diagram_json(text, "g.json"); });
  // Line 1 format, 2 "sites":[, 3-5 sites, 6 ], 7 "nodes":[, 8-10 nodes, 11 ], 12 "arcs":[, 13 arc 0.
  EXPECT_EQ(e.line(), 13);
  EXPECT_EQ(e.message(), "invalid JSON: number overflow parsing '-1e999'");
}

TEST(DiagramJson, WritingNonFiniteThrows) {
  auto d = sample();
  d.nodes[1].y = NAN;
  std::ostringstream out;
  try {
    write_diagram_json(d, out);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("nodes[1].y"), std::string::npos);
  }
  // The writer streams element by element, yet refuses before its first byte: a
  // non-finite number late in the file leaves the stream empty. Each member is named by its path.
  for (const auto& [spoil, path] : std::vector<std::pair<std::function<void(Diagram&)>, std::string>>{
           {[](Diagram& g) { g.sites.back().weight = INFINITY; }, "sites[" },
           {[](Diagram& g) {
              for (auto& a : g.arcs)
                if (auto* c = std::get_if<Circle>(&a.curve)) { c->r = NAN; return; }
            }, ".circle.r"},
           {[](Diagram& g) { g.clip.push_back({0.0, NAN}); }, "[1]"}}) {
    auto g = sample();
    spoil(g);
    std::ostringstream empty;
    try {
      write_diagram_json(g, empty);
      ADD_FAILURE() << "expected std::invalid_argument for " << path;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
    EXPECT_TRUE(empty.str().empty()) << path;
  }
}

TEST(DiagramJson, ReadsFromFile) {
  testing::TempDir dir;
  const auto d = sample();
  expect_identical(d, read_diagram_json(dir.write("g.json", to_json(d))));
  EXPECT_NE(input_error_from([&] { read_diagram_json(dir / "missing.json"); }).message().find("cannot open"), std::string::npos);
}

}  // namespace
}  // namespace covmap::io
