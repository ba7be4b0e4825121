#include "bench/site_distributions.h"

#include <charconv>
#include <cmath>
#include <random>
#include <set>
#include <utility>

namespace covmap::bench {

namespace {

// 53 random bits -> a double in [0, 1), identical on every platform.
double unit_interval(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1p-53; }

std::mt19937_64 stream(std::uint64_t seed, std::uint64_t n, std::uint64_t purpose) {
  std::seed_seq seq{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                    static_cast<std::uint32_t>(n), static_cast<std::uint32_t>(n >> 32),
                    static_cast<std::uint32_t>(purpose)};
  return std::mt19937_64(seq);
}

bool parse_number(const std::string& text, double* out) {
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, *out);
  return ec == std::errc() && ptr == end && std::isfinite(*out);
}

}  // namespace

std::string Distribution::name() const {
  switch (family) {
    case WeightFamily::kUniform12: return "uniform12";
    case WeightFamily::kUniform01: return "uniform01";
    case WeightFamily::kCorrelated: break;
  }
  if (alpha == 1.0 && beta == 1.0) return "correlated";
  auto number = [](double v) {
    std::string s = std::to_string(v);
    s.erase(s.find_last_not_of('0') + 1);
    if (s.back() == '.') s.pop_back();
    return s;
  };
  return "correlated:" + number(alpha) + ":" + number(beta);
}

std::optional<Distribution> parse_distribution(const std::string& text, std::string* error) {
  if (text == "uniform12") return Distribution{WeightFamily::kUniform12};
  if (text == "uniform01") return Distribution{WeightFamily::kUniform01};
  if (text == "correlated") return Distribution{WeightFamily::kCorrelated, 1.0, 1.0};
  const std::string prefix = "correlated:";
  if (text.rfind(prefix, 0) == 0) {
    const std::string rest = text.substr(prefix.size());
    const auto colon = rest.find(':');
    Distribution d{WeightFamily::kCorrelated};
    if (colon != std::string::npos && parse_number(rest.substr(0, colon), &d.alpha) &&
        parse_number(rest.substr(colon + 1), &d.beta) && d.alpha >= 0 && d.beta >= 0 &&
        d.alpha + d.beta > 0)
      return d;
    if (error) *error = "'" + text + "': expected correlated:A:B with A, B >= 0 and A + B > 0";
    return std::nullopt;
  }
  if (error)
    *error = "'" + text + "': expected uniform12, uniform01, correlated or correlated:A:B";
  return std::nullopt;
}

std::vector<Site> make_sites(std::size_t n, const Distribution& dist, std::uint64_t seed) {
  // Positions: uniform in [0,1)², redrawn until pairwise distinct (a repeat of a 53-bit pair is
  // astronomically unlikely, but the engine rejects it, so make it impossible).
  auto position_rng = stream(seed, n, 0);
  std::set<std::pair<double, double>> seen;
  std::vector<Site> sites(n);
  for (std::size_t i = 0; i < n; ++i) {
    double x = 0.0, y = 0.0;
    do {
      x = unit_interval(position_rng);
      y = unit_interval(position_rng);
    } while (!seen.emplace(x, y).second);
    sites[i].id = std::to_string(i);
    sites[i].x = x;
    sites[i].y = y;
  }
  auto weight_rng = stream(seed, n, 1 + static_cast<std::uint64_t>(dist.family));
  const double half_diagonal = std::sqrt(0.5);
  for (auto& s : sites) {
    const double u = unit_interval(weight_rng);
    switch (dist.family) {
      case WeightFamily::kUniform12: s.weight = 1.0 + u; break;
      case WeightFamily::kUniform01: s.weight = 0.1 + u; break;
      case WeightFamily::kCorrelated: {
        const double d = std::hypot(s.x - 0.5, s.y - 0.5) / half_diagonal;
        // r in (0, 1] keeps the weight positive whenever B > 0; with B = 0 only a site exactly at
        // the centre (0.5, 0.5) would get weight 0, and the engine would reject it by name.
        const double r = 1.0 - u;
        s.weight = (dist.alpha * d + dist.beta * r) / (dist.alpha + dist.beta);
        break;
      }
    }
  }
  return sites;
}

}  // namespace covmap::bench
