// Checks shared by every reader of site lists (internal to io/): the CSV and JSON sites readers
// and the arcgraph reader all hold sites to the same rules, with the same wording.
#pragma once

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

// Whole-list checks (non-empty, unique ids, unique positions), then either the table or one
// InputError listing every problem of every site, in file order.
SiteTable finish_sites(std::vector<SiteDraft> drafts, const std::string& file);

}  // namespace covmap::io::detail
