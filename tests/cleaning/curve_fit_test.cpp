// Curve fitting of map cleaning (cleaning/curve_fit.h) against closed forms: points on
// known circles and lines, optimality of the least-squares answer by perturbation, and curves
// forced through two points.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <variant>
#include <vector>

#include "cleaning/curve_fit.h"

namespace covmap::cleaning {
namespace {


constexpr double kPi = 3.14159265358979323846;

std::vector<Point> arc_points(Circle c, double from, double to, int n) {
  std::vector<Point> pts;
  for (int k = 0; k < n; ++k) {
    const double t = from + (to - from) * k / (n - 1);
    pts.push_back({c.cx + c.r * std::cos(t), c.cy + c.r * std::sin(t)});
  }
  return pts;
}

// Independent geometry: distance of p to the circle or line.
double true_distance(const Curve& curve, Point p) {
  if (const auto* c = std::get_if<Circle>(&curve)) return std::hypot(p.x - c->cx, p.y - c->cy) - c->r;
  const auto& l = std::get<Line>(curve);
  return ((p.x - l.x) * l.dy - (p.y - l.y) * l.dx) / std::hypot(l.dx, l.dy);
}

double sum_squares(const std::vector<Point>& pts, const Curve& c) {
  double s = 0.0;
  for (const Point& p : pts) s += true_distance(c, p) * true_distance(c, p);
  return s;
}

TEST(MapCleaningFit, ExactArcGivesItsCircle) {
  const Circle truth{1234.5, -987.0, 250.0};
  const auto pts = arc_points(truth, 0.3, 0.3 + kPi / 2, 40);
  const FittedCurve fit = fit_curve(pts, 10.0, 1.05, false);
  ASSERT_TRUE(std::holds_alternative<Circle>(fit.curve));
  const auto& c = std::get<Circle>(fit.curve);
  EXPECT_NEAR(c.cx, truth.cx, 1e-7);
  EXPECT_NEAR(c.cy, truth.cy, 1e-7);
  EXPECT_NEAR(c.r, truth.r, 1e-7);
  EXPECT_LT(fit.rms, 1e-8);
}

TEST(MapCleaningFit, ShortNoisyArcStaysCloseToItsCircle) {
  // 10° of a circle with noise of 1 % of the radius' sagitta scale: Kåsa alone is biased here;
  // the geometric refinement is not.
  const Circle truth{0.0, 0.0, 5000.0};
  auto pts = arc_points(truth, 1.0, 1.0 + 10.0 * kPi / 180.0, 200);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> noise(-1.0, 1.0);
  for (Point& p : pts) p.x += noise(rng), p.y += noise(rng);
  const FittedCurve fit = fit_curve(pts, 1e6, 1.05, false);
  ASSERT_TRUE(std::holds_alternative<Circle>(fit.curve));
  const auto& c = std::get<Circle>(fit.curve);
  EXPECT_NEAR(c.r, truth.r, 0.02 * truth.r);
  // A least-squares optimum: no small change of centre or radius lowers the sum of squares.
  const double best = sum_squares(pts, fit.curve);
  for (int k = 0; k < 3; ++k)
    for (double sign : {-1.0, 1.0}) {
      Circle moved = c;
      (k == 0 ? moved.cx : k == 1 ? moved.cy : moved.r) += sign * 0.05;
      EXPECT_GE(sum_squares(pts, moved), best * (1.0 - 1e-9)) << "parameter " << k << " sign " << sign;
    }
}

TEST(MapCleaningFit, CollinearPointsGiveALine) {
  std::vector<Point> pts;
  for (int k = 0; k < 30; ++k) pts.push_back({1e5 + 3.0 * k, 2e5 - 7.0 * k});
  const FittedCurve fit = fit_curve(pts, 1.0, 1.05, false);
  ASSERT_TRUE(std::holds_alternative<Line>(fit.curve));
  for (const Point& p : pts) EXPECT_NEAR(true_distance(fit.curve, p), 0.0, 1e-8);
  // Direction: along the points' order.
  const auto& l = std::get<Line>(fit.curve);
  EXPECT_GT(l.dx * 3.0 - l.dy * 7.0, 0.0);
}

TEST(MapCleaningFit, HugeRadiusWithNoiseDegradesIntoALine) {
  // Radius 10^6 chain lengths: the sagitta (1e-7) is far below the noise (1e-2), so a line fits
  // as well and is preferred; nothing overflows on the way.
  const double length = 100.0;
  const Circle truth{0.0, -1e8, 1e8};
  auto pts = arc_points(truth, kPi / 2 - 0.5e-6, kPi / 2 + 0.5e-6, 101);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> noise(-0.01, 0.01);
  for (Point& p : pts) p.y += noise(rng);
  const FittedCurve fit = fit_curve(pts, 1.0, 1.05, false);
  ASSERT_TRUE(std::holds_alternative<Line>(fit.curve));
  EXPECT_LT(fit.max_deviation, 0.02);
  EXPECT_GT(length, 0.0);
}

TEST(MapCleaningFit, AstronomicalRadiusIsALineEvenWhenExact) {
  const Circle truth{0.0, -1e15, 1e15};
  const auto pts = arc_points(truth, kPi / 2 - 1e-13, kPi / 2 + 1e-13, 50);
  const FittedCurve fit = fit_curve(pts, 1.0, 1.05, false);
  EXPECT_TRUE(std::holds_alternative<Line>(fit.curve));
  EXPECT_LT(fit.max_deviation, 1e-3);
}

TEST(MapCleaningFit, ClosedLoopIsACircleAndOutliersDoNotPullIt) {
  const Circle truth{50.0, 60.0, 20.0};
  auto pts = arc_points(truth, 0.0, 2 * kPi * 0.99, 100);
  // Five gross outliers (a staircase hook near a junction, say): the Huber loss caps their pull.
  for (int k = 0; k < 5; ++k) pts[static_cast<std::size_t>(k * 20)].x += 15.0;
  const FittedCurve fit = fit_curve(pts, 1.0, 1.05, true);
  ASSERT_TRUE(std::holds_alternative<Circle>(fit.curve));
  const auto& c = std::get<Circle>(fit.curve);
  EXPECT_NEAR(c.cx, truth.cx, 0.3);
  EXPECT_NEAR(c.cy, truth.cy, 0.3);
  EXPECT_NEAR(c.r, truth.r, 0.3);
}

TEST(MapCleaningFit, CurveThroughTwoPointsPassesThroughThem) {
  const Circle truth{10.0, 20.0, 300.0};
  auto pts = arc_points(truth, 0.2, 1.4, 60);
  const Point p = pts.front(), q = pts.back();
  std::vector<Point> inner(pts.begin() + 1, pts.end() - 1);
  // A guess that is off: the family through p and q still finds the true circle.
  const Curve c = fit_through(inner, p, q, Circle{0.0, 0.0, 250.0}, 5.0);
  ASSERT_TRUE(std::holds_alternative<Circle>(c));
  EXPECT_NEAR(true_distance(c, p), 0.0, 1e-9);
  EXPECT_NEAR(true_distance(c, q), 0.0, 1e-9);
  EXPECT_NEAR(std::get<Circle>(c).r, truth.r, 1e-6);
  EXPECT_NEAR(std::get<Circle>(c).cx, truth.cx, 1e-6);
  // Ends moved off the circle: the result still passes through the given ends.
  const Point p2{p.x + 1.0, p.y - 0.5}, q2{q.x - 0.7, q.y + 0.3};
  const Curve moved = fit_through(inner, p2, q2, truth, 5.0);
  EXPECT_NEAR(true_distance(moved, p2), 0.0, 1e-9);
  EXPECT_NEAR(true_distance(moved, q2), 0.0, 1e-9);
  // A line guess gives the line through both ends, directed from p to q.
  const Curve line = fit_through(inner, p, q, Line{}, 5.0);
  ASSERT_TRUE(std::holds_alternative<Line>(line));
  EXPECT_NEAR(true_distance(line, q), 0.0, 1e-9);
  EXPECT_GT((q.x - p.x) * std::get<Line>(line).dx + (q.y - p.y) * std::get<Line>(line).dy, 0.0);
}

TEST(MapCleaningFit, MoreThanHalfACircleThroughTwoPoints) {
  // A chain that goes the long way round (300° of the circle) between its ends.
  const Circle truth{0.0, 0.0, 40.0};
  const auto pts = arc_points(truth, 0.0, 300.0 * kPi / 180.0, 120);
  std::vector<Point> inner(pts.begin() + 1, pts.end() - 1);
  const Curve c = fit_through(inner, pts.front(), pts.back(), Circle{5.0, -3.0, 38.0}, 2.0);
  ASSERT_TRUE(std::holds_alternative<Circle>(c));
  EXPECT_NEAR(std::get<Circle>(c).r, truth.r, 1e-6);
  EXPECT_NEAR(std::get<Circle>(c).cx, truth.cx, 1e-6);
  EXPECT_NEAR(std::get<Circle>(c).cy, truth.cy, 1e-6);
}

TEST(MapCleaningFit, SignedDistanceAndGradient) {
  Point g;
  EXPECT_DOUBLE_EQ(distance_to(Circle{1.0, 1.0, 2.0}, {4.0, 5.0}, &g), 3.0);
  EXPECT_DOUBLE_EQ(g.x, 0.6);
  EXPECT_DOUBLE_EQ(g.y, 0.8);
  // Left of a line is positive; the gradient is the left normal.
  EXPECT_DOUBLE_EQ(distance_to(Line{0.0, 0.0, 2.0, 0.0}, {5.0, 3.0}, &g), 3.0);
  EXPECT_DOUBLE_EQ(g.x, 0.0);
  EXPECT_DOUBLE_EQ(g.y, 1.0);
}

}  // namespace
}  // namespace covmap::cleaning
