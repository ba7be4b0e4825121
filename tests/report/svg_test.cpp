#include "report/svg.h"

#include <gtest/gtest.h>

#include "markup_checks.h"

#include <algorithm>
#include <cmath>
#include <regex>
#include <sstream>
#include <vector>

#include "core/point_in_polygon.h"
#include "report/svg_geometry.h"

namespace covmap::report {
namespace {


// Two sites, weights 1 and 2: the bisector is the Apollonius circle (x+1)^2 + y^2 = 4 around 'a'.
// The circle run counter-clockwise has 'a' on its left.
Diagram apollonius_pair(const std::string& first_id = "a") {
  Diagram d;
  d.sites = {{first_id, 0, 0, 1}, {"b", 3, 0, 2}};
  d.arcs = {{kNone, kNone, Circle{-1, 0, 2}, true, 0, 1, false}};
  add_face(d, {0, true, false}, {{{0, true}}});
  add_face(d, {1, false, false}, {{{0, false}}});
  return d;
}

// Equal weights at x = 0, 2, 4: bisectors x = 1 and x = 3, both run upwards (+y), so the site to
// the west is on the left. The middle face is a strip, given as two separate boundary cycles.
Diagram three_in_a_row() {
  Diagram d;
  d.sites = {{"w", 0, 0, 1}, {"m", 2, 0, 1}, {"e", 4, 0, 1}};
  d.arcs = {{kNone, kNone, Line{1, 0, 0, 1}, true, 0, 1, false},
            {kNone, kNone, Line{3, 0, 0, 1}, true, 1, 2, false}};
  add_face(d, {0, false, false}, {{{0, true}}});
  add_face(d, {1, false, false}, {{{0, false}}, {{1, true}}});
  add_face(d, {2, false, false}, {{{1, false}}});
  return d;
}

// Three equal-weight sites around the origin: three rays from one node, three unbounded wedges,
// each face boundary passing through infinity once.
Diagram three_wedges() {
  Diagram d;
  d.sites = {{"p", 1, 0, 1}, {"q", -0.5, std::sqrt(0.75), 1}, {"r", -0.5, -std::sqrt(0.75), 1}};
  d.nodes = {{0, 0}};
  // Ray k points away from the node between sites; direction = bisector directions.
  const double s = std::sqrt(0.75);
  d.arcs = {{0, kNone, Line{0, 0, 0.5, s}, true, 1, 0, false},     // between p and q, left q
            {0, kNone, Line{0, 0, -1, 0}, true, 2, 1, false},      // between q and r, left r
            {0, kNone, Line{0, 0, 0.5, -s}, true, 0, 2, false}};   // between r and p, left p
  add_face(d, {0, false, false}, {{{2, true}, {0, false}}});
  add_face(d, {1, false, false}, {{{0, true}, {1, false}}});
  add_face(d, {2, false, false}, {{{1, true}, {2, false}}});
  return d;
}

std::string render(const Diagram& d, const SvgOptions& o = {}) {
  std::ostringstream out;
  write_svg(d, out, o);
  return out.str();
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// Checks that every element is closed in order and that no raw '&' escapes entity syntax: enough
// to catch broken output without an XML library.
void expect_well_formed(const std::string& svg) {
  testing::expect_well_formed_markup(svg, {}, "amp|lt|gt|quot|apos");
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  EXPECT_EQ(svg.find("inf"), std::string::npos);
}

std::vector<std::string> face_paths(const std::string& svg) {
  std::vector<std::string> out;
  const std::regex face(R"re(<path class="face[^"]*" fill="[^"]*" d="([^"]*)")re");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), face); it != std::sregex_iterator(); ++it) out.push_back((*it)[1]);
  return out;
}

// Subpaths of M/L/Z path data as polygons (arc commands are not expected here).
std::vector<std::vector<Point>> polygons(const std::string& d) {
  std::vector<std::vector<Point>> out;
  std::istringstream in(d);
  std::string command;
  while (in >> command) {
    if (command == "M") out.emplace_back();
    if (command == "M" || command == "L") {
      double x = 0, y = 0;
      in >> x >> y;
      out.back().push_back({x, y});
    }
    EXPECT_TRUE(command == "M" || command == "L" || command == "Z") << command;
  }
  return out;
}

// Even-odd rule over all subpaths, as the SVG renders it.
bool filled(const std::string& d, double px, double py) { return inside_rings(polygons(d), {px, py}); }

// The path data printer puts a space after each command letter; polygons() relies on it.
std::string spaced(std::string d) {
  return std::regex_replace(d, std::regex(R"(([MLZ]))"), "$1 ");
}

TEST(Svg, FullCircleFacesUseTwoHalfArcs) {
  const std::string svg = render(apollonius_pair());
  expect_well_formed(svg);
  const auto faces = face_paths(svg);
  ASSERT_EQ(faces.size(), 2u);
  // Inside face: counter-clockwise, from (1,0) via the antipode (-3,0).
  EXPECT_EQ(faces[0], "M1 0 A2 2 0 0 1 -3 0 A2 2 0 0 1 1 0 Z");
  // Outside face: a box around everything, with the circle run clockwise as a hole.
  EXPECT_EQ(count(faces[1], "A2 2 0 0 0"), 2u) << faces[1];
  EXPECT_EQ(count(faces[1], "M"), 2u);
  EXPECT_NE(svg.find("fill-rule=\"evenodd\""), std::string::npos);
  EXPECT_NE(svg.find("scale(1,-1)"), std::string::npos);
}

TEST(Svg, StrokeWidthsArePixelsConvertedToWorldUnitsOrNonScaling) {
  SvgOptions o;
  o.view = std::array<double, 4>{0, 0, 8, 4};  // 100 pixels per world unit at the default 800 px
  o.arc_width_px = 2;
  const std::string portable = render(apollonius_pair(), o);
  EXPECT_NE(portable.find("<path stroke-width=\"0.02\" d="), std::string::npos);
  EXPECT_NE(portable.find("height=\"400\""), std::string::npos);
  EXPECT_EQ(portable.find("vector-effect"), std::string::npos);
  o.non_scaling_stroke = true;
  const std::string zoomable = render(apollonius_pair(), o);
  EXPECT_NE(zoomable.find("<path stroke-width=\"2\" vector-effect=\"non-scaling-stroke\" d="), std::string::npos);
}

TEST(Svg, ArcWithNodesGetsLargeArcAndSweepFlags) {
  Diagram d = apollonius_pair();
  // Split the circle at (1,0) and (-1,2): a quarter counter-clockwise, three quarters onwards.
  d.nodes = {{1, 0}, {-1, 2}};
  d.arcs = {{0, 1, Circle{-1, 0, 2}, true, 0, 1, false}, {1, 0, Circle{-1, 0, 2}, true, 0, 1, false}};
  clear_faces(d);
  add_face(d, {0, true, false}, {{{0, true}, {1, true}}});
  add_face(d, {1, false, false}, {{{1, false}, {0, false}}});
  const auto faces = face_paths(render(d));
  ASSERT_EQ(faces.size(), 2u);
  EXPECT_EQ(faces[0], "M1 0 A2 2 0 0 1 -1 2 A2 2 0 1 1 1 0 Z");
  EXPECT_NE(faces[1].find("M1 0 A2 2 0 1 0 -1 2 A2 2 0 0 0 1 0 Z"), std::string::npos) << faces[1];
}

TEST(Svg, HalfPlanesAndStripFillTheRightSide) {
  const std::string svg = render(three_in_a_row());
  expect_well_formed(svg);
  const auto faces = face_paths(svg);
  ASSERT_EQ(faces.size(), 3u);
  const double probes[] = {0, 2, 4};  // x of each site; y = 0 and y = +-1.5
  for (std::size_t f = 0; f < 3; ++f) {
    for (std::size_t s = 0; s < 3; ++s) {
      for (const double y : {-1.5, 0.0, 1.5}) {
        EXPECT_EQ(filled(spaced(faces[f]), probes[s], y), f == s) << "face " << f << " at site " << s << ": " << faces[f];
      }
    }
  }
}

TEST(Svg, WedgesThroughInfinityFillTheRightSide) {
  const auto d = three_wedges();
  const auto faces = face_paths(render(d));
  ASSERT_EQ(faces.size(), 3u);
  for (std::size_t f = 0; f < 3; ++f) {
    for (std::size_t s = 0; s < 3; ++s) {
      EXPECT_EQ(filled(spaced(faces[f]), d.sites[s].x, d.sites[s].y), f == s) << "face " << f << ": " << faces[f];
      EXPECT_EQ(filled(spaced(faces[f]), 1.5 * d.sites[s].x, 1.5 * d.sites[s].y), f == s) << "face " << f << " further out";
    }
  }
}

TEST(Svg, RaysAreCutOutsideTheView) {
  const auto d = three_wedges();
  const Box view{-2, -2, 2, 2};
  const auto far = detail::far_box(d, view);
  EXPECT_LT(far.xmin, view.xmin);
  EXPECT_GT(far.ymax, view.ymax);
  const std::string ray = detail::arc_path(d, 1, far);  // along -x from the origin
  EXPECT_EQ(ray, "M0 0 L" + detail::svg_number(far.xmin) + " 0");
}

// The <text> elements of the labels group (the scale bar has a <text> of its own).
std::size_t label_count(const std::string& svg) {
  const auto begin = svg.find("<g class=\"labels\"");
  if (begin == std::string::npos) return 0;
  return count(svg.substr(begin, svg.find("</g>", begin) - begin), "<text");
}

TEST(Svg, EscapesIdsAndCapsTheNumberOfLabels) {
  const std::string svg = render(apollonius_pair("<a & \"b\">"));
  expect_well_formed(svg);
  EXPECT_EQ(svg.find("<a & "), std::string::npos);
  EXPECT_NE(svg.find("&lt;a &amp; &quot;b&quot;&gt;"), std::string::npos);
  EXPECT_EQ(label_count(svg), 2u);
  SvgOptions few;
  few.max_labels = 1;
  EXPECT_EQ(label_count(render(apollonius_pair(), few)), 1u);
  few.max_labels = 0;
  EXPECT_EQ(label_count(render(apollonius_pair(), few)), 0u);
}

TEST(Svg, WithoutFacesDrawsArcsOnly) {
  auto d = apollonius_pair();
  clear_faces(d);
  const std::string svg = render(d);
  expect_well_formed(svg);
  EXPECT_TRUE(face_paths(svg).empty());
  EXPECT_NE(svg.find("d=\"M1 0 A2 2 0 0 1 -3 0 A2 2 0 0 1 1 0\""), std::string::npos);
}

TEST(Svg, FrameArcsAndNodesAreDrawn) {
  Diagram d = apollonius_pair();
  d.nodes = {{0, 0}, {1, 0}};
  d.arcs.push_back({0, 1, Line{0, 0, 1, 0}, true, 0, kNone, true});
  const std::string svg = render(d);
  EXPECT_EQ(count(svg, "class=\"frame\""), 1u);
  EXPECT_EQ(count(svg, "<circle"), 4u);  // two nodes, two sites
}

TEST(Svg, OptionsAreValidated) {
  SvgOptions o;
  std::string why;
  EXPECT_TRUE(o.is_valid(&why));
  o.view = std::array<double, 4>{0, 0, 0, 1};
  EXPECT_FALSE(o.is_valid(&why));
  EXPECT_NE(why.find("view"), std::string::npos);
  std::ostringstream out;
  EXPECT_THROW(write_svg(apollonius_pair(), out, o), std::invalid_argument);
}

TEST(Svg, DistinctColoursForNumbers) {
  std::vector<std::string> seen;
  for (std::size_t i = 0; i < 12; ++i) {
    const auto c = site_colour(i);
    EXPECT_TRUE(std::regex_match(c, std::regex("#[0-9a-f]{6}"))) << c;
    EXPECT_EQ(std::count(seen.begin(), seen.end(), c), 0) << c;
    seen.push_back(c);
  }
}

}  // namespace
}  // namespace covmap::report
