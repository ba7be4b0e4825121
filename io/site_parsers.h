// The two site-list syntaxes behind read_sites (internal to io/). Both end in finish_sites, so the
// same rules and wording apply whatever the syntax. And the JSON form of one site, for the writers.
#pragma once

#include <string>
#include <string_view>

#include "io/json_fields.h"
#include "io/json_out.h"
#include "io/sites_io.h"

namespace covmap::io::detail {

SiteTable parse_sites_csv(std::string_view text, const std::string& file);
SiteTable parse_sites_json(std::string_view text, const std::string& file);

// The "sites" array of a covmap.sites/1 or covmap.arcgraph/1 document; `path` is its JSON path.
SiteTable sites_from_json(const Json& sites, const std::string& path, const std::string& file);

// One element of a "sites" array, {"id":..,"x":..,"y":..,"weight":..[,"name":..]}, as both
// covmap.sites/1 and covmap.arcgraph/1 write it. The caller has checked the numbers are finite and
// the strings UTF-8.
void write_site_json(JsonOut& out, const Site& site);

}  // namespace covmap::io::detail
