#include "cleaning/tolerances.h"
#include "cleaning/curve_fit.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace covmap::cleaning {
namespace {


constexpr double kPi = 3.14159265358979323846;

// Points in a frame centred at `origin`, scaled by 1 / scale, rotated so that `axis` is +x.
struct Frame {
  Point origin;
  double scale = 1.0;
  Point axis{1.0, 0.0};  // unit
  Point to_local(Point p) const {
    const double x = (p.x - origin.x) / scale, y = (p.y - origin.y) / scale;
    return {x * axis.x + y * axis.y, -x * axis.y + y * axis.x};
  }
  Point to_world(Point p) const {
    return {origin.x + scale * (p.x * axis.x - p.y * axis.y), origin.y + scale * (p.x * axis.y + p.y * axis.x)};
  }
  Point direction_to_world(Point d) const { return {d.x * axis.x - d.y * axis.y, d.x * axis.y + d.y * axis.x}; }
};

double huber_weight(double r, double h) {
  const double a = std::abs(r);
  return a <= h ? 1.0 : h / a;
}
double huber_cost(double r, double h) {
  const double a = std::abs(r);
  return a <= h ? 0.5 * r * r : h * a - 0.5 * h * h;
}

// The curvature form in local coordinates: A|p|² + s (cos θ x + sin θ y) + D, s = √(1 + 4AD).
struct Form {
  double a = 0.0, d = 0.0, theta = 0.0;
  bool valid() const { return 1.0 + 4.0 * a * d > 0.0 && std::isfinite(a) && std::isfinite(d) && std::isfinite(theta); }
  double s() const { return std::sqrt(std::max(0.0, 1.0 + 4.0 * a * d)); }
};

// The Form's numbers that do not depend on the point (one sine and cosine per evaluation, not
// per point).
struct Evaluated {
  double a, d, s, c, sn;
  explicit Evaluated(const Form& f) : a(f.a), d(f.d), s(f.s()), c(std::cos(f.theta)), sn(std::sin(f.theta)) {}
};

// Geometric distance 2P / (1 + √(1 + 4AP)) and its gradient in (A, D, θ).
double form_distance(const Evaluated& f, Point p, std::array<double, 3>* gradient) {
  const double u = f.c * p.x + f.sn * p.y, v = -f.sn * p.x + f.c * p.y, r2 = p.x * p.x + p.y * p.y;
  const double P = f.a * r2 + f.s * u + f.d;
  const double Q = std::sqrt(std::max(0.0, 1.0 + 4.0 * f.a * P));
  const double dist = 2.0 * P / (1.0 + Q);
  if (gradient) {
    // d(dist)/dP = 1/Q; A also enters through Q: −dist²/Q. Q → 0 only at the circle's centre.
    const double q = std::max(Q, std::numeric_limits<double>::min());
    const double sd = std::max(f.s, std::numeric_limits<double>::min());
    (*gradient)[0] = (r2 + 2.0 * f.d / sd * u - dist * dist) / q;
    (*gradient)[1] = (1.0 + 2.0 * f.a / sd * u) / q;
    (*gradient)[2] = f.s * v / q;
  }
  return dist;
}

double robust_cost(const Form& f, const std::vector<Point>& pts, double h) {
  const Evaluated e(f);
  double cost = 0.0;
  for (const Point& p : pts) cost += huber_cost(form_distance(e, p, nullptr), h);
  return cost;
}

// Symmetric positive (semi)definite solve by Gaussian elimination with partial pivoting; false if
// singular.
template <std::size_t N>
bool solve(std::array<std::array<double, N>, N> m, std::array<double, N> b, std::array<double, N>& x) {
  for (std::size_t c = 0; c < N; ++c) {
    std::size_t pivot = c;
    for (std::size_t r = c + 1; r < N; ++r)
      if (std::abs(m[r][c]) > std::abs(m[pivot][c])) pivot = r;
    if (!(std::abs(m[pivot][c]) > 0.0)) return false;
    std::swap(m[c], m[pivot]);
    std::swap(b[c], b[pivot]);
    for (std::size_t r = c + 1; r < N; ++r) {
      const double f = m[r][c] / m[c][c];
      for (std::size_t k = c; k < N; ++k) m[r][k] -= f * m[c][k];
      b[r] -= f * b[c];
    }
  }
  for (std::size_t c = N; c-- > 0;) {
    double v = b[c];
    for (std::size_t k = c + 1; k < N; ++k) v -= m[c][k] * x[k];
    x[c] = v / m[c][c];
  }
  return std::all_of(x.begin(), x.end(), [](double v) { return std::isfinite(v); });
}

// Levenberg–Marquardt on (A, D, θ) with Huber weights re-evaluated at every iteration.
Form refine(Form f, const std::vector<Point>& pts, double h) {
  double cost = robust_cost(f, pts, h);
  double lambda = tolerance::kFitInitialDamping;
  for (int it = 0; it < tolerance::kFitIterations; ++it) {
    std::array<std::array<double, 3>, 3> jtj{};
    std::array<double, 3> jtr{};
    const Evaluated e(f);
    for (const Point& p : pts) {
      std::array<double, 3> g{};
      const double r = form_distance(e, p, &g);
      const double w = huber_weight(r, h);
      for (std::size_t i = 0; i < 3; ++i) {
        jtr[i] += w * g[i] * r;
        for (std::size_t j = 0; j < 3; ++j) jtj[i][j] += w * g[i] * g[j];
      }
    }
    bool improved = false;
    while (lambda < tolerance::kFitMaxDamping) {
      auto m = jtj;
      for (std::size_t i = 0; i < 3; ++i) m[i][i] += lambda * std::max(jtj[i][i], tolerance::kFitMinDamping);
      std::array<double, 3> step{};
      std::array<double, 3> rhs{-jtr[0], -jtr[1], -jtr[2]};
      if (!solve(m, rhs, step)) {
        lambda *= 10.0;
        continue;
      }
      Form next{f.a + step[0], f.d + step[1], f.theta + step[2]};
      if (next.valid()) {
        const double next_cost = robust_cost(next, pts, h);
        if (next_cost <= cost) {
          const double decrease = cost - next_cost;
          f = next;
          const double old = cost;
          cost = next_cost;
          lambda = std::max(lambda / 10.0, tolerance::kFitMinDamping);
          improved = decrease > tolerance::kFitCostDecrease * std::max(old, std::numeric_limits<double>::min());
          break;
        }
      }
      lambda *= 10.0;
    }
    if (!improved) break;
  }
  return f;
}

// Orthogonal (total least squares) line, Huber-reweighted a few times, as a Form with A = 0.
Form line_fit(const std::vector<Point>& pts, double h) {
  std::vector<double> w(pts.size(), 1.0);
  Form f;
  for (int round = 0; round < tolerance::kLineReweightings; ++round) {
    double sw = 0.0, mx = 0.0, my = 0.0;
    for (std::size_t i = 0; i < pts.size(); ++i) sw += w[i], mx += w[i] * pts[i].x, my += w[i] * pts[i].y;
    mx /= sw, my /= sw;
    double sxx = 0.0, syy = 0.0, sxy = 0.0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const double dx = pts[i].x - mx, dy = pts[i].y - my;
      sxx += w[i] * dx * dx, syy += w[i] * dy * dy, sxy += w[i] * dx * dy;
    }
    // The normal is the eigenvector of the smaller eigenvalue of the scatter matrix.
    const double direction = 0.5 * std::atan2(2.0 * sxy, sxx - syy);
    f.theta = direction + 0.5 * kPi;
    f.a = 0.0;
    f.d = -(std::cos(f.theta) * mx + std::sin(f.theta) * my);
    const Evaluated e(f);
    for (std::size_t i = 0; i < pts.size(); ++i) w[i] = huber_weight(form_distance(e, pts[i], nullptr), h);
  }
  return f;
}

// Kåsa's algebraic circle (x² + y² + a x + b y + c = 0 in least squares) as a Form; nullopt-like
// `false` when the system is singular (collinear points).
bool kasa(const std::vector<Point>& pts, Form& out) {
  std::array<std::array<double, 3>, 3> m{};
  std::array<double, 3> rhs{};
  for (const Point& p : pts) {
    const std::array<double, 3> row{p.x, p.y, 1.0};
    const double z = -(p.x * p.x + p.y * p.y);
    for (std::size_t i = 0; i < 3; ++i) {
      rhs[i] += row[i] * z;
      for (std::size_t j = 0; j < 3; ++j) m[i][j] += row[i] * row[j];
    }
  }
  std::array<double, 3> x{};
  if (!solve(m, rhs, x)) return false;
  const double mx = -0.5 * x[0], my = -0.5 * x[1];
  const double r2 = mx * mx + my * my - x[2];
  if (!(r2 > 0.0) || !std::isfinite(r2)) return false;
  const double radius = std::sqrt(r2);
  out.a = 0.5 / radius;
  out.d = out.a * (mx * mx + my * my - r2);
  out.theta = std::atan2(-my, -mx);  // (B, C) = −2A (mx, my)
  return out.valid();
}

// The Form in the frame's local coordinates as a world curve.
Curve to_curve(const Form& f, const Frame& frame) {
  const double s = f.s();
  const double b = s * std::cos(f.theta), c = s * std::sin(f.theta);
  if (std::abs(f.a) < tolerance::kLineCurvature) {
    // b x + c y + D = 0 with |(b, c)| = s ≈ 1 (A ≈ 0).
    const double n = std::hypot(b, c);
    const Point foot = frame.to_world({-f.d * b / (n * n), -f.d * c / (n * n)});
    const Point dir = frame.direction_to_world({-c / n, b / n});
    return Line{foot.x, foot.y, dir.x, dir.y};
  }
  const Point centre = frame.to_world({-b / (2.0 * f.a), -c / (2.0 * f.a)});
  return Circle{centre.x, centre.y, frame.scale / (2.0 * std::abs(f.a))};
}

double sum_squares(std::span<const Point> points, const Curve& curve) {
  double ss = 0.0;
  for (const Point& p : points) {
    const double d = distance_to(curve, p);
    ss += d * d;
  }
  return ss;
}

Line line_through(Point p, Point q) {
  const double l = std::hypot(q.x - p.x, q.y - p.y);
  if (!(l > 0.0)) return Line{p.x, p.y, 1.0, 0.0};
  return Line{p.x, p.y, (q.x - p.x) / l, (q.y - p.y) / l};
}

}  // namespace

double distance_to(const Curve& curve, Point p, Point* gradient) {
  if (const auto* c = std::get_if<Circle>(&curve)) {
    const double dx = p.x - c->cx, dy = p.y - c->cy, r = std::hypot(dx, dy);
    if (gradient) *gradient = r > 0.0 ? Point{dx / r, dy / r} : Point{1.0, 0.0};
    return r - c->r;
  }
  const auto& l = std::get<Line>(curve);
  const double n = std::hypot(l.dx, l.dy);
  const Point normal{-l.dy / n, l.dx / n};
  if (gradient) *gradient = normal;
  return normal.x * (p.x - l.x) + normal.y * (p.y - l.y);
}

void deviation(std::span<const Point> points, const Curve& curve, double& rms, double& max) {
  double ss = 0.0;
  max = 0.0;
  for (const Point& p : points) {
    const double d = distance_to(curve, p);
    ss += d * d;
    max = std::max(max, std::abs(d));
  }
  rms = points.empty() ? 0.0 : std::sqrt(ss / static_cast<double>(points.size()));
}

FittedCurve fit_curve(std::span<const Point> points, double huber, double line_preference, bool force_circle) {
  FittedCurve out;
  const std::size_t n = points.size();
  if (n < tolerance::kMinFitPoints) {
    out.curve = n == 0 ? Line{} : line_through(points.front(), points.back());
    deviation(points, out.curve, out.rms, out.max_deviation);
    return out;
  }
  Frame frame;
  frame.origin = points[n / 2];
  double extent = 0.0;
  for (const Point& p : points) extent = std::max(extent, std::hypot(p.x - frame.origin.x, p.y - frame.origin.y));
  if (!(extent > 0.0)) {
    out.curve = Line{frame.origin.x, frame.origin.y, 1.0, 0.0};
    return out;
  }
  frame.scale = extent;
  std::vector<Point> local;
  local.reserve(n);
  for (const Point& p : points) local.push_back(frame.to_local(p));
  const double h = huber / extent;

  const Form line = line_fit(local, h);
  Form circle = refine(line, local, h);
  Form algebraic;
  if (kasa(local, algebraic)) {
    const Form from_kasa = refine(algebraic, local, h);
    if (robust_cost(from_kasa, local, h) < robust_cost(circle, local, h)) circle = from_kasa;
  }
  const Curve line_curve = to_curve(line, frame), circle_curve = to_curve(circle, frame);
  bool use_line = true;
  if (std::holds_alternative<Line>(circle_curve)) {
    use_line = true;  // the circle's curvature vanished: it is a line anyway
  } else if (force_circle) {
    use_line = false;
  } else if (n > 3) {
    // Per degree of freedom: the circle's extra parameter always lowers the plain rms a little.
    const double line_rms = std::sqrt(sum_squares(points, line_curve) / static_cast<double>(n - 2));
    const double circle_rms = std::sqrt(sum_squares(points, circle_curve) / static_cast<double>(n - 3));
    use_line = line_rms <= line_preference * circle_rms + tolerance::kRmsFloor * extent;
  }
  out.curve = use_line ? line_curve : circle_curve;
  if (auto* l = std::get_if<Line>(&out.curve)) {
    // Lines run the way the chain does.
    if (l->dx * (points.back().x - points.front().x) + l->dy * (points.back().y - points.front().y) < 0.0)
      l->dx = -l->dx, l->dy = -l->dy;
  }
  deviation(points, out.curve, out.rms, out.max_deviation);
  return out;
}

Curve fit_through(std::span<const Point> points, Point p, Point q, const Curve& guess, double huber) {
  const double chord = std::hypot(q.x - p.x, q.y - p.y);
  if (std::holds_alternative<Line>(guess) || !(chord > 0.0) || points.empty()) return line_through(p, q);
  // Local frame: origin at the chord's midpoint, +x towards q, unit = half the chord. The circles
  // through (±1, 0): sin φ/2 · (x² + y² − 1) + cos φ · y = 0 (curvature form, A = sin φ / 2).
  Frame frame;
  frame.origin = {0.5 * (p.x + q.x), 0.5 * (p.y + q.y)};
  frame.scale = 0.5 * chord;
  frame.axis = {(q.x - p.x) / chord, (q.y - p.y) / chord};
  std::vector<Point> local;
  local.reserve(points.size());
  for (const Point& x : points) local.push_back(frame.to_local(x));
  const double h = huber / frame.scale;

  // The family's distance at one φ, for all points: sine and cosine once.
  const auto distance = [](double sine, double cosine, Point x, double* derivative) {
    const double a = 0.5 * sine;
    const double w = x.x * x.x + x.y * x.y - 1.0;
    const double P = a * w + cosine * x.y;
    const double Q = std::sqrt(std::max(0.0, 1.0 + 4.0 * a * P));
    const double d = 2.0 * P / (1.0 + Q);
    if (derivative) {
      const double qq = std::max(Q, std::numeric_limits<double>::min());
      *derivative = (0.5 * cosine * w - sine * x.y - d * d * 0.5 * cosine) / qq;
    }
    return d;
  };
  const auto cost = [&](double phi) {
    const double sine = std::sin(phi), cosine = std::cos(phi);
    double total = 0.0;
    for (const Point& x : local) total += huber_cost(distance(sine, cosine, x, nullptr), h);
    return total;
  };
  // Starting values: the guess's centre moved onto the chord's bisector, and the circle through
  // p, q and the middle point.
  std::vector<double> starts;
  const auto& g = std::get<Circle>(guess);
  const Point centre = frame.to_local({g.cx, g.cy});
  starts.push_back(std::atan2(1.0, -centre.y));
  {
    const Point m = local[local.size() / 2];
    // Circle through (±1, 0) and m: centre (0, k) with 1 + k² = m.x² + (m.y − k)².
    if (std::abs(m.y) > 0.0) starts.push_back(std::atan2(1.0, -((m.x * m.x + m.y * m.y - 1.0) / (2.0 * m.y))));
  }
  double best_phi = starts.front(), best_cost = std::numeric_limits<double>::infinity();
  for (double phi : starts) {
    double c0 = cost(phi), lambda = tolerance::kFitInitialDamping;
    for (int it = 0; it < tolerance::kFitIterations; ++it) {
      double jtj = 0.0, jtr = 0.0;
      const double sine = std::sin(phi), cosine = std::cos(phi);
      for (const Point& x : local) {
        double g1 = 0.0;
        const double r = distance(sine, cosine, x, &g1);
        const double w = huber_weight(r, h);
        jtj += w * g1 * g1, jtr += w * g1 * r;
      }
      bool improved = false;
      while (lambda < tolerance::kFitMaxDamping) {
        const double step = -jtr / (jtj * (1.0 + lambda) + std::numeric_limits<double>::min());
        const double c1 = cost(phi + step);
        if (std::isfinite(step) && c1 <= c0) {
          improved = c0 - c1 > tolerance::kFitCostDecrease * std::max(c0, std::numeric_limits<double>::min());
          phi += step, c0 = c1;
          lambda = std::max(lambda / 10.0, tolerance::kFitMinDamping);
          break;
        }
        lambda *= 10.0;
      }
      if (!improved) break;
    }
    if (c0 < best_cost) best_cost = c0, best_phi = phi;
  }
  const double sine = std::sin(best_phi);
  if (std::abs(sine) < tolerance::kLineCurvature) return line_through(p, q);
  const double k = -std::cos(best_phi) / sine;
  const Point c = frame.to_world({0.0, k});
  return Circle{c.x, c.y, frame.scale / std::abs(sine)};
}

}  // namespace covmap::cleaning
