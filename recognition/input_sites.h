// What recognize() says about the sites an input graph carries (Diagram::sites and the arcs'
// left_site / right_site labels): do they agree with the sites reconstructed from the arcs alone?
//
// Contract: recognition never uses the input's sites; when the input carries some (a non-empty
// Diagram::sites), recognize() keeps a copy of them and of the arcs' labels and, for a bisector
// graph, compares them with its reconstruction (Reconstruction::input_sites). Input sites are
// paired with reconstructed ones through the faces: the site an arc side names in the input and
// the site recognition assigned to the face on that side. Then
//   - a label that pairs with two reconstructed sites, or a reconstructed site that two labels name,
//     is a conflicting label; an arc side without a label where the reconstruction has a site is a
//     missing label;
//   - a paired site whose position is farther than the tolerance (relative_tolerance times the
//     input's scale, plus relative_tolerance times the reconstructed site's distance d from the
//     box of the graph's nodes: the graph fixes a site d away only to that, as the verification's
//     allowance says) from its partner differs in position — a swapped label when it is instead
//     at the position of another reconstructed site;
//   - weights are known only up to one common factor: the median of the paired ratios is that
//     factor, and a pair whose ratio differs from it by more than relative_tolerance (relatively,
//     widened for far sites by the same factor as the position's) differs in weight.
// When the graph does not fix the sites (Reconstruction::unique false) only the labels are
// compared: positions and weights of a family's member say nothing about the input's. When two
// solutions survive (Reconstruction::candidates), the input is compared with the one it fits best.
// Input sites that no arc names (e.g. outside a clipped map's frame) are not compared.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/diagram.h"

namespace covmap::recognition {

enum class SiteDifferenceKind { kPosition, kWeight, kSwappedLabel, kConflictingLabel, kMissingLabel };
// "position", "weight", "swapped_label", "conflicting_label", "missing_label"
// (covmap.reconstruction/1).
std::string_view to_string(SiteDifferenceKind kind);

struct SiteDifference {
  SiteDifferenceKind kind = SiteDifferenceKind::kPosition;
  int input_site = kNone;          // index into the input's sites (kNone: a missing label)
  int reconstructed_site = kNone;  // index into Reconstruction::sites
  int arc = kNone;                 // labels: an arc where the label is wrong or missing
  double amount = 0.0;             // position: a distance; weight: |ratio / common ratio − 1|
  double relative = 0.0;           // amount over its tolerance (> 1 for every difference listed)
  std::string message;
};

struct InputSitesComparison {
  bool agree = true;
  bool positions_compared = true;  // false when the reconstruction is not unique
  std::vector<SiteDifference> differences;
  // Per reconstructed site: the input site whose labels name its faces, when the two pair one to
  // one (whatever their positions); kNone when no label or several name it.
  std::vector<int> input_site;
};

// The input's sites and arc labels as recognize() received them.
struct InputLabels {
  std::vector<Site> sites;
  std::vector<int> left, right;  // per arc
};

// The reconstructed sites called as the input calls them: each one paired with an input site
// (comparison.input_site) takes that site's id and name, so that pictures and messages of the
// reconstruction name (and colour) a site as the input did. Positions and weights stay the
// reconstruction's; unpaired sites keep their own ids.
std::vector<Site> named_as_input(std::vector<Site> reconstructed, const std::vector<Site>& input,
                                 const InputSitesComparison& comparison);

}  // namespace covmap::recognition
