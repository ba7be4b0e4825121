#include "fitting/validate.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace covmap::fitting::detail {
namespace {

std::string number(double v) {
  std::ostringstream out;
  out.precision(17);
  out << v;
  return out.str();
}

class Problems {
 public:
  void add(std::string item, std::string message) { list_.push_back(std::move(item) + ": " + std::move(message)); }
  bool empty() const { return list_.empty(); }

  [[noreturn]] void raise() const {
    std::string text = "refine_sites: ";
    if (list_.size() == 1) {
      text += list_.front();
    } else {
      text += std::to_string(list_.size()) + " problems";
      for (std::size_t i = 0; i < list_.size() && i < kMaxListed; ++i) text += "\n  " + list_[i];
      if (list_.size() > kMaxListed) text += "\n  ... and " + std::to_string(list_.size() - kMaxListed) + " more";
    }
    throw std::invalid_argument(text);
  }

 private:
  std::vector<std::string> list_;
};

void check_sites(std::span<const Site> sites, Problems& problems) {
  if (sites.empty()) problems.add("initial", "no sites");
  for (std::size_t i = 0; i < sites.size(); ++i) {
    const Site& s = sites[i];
    const std::string item = "initial[" + std::to_string(i) + "]" + (s.id.empty() ? "" : " (site '" + s.id + "')");
    if (!std::isfinite(s.x) || !std::isfinite(s.y)) {
      problems.add(item, "position must be finite (got " + number(s.x) + ", " + number(s.y) + ")");
    }
    if (!std::isfinite(s.weight) || !(s.weight > 0)) {
      problems.add(item, "weight must be finite and positive (got " + number(s.weight) + ")");
    }
  }
}

// Returns whether `index` names a site; reports it otherwise.
bool check_index(int index, std::size_t sites, const std::string& item, const char* field, Problems& problems) {
  if (index >= 0 && static_cast<std::size_t>(index) < sites) return true;
  problems.add(item, std::string(field) + " " + std::to_string(index) + " out of range (" + std::to_string(sites) +
                         " sites)");
  return false;
}

void check_samples(std::span<const Site> sites, std::span<const BoundarySample> samples, Problems& problems) {
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const BoundarySample& s = samples[i];
    const std::string item = "samples[" + std::to_string(i) + "] (chain " + std::to_string(s.chain) + ")";
    const bool finite = std::isfinite(s.p.x) && std::isfinite(s.p.y);
    if (!finite) problems.add(item, "point must be finite (got " + number(s.p.x) + ", " + number(s.p.y) + ")");
    if (!std::isfinite(s.sigma) || !(s.sigma > 0)) {
      problems.add(item, "sigma must be finite and positive (got " + number(s.sigma) + ")");
    }
    const bool a_ok = check_index(s.site_a, sites.size(), item, "site_a", problems);
    if (s.site_b == kNone) {  // a range edge of site_a
      if (a_ok && finite && s.p.x == sites[s.site_a].x &&
          s.p.y == sites[s.site_a].y)
        problems.add(item, "range-edge point is exactly at site " + std::to_string(s.site_a));
      continue;
    }
    const bool b_ok = check_index(s.site_b, sites.size(), item, "site_b", problems);
    if (s.site_a == s.site_b) {
      problems.add(item, "site_a and site_b are the same site (" + std::to_string(s.site_a) + ")");
      continue;
    }
    if (a_ok && b_ok && sites[s.site_a].x == sites[s.site_b].x && sites[s.site_a].y == sites[s.site_b].y) {
      problems.add(item, "sites " + std::to_string(s.site_a) + " and " + std::to_string(s.site_b) +
                             " start at the same position: their bisector is undefined");
    }
    // A boundary point lies strictly outside both sites (each site is inside its own cell); at a
    // site the residual's distance has no derivative.
    for (const auto& [ok, index] : {std::pair(a_ok, s.site_a), std::pair(b_ok, s.site_b)}) {
      if (ok && finite && s.p.x == sites[index].x && s.p.y == sites[index].y) {
        problems.add(item, "point is exactly at site " + std::to_string(index));
      }
    }
  }
}

void check_priors(std::size_t sites, std::span<const SitePrior> priors, Problems& problems) {
  for (std::size_t i = 0; i < priors.size(); ++i) {
    const SitePrior& p = priors[i];
    const std::string item = "priors[" + std::to_string(i) + "]";
    check_index(p.site, sites, item, "site", problems);
    if (std::isnan(p.position_sigma) || std::isinf(p.position_sigma)) {
      problems.add(item, "position_sigma must be finite (got " + number(p.position_sigma) + ")");
    } else if (p.position_sigma > 0 && !(std::isfinite(p.position.x) && std::isfinite(p.position.y))) {
      problems.add(item, "position must be finite (got " + number(p.position.x) + ", " + number(p.position.y) + ")");
    }
    if (std::isnan(p.log_weight_sigma) || std::isinf(p.log_weight_sigma)) {
      problems.add(item, "log_weight_sigma must be finite (got " + number(p.log_weight_sigma) + ")");
    } else if (p.log_weight_sigma > 0 && !std::isfinite(p.log_weight)) {
      problems.add(item, "log_weight must be finite (got " + number(p.log_weight) + ")");
    }
  }
}

}  // namespace

void validate_inputs(std::span<const Site> initial, std::span<const BoundarySample> samples,
                     std::span<const SitePrior> priors) {
  Problems problems;
  check_sites(initial, problems);
  check_samples(initial, samples, problems);
  check_priors(initial.size(), priors, problems);
  if (!problems.empty()) problems.raise();
}

}  // namespace covmap::fitting::detail
