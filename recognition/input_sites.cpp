// The input's own sites against the reconstruction (input_sites.h).
#include "recognition/input_sites.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "core/extent.h"
#include "recognition/mwvd_check.h"
#include "recognition/recognize_stages.h"

namespace covmap::recognition {

std::string_view to_string(SiteDifferenceKind kind) {
  switch (kind) {
    case SiteDifferenceKind::kPosition: return "position";
    case SiteDifferenceKind::kWeight: return "weight";
    case SiteDifferenceKind::kSwappedLabel: return "swapped_label";
    case SiteDifferenceKind::kConflictingLabel: return "conflicting_label";
    case SiteDifferenceKind::kMissingLabel: return "missing_label";
  }
  return "position";  // unreachable: every enumerator is handled above
}

namespace {

std::string quoted(const std::vector<Site>& sites, int k) { return "'" + sites[k].id + "'"; }

// Input site ↔ reconstructed site, read off every arc side; label faults on the way.
struct Pairing {
  std::map<int, std::set<int>> of_input, of_reconstructed;
  std::map<std::pair<int, int>, int> first_arc;  // (input, reconstructed) → an arc showing it
  std::vector<SiteDifference> label_faults;
};

Pairing pair_sites(const InputLabels& in, const Reconstruction& r) {
  const std::vector<mwvd::ArcSites> rec = mwvd::arc_sites(r.graph, r.face_site);
  Pairing p;
  bool missing_reported = false;
  for (std::size_t a = 0; a < rec.size() && a < in.left.size(); ++a)
    for (const auto& [label, site] : {std::pair{in.left[a], rec[a].left}, std::pair{in.right[a], rec[a].right}}) {
      if (site == kNone) continue;  // outside the frame, or a face recognition gave no site
      if (label == kNone) {
        if (!missing_reported && !r.graph.arcs[a].frame) {
          std::ostringstream m;
          m << "arc " << a << " names no site on the side of reconstructed site " << site;
          p.label_faults.push_back({SiteDifferenceKind::kMissingLabel, kNone, site, static_cast<int>(a), 1.0, INFINITY, m.str()});
          missing_reported = true;  // one is enough to disagree; the rest say the same
        }
        continue;
      }
      p.of_input[label].insert(site);
      p.of_reconstructed[site].insert(label);
      p.first_arc.emplace(std::pair{label, site}, static_cast<int>(a));
    }
  for (const auto& [label, sites] : p.of_input)
    if (sites.size() > 1) {
      std::ostringstream m;
      m << "input site " << quoted(in.sites, label) << " names the faces of " << sites.size()
        << " different reconstructed sites";
      p.label_faults.push_back({SiteDifferenceKind::kConflictingLabel, label, *sites.begin(),
                                p.first_arc.at({label, *std::next(sites.begin())}), static_cast<double>(sites.size()),
                                INFINITY, m.str()});
    }
  for (const auto& [site, labels] : p.of_reconstructed)
    if (labels.size() > 1) {
      std::ostringstream m;
      m << "the faces of reconstructed site " << site << " are named by " << labels.size()
        << " different input sites (" << quoted(in.sites, *labels.begin()) << ", "
        << quoted(in.sites, *std::next(labels.begin())) << ")";
      p.label_faults.push_back({SiteDifferenceKind::kConflictingLabel, *std::next(labels.begin()), site,
                                p.first_arc.at({*std::next(labels.begin()), site}), static_cast<double>(labels.size()),
                                INFINITY, m.str()});
    }
  return p;
}

// (input, reconstructed) pairs that name each other only (conflicts are reported as label faults).
std::vector<std::pair<int, int>> one_to_one(const Pairing& p) {
  std::vector<std::pair<int, int>> pairs;
  for (const auto& [label, sites] : p.of_input)
    if (sites.size() == 1 && p.of_reconstructed.at(*sites.begin()).size() == 1) pairs.emplace_back(label, *sites.begin());
  return pairs;
}

// Swapped labels are looked for (by a scan of the sites) for this many position differences; the
// rest are reported as positions (a graph whose labels are all wrong needs no more evidence).
constexpr std::size_t kSwapLookups = 1000;

// The reconstructed site at q (within tol) other than `except`; kNone if none.
int other_site_at(const std::vector<Site>& sites, Point q, int except, double tol) {
  for (std::size_t k = 0; k < sites.size(); ++k)
    if (static_cast<int>(k) != except && std::hypot(sites[k].x - q.x, sites[k].y - q.y) <= tol)
      return static_cast<int>(k);
  return kNone;
}

// How far a reconstructed site is from the graph (0 inside the box of its nodes): the graph fixes a
// site d away only to about τ·d (cocircular sites 50 away from nodes crowded within 10⁻⁸ of their
// centre), as the verification's allowance says.
double distance_from(const Box& box, const Site& s) {
  return std::hypot(std::max({box.xmin - s.x, s.x - box.xmax, 0.0}), std::max({box.ymin - s.y, s.y - box.ymax, 0.0}));
}

// The pairs against one solution's sites (`sites`, indexed as Reconstruction::sites).
void compare_positions_and_weights(const InputLabels& in, const std::vector<Site>& sites, const Box& box,
                                   const Pairing& p, double tol, double tau, std::vector<SiteDifference>& out) {
  const std::vector<std::pair<int, int>> pairs = one_to_one(p);
  std::vector<double> ratios;
  for (const auto& [label, site] : pairs) ratios.push_back(in.sites[label].weight / sites[site].weight);
  if (ratios.empty()) return;
  std::nth_element(ratios.begin(), ratios.begin() + ratios.size() / 2, ratios.end());
  const double common = ratios[ratios.size() / 2];
  for (const auto& [label, site] : pairs) {
    const Site& s = in.sites[label];
    const Site& t = sites[site];
    const int arc = p.first_arc.at({label, site});
    const double distance = std::hypot(s.x - t.x, s.y - t.y);
    const double position_tol = tol + tau * distance_from(box, t);
    const double weight_tol = tol > 0 ? tau * position_tol / tol : tau;  // weights widen by the same factor
    if (distance > position_tol) {
      const int other = out.size() < kSwapLookups ? other_site_at(sites, {s.x, s.y}, site, position_tol) : kNone;
      std::ostringstream m;
      m << "input site " << quoted(in.sites, label) << " at (" << s.x << ", " << s.y << ") names the face of the site "
        << "reconstructed at (" << t.x << ", " << t.y << "), " << distance << " away (" << distance / position_tol
        << " tolerances)";
      if (other != kNone) m << "; its position is that of reconstructed site " << other << ": a swapped label";
      out.push_back({other != kNone ? SiteDifferenceKind::kSwappedLabel : SiteDifferenceKind::kPosition, label, site,
                     arc, distance, distance / position_tol, m.str()});
      continue;  // its weight belongs to another site too
    }
    const double off = std::abs(s.weight / t.weight / common - 1.0);
    if (off > weight_tol) {
      std::ostringstream m;
      m << "input site " << quoted(in.sites, label) << ": weight " << s.weight << " is " << s.weight / common
        << " after the common factor " << common << " of all sites; the reconstruction says " << t.weight
        << " (off by a factor " << s.weight / t.weight / common << ", " << off / weight_tol << " tolerances)";
      out.push_back({SiteDifferenceKind::kWeight, label, site, arc, off, off / weight_tol, m.str()});
    }
  }
}

}  // namespace

namespace stages {

std::optional<InputLabels> input_labels(const Diagram& g) {
  if (g.sites.empty()) return std::nullopt;
  InputLabels out{g.sites, {}, {}};
  out.left.reserve(g.arcs.size());
  out.right.reserve(g.arcs.size());
  for (const Arc& a : g.arcs) out.left.push_back(a.left_site), out.right.push_back(a.right_site);
  return out;
}

InputSitesComparison compare_input_sites(const InputLabels& in, const Reconstruction& r, double tol, double tau) {
  InputSitesComparison out;
  Pairing p = pair_sites(in, r);
  out.differences = std::move(p.label_faults);
  out.positions_compared = r.unique;
  out.input_site.assign(r.sites.size(), kNone);
  for (const auto& [label, site] : one_to_one(p))
    if (site >= 0 && static_cast<std::size_t>(site) < r.sites.size()) out.input_site[site] = label;
  if (r.unique) {
    // Where two solutions survive (Lemma 6) the input's sites may be either: the one they fit best.
    const Box box = graph_extent(r.graph);
    std::vector<SiteDifference> best;
    bool first = true;
    for (const std::vector<Site>& sites : r.candidates.size() > 1 ? r.candidates : std::vector<std::vector<Site>>{r.sites}) {
      if (sites.size() != r.sites.size()) continue;
      std::vector<SiteDifference> found;
      compare_positions_and_weights(in, sites, box, p, tol, tau, found);
      if (first || found.size() < best.size()) best = std::move(found);
      first = false;
    }
    out.differences.insert(out.differences.end(), best.begin(), best.end());
  }
  out.agree = out.differences.empty();
  return out;
}

}  // namespace stages

std::vector<Site> named_as_input(std::vector<Site> reconstructed, const std::vector<Site>& input,
                                 const InputSitesComparison& comparison) {
  for (std::size_t k = 0; k < reconstructed.size() && k < comparison.input_site.size(); ++k) {
    const int paired = comparison.input_site[k];
    if (paired == kNone || static_cast<std::size_t>(paired) >= input.size()) continue;
    reconstructed[k].id = input[paired].id;
    reconstructed[k].name = input[paired].name;
  }
  return reconstructed;
}

}  // namespace covmap::recognition
