// One-parameter families in recognize() (paper 5, §4.2: every node of the start face gives the same
// solution circle): which members of the circle put every pair of sites on the two sides of their
// arc. Each arc's demand, pulled back to the start face (pulled_back_bounds), is a generalized disk;
// on the circle, parametrised by an angle θ, it is an arc of θ (the form's value is
// a0 + a1 cos θ + a2 sin θ); the members are the intersection of those arcs. The representative is
// the middle of the widest piece: the member farthest (in θ) from every bound.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "recognition/recognize_stages.h"

namespace covmap::recognition::stages {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// The point of `circle` at parameter θ: its centre plus radius·e^{iθ}; a line through p0 with unit
// direction u is the image of the circle under θ ↦ p0 + ℓ tan(θ/2) u (θ = π is ∞).
struct CircleParameter {
  bool line = false;
  mobius::Complex centre, u;
  double radius = 0.0, ell = 1.0;

  mobius::Complex at(double theta) const {
    return line ? centre + ell * std::tan(0.5 * theta) * u : centre + std::polar(radius, theta);
  }
  // (a0, a1, a2) with form(at(θ)) ∝ a0 + a1 cos θ + a2 sin θ (a positive factor for lines).
  std::array<double, 3> coefficients(const mobius::GeneralizedCircle& b) const {
    if (!line) {
      const mobius::Complex w = b.A * std::conj(centre) + std::conj(b.B);
      const double a0 = b.A * (std::norm(centre) + radius * radius) + 2.0 * std::real(std::conj(b.B) * centre) + b.C;
      return {a0, 2.0 * radius * w.real(), -2.0 * radius * w.imag()};
    }
    const double P = b.value(centre);
    const double Q = 2.0 * ell * (b.A * std::real(std::conj(centre) * u) + std::real(std::conj(b.B) * u));
    const double R = b.A * ell * ell;
    return {0.5 * (P + R), 0.5 * (P - R), 0.5 * Q};
  }
};

std::optional<CircleParameter> parameter_of(const mobius::GeneralizedCircle& c, double scale) {
  CircleParameter p;
  if (c.is_line()) {
    if (std::abs(c.B) == 0) return std::nullopt;
    p.line = true;
    p.centre = -c.C * c.B / (2.0 * std::norm(c.B));
    p.u = mobius::Complex(0, 1) * c.B / std::abs(c.B);
    p.ell = scale;
    return p;
  }
  const auto centre = c.centre();
  const auto radius = c.radius();
  if (!centre || !radius) return std::nullopt;
  p.centre = *centre;
  p.radius = *radius;
  return p;
}

}  // namespace

std::vector<mobius::Complex> family_members(const TracedGraph& t, int start, const mobius::GeneralizedCircle& circle) {
  const auto param = parameter_of(circle, t.scale);
  if (!param) return {};
  // Events of the allowed arcs of θ in [0, 2π): +1 where one begins, -1 where it ends.
  std::vector<std::pair<double, int>> events;
  int partial = 0;
  for (const mobius::GeneralizedCircle& b : pulled_back_bounds(t, start)) {
    const auto [a0, a1, a2] = param->coefficients(b);
    const double amplitude = std::hypot(a1, a2);
    if (!(amplitude > 0)) {
      if (a0 > 0) return {};  // never satisfied on the circle
      continue;               // always satisfied
    }
    const double level = -a0 / amplitude;  // allowed: cos(θ - φ) ≤ level
    if (level >= 1.0) continue;
    if (level < -1.0) return {};
    const double half = std::numbers::pi - std::acos(level);
    double begin = std::fmod(std::atan2(a2, a1) + std::numbers::pi - half, kTwoPi);
    if (begin < 0) begin += kTwoPi;
    const double end = begin + 2.0 * half;
    ++partial;
    events.push_back({begin, +1});
    if (end <= kTwoPi) {
      events.push_back({end, -1});
    } else {
      events.push_back({kTwoPi, -1});
      events.push_back({0.0, +1});
      events.push_back({end - kTwoPi, -1});
    }
  }
  if (partial == 0) return {param->at(param->line ? 0.0 : 0.5)};
  std::sort(events.begin(), events.end(), [](const auto& a, const auto& b) {
    return a.first < b.first || (a.first == b.first && a.second < b.second);  // ends before begins
  });
  // Pieces where all partial arcs overlap, widest first (a piece through θ = 0 is joined).
  std::vector<std::pair<double, double>> pieces;
  int count = 0;
  for (std::size_t k = 0; k < events.size(); ++k) {
    count += events[k].second;
    if (count == partial && k + 1 < events.size() && events[k + 1].first > events[k].first)
      pieces.push_back({events[k].first, events[k + 1].first});
  }
  if (pieces.size() > 1 && pieces.front().first == 0.0 && pieces.back().second == kTwoPi) {
    pieces.front().first = pieces.back().first - kTwoPi;
    pieces.pop_back();
  }
  std::sort(pieces.begin(), pieces.end(),
            [](const auto& a, const auto& b) { return a.second - a.first > b.second - b.first; });
  std::vector<mobius::Complex> members;
  for (const auto& [lo, hi] : pieces) {
    const double theta = 0.5 * (lo + hi);
    if (param->line && std::abs(std::cos(0.5 * theta)) < 1e-300) continue;  // ∞ is no site
    members.push_back(param->at(theta));
  }
  return members;
}

}  // namespace covmap::recognition::stages
