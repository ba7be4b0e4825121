// report.html: self-contained, escaped, one table row per sensor, summary counts, well-formed,
// and small for large maps; and its building blocks (simplification, path data, escaping).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <regex>
#include <set>
#include <sstream>

#include "report/audit_html_map.h"
#include "report/audit_html_text.h"
#include "report/audit_report.h"
#include "audit_test_fixture.h"

namespace covmap::report {
namespace {

using detail::GridPoint;
using testing::AuditFixture;
using testing::audit_fixture;
using testing::context_of;

std::string html_of(const AuditReportContext& c) {
  std::ostringstream out;
  write_audit_html(c, out);
  return out.str();
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

std::string between(const std::string& text, const std::string& open, const std::string& close) {
  const auto a = text.find(open);
  const auto b = text.find(close, a);
  if (a == std::string::npos || b == std::string::npos) return {};
  return text.substr(a + open.size(), b - a - open.size());
}

// Tags close in order (void elements and self-closed tags aside), outside <style> and <script>
// whose content is not markup; every '&' starts an entity.
void expect_well_formed(const std::string& html) {
  std::string markup = std::regex_replace(html, std::regex(R"(<style>[\s\S]*?</style>)"), "");
  markup = std::regex_replace(markup, std::regex(R"(<script>[\s\S]*?</script>)"), "");
  static const std::set<std::string> kVoid = {"meta", "input", "br", "img", "link", "hr"};
  std::vector<std::string> open;
  const std::regex tag(R"(<(/?)([A-Za-z!][\w:-]*)[^>]*?(/?)>)");
  for (auto it = std::sregex_iterator(markup.begin(), markup.end(), tag); it != std::sregex_iterator(); ++it) {
    const auto& m = *it;
    const std::string name = m[2];
    if (name == "!DOCTYPE" || kVoid.count(name)) continue;
    if (m[1] == "/") {
      ASSERT_FALSE(open.empty()) << "stray </" << name << ">";
      ASSERT_EQ(open.back(), name);
      open.pop_back();
    } else if (m[3] != "/") {
      open.push_back(name);
    }
  }
  EXPECT_TRUE(open.empty()) << "unclosed <" << (open.empty() ? "" : open.back()) << ">";
  EXPECT_FALSE(std::regex_search(markup, std::regex(R"(&(?!(amp|lt|gt|quot|#39|alpha|sigma|chi|sup2|rarr);))")));
}

TEST(AuditHtml, SelfContainedWellFormedPage) {
  const AuditFixture f = audit_fixture(true);
  const std::string html = html_of(context_of(f));
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("</html>"), std::string::npos);
  EXPECT_EQ(count(html, "<svg"), 1u);
  EXPECT_EQ(count(html, "<style>"), 1u);
  EXPECT_EQ(count(html, "<script>"), 1u);
  expect_well_formed(html);
  // Nothing to fetch: no URL (an xmlns would be the only allowed "http"), no src/href attribute,
  // no CSS import, url() only for in-page references.
  EXPECT_EQ(count(html, "http"), count(html, "xmlns=\"http")) << "URL near " << html.substr(std::min(html.find("http"), html.size()), 40);
  EXPECT_FALSE(std::regex_search(html, std::regex(R"(<[^>]*\s(src|href)\s*=)", std::regex::icase)));
  EXPECT_EQ(html.find("@import"), std::string::npos);
  for (auto at = html.find("url("); at != std::string::npos; at = html.find("url(", at + 1)) {
    EXPECT_EQ(html.compare(at, 5, "url(#"), 0) << html.substr(at, 40);
  }
}

TEST(AuditHtml, OneTableRowPerSensorInOrder) {
  const AuditFixture f = audit_fixture(false);
  const std::string html = html_of(context_of(f));
  const std::string body = between(html, "<tbody>", "</tbody>");
  EXPECT_EQ(count(body, "<tr"), f.result.sensors.size());
  std::size_t at = 0;
  for (const auto& s : f.result.sensors) {
    const auto found = body.find("<td><code>" + s.id + "</code></td>", at);
    ASSERT_NE(found, std::string::npos) << s.id;
    at = found;
  }
  // Sortable: every header cell says how to sort, numeric cells carry exact values.
  const std::string head = between(html, "<thead>", "</thead>");
  EXPECT_EQ(count(head, "<th data-type="), count(head, "<th"));
  EXPECT_NE(body.find("data-v=\"412\""), std::string::npos);  // b's chi2
  EXPECT_NE(body.find("data-v=\"100\""), std::string::npos);  // b's position error
  EXPECT_EQ(body.find("data-v=\"nan"), std::string::npos);
  EXPECT_EQ(body.find("data-v=\"inf"), std::string::npos);
}

TEST(AuditHtml, SummaryCountsVerdicts) {
  const AuditFixture f = audit_fixture(true);
  const std::string html = html_of(context_of(f));
  // Counted here from the fixture's verdicts, independently of count_verdicts.
  std::size_t consistent = 0, inconsistent = 0, not_in_map = 0, unreported = 0;
  for (const auto& s : f.result.sensors) {
    consistent += s.verdict == audit::SensorVerdict::kConsistent;
    inconsistent += s.verdict == audit::SensorVerdict::kInconsistent;
    not_in_map += s.verdict == audit::SensorVerdict::kNotInMap;
    unreported += !s.reported;
  }
  EXPECT_NE(html.find("id=\"count-sensors\">" + std::to_string(f.result.sensors.size()) + "<"), std::string::npos);
  EXPECT_NE(html.find("id=\"count-consistent\">" + std::to_string(consistent) + "<"), std::string::npos);
  EXPECT_NE(html.find("id=\"count-inconsistent\">" + std::to_string(inconsistent) + "<"), std::string::npos);
  EXPECT_NE(html.find("id=\"count-not-in-map\">" + std::to_string(not_in_map) + "<"), std::string::npos);
  EXPECT_NE(html.find("id=\"count-unreported\">" + std::to_string(unreported) + "<"), std::string::npos);
  EXPECT_NE(html.find("id=\"cleaning-repairs\">28<"), std::string::npos);
  EXPECT_NE(html.find(f.map.projection->description()), std::string::npos);
  EXPECT_NE(html.find("0.975"), std::string::npos);  // refined mean IoU
}

// Issue 12: the page called undetermined sensors "other verdict" and left them out of the legend.
// Every verdict has a card with its count (zero included), its words in the legend, and the cards
// add up to the sensors.
TEST(AuditHtml, EveryVerdictNamedCountedAndInTheLegend) {
  const AuditFixture f = testing::audit_fixture_with_undetermined(true);
  const std::string html = html_of(context_of(f));
  EXPECT_EQ(html.find("other verdict"), std::string::npos);
  EXPECT_EQ(html.find("v-other"), std::string::npos);
  const std::string legend = between(html, "<p class=\"legend\">", "</p>");
  std::size_t total = 0;
  for (const audit::SensorVerdict v : audit::kAllSensorVerdicts) {
    const std::string name = std::regex_replace(std::string(audit::to_string(v)), std::regex("_"), "-");
    const std::string words = detail::html_escape(verdict_words(v));
    const std::size_t want = static_cast<std::size_t>(std::count_if(
        f.result.sensors.begin(), f.result.sensors.end(), [&](const audit::SensorAudit& a) { return a.verdict == v; }));
    EXPECT_NE(html.find("id=\"count-" + name + "\">" + std::to_string(want) + "</b>" + words + "<"), std::string::npos)
        << name;
    EXPECT_NE(legend.find(words), std::string::npos) << name;
    EXPECT_NE(html.find(".card.v-" + name + "{"), std::string::npos) << name;  // styled like the legend
    total += want;
  }
  EXPECT_EQ(total, f.result.sensors.size());
  EXPECT_NE(html.find("id=\"count-undetermined\">1<"), std::string::npos);
  // The undetermined sensor's row has no χ² (an empty cell), not 0.
  const std::string row = between(html, "<tr class=\"v-undetermined\">", "</tr>");
  ASSERT_FALSE(row.empty());
  std::vector<std::string> cells;
  const std::regex cell(R"(<td[^>]*>)");
  for (auto it = std::sregex_iterator(row.begin(), row.end(), cell); it != std::sregex_iterator(); ++it)
    cells.push_back(it->str());
  ASSERT_GT(cells.size(), 5u);
  EXPECT_EQ(cells[5], "<td class=\"n\" data-v=\"\">") << row;  // column 6: χ²
}

TEST(AuditHtml, MapShowsCellsBoundariesArrowsAndDots) {
  const AuditFixture f = audit_fixture(false);
  const std::string html = html_of(context_of(f));
  const std::string svg = between(html, "<svg", "</svg>");
  EXPECT_EQ(count(between(svg, "id=\"layer-cells\"", "</g>"), "<path"), f.map.cells.size());
  EXPECT_EQ(count(svg, "<line class=\"shift v-consistent\""), 2u);    // a, d
  EXPECT_EQ(count(svg, "<line class=\"shift v-inconsistent\""), 1u);  // b
  EXPECT_EQ(count(svg, "<circle class=\"sensor "), 4u);               // in the map: a-d
  EXPECT_EQ(count(svg, "<circle class=\"reported "), 4u);             // reported: a, b, d, e
  // Green and red arrows, as the brief asks.
  EXPECT_NE(svg.find("class=\"shift v-consistent\" x1"), std::string::npos);
  EXPECT_NE(between(svg, "<line class=\"shift v-inconsistent\"", ">").find("stroke=\"#d73027\""), std::string::npos);
  EXPECT_NE(between(svg, "<line class=\"shift v-consistent\"", ">").find("stroke=\"#1a9850\""), std::string::npos);
  const std::string boundaries = between(svg, "class=\"boundaries\" d=\"", "\"");
  std::size_t bisector_arcs = 0;
  for (const auto& arc : f.result.refined_diagram.arcs) bisector_arcs += arc.frame ? 0 : 1;
  EXPECT_EQ(count(boundaries, "M"), bisector_arcs);  // one subpath per arc (b|a, b|c, b|d)
  EXPECT_GT(count(between(svg, "class=\"frame\" d=\"", "\""), "M"), 3u);
  EXPECT_NE(svg.find("<title>b \xE2\x80\x94 inconsistent"), std::string::npos);
}

TEST(AuditHtml, EscapesEveryStringFromInput) {
  const std::string evil = "<script>alert(\"x\")</script>&'";
  AuditFixture f = audit_fixture(false, evil);
  f.result.messages.push_back("<b>bold</b>");
  f.result.sensors[1].reason = "<img onerror=alert(1)>";
  AuditReportContext c = context_of(f);
  c.map_file = "<evil>.geojson";
  c.command_line = "covmap audit \"<evil>.geojson\"";
  const std::string html = html_of(c);
  EXPECT_EQ(count(html, "<script"), 1u);  // only the page's own
  EXPECT_EQ(html.find("<img"), std::string::npos);
  EXPECT_EQ(html.find("<b>bold"), std::string::npos);
  EXPECT_EQ(html.find("<evil>"), std::string::npos);
  const std::string escaped = "&lt;script&gt;alert(&quot;x&quot;)&lt;/script&gt;&amp;&#39;";
  EXPECT_GE(count(html, escaped), 3u);  // table row, cell title, dot title
  expect_well_formed(html);
}

TEST(AuditHtml, InvalidOptionsThrow) {
  const AuditFixture f = audit_fixture(false);
  AuditReportContext c = context_of(f);
  c.render.html_grid_px = 0.0;
  std::ostringstream out;
  EXPECT_THROW(write_audit_html(c, out), std::invalid_argument);
}

// A map of 10^4 cells whose edges wiggle by less than a tenth of a pixel (raster noise), 200
// vertices each: the picture must not grow with the vertex count.
TEST(AuditHtml, LargeMapStaysSmall) {
  AuditFixture f = audit_fixture(false);
  constexpr int kSide = 100;
  constexpr double kCell = 1000.0;  // m; the map is 100 km wide, 960 px: 1 px ≈ 104 m
  constexpr int kSteps = 25;        // per edge
  constexpr double kWiggle = 5.0;   // m, ≈ 0.05 px
  f.map.cells.clear();
  std::size_t vertices = 0;
  for (int i = 0; i < kSide; ++i) {
    for (int j = 0; j < kSide; ++j) {
      const double x0 = i * kCell, y0 = j * kCell;
      Ring ring;
      const Point corners[] = {{x0, y0}, {x0 + kCell, y0}, {x0 + kCell, y0 + kCell}, {x0, y0 + kCell}};
      for (int e = 0; e < 4; ++e) {
        const auto a = corners[e], b = corners[(e + 1) % 4];
        for (int k = 0; k < kSteps; ++k) {
          const double t = static_cast<double>(k) / kSteps;
          const double off = (k % 2) ? kWiggle : 0.0;  // a staircase-like zig-zag across the edge
          const double nx = -(b.y - a.y) / kCell, ny = (b.x - a.x) / kCell;
          ring.push_back({a.x + t * (b.x - a.x) + off * nx, a.y + t * (b.y - a.y) + off * ny});
          ring.push_back({a.x + (t + 0.5 / kSteps) * (b.x - a.x) + off * nx, a.y + (t + 0.5 / kSteps) * (b.y - a.y) + off * ny});
        }
      }
      vertices += ring.size();
      std::string sensor(1, 's');  // appended, not "s" + ...: GCC 12 false -Wrestrict (PR 105651)
      sensor += std::to_string((i * kSide + j) % 4);
      f.map.cells.push_back({sensor, i * kSide + j, {{ring, {}}}});
    }
  }
  ASSERT_EQ(vertices, 2'000'000u);
  const std::string html = html_of(context_of(f));
  const std::string cells = between(html, "id=\"layer-cells\"", "</g>");
  EXPECT_EQ(count(cells, "<path"), static_cast<std::size_t>(kSide * kSide));
  // A square drawn as 4 corners costs about 80 bytes with its <path> and <title>; 200 vertices
  // written as they are would cost well over 1000.
  EXPECT_LT(cells.size(), 150u * kSide * kSide);
  EXPECT_LT(html.size(), 2'000'000u);
}

// ------------------------------------------------------------------------------ building blocks

// Distance from p to segment a-b.
double distance(const GridPoint& p, const GridPoint& a, const GridPoint& b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double len2 = dx * dx + dy * dy;
  const double t = len2 == 0 ? 0 : std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0, 1.0);
  return std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy);
}

// Every input point lies within `tolerance` of the kept polyline (brute force over its segments),
// and the kept points are input points in input order.
void expect_faithful(const std::vector<GridPoint>& in, const std::vector<GridPoint>& kept, double tolerance, bool closed) {
  ASSERT_FALSE(kept.empty());
  std::size_t at = 0;
  for (const auto& k : kept) {
    while (at < in.size() && !(in[at] == k)) ++at;
    ASSERT_LT(at, in.size()) << "kept point not in input order";
  }
  const std::size_t segments = closed ? kept.size() : kept.size() - 1;
  for (const auto& p : in) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t s = 0; s < segments; ++s) best = std::min(best, distance(p, kept[s], kept[(s + 1) % kept.size()]));
    EXPECT_LE(best, tolerance + 1e-9);
  }
}

TEST(AuditSimplify, RandomPolylinesStayWithinTolerance) {
  std::mt19937 random(7);
  std::uniform_int_distribution<int> step(-6, 6);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<GridPoint> line{{0, 0}};
    for (int i = 0; i < 200; ++i) line.push_back({line.back().x + 3 + step(random), line.back().y + step(random)});
    for (const double tolerance : {0.0, 1.5, 4.0}) {
      const auto kept = detail::simplify(line, tolerance, false);
      expect_faithful(line, kept, tolerance, false);
      EXPECT_EQ(kept.front(), line.front());
      EXPECT_EQ(kept.back(), line.back());
    }
  }
}

TEST(AuditSimplify, ClosedRingsKeepCornersAndDropNoise) {
  // A 100 x 60 rectangle sampled every unit with ±1 unit noise on the sides.
  std::vector<GridPoint> ring;
  for (int x = 0; x < 100; ++x) ring.push_back({x, x % 2});
  for (int y = 0; y < 60; ++y) ring.push_back({100 + y % 2, y});
  for (int x = 100; x > 0; --x) ring.push_back({x, 60 - x % 2});
  for (int y = 60; y > 0; --y) ring.push_back({-(y % 2), y});
  const auto kept = detail::simplify(ring, 2.5, true);
  expect_faithful(ring, kept, 2.5, true);
  EXPECT_LE(kept.size(), 8u);
  EXPECT_GE(kept.size(), 4u);
  // A ring thinner than the tolerance vanishes; repeats do not count as points.
  EXPECT_TRUE(detail::simplify(std::vector<GridPoint>{{0, 0}, {50, 0}, {50, 1}, {0, 1}}, 2.0, true).empty());
  EXPECT_TRUE(detail::simplify(std::vector<GridPoint>{{3, 3}, {3, 3}, {3, 3}}, 0.0, true).empty());
  EXPECT_TRUE(detail::simplify(std::vector<GridPoint>{{3, 3}, {3, 3}}, 0.0, false).empty());
}

// Reads "M x y l dx dy dx dy ... [z]" back into absolute points.
std::vector<GridPoint> parse_grid_path(const std::string& d, bool& closed) {
  const std::string spaced = std::regex_replace(std::regex_replace(d, std::regex(R"(([Mlz]))"), " $1 "), std::regex("-"), " -");
  std::istringstream in(spaced);
  std::string token;
  std::vector<GridPoint> out;
  closed = false;
  std::vector<long long> numbers;
  while (in >> token) {
    if (token == "M" || token == "l") continue;
    if (token == "z") {
      closed = true;
      continue;
    }
    numbers.push_back(std::stoll(token));
  }
  EXPECT_EQ(numbers.size() % 2, 0u);
  for (std::size_t i = 0; i + 1 < numbers.size(); i += 2) {
    if (out.empty()) out.push_back({numbers[i], numbers[i + 1]});
    else out.push_back({out.back().x + numbers[i], out.back().y + numbers[i + 1]});
  }
  return out;
}

TEST(AuditGridPath, RelativeCommandsRoundTrip) {
  const std::vector<GridPoint> points{{12, 5}, {15, 1}, {15, 8}, {-4, -9}, {0, 0}, {1000000, -3}};
  for (const bool close : {false, true}) {
    const std::string d = detail::grid_path(points, close);
    EXPECT_EQ(d.front(), 'M');
    bool closed = false;
    EXPECT_EQ(parse_grid_path(d, closed), points) << d;
    EXPECT_EQ(closed, close);
  }
  EXPECT_EQ(detail::grid_path(std::vector<GridPoint>{{12, 5}, {15, 1}, {15, 8}}, true), "M12 5l3-4 0 7z");
}

TEST(AuditHtmlText, EscapingAndUtf8Repair) {
  EXPECT_EQ(detail::html_escape("a<b>&\"c'"), "a&lt;b&gt;&amp;&quot;c&#39;");
  EXPECT_EQ(detail::html_escape("Z\xC3\xBCrich \xE2\x82\xAC \xF0\x9F\x93\xA1"), "Z\xC3\xBCrich \xE2\x82\xAC \xF0\x9F\x93\xA1");
  const std::string fffd = "\xEF\xBF\xBD";
  EXPECT_EQ(detail::html_escape("x\xFFy"), "x" + fffd + "y");
  EXPECT_EQ(detail::html_escape("\xC3"), fffd);                    // truncated sequence
  EXPECT_EQ(detail::html_escape("\xC0\xAF"), fffd + fffd);         // overlong '/'
  EXPECT_EQ(detail::html_escape("\xED\xA0\x80"), fffd + fffd + fffd);  // surrogate
  EXPECT_EQ(detail::html_escape(std::string("a\0b\x01\tc\n", 7)), "a" + fffd + "b" + fffd + "\tc\n");
  EXPECT_EQ(detail::human_number(std::numeric_limits<double>::quiet_NaN()), "\xE2\x80\x93");
  EXPECT_EQ(detail::human_number(12.345), "12.3");
  // Issue 13: numbers for people in fixed notation ("2.51e+03 m" was on the page).
  EXPECT_EQ(detail::human_number(2510.4), "2510");
  EXPECT_EQ(detail::human_number(-0.012345), "-0.0123");
  EXPECT_EQ(detail::human_number(0.0), "0");
  EXPECT_EQ(detail::human_number(1.5e-7), "1.5e-07");  // very small: the exponent says more
  EXPECT_EQ(detail::human_number(3e20), "3e+20");
  EXPECT_EQ(detail::sort_key(std::nullopt), "");
  EXPECT_EQ(detail::sort_key(0.1), "0.1");
}

TEST(AuditHtml, AMisfitMapSaysSoFirstAndNamesItsReach) {
  // Issue 12: when the map does not follow the model, the page says so before any verdict; the
  // reception limit is stated with its numbers. The fixture's values are the oracle.
  AuditFixture f = audit_fixture(false);
  f.result.model_fit.known = true;
  f.result.model_fit.ratio = 37.5;
  f.result.model_fit.reports_median_p = 0.0004;
  f.result.model_fit.misfit = true;
  f.result.model_fit.misfit_sensors = 2;
  f.result.model_fit.misfit_area_share = 0.25;
  f.result.sensors[0].verdict = audit::SensorVerdict::kModelMisfit;
  f.result.reception = audit::ReceptionLimit{16008.0, 1.7, -104.2, 26};
  const std::string html = html_of(context_of(f));
  const auto fit = html.find("id=\"model-fit\" class=\"misfit\"");
  ASSERT_NE(fit, std::string::npos);
  EXPECT_LT(fit, html.find("id=\"summary\""));
  const std::string text = between(html.substr(fit), ">", "</p>");
  EXPECT_NE(text.find("does not follow the path-loss model"), std::string::npos) << text;
  EXPECT_NE(text.find("38 times"), std::string::npos) << text;  // 37.5 shown as a whole number
  EXPECT_NE(text.find("2 sensors (25.0 %"), std::string::npos) << text;
  const std::string reach = between(html, "id=\"reception\" class=\"meta\">", "</p>");
  EXPECT_NE(reach.find("16.0 km"), std::string::npos) << reach;
  EXPECT_NE(reach.find("26 sensors"), std::string::npos) << reach;
  EXPECT_NE(reach.find("-104.2 dBm"), std::string::npos) << reach;
  EXPECT_EQ(count(html, "id=\"count-model-misfit\""), 1u);
  expect_well_formed(html);
}

TEST(AuditHtml, AMapThatFitsSaysSoWithoutAlarm) {
  AuditFixture f = audit_fixture(false);
  f.result.model_fit.known = true;
  f.result.model_fit.ratio = 0.81;
  const std::string html = html_of(context_of(f));
  EXPECT_NE(html.find("id=\"model-fit\" class=\"meta\""), std::string::npos);
  EXPECT_EQ(html.find("class=\"misfit\""), std::string::npos);
  EXPECT_EQ(html.find("id=\"reception\""), std::string::npos);  // no reach: no sentence
}

}  // namespace
}  // namespace covmap::report
