// The JSON syntax for site lists: covmap.sites/1, and the "sites" array that arcgraph/1 shares.
#include "io/site_parsers.h"
#include "io/site_validation.h"

namespace covmap::io::detail {
namespace {

// "missing x" / "x must be a number (got string \"a\")": a field problem phrased for a site.
std::string phrase(const FieldError& e) { return e.message == "missing" ? "missing " + e.path : e.path + " " + e.message; }

}  // namespace

SiteTable sites_from_json(const Json& sites, const std::string& path, const std::string& file) {
  if (!sites.is_array()) throw InputError(file, 0, path, "must be an array (got " + describe(sites) + ")");
  std::vector<SiteDraft> drafts;
  drafts.reserve(sites.size());
  for (std::size_t i = 0; i < sites.size(); ++i) {
    SiteDraft draft;
    draft.origin = element_path(path, i);
    const Json& entry = sites[i];
    if (!entry.is_object()) {
      draft.problems.push_back("must be an object (got " + describe(entry) + ")");
      drafts.push_back(std::move(draft));
      continue;
    }
    // The id first, so the messages about the other fields can name the site.
    try {
      draft.site.id = site_id(member(entry, "id", ""), "id");
    } catch (const FieldError& e) {
      draft.problems.push_back(phrase(e));
    }
    const std::pair<const char*, double*> numbers[] = {
        {"x", &draft.site.x}, {"y", &draft.site.y}, {"weight", &draft.site.weight}};
    for (const auto& [key, target] : numbers) {
      try {
        *target = number(member(entry, key, ""), key);
      } catch (const FieldError& e) {
        draft.problems.push_back(phrase(e));
      }
    }
    // The name is optional; when given it must be a string (a label for people, not an identity).
    if (const Json* name = optional_member(entry, "name")) {
      if (name->is_string()) draft.site.name = name->get<std::string>();
      else draft.problems.push_back("name must be a string (got " + describe(*name) + "; leave it out for no name)");
    }
    if (draft.usable()) check_site_values(draft);
    drafts.push_back(std::move(draft));
  }
  return finish_sites(std::move(drafts), file);
}

SiteTable parse_sites_json(std::string_view text, const std::string& file) {
  const Json root = parse_json(text, file);
  check_format_tag(root, "covmap.sites/1", file);
  const auto it = root.find("sites");
  if (it == root.end()) throw InputError(file, 0, "sites", "missing");
  return sites_from_json(*it, "sites", file);
}

}  // namespace covmap::io::detail
