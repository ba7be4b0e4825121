// Diagrams for the arc graph tests (diagram_json_test, fast_readers_test), and bit-exact comparison.
#pragma once

#include <gtest/gtest.h>

#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>

#include "core/diagram.h"

namespace covmap::io::testing {

// Bit-level equality, so 0.0 vs -0.0 or a last-digit change counts as different.
inline bool same(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

inline void expect_identical(const Diagram& a, const Diagram& b) {
  ASSERT_EQ(a.sites.size(), b.sites.size());
  for (std::size_t i = 0; i < a.sites.size(); ++i) {
    EXPECT_EQ(a.sites[i].id, b.sites[i].id);
    EXPECT_EQ(a.sites[i].name, b.sites[i].name);
    EXPECT_TRUE(same(a.sites[i].x, b.sites[i].x) && same(a.sites[i].y, b.sites[i].y) &&
                same(a.sites[i].weight, b.sites[i].weight)) << "site " << i;
  }
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  for (std::size_t i = 0; i < a.nodes.size(); ++i) {
    EXPECT_TRUE(same(a.nodes[i].x, b.nodes[i].x) && same(a.nodes[i].y, b.nodes[i].y)) << "node " << i;
  }
  ASSERT_EQ(a.arcs.size(), b.arcs.size());
  for (std::size_t i = 0; i < a.arcs.size(); ++i) {
    const auto &x = a.arcs[i], &y = b.arcs[i];
    EXPECT_EQ(x.from, y.from) << "arc " << i;
    EXPECT_EQ(x.to, y.to) << "arc " << i;
    EXPECT_EQ(x.ccw, y.ccw) << "arc " << i;
    EXPECT_EQ(x.left_site, y.left_site) << "arc " << i;
    EXPECT_EQ(x.right_site, y.right_site) << "arc " << i;
    EXPECT_EQ(x.frame, y.frame) << "arc " << i;
    ASSERT_EQ(x.curve.index(), y.curve.index()) << "arc " << i;
    if (const auto* c = std::get_if<Circle>(&x.curve)) {
      const auto& d = std::get<Circle>(y.curve);
      EXPECT_TRUE(same(c->cx, d.cx) && same(c->cy, d.cy) && same(c->r, d.r)) << "arc " << i;
    } else {
      const auto &l = std::get<Line>(x.curve), &m = std::get<Line>(y.curve);
      EXPECT_TRUE(same(l.x, m.x) && same(l.y, m.y) && same(l.dx, m.dx) && same(l.dy, m.dy)) << "arc " << i;
    }
  }
  ASSERT_EQ(a.faces.size(), b.faces.size());
  for (std::size_t i = 0; i < a.faces.size(); ++i) {
    const auto &f = a.faces[i], &g = b.faces[i];
    const FaceCycles fc = face_cycles(a, f), gc = face_cycles(b, g);
    EXPECT_EQ(f.site, g.site);
    EXPECT_EQ(f.bounded, g.bounded);
    EXPECT_EQ(f.orphan, g.orphan);
    ASSERT_EQ(fc.size(), gc.size()) << "face " << i;
    for (std::size_t c = 0; c < fc.size(); ++c) {
      ASSERT_EQ(fc[c].size(), gc[c].size());
      for (std::size_t k = 0; k < fc[c].size(); ++k) {
        EXPECT_EQ(fc[c][k].arc, gc[c][k].arc);
        EXPECT_EQ(fc[c][k].forward, gc[c][k].forward);
      }
    }
  }
  ASSERT_EQ(a.clip.size(), b.clip.size());
  for (std::size_t i = 0; i < a.clip.size(); ++i) EXPECT_TRUE(same(a.clip[i].x, b.clip[i].x) && same(a.clip[i].y, b.clip[i].y));
}

// Not a real Voronoi diagram (the reader checks structure, not geometry), but it has every feature
// the format can express, and doubles chosen to break a careless printer.
inline Diagram sample() {
  Diagram d;
  d.sites = {{"a", 0.1, -0.0, 1.0 / 3.0}, {"b", 5e-324, 1e300, 2.0}, {"c & <d>", -7.25, std::nextafter(1.0, 2.0), DBL_MAX}};
  d.sites[1].name = "Mast \"b\", north";  // names are optional: one site has one
  d.nodes = {{1.0 / 3.0, 2.0 / 3.0}, {-1e-300, 123456789.123456789}, {0.30000000000000004, 0.0}};
  d.arcs = {
      {kNone, kNone, Circle{-1, 0, 2}, true, 0, 1, false},                   // full circle
      {0, 1, Circle{0.1, 0.2, std::sqrt(2.0)}, false, 1, 2, false},         // clockwise arc
      {kNone, kNone, Line{1, 0, 0, 1}, true, 0, 2, false},                  // whole line
      {2, kNone, Line{0.1, 0.7, -std::sqrt(0.5), std::sqrt(0.5)}, true, 2, 1, false},  // ray
      {kNone, 0, Line{3, 3, 1, 0}, true, 1, 0, false},                      // ray from infinity
      {1, 2, Line{0, 0, 1, 1}, true, 2, kNone, true},                       // frame
  };
  add_face(d, {0, true, false}, {{{0, true}}});
  add_face(d, {1, false, false}, {{{0, false}}, {{3, false}, {4, true}}});
  add_face(d, {2, true, true}, {{{1, true}, {5, false}, {3, true}}});
  d.clip = {{-10, -10}, {10, -10}, {10, 10}, {-10, 0.1}};
  return d;
}

}  // namespace covmap::io::testing
