// report.html: self-contained, escaped, one table row per sensor, summary counts, well-formed,
// and small for large maps; and its building blocks (simplification, path data, escaping).
#include <gtest/gtest.h>

#include "markup_checks.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <regex>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

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
  markup = std::regex_replace(markup, std::regex(R"(<script[^>]*>[\s\S]*?</script>)"), "");
  testing::expect_well_formed_markup(markup, {"meta", "input", "br", "img", "link", "hr"},
                                     "amp|lt|gt|quot|#39|alpha|sigma|chi|sup2|rarr|minus|times|plusmn|hellip");
}

// The page's data block (report/audit_html_data.h), parsed as JSON.
nlohmann::json page_data(const std::string& html) {
  const std::string open = "<script type=\"application/json\" id=\"report-data\">";
  const std::string text = between(html, open, "</script>");
  EXPECT_FALSE(text.empty()) << "no data block";
  nlohmann::json data = nlohmann::json::parse(text);
  // Sensors come by column; the tests read them as one object per sensor.
  nlohmann::json rows = nlohmann::json::array();
  const nlohmann::json& columns = data["sensors"];
  const std::size_t n = columns.empty() ? 0 : columns.begin()->size();
  for (std::size_t i = 0; i < n; ++i) {
    nlohmann::json row;
    for (const auto& [key, values] : columns.items()) {
      EXPECT_EQ(values.size(), n) << key;
      row[key] = values.at(i);
    }
    rows.push_back(row);
  }
  data["sensors"] = rows;
  return data;
}

std::size_t verdict_index(audit::SensorVerdict v) {
  return static_cast<std::size_t>(std::find(std::begin(audit::kAllSensorVerdicts), std::end(audit::kAllSensorVerdicts), v) -
                                  std::begin(audit::kAllSensorVerdicts));
}

TEST(AuditHtml, SelfContainedWellFormedPage) {
  const AuditFixture f = audit_fixture(true);
  const std::string html = html_of(context_of(f));
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("</html>"), std::string::npos);
  EXPECT_EQ(count(html, "<style>"), 1u);
  EXPECT_EQ(count(html, "<script>"), 1u);  // the page's script
  EXPECT_EQ(count(html, "<script type=\"application/json\" id=\"report-data\">"), 1u);
  EXPECT_EQ(count(html, "<canvas id=\"map-canvas\""), 1u);
  expect_well_formed(html);
  // Nothing to fetch: no URL at all without --basemap, no src/href attribute, no CSS import or url().
  EXPECT_EQ(count(html, "http"), 0u) << "URL near " << html.substr(std::min(html.find("http"), html.size()), 40);
  EXPECT_FALSE(std::regex_search(html, std::regex(R"(<[^>]*\s(src|href)\s*=)", std::regex::icase)));
  EXPECT_EQ(html.find("@import"), std::string::npos);
  EXPECT_EQ(html.find("url("), std::string::npos);
  EXPECT_EQ(html.find("id=\"basemap-toggle\""), std::string::npos);
  EXPECT_TRUE(page_data(html)["basemap"].is_null());
}

// The first screen is the answer. In the page's order: the verdict counts, the map, the
// list of sensors needing attention; the table after them, the details last and folded.
TEST(AuditHtml, AnswerFirstDetailsFolded) {
  const AuditFixture f = audit_fixture(true);
  const std::string html = html_of(context_of(f));
  const auto at = [&](const std::string& what) {
    const auto p = html.find(what);
    EXPECT_NE(p, std::string::npos) << what;
    return p;
  };
  EXPECT_LT(at("id=\"count-sensors\""), at("id=\"map-canvas\""));
  EXPECT_LT(at("id=\"map-canvas\""), at("id=\"attention\""));
  EXPECT_LT(at("id=\"attention\""), at("id=\"sensor-table\""));
  EXPECT_LT(at("id=\"sensor-table\""), at("<details id=\"details\">"));
  EXPECT_LT(at("<details id=\"details\">"), at("id=\"cleaning-repairs\""));
  // Solver words only among the analysts' notes, inside the folded details.
  EXPECT_GT(html.find(f.result.refinement_summary), html.find("Notes for analysts"));
  // The attention list: every sensor but the consistent ones, worst first (b is inconsistent, e
  // not in the map, c unreported; the fixture's verdicts are the oracle).
  const std::string list = between(html, "<ol id=\"attention\">", "</ol>");
  std::vector<std::string> ids;
  const std::regex item(R"re(data-sensor-id="([^"]*)")re");
  for (auto it = std::sregex_iterator(list.begin(), list.end(), item); it != std::sregex_iterator(); ++it) ids.push_back((*it)[1]);
  std::vector<std::string> want;
  for (const audit::SensorVerdict v : {audit::SensorVerdict::kInconsistent, audit::SensorVerdict::kModelMisfit,
                                       audit::SensorVerdict::kNotInMap, audit::SensorVerdict::kUnreported,
                                       audit::SensorVerdict::kUndetermined})
    for (const auto& s : f.result.sensors)
      if (s.verdict == v) want.push_back(s.id);
  EXPECT_EQ(ids, want);
  EXPECT_NE(html.find("id=\"attention-count\">" + std::to_string(want.size()) + "<"), std::string::npos);
}

TEST(AuditHtml, EverySensorInTheDataWorstFirst) {
  const AuditFixture f = audit_fixture(false);
  const nlohmann::json data = page_data(html_of(context_of(f)));
  const auto& sensors = data["sensors"];
  ASSERT_EQ(sensors.size(), f.result.sensors.size());
  std::set<std::string> ids;
  for (const auto& s : sensors) ids.insert(s["id"].get<std::string>());
  for (const auto& s : f.result.sensors) EXPECT_EQ(ids.count(s.id), 1u) << s.id;
  // Ordered by the documented severity of verdicts.
  const std::vector<std::size_t> rank = {3, 5, 0, 4, 2, 1};  // by kAllSensorVerdicts index
  for (std::size_t i = 1; i < sensors.size(); ++i)
    EXPECT_LE(rank[sensors[i - 1]["verdict"].get<std::size_t>()], rank[sensors[i]["verdict"].get<std::size_t>()]) << i;
  // The numbers behind the verdict, exact; unknown ones null, never NaN or a made-up 0.
  for (const auto& s : sensors) {
    if (s["id"] == "b") {
      EXPECT_EQ(s["chi2"], 412.0);
      EXPECT_EQ(s["moved"], 100.0);
      EXPECT_EQ(s["verdict"], verdict_index(audit::SensorVerdict::kInconsistent));
    }
    if (s["id"] == "c") EXPECT_TRUE(s["chi2"].is_null());  // unreported
  }
}

// A sensor's name, when the input gives one, is shown beside its id in the list and in
// the data the map's labels, hover and search use.
TEST(AuditHtml, NamesBesideIds) {
  AuditFixture f = audit_fixture(false);
  f.result.sensors[1].name = "Bern <Nord> & Co";  // b, inconsistent: listed
  const std::string html = html_of(context_of(f));
  const std::string item = between(html, "data-sensor-id=\"b\">", "</li>");
  EXPECT_NE(item.find("<span class=\"name\">Bern &lt;Nord&gt; &amp; Co</span>"), std::string::npos) << item;
  const nlohmann::json data = page_data(html);
  for (const auto& s : data["sensors"]) EXPECT_EQ(s["name"], s["id"] == "b" ? "Bern <Nord> & Co" : "") << s["id"];
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
  EXPECT_NE(html.find(f.map.frame->description()), std::string::npos);
  EXPECT_NE(html.find("97.50 %"), std::string::npos);  // refined mean IoU 0.975
}

// No "other verdict": undetermined sensors are named and in the legend like every verdict. Every
// verdict has a card with its count (zero included); the legend names exactly the verdicts drawn
// on the map, and the cards add up to the sensors.
TEST(AuditHtml, EveryVerdictNamedCountedAndTheLegendMatchesTheMap) {
  const AuditFixture f = testing::audit_fixture_with_undetermined(true);
  const std::string html = html_of(context_of(f));
  EXPECT_EQ(html.find("other verdict"), std::string::npos);
  EXPECT_EQ(html.find("v-other"), std::string::npos);
  const std::string legend = between(html, "<ul id=\"map-legend\" class=\"legend\">", "</ul>");
  std::size_t total = 0;
  for (const audit::SensorVerdict v : audit::kAllSensorVerdicts) {
    const std::string name = std::regex_replace(std::string(audit::to_string(v)), std::regex("_"), "-");
    const std::string words = detail::html_escape(verdict_words(v));
    const std::size_t want = static_cast<std::size_t>(std::count_if(
        f.result.sensors.begin(), f.result.sensors.end(), [&](const audit::SensorAudit& a) { return a.verdict == v; }));
    EXPECT_NE(html.find("id=\"count-" + name + "\">" + std::to_string(want) + "</b>" + words + "<"), std::string::npos)
        << name;
    EXPECT_EQ(legend.find("data-symbol=\"" + std::string(audit::to_string(v)) + "\"") != std::string::npos, want > 0) << name;
    EXPECT_NE(html.find(".card.v-" + name + "{"), std::string::npos) << name;  // styled like the legend
    total += want;
  }
  EXPECT_EQ(total, f.result.sensors.size());
  EXPECT_NE(html.find("id=\"count-undetermined\">1<"), std::string::npos);
  // The undetermined sensor has no χ² (null), not 0.
  bool seen = false;
  const nlohmann::json data = page_data(html);
  for (const auto& s : data["sensors"]) {
    if (s["verdict"] != verdict_index(audit::SensorVerdict::kUndetermined)) continue;
    EXPECT_TRUE(s["chi2"].is_null());
    seen = true;
  }
  EXPECT_TRUE(seen);
}

// Reads an encoded polyline [x0, y0, dx, dy, ...] back into points.
std::vector<GridPoint> decode(const nlohmann::json& encoded) {
  std::vector<GridPoint> out;
  for (std::size_t i = 0; i + 1 < encoded.size(); i += 2) {
    const std::int64_t x = encoded[i], y = encoded[i + 1];
    out.push_back(out.empty() ? GridPoint{x, y} : GridPoint{out.back().x + x, out.back().y + y});
  }
  return out;
}

TEST(AuditHtml, MapDataHoldsCellsBoundariesAndMarks) {
  const AuditFixture f = audit_fixture(false);
  const nlohmann::json data = page_data(html_of(context_of(f)));
  EXPECT_EQ(data["cells"].size(), f.map.cells.size());
  std::size_t dots = 0, rings = 0, arrows = 0;
  for (const auto& s : data["sensors"]) {
    dots += !s["x"].is_null();
    rings += !s["rx"].is_null();
    arrows += !s["x"].is_null() && !s["rx"].is_null();
  }
  EXPECT_EQ(dots, 4u);    // in the map: a-d
  EXPECT_EQ(rings, 4u);   // reported: a, b, d, e
  EXPECT_EQ(arrows, 3u);  // a, b, d
  std::size_t bisector_arcs = 0;
  for (const auto& arc : f.result.refined_diagram.arcs) bisector_arcs += arc.frame ? 0 : 1;
  EXPECT_EQ(data["boundaries"].size(), bisector_arcs);  // one polyline per arc (b|a, b|c, b|d)
  EXPECT_GT(data["frame"].size(), 3u);
  // Every cell ring lies on the grid, inside the frame's margin, and each cell names its sensor.
  const std::int64_t w = data["grid"]["w"], h = data["grid"]["h"];
  for (const auto& cell : data["cells"]) {
    const std::size_t s = cell[0];
    ASSERT_LT(s, data["sensors"].size());
    for (std::size_t r = 1; r < cell.size(); ++r)
      for (const GridPoint& p : decode(cell[r])) {
        EXPECT_GE(p.x, 0);
        EXPECT_LE(p.x, w);
        EXPECT_GE(p.y, 0);
        EXPECT_LE(p.y, h);
      }
  }
  // A sensor's grid position maps back to its map position within half a grid unit.
  const double m = data["grid"]["m"], x0 = data["grid"]["x0"], y0 = data["grid"]["y0"];
  for (const auto& s : data["sensors"]) {
    if (s["x"].is_null()) continue;
    const auto& truth = *std::find_if(f.result.sensors.begin(), f.result.sensors.end(),
                                      [&](const audit::SensorAudit& a) { return a.id == s["id"]; });
    EXPECT_NEAR(x0 + s["x"].get<double>() * m, truth.position.x, 0.51 * m);
    EXPECT_NEAR(y0 - s["y"].get<double>() * m, truth.position.y, 0.51 * m);
  }
}

// Geographic maps carry a lon/lat grid for the cursor's coordinates: checked here against the
// projection's own inverse at points between the nodes.
TEST(AuditHtml, GeographicMapsCarryLonLatForTheCursor) {
  const AuditFixture f = audit_fixture(true);
  const nlohmann::json data = page_data(html_of(context_of(f)));
  const auto& L = data["lonlat"];
  ASSERT_FALSE(L.is_null());
  const int n = L["n"];
  const double w = data["grid"]["w"], h = data["grid"]["h"], m = data["grid"]["m"], x0 = data["grid"]["x0"], y0 = data["grid"]["y0"];
  for (const double u : {0.13, 0.5, 0.77}) {
    for (const double v : {0.21, 0.64}) {
      const double gx = u * w, gy = v * h, fu = u * n - std::floor(u * n), fv = v * n - std::floor(v * n);
      const int i = static_cast<int>(std::floor(u * n)), j = static_cast<int>(std::floor(v * n));
      const auto at = [&](const nlohmann::json& a, int ii, int jj) { return a[jj * (n + 1) + ii].get<double>(); };
      const auto mix = [&](const nlohmann::json& a) {
        return (1 - fv) * ((1 - fu) * at(a, i, j) + fu * at(a, i + 1, j)) + fv * ((1 - fu) * at(a, i, j + 1) + fu * at(a, i + 1, j + 1));
      };
      const io::LonLat truth = f.map.frame->inverse({x0 + gx * m, y0 - gy * m});
      EXPECT_NEAR(mix(L["lon"]), truth.lon, 1e-5);  // about a metre
      EXPECT_NEAR(mix(L["lat"]), truth.lat, 1e-5);
    }
  }
}

TEST(AuditHtml, ABasemapOnlyWhenAskedAndOnlyForGeographicMaps) {
  AuditFixture f = audit_fixture(true);
  AuditReportContext c = context_of(f);
  c.render.basemap_url = "https://tiles.example/{z}/{x}/{y}.png";
  std::string html = html_of(c);
  EXPECT_NE(html.find("id=\"basemap-toggle\""), std::string::npos);
  EXPECT_EQ(page_data(html)["basemap"]["url"], c.render.basemap_url);
  c.render.basemap_url = "https://tiles.example/{z}/{x}.png";  // no {y}
  std::ostringstream out;
  EXPECT_THROW(write_audit_html(c, out), std::invalid_argument);
  AuditFixture planar = audit_fixture(false);
  AuditReportContext p = context_of(planar);
  p.render.basemap_url = "https://tiles.example/{z}/{x}/{y}.png";
  html = html_of(p);
  EXPECT_EQ(html.find("id=\"basemap-toggle\""), std::string::npos);
  EXPECT_TRUE(page_data(html)["basemap"].is_null());
}

TEST(AuditHtml, EscapesEveryStringFromInput) {
  const std::string evil = "<script>alert(\"x\")</script>&'";
  AuditFixture f = audit_fixture(false, evil);
  f.result.messages.push_back("<b>bold</b>");
  f.result.sensors[1].reason = "<img onerror=alert(1)>";
  f.result.sensors[0].verdict = audit::SensorVerdict::kInconsistent;  // listed by id in the attention list
  AuditReportContext c = context_of(f);
  c.map_file = "<evil>.geojson";
  c.command_line = "covmap audit \"<evil>.geojson\"";
  const std::string html = html_of(c);
  EXPECT_EQ(count(html, "<script"), 2u);  // only the page's own: its data and its script
  EXPECT_EQ(html.find("<img"), std::string::npos);
  EXPECT_EQ(html.find("<b>bold"), std::string::npos);
  EXPECT_EQ(html.find("<evil>"), std::string::npos);
  const std::string escaped = "&lt;script&gt;alert(&quot;x&quot;)&lt;/script&gt;&amp;&#39;";
  EXPECT_GE(count(html, escaped), 1u);  // the attention list
  // In the data block the strings survive intact once parsed.
  bool found = false;
  const nlohmann::json data = page_data(html);
  for (const auto& s : data["sensors"]) found = found || s["id"] == evil;
  EXPECT_TRUE(found);
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
  const nlohmann::json data = page_data(html);
  EXPECT_EQ(data["cells"].size(), static_cast<std::size_t>(kSide * kSide));
  // A square kept as its 4 corners costs about 40 bytes; 200 vertices written as they are would
  // cost well over 1000.
  EXPECT_LT(data["cells"].dump().size(), 60u * kSide * kSide);
  EXPECT_LT(html.size(), 1'000'000u);
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

TEST(AuditDeltaEncode, StepsRoundTrip) {
  const std::vector<GridPoint> points{{12, 5}, {15, 1}, {15, 8}, {-4, -9}, {0, 0}, {1000000, -3}};
  const std::vector<std::int64_t> encoded = detail::delta_encode(points);
  EXPECT_EQ(decode(nlohmann::json(encoded)), points);
  EXPECT_EQ(detail::delta_encode(std::vector<GridPoint>{{12, 5}, {15, 1}, {15, 8}}), (std::vector<std::int64_t>{12, 5, 3, -4, 0, 7}));
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
  // Numbers for people in fixed notation (never "2.51e+03 m").
  EXPECT_EQ(detail::human_number(2510.4), "2510");
  EXPECT_EQ(detail::human_number(-0.012345), "-0.0123");
  EXPECT_EQ(detail::human_number(0.0), "0");
  EXPECT_EQ(detail::human_number(1.5e-7), "1.5e-07");  // very small: the exponent says more
  EXPECT_EQ(detail::human_number(3e20), "3e+20");
  EXPECT_EQ(detail::sort_key(std::nullopt), "");
  EXPECT_EQ(detail::sort_key(0.1), "0.1");
}

TEST(AuditHtml, AMisfitMapSaysSoFirstAndNamesItsReach) {
  // When the map does not follow the model, the page says so before any verdict; the
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
