#include "recognition_families.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <set>
#include <utility>
#include <variant>

namespace covmap::recognition::testing {
namespace {

// A double in [0, 1) from 53 random bits: the same on every standard library.
double unit(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

std::vector<Site> family_sites(RecognitionFamily family, int n, std::mt19937_64& rng) {
  std::vector<Site> sites;
  std::set<std::pair<double, double>> seen;
  auto add = [&](double x, double y, double w) {
    if (seen.insert({x, y}).second) sites.push_back({std::to_string(sites.size()), x, y, w});
  };
  const double two_pi = 2.0 * std::acos(-1.0);
  for (int i = 0; i < n; ++i) {
    switch (family) {
      case RecognitionFamily::kRandom: add(unit(rng), unit(rng), 1.0 + unit(rng)); break;
      case RecognitionFamily::kEqual: add(unit(rng), unit(rng), 1.0); break;
      case RecognitionFamily::kCollinear: {
        const double t = unit(rng);
        add(0.8 * t, 0.6 * t, 1.0 + std::floor(3.0 * unit(rng)));
        break;
      }
      case RecognitionFamily::kCocircular: {
        const double a = two_pi * unit(rng);
        add(0.5 + 0.5 * std::cos(a), 0.5 + 0.5 * std::sin(a), 1.0);
        break;
      }
      case RecognitionFamily::kGrid: {
        const int side = std::max(3, static_cast<int>(std::ceil(std::sqrt(2.0 * n))));
        add(std::floor(side * unit(rng)) / side, std::floor(side * unit(rng)) / side, unit(rng) < 0.5 ? 1.0 : 2.0);
        break;
      }
    }
  }
  return sites;
}

double perturbed(double v, const Perturbation& p, std::mt19937_64& rng) {
  if (p.ulp) {
    const double toward = unit(rng) < 0.5 ? -INFINITY : INFINITY;
    return std::nextafter(v, toward);
  }
  return v + p.amount * (2.0 * unit(rng) - 1.0);  // the family's extent is 1
}

}  // namespace

std::string to_string(RecognitionFamily family) {
  switch (family) {
    case RecognitionFamily::kRandom: return "random";
    case RecognitionFamily::kEqual: return "equal";
    case RecognitionFamily::kCollinear: return "collinear";
    case RecognitionFamily::kCocircular: return "cocircular";
    case RecognitionFamily::kGrid: return "grid";
  }
  return "?";
}

std::optional<RecognitionFamily> recognition_family_from_string(const std::string& name) {
  for (RecognitionFamily f : {RecognitionFamily::kRandom, RecognitionFamily::kEqual, RecognitionFamily::kCollinear,
                              RecognitionFamily::kCocircular, RecognitionFamily::kGrid})
    if (to_string(f) == name) return f;
  return std::nullopt;
}

std::string Perturbation::name() const {
  if (ulp) return "ulp";
  if (amount == 0.0) return "0";
  char text[32];
  std::snprintf(text, sizeof text, "%g", amount);
  return text;
}

std::optional<Perturbation> perturbation_from_string(const std::string& text) {
  if (text == "ulp") return Perturbation{true, 0.0};
  char* end = nullptr;
  const double amount = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0' || !(amount >= 0.0) || !std::isfinite(amount)) return std::nullopt;
  return Perturbation{false, amount};
}

std::vector<Site> recognition_sites(RecognitionFamily family, int n, std::uint64_t seed, const Perturbation& p,
                                    const Similarity& t) {
  std::mt19937_64 rng(seed);
  std::vector<Site> sites = family_sites(family, n, rng);
  const double c = std::cos(t.angle), s = std::sin(t.angle);
  std::set<std::pair<double, double>> seen;
  std::vector<Site> out;
  for (Site site : sites) {
    const double x = perturbed(site.x, p, rng), y = perturbed(site.y, p, rng);
    site.x = t.offset_x + t.scale * (c * x - s * y);
    site.y = t.offset_y + t.scale * (s * x + c * y);
    if (seen.insert({site.x, site.y}).second) out.push_back(site);
  }
  return out;
}

void round_graph(Diagram& g, int digits) {
  auto round = [digits](double& v) {
    if (!std::isfinite(v) || v == 0.0) return;
    char text[64];
    std::snprintf(text, sizeof text, "%.*e", digits - 1, v);
    v = std::strtod(text, nullptr);
  };
  for (Node& n : g.nodes) round(n.x), round(n.y);
  for (Arc& a : g.arcs) {
    if (auto* c = std::get_if<Circle>(&a.curve)) {
      round(c->cx), round(c->cy), round(c->r);
    } else {
      auto& l = std::get<Line>(a.curve);
      round(l.x), round(l.y), round(l.dx), round(l.dy);
    }
  }
}

}  // namespace covmap::recognition::testing

#include <algorithm>

namespace covmap::recognition::testing {

RoundTripError round_trip_error(const std::vector<Site>& truth, const Diagram& drawn,
                                const Reconstruction& r) {
  RoundTripError e;
  double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
  for (const Site& s : truth)
    xmin = std::min(xmin, s.x), xmax = std::max(xmax, s.x), ymin = std::min(ymin, s.y), ymax = std::max(ymax, s.y);
  const double extent = std::max(std::hypot(xmax - xmin, ymax - ymin), std::numeric_limits<double>::min());
  // Per traced face: (reconstructed site, true site).
  std::vector<std::pair<int, int>> pairs;
  for (std::size_t f = 0; f < r.graph.faces.size() && f < r.face_site.size(); ++f) {
    if (r.face_site[f] == kNone) continue;
    const FaceCycles cycles = face_cycles(r.graph, r.graph.faces[f]);
    if (cycles.empty() || cycles.front().empty()) continue;
    const HalfArc h = cycles.front().front();
    const Arc& a = drawn.arcs[h.arc];
    const int site = h.forward ? a.left_site : a.right_site;
    if (site == kNone) continue;
    pairs.emplace_back(r.face_site[f], site);
  }
  if (pairs.empty()) return e;
  int heaviest = 0;
  for (std::size_t k = 1; k < pairs.size(); ++k)
    if (r.sites[pairs[k].first].weight > r.sites[pairs[heaviest].first].weight) heaviest = static_cast<int>(k);
  const double factor = r.sites[pairs[heaviest].first].weight / truth[pairs[heaviest].second].weight;
  for (const auto& [got, want] : pairs) {
    const Site& s = r.sites[got];
    const Site& t = truth[want];
    e.position = std::max(e.position, std::hypot(s.x - t.x, s.y - t.y) / extent);
    e.weight = std::max(e.weight, std::abs(s.weight / t.weight / factor - 1.0));
  }
  e.faces_compared = static_cast<int>(pairs.size());
  return e;
}

}  // namespace covmap::recognition::testing
