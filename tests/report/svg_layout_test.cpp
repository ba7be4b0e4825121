// The SVG pictures' layout (report/svg.h): width from the data, labels that never overlap, names,
// the scale bar. Every check reads the written SVG and recomputes what it means independently
// (boxes from the text positions and the font size by the metric svg.h states, pixels from the
// width and viewBox attributes).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "report/svg.h"
#include "report/svg_layout.h"

namespace covmap::report {
namespace {

std::string render(const Diagram& d, const SvgOptions& o = {}) {
  std::ostringstream out;
  write_svg(d, out, o);
  return out.str();
}

Diagram sites_only(std::vector<Site> sites) {
  Diagram d;
  d.sites = std::move(sites);
  return d;
}

// n x n sites one unit apart: every site's nearest neighbour is exactly 1 away.
std::vector<Site> lattice(int n) {
  std::vector<Site> sites;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) sites.push_back({std::to_string(i * n + j), double(i), double(j), 1.0});
  return sites;
}

std::vector<Site> random_sites(std::size_t n, double side, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> at(0, side), weight(1, 3);
  std::vector<Site> sites;
  for (std::size_t i = 0; i < n; ++i) sites.push_back({"s" + std::to_string(i), at(rng), at(rng), weight(rng)});
  return sites;
}

// The picture's size attributes and its viewBox.
struct Picture {
  double width = 0, height = 0;
  double vx = 0, vy = 0, vw = 0, vh = 0;
  double scale() const { return width / vw; }  // pixels per world unit
};

Picture picture(const std::string& svg) {
  std::smatch m;
  const std::regex head(R"re(<svg [^>]*width="([^"]+)" height="([^"]+)" viewBox="([^ ]+) ([^ ]+) ([^ ]+) ([^"]+)")re");
  EXPECT_TRUE(std::regex_search(svg, m, head));
  return {std::stod(m[1]), std::stod(m[2]), std::stod(m[3]), std::stod(m[4]), std::stod(m[5]), std::stod(m[6])};
}

struct Label {
  double x = 0, y = 0;
  std::string text;
};

// The labels group: its font size and its texts (entities undone for &amp; only, enough here).
std::pair<double, std::vector<Label>> labels(const std::string& svg) {
  const auto begin = svg.find("<g class=\"labels\"");
  if (begin == std::string::npos) return {0, {}};
  const std::string group = svg.substr(begin, svg.find("</g>", begin) - begin);
  std::smatch m;
  EXPECT_TRUE(std::regex_search(group, m, std::regex(R"re(font-size="([^"]+)")re")));
  const double font = std::stod(m[1]);
  std::vector<Label> out;
  const std::regex text(R"re(<text x="([^"]+)" y="([^"]+)">([^<]*)</text>)re");
  for (auto it = std::sregex_iterator(group.begin(), group.end(), text); it != std::sregex_iterator(); ++it)
    out.push_back({std::stod((*it)[1]), std::stod((*it)[2]), std::regex_replace((*it)[3].str(), std::regex("&amp;"), "&")});
  return {font, out};
}

// svg.h's metric, in the file's units: 0.62 em per code point, 0.8 em above the baseline, 0.25
// below, and half the 1/4 em halo round it.
struct Rect {
  double x0, y0, x1, y1;
};
Rect box_of(const Label& l, double font) {
  std::size_t chars = 0;
  for (const unsigned char c : l.text) chars += (c & 0xC0) != 0x80;
  const double halo = font / 8;
  return {l.x - halo, l.y - 0.8 * font - halo, l.x + 0.62 * font * double(chars) + halo, l.y + 0.25 * font + halo};
}

TEST(SvgWidth, AnExplicitWidthWins) {
  SvgOptions o;
  o.width_px = 1234;
  EXPECT_DOUBLE_EQ(picture(render(sites_only(lattice(60)), o)).width, 1234);
}

TEST(SvgWidth, FewSitesGetTheSmallestWidth) {
  EXPECT_DOUBLE_EQ(picture(render(sites_only(random_sites(20, 100, 1)))).width, detail::kMinWidthPx);
}

TEST(SvgWidth, DenseSitesGetTwelvePixelsBetweenNeighbours) {
  // A lattice's nearest-neighbour spacing is 1, so the picture must draw one world unit as 12 px.
  const Picture p = picture(render(sites_only(lattice(100))));
  EXPECT_GT(p.width, detail::kMinWidthPx);
  EXPECT_LT(p.width, detail::kMaxWidthPx);
  EXPECT_NEAR(p.scale(), 12.0, 1e-6);
  EXPECT_NEAR(p.height / p.vh, 12.0, 1e-6);
}

TEST(SvgWidth, VeryDenseSitesAreClampedToTheLargestWidth) {
  SvgOptions o;
  o.max_labels = 0;  // the width is what is under test
  EXPECT_DOUBLE_EQ(picture(render(sites_only(lattice(400)), o)).width, detail::kMaxWidthPx);
}

// Brute force: every site against every other.
double brute_median_spacing(const std::vector<Site>& sites) {
  std::vector<double> nearest;
  for (const Site& s : sites) {
    double best = std::numeric_limits<double>::infinity();
    for (const Site& t : sites) {
      const double d = std::hypot(s.x - t.x, s.y - t.y);
      if (d > 0) best = std::min(best, d);
    }
    nearest.push_back(best);
  }
  std::sort(nearest.begin(), nearest.end());
  return nearest[nearest.size() / 2];
}

TEST(SvgWidth, MedianSpacingMatchesBruteForce) {
  for (const unsigned seed : {1u, 2u, 3u}) {
    const auto sites = random_sites(700, 50, seed);  // below the sample size: exact
    EXPECT_DOUBLE_EQ(detail::median_nearest_spacing(sites), brute_median_spacing(sites)) << seed;
  }
  const auto many = random_sites(6000, 50, 4);  // sampled: close to the whole list's median
  EXPECT_NEAR(detail::median_nearest_spacing(many) / brute_median_spacing(many), 1.0, 0.1);
  auto line = random_sites(500, 50, 5);  // all on a vertical line (the scan runs along y)
  for (auto& s : line) s.x = 3;
  EXPECT_DOUBLE_EQ(detail::median_nearest_spacing(line), brute_median_spacing(line));
  EXPECT_EQ(detail::median_nearest_spacing(std::vector<Site>{{"a", 1, 1, 1}}), 0.0);
}

void expect_no_overlap_and_inside(const std::string& svg) {
  const Picture p = picture(svg);
  const auto [font, placed] = labels(svg);
  std::vector<Rect> boxes;
  for (const Label& l : placed) boxes.push_back(box_of(l, font));
  // Boxes are compared with a hair of slack (1e-6 px) for the ten-digit numbers in the file.
  const double slack = 1e-6 / p.scale();
  for (const Rect& b : boxes) {
    EXPECT_GE(b.x0, p.vx - slack);
    EXPECT_GE(b.y0, p.vy - slack);
    EXPECT_LE(b.x1, p.vx + p.vw + slack);
    EXPECT_LE(b.y1, p.vy + p.vh + slack);
  }
  for (std::size_t i = 0; i < boxes.size(); ++i)
    for (std::size_t j = i + 1; j < boxes.size(); ++j) {
      const Rect &a = boxes[i], &b = boxes[j];
      const bool apart = a.x1 <= b.x0 + slack || b.x1 <= a.x0 + slack || a.y1 <= b.y0 + slack || b.y1 <= a.y0 + slack;
      EXPECT_TRUE(apart) << "'" << placed[i].text << "' and '" << placed[j].text << "' overlap";
    }
}

TEST(SvgLabels, DenseSitesGetSomeLabelsAndNoneOverlap) {
  const Diagram d = sites_only(random_sites(3000, 10, 7));
  SvgOptions o;
  o.width_px = 800;  // crowded on purpose
  const std::string svg = render(d, o);
  const auto placed = labels(svg).second;
  EXPECT_GT(placed.size(), 50u);
  EXPECT_LT(placed.size(), d.sites.size());
  expect_no_overlap_and_inside(svg);
}

TEST(SvgLabels, SparseSitesGetEveryLabel) {
  Diagram d = sites_only(lattice(5));
  for (auto& s : d.sites) s.x *= 30, s.y *= 30;  // 30 units apart in a 120-unit square
  const std::string svg = render(d);
  const auto placed = labels(svg).second;
  std::set<std::string> texts;
  for (const auto& l : placed) texts.insert(l.text);
  EXPECT_EQ(texts.size(), d.sites.size());
  for (const auto& s : d.sites) EXPECT_EQ(texts.count(s.id), 1u) << s.id;
  expect_no_overlap_and_inside(svg);
}

TEST(SvgLabels, NamesReplaceIdsAndHeaviestSitesComeFirst) {
  Diagram d = sites_only({{"1", 0, 0, 1}, {"2", 10, 0, 3}, {"3", 0, 10, 2}});
  d.sites[1].name = "North & mast";
  const auto placed = labels(render(d)).second;
  std::set<std::string> texts;
  for (const auto& l : placed) texts.insert(l.text);
  EXPECT_EQ(texts, (std::set<std::string>{"1", "North & mast", "3"}));
  SvgOptions one;
  one.max_labels = 1;
  const auto heaviest = labels(render(d, one)).second;
  ASSERT_EQ(heaviest.size(), 1u);
  EXPECT_EQ(heaviest[0].text, "North & mast");
}

// ---- scale bar ----

// The longest of 1, 2, 5 x 10^k (k from -30 to 30) not above `at_most`, by enumeration.
double enumerated_round_length(double at_most) {
  double best = 0;
  for (int k = -30; k <= 30; ++k)
    for (const double m : {1.0, 2.0, 5.0}) {
      const double v = m * std::pow(10.0, k);
      if (v <= at_most * (1 + 1e-12)) best = std::max(best, v);
    }
  return best;
}

TEST(SvgScaleBar, RoundLengthIsTheLongestOneTwoFiveBelowTheLimit) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> exponent(-8, 8);
  for (int i = 0; i < 2000; ++i) {
    const double at_most = std::pow(10.0, exponent(rng));
    EXPECT_NEAR(detail::round_length(at_most) / enumerated_round_length(at_most), 1.0, 1e-12) << at_most;
  }
  for (const double exact : {1.0, 2.0, 5.0, 10.0, 0.001, 5000.0}) EXPECT_NEAR(detail::round_length(exact), exact, exact * 1e-12);
  EXPECT_EQ(detail::round_length_text(500), "500");
  EXPECT_EQ(detail::round_length_text(0.02), "0.02");
  EXPECT_EQ(detail::round_length_text(2e6), "2000000");
}

// The bar's ends (file units) and its label, read from the written SVG.
struct Bar {
  double x0 = 0, x1 = 0;
  std::string label;
};

Bar bar(const std::string& svg) {
  std::smatch m;
  const std::regex line(R"re(class="scale-bar-line"[^>]* d="M([^ ]+) [^ ]+ V[^ ]+ H([^ ]+) )re");
  EXPECT_TRUE(std::regex_search(svg, m, line)) << svg.substr(svg.find("scale-bar"), 400);
  Bar b{std::stod(m[1]), std::stod(m[2]), ""};
  std::smatch t;
  const std::string tail = svg.substr(svg.find("class=\"scale-bar\""));
  EXPECT_TRUE(std::regex_search(tail, t, std::regex(R"re(<text [^>]*>([^<]*)</text>)re")));
  b.label = t[1];
  return b;
}

TEST(SvgScaleBar, KnownViewGivesAKnownBar) {
  SvgOptions o;
  o.view = std::array<double, 4>{0, 0, 8, 4};  // a fifth of 8 is 1.6: the bar is 1 unit
  o.width_px = 800;                             // 100 px per unit
  const std::string svg = render(sites_only({{"a", 1, 1, 1}, {"b", 5, 2, 1}}), o);
  const Bar b = bar(svg);
  EXPECT_NEAR((b.x1 - b.x0) * picture(svg).scale(), 100.0, 1e-6);
  EXPECT_EQ(b.label, "1 units");
  o.units = "m";
  o.view = std::array<double, 4>{0, 0, 3000, 1000};  // a fifth is 600: the bar is 500 m
  const std::string metres = render(sites_only({{"a", 1, 1, 1}, {"b", 5, 2, 1}}), o);
  EXPECT_EQ(bar(metres).label, "500 m");
  EXPECT_NEAR((bar(metres).x1 - bar(metres).x0) * picture(metres).scale(), 500 * 800.0 / 3000, 1e-6);
}

TEST(SvgScaleBar, AutomaticViewsGetAFifthOfTheWidthAtMost) {
  for (const double side : {0.003, 1.0, 77.0, 25000.0}) {
    const std::string svg = render(sites_only(random_sites(40, side, 3)));
    const Picture p = picture(svg);
    const Bar b = bar(svg);
    const double length = b.x1 - b.x0, pixels = length * p.scale();
    EXPECT_LE(pixels, p.width / 5 * (1 + 1e-9)) << side;
    EXPECT_GT(pixels, p.width / 12.5) << side;  // the next round length would pass a fifth
    const double mantissa = length / std::pow(10.0, std::floor(std::log10(length) + 1e-9));
    EXPECT_TRUE(std::abs(mantissa - 1) < 1e-6 || std::abs(mantissa - 2) < 1e-6 || std::abs(mantissa - 5) < 1e-6)
        << length;
    EXPECT_NE(b.label.find(" units"), std::string::npos);
    EXPECT_NEAR(std::stod(b.label), length, length * 1e-9);
    EXPECT_GE(std::min(b.x0, b.x1), p.vx);  // inside the picture
  }
}

}  // namespace
}  // namespace covmap::report
