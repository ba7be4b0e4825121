// The CSV syntax for site lists: a header line naming the columns, then one site per line; lines,
// delimiters, quoting and decimal commas as io/csv_table.h reads them.
#include <array>
#include <string>

#include "io/csv_table.h"
#include "io/site_parsers.h"
#include "io/site_validation.h"
#include "io/text_util.h"

namespace covmap::io::detail {
namespace {

enum Column : std::size_t { kId, kX, kY, kWeight, kName };
// name is optional: a name for people (labels in pictures); absent or empty: no name.
constexpr std::array<CsvColumn, 5> kColumns = {{{"id", true, {}},
                                                {"x", true, {}},
                                                {"y", true, {}},
                                                {"weight", true, {}},
                                                {"name", false, "name is optional, but at most once"}}};

}  // namespace

SiteTable parse_sites_csv(std::string_view text, const std::string& file) {
  CsvTable table(text, file, kColumns, "id,x,y,weight");
  std::vector<SiteDraft> drafts;
  CsvRow row;
  while (table.next(row)) {
    SiteDraft draft;
    draft.line = row.line;
    draft.origin = "line " + std::to_string(row.line);
    if (!row.error.empty()) {
      draft.problems.push_back(row.error);
      drafts.push_back(std::move(draft));
      continue;
    }
    if (const auto* id = row.field(kId); id && !id->empty()) draft.site.id = *id;
    std::array<double*, 4> targets = {nullptr, &draft.site.x, &draft.site.y, &draft.site.weight};
    for (const Column c : {kId, kX, kY, kWeight}) {
      const std::string* value = row.field(c);
      if (!value) {
        draft.problems.push_back(row.missing(c));
        continue;
      }
      if (c == kId) {
        if (value->empty()) draft.problems.push_back("id is empty");
        else if (!valid_utf8(*value)) draft.problems.push_back("id is not valid UTF-8");
        continue;
      }
      std::string error;
      if (const auto number = row.number(c, error)) {
        *targets[c] = *number;
      } else {
        draft.problems.push_back(error);
      }
    }
    // A row shorter than the header has no name: the name is optional, so that is no problem.
    if (const std::string* name = row.field(kName)) {
      if (valid_utf8(*name)) draft.site.name = *name;
      else draft.problems.push_back("name is not valid UTF-8");
    }
    if (draft.usable()) check_site_values(draft);
    drafts.push_back(std::move(draft));
  }
  return finish_sites(std::move(drafts), file);
}

}  // namespace covmap::io::detail
