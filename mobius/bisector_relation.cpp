#include "mobius/bisector_relation.h"

#include <cmath>

#include "mobius/mobius.h"

namespace covmap::mobius {

WeightedPoint partner_across(const GeneralizedCircle& bisector, const WeightedPoint& site) {
  const SpherePoint image = Mobius::inversion(bisector).apply(site.position);
  WeightedPoint out;
  out.position = image ? *image : Complex(INFINITY, INFINITY);
  if (bisector.is_line()) {
    out.weight = site.weight;
  } else {
    // w_j = w_i · |c - s_j| / r = w_i · r / |c - s_i|.
    const Complex c = *bisector.centre();
    const double r = *bisector.radius();
    out.weight = site.weight * r / std::abs(site.position - c);
  }
  return out;
}

ArcBisector arc_bisector(const Arc& arc, const std::vector<Node>& nodes) {
  ArcBisector b;
  const int at = arc.from != kNone ? arc.from : arc.to;
  if (const auto* c = std::get_if<Circle>(&arc.curve)) {
    const Complex centre(c->cx, c->cy);
    b.v = at != kNone ? Complex(nodes[at].x, nodes[at].y) : centre + c->r;
    b.gamma = centre - b.v;
    return b;
  }
  const auto& l = std::get<Line>(arc.curve);
  b.line = true;
  b.v = at != kNone ? Complex(nodes[at].x, nodes[at].y) : Complex(l.x, l.y);
  b.gamma = Complex(l.dx, l.dy) / std::hypot(l.dx, l.dy);
  return b;
}

ArcBisector arc_bisector(const Arc& arc, const std::vector<Node>& nodes, Complex near) {
  ArcBisector b = arc_bisector(arc, nodes);
  auto consider = [&](Complex v) {
    if (std::norm(v - near) >= std::norm(b.v - near)) return;
    b.v = v;
    if (const auto* c = std::get_if<Circle>(&arc.curve)) b.gamma = Complex(c->cx, c->cy) - v;
  };
  if (arc.from != kNone && arc.to != kNone) consider(Complex(nodes[arc.to].x, nodes[arc.to].y));
  if (const auto* l = std::get_if<Line>(&arc.curve)) consider(Complex(l->x, l->y));
  return b;
}

WeightedPoint partner_across(const ArcBisector& b, const WeightedPoint& site) {
  const Complex delta = site.position - b.v;
  if (b.line) return {b.v + b.gamma * b.gamma * std::conj(delta), site.weight};
  const Complex away = delta - b.gamma;  // p - c
  const double away2 = std::norm(away);  // γ conj(δ) / conj(away) = γ conj(δ) away / |away|²
  return {b.v + b.gamma * std::conj(delta) * away / away2, site.weight * std::sqrt(std::norm(b.gamma) / away2)};
}

bool strictly_inside(const ArcBisector& b, Complex p) {
  const Complex delta = p - b.v;
  if (b.line) return std::imag(std::conj(b.gamma) * delta) > 0;
  return std::norm(delta) < 2.0 * std::real(std::conj(b.gamma) * delta);
}

}  // namespace covmap::mobius
