// Checks shared by every reader of site lists (internal to io/): the CSV and JSON sites readers
// and the arcgraph reader all hold sites to the same rules, with the same wording.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "io/input_error.h"
#include "io/sites_io.h"
#include "core/diagram.h"

namespace covmap::io::detail {

// A site as read, before the whole-list checks.
struct SiteDraft {
  Site site;
  int line = 0;        // line in a CSV file; 0 for JSON
  std::string origin;  // "line 7" or "sites[3]"
  std::vector<std::string> problems;  // what is wrong with this site so far, in the order found
  bool usable() const { return problems.empty(); }  // only usable sites take part in duplicate checks
};

// How a problem names the site: "site 'b'" for CSV (the line says where),
// "sites[3] (site 'b')" for JSON.
std::string site_label(const SiteDraft& draft);

// Per-site value checks: finite coordinates, finite positive weight.
void check_site_values(SiteDraft& draft);
// True when check_site_values would find nothing to say about the site.
bool site_values_valid(const Site& site);

// The whole-list checks on their own, for any sequence of sites: repeat(i, first) is called for
// every site i with the same id as an earlier one (find_repeated_ids; in increasing i) or exactly
// the same position, 0 and -0 alike (find_repeated_positions; in no particular order), `first` the
// earliest such site. site(i) is site i, or nullptr for a site left out of the check; positions
// must be finite. Linear in the sites for ids (a flat hash table), n log n for positions (a sort).
using SiteAt = std::function<const Site*(std::size_t i)>;
using Repeat = std::function<void(std::size_t i, std::size_t first)>;
void find_repeated_ids(std::size_t count, const SiteAt& site, const Repeat& repeat);
void find_repeated_positions(std::size_t count, const SiteAt& site, const Repeat& repeat);

// Whole-list checks (non-empty, unique ids, unique positions), then either the table or one
// InputError listing every problem of every site, in file order.
SiteTable finish_sites(std::vector<SiteDraft> drafts, const std::string& file);

}  // namespace covmap::io::detail
