#include "check/check_normalization.h"

#include <algorithm>
#include <cmath>
#include <variant>

#include "core/weighted_owner.h"

namespace covmap::check::detail {
namespace {

// Lengths and weights whose binary exponent lies within ±kComfortableExponent are checked as they
// are: their squares and quotients stay far from overflow and from denormals (2^±1022).
constexpr int kComfortableExponent = 100;

// The exponent e with v = m·2^e, 0.5 ≤ m < 1 (v finite and positive).
int exponent_of(double v) {
  int e = 0;
  std::frexp(v, &e);
  return e;
}

bool comfortable(int exponent) { return std::abs(exponent) <= kComfortableExponent; }

}  // namespace

Normalization normalization_for(const Diagram& d) {
  Normalization n;
  double largest_weight = 0.0;
  for (const Site& s : d.sites)
    if (site_is_valid(s)) largest_weight = std::max(largest_weight, s.weight);
  if (largest_weight > 0.0 && !comfortable(exponent_of(largest_weight)))
    n.weight_exponent = -exponent_of(largest_weight);
  const double scale = diagram_scale(d);
  double largest_coordinate = 0.0;
  for (const Site& s : d.sites)
    if (site_is_valid(s)) largest_coordinate = std::max({largest_coordinate, std::abs(s.x), std::abs(s.y)});
  // diagram_scale is 1 when the sites do not span a box; then the coordinates decide.
  const double length = largest_coordinate > 0.0 && scale == 1.0 ? largest_coordinate : scale;
  if (!comfortable(exponent_of(length)) || (largest_coordinate > 0.0 && !comfortable(exponent_of(largest_coordinate))))
    n.length_exponent = -exponent_of(length);
  return n;
}

Diagram normalized(const Diagram& d, const Normalization& n) {
  Diagram out = d;
  const auto len = [&](double v) { return std::ldexp(v, n.length_exponent); };
  for (Site& s : out.sites) {
    s.x = len(s.x);
    s.y = len(s.y);
    s.weight = std::ldexp(s.weight, n.weight_exponent);
  }
  for (Node& v : out.nodes) v = {len(v.x), len(v.y)};
  for (Arc& a : out.arcs) {
    if (auto* c = std::get_if<Circle>(&a.curve))
      *c = {len(c->cx), len(c->cy), len(c->r)};
    else if (auto* l = std::get_if<Line>(&a.curve))
      *l = {len(l->x), len(l->y), l->dx, l->dy};
  }
  for (Point& p : out.clip) p = {len(p.x), len(p.y)};
  return out;
}

void scale_back(CheckReport& report, const Normalization& n) {
  if (n.length_exponent == 0) return;
  const auto back = [&](double v) { return std::ldexp(v, -n.length_exponent); };
  report.scale = back(report.scale);
  report.eps = back(report.eps);
  report.message_length_unit = std::ldexp(1.0, -n.length_exponent);
  for (Violation& v : report.violations) {
    v.x = back(v.x);
    v.y = back(v.y);
  }
}

}  // namespace covmap::check::detail
