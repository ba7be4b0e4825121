// The same site has the same colour in every picture (report/svg.h: site_colour_for): whatever
// the order of the sites, and in `recognize`'s picture of the arc graph that `diagram` drew.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "io/diagram_json.h"
#include "recognition/graph_repair.h"
#include "recognition/recognize.h"
#include "report/svg.h"
#include "voronoi/engine.h"

namespace covmap::report {
namespace {

std::string render(const Diagram& d) {
  std::ostringstream out;
  write_svg(d, out);
  return out.str();
}

// Site id -> the fill of its faces, read from the picture's face paths and their titles
// ("site <id>" or "site <id> (<name>)"). Fails the test if one site's faces differ in fill.
std::map<std::string, std::string> face_fills(const std::string& svg) {
  std::map<std::string, std::string> fill;
  const std::regex face(R"re(<path class="face[^"]*" fill="([^"]+)" d="[^"]*"><title>site ([^ <]+)[^<]*</title>)re");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), face); it != std::sregex_iterator(); ++it) {
    const auto [at, inserted] = fill.emplace((*it)[2], (*it)[1]);
    EXPECT_EQ(at->second, (*it)[1].str()) << "site " << at->first << " has faces of two colours";
  }
  return fill;
}

// Hue in degrees of "#rrggbb" (the HSL hue, as the CSS colour algorithm defines it).
double hue(const std::string& hex) {
  const double r = std::stoi(hex.substr(1, 2), nullptr, 16) / 255.0, g = std::stoi(hex.substr(3, 2), nullptr, 16) / 255.0,
               b = std::stoi(hex.substr(5, 2), nullptr, 16) / 255.0;
  const double max = std::max({r, g, b}), min = std::min({r, g, b}), c = max - min;
  double h = max == r ? std::fmod((g - b) / c, 6.0) : max == g ? (b - r) / c + 2 : (r - g) / c + 4;
  h *= 60;
  return h < 0 ? h + 360 : h;
}

double hue_distance(double a, double b) {
  const double d = std::fmod(std::abs(a - b), 360.0);
  return std::min(d, 360 - d);
}

TEST(SiteColour, ConsecutiveIntegerIdsAreWellSeparated) {
  // Successive golden angles: the first 12 multiples of 137.5 degrees are at least 20.06 apart
  // (three-gap theorem; the smallest gap, computed separately); the hues are read back from the hex
  // text, whose rounding costs about a degree.
  std::vector<double> hues;
  for (int i = 0; i < 12; ++i) hues.push_back(hue(site_colour_for(std::to_string(i))));
  for (std::size_t i = 0; i < hues.size(); ++i) {
    for (std::size_t j = i + 1; j < hues.size(); ++j) {
      EXPECT_GT(hue_distance(hues[i], hues[j]), 18.0) << i << " " << j;
    }
    if (i > 0) {
      EXPECT_NEAR(hue_distance(hues[i], hues[i - 1]), 137.50776, 2.0) << i;
    }
  }
}

TEST(SiteColour, DependsOnTheIdOnly) {
  EXPECT_EQ(site_colour_for("north"), site_colour_for(std::string("nor") + "th"));
  std::set<std::string> seen;
  for (const char* id : {"north", "south", "east", "west", "a", "b", "c", "s0", "s1", "017", "-3", "3"})
    seen.insert(site_colour_for(id));
  EXPECT_GE(seen.size(), 11u);  // text hashes may, rarely, share a colour; not most of them
  EXPECT_EQ(site_colour_for("7"), site_colour(7));
}

std::vector<Site> random_sites(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> at(0, 100), weight(1, 2.5);
  std::vector<Site> sites;
  for (std::size_t i = 0; i < n; ++i) sites.push_back({std::to_string(100 + i), at(rng), at(rng), weight(rng)});
  return sites;
}

TEST(SiteColour, TheOrderOfTheSitesDoesNotChangeTheirColours) {
  std::vector<Site> sites = random_sites(15, 3);
  const auto before = face_fills(render(voronoi::build_diagram(sites)));
  std::reverse(sites.begin(), sites.end());
  EXPECT_EQ(face_fills(render(voronoi::build_diagram(sites))), before);
  EXPECT_EQ(before.size(), sites.size());
}

// What `covmap diagram` then `covmap recognize --svg` do: the diagram written as an arc graph, read
// back, recognized, and the reconstruction drawn under the input's ids (recognition::named_as_input).
TEST(SiteColour, DiagramAndRecognizePicturesColourEachSiteAlike) {
  for (const unsigned seed : {5u, 6u}) {
    std::vector<Site> sites = random_sites(12, seed);
    sites[2].name = "Gate mast";
    const Diagram diagram = voronoi::build_diagram(sites);
    std::ostringstream json;
    io::write_diagram_json(diagram, json);
    Diagram graph = io::parse_diagram_json(json.str(), "g.json", io::ArcLabels::kOptional);
    const std::vector<Site> input = graph.sites;
    recognition::prepare_input_graph(graph);
    const recognition::Reconstruction r = recognition::recognize(std::move(graph));
    ASSERT_TRUE(r.bisector_graph) << r.reason;
    ASSERT_TRUE(r.input_sites.has_value());
    const auto drawn = face_fills(render(diagram));
    const auto recognized = face_fills(render(voronoi::build_diagram(recognition::named_as_input(r.sites, input, *r.input_sites))));
    ASSERT_EQ(drawn.size(), sites.size());
    EXPECT_EQ(recognized, drawn) << "seed " << seed;
    // Without the input's names the reconstruction's own ids differ: the check above can fail.
    EXPECT_NE(face_fills(render(voronoi::build_diagram(r.sites))), drawn);
  }
}

TEST(SiteColour, NamedAsInputKeepsUnpairedSitesAndTakesNames) {
  std::vector<Site> reconstructed = {{"s0", 0, 0, 1}, {"s1", 1, 0, 1}, {"s2", 2, 0, 1}};
  std::vector<Site> input = {{"a", 9, 9, 2}, {"b", 8, 8, 2}};
  input[1].name = "Bee";
  recognition::InputSitesComparison c;
  c.input_site = {1, kNone, 0};
  const auto named = recognition::named_as_input(reconstructed, input, c);
  EXPECT_EQ(named[0].id, "b");
  EXPECT_EQ(named[0].name, "Bee");
  EXPECT_EQ(named[0].x, 0);  // positions and weights stay the reconstruction's
  EXPECT_EQ(named[1].id, "s1");
  EXPECT_EQ(named[2].id, "a");
  EXPECT_EQ(named[2].weight, 1);
}

}  // namespace
}  // namespace covmap::report
