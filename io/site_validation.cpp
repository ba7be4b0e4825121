#include "io/site_validation.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string_view>
#include <unordered_map>

#include "core/large_buffer.h"
#include "io/text_util.h"

namespace covmap::io::detail {

std::string site_label(const SiteDraft& draft) {
  const std::string id = draft.site.id.empty() ? "" : "site " + quote_id(draft.site.id);
  if (draft.line > 0) return id.empty() ? "row" : id;
  return id.empty() ? draft.origin : draft.origin + " (" + id + ")";
}

void check_site_values(SiteDraft& draft) {
  const auto& s = draft.site;
  if (!std::isfinite(s.x)) draft.problems.push_back("x must be finite (got " + format_number(s.x) + ")");
  if (!std::isfinite(s.y)) draft.problems.push_back("y must be finite (got " + format_number(s.y) + ")");
  if (!std::isfinite(s.weight)) {
    draft.problems.push_back("weight must be finite (got " + format_number(s.weight) + ")");
  } else if (!(s.weight > 0)) {
    draft.problems.push_back("weight must be positive (got " + format_number(s.weight) + ")");
  }
}

namespace {

// "site 'a' (line 4)" / "site 'a' (sites[0])": how a message refers to the other site of a pair.
std::string reference(const SiteDraft& other) { return "site " + quote_id(other.site.id) + " (" + other.origin + ")"; }

void check_unique_ids(std::vector<SiteDraft>& drafts) {
  // Views into the drafts' own ids (no copies: a million sites would be a million strings more).
  std::unordered_map<std::string_view, std::size_t> first;
  first.reserve(drafts.size());
  for (std::size_t i = 0; i < drafts.size(); ++i) {
    if (drafts[i].site.id.empty()) continue;  // already reported as missing
    const auto [it, inserted] = first.emplace(drafts[i].site.id, i);
    if (!inserted) drafts[i].problems.push_back("duplicate id; first used by " + reference(drafts[it->second]));
  }
}

void check_unique_positions(std::vector<SiteDraft>& drafts) {
  // Exact equality only: nearly coincident sites are legal input, and deciding how near is too near
  // belongs to the engine's tolerances, not to the file reader.
  struct Position {
    double x, y;
    std::size_t index;  // the tie-break keeps file order within a position: the first is reported against
    auto operator<=>(const Position&) const = default;
  };
  // Sorted as compact records, not as indices into the drafts (whose scattered reads made this the
  // slowest part of reading a million sites).
  std::vector<Position> order;
  order.reserve(drafts.size());
  advise_huge_pages(order.data(), order.capacity() * sizeof(Position));
  for (std::size_t i = 0; i < drafts.size(); ++i) {
    if (drafts[i].usable()) order.push_back({drafts[i].site.x, drafts[i].site.y, i});
  }
  std::sort(order.begin(), order.end());
  std::size_t run_start = 0;  // first site (in sorted order) at the current position
  for (std::size_t k = 1; k < order.size(); ++k) {
    if (order[k].x != order[run_start].x || order[k].y != order[run_start].y) {
      run_start = k;
      continue;
    }
    const auto& s = drafts[order[k].index].site;
    drafts[order[k].index].problems.push_back("same position (" + format_number(s.x) + ", " + format_number(s.y) +
                                              ") as " + reference(drafts[order[run_start].index]));
  }
}

}  // namespace

SiteTable finish_sites(std::vector<SiteDraft> drafts, const std::string& file) {
  if (drafts.empty()) throw InputError(file, 0, "", "no sites");
  // Positions first: a site whose only fault is a repeated id still has a meaningful position.
  check_unique_positions(drafts);
  check_unique_ids(drafts);
  std::vector<InputProblem> problems;
  for (const auto& d : drafts) {
    for (const auto& message : d.problems) problems.push_back({d.line, site_label(d), message});
  }
  if (!problems.empty()) throw InputError(file, std::move(problems));

  SiteTable table;
  table.sites.reserve(drafts.size());
  table.origin.reserve(drafts.size());
  advise_huge_pages(table.sites.data(), table.sites.capacity() * sizeof(Site));  // core/large_buffer.h
  advise_huge_pages(table.origin.data(), table.origin.capacity() * sizeof(std::string));
  for (auto& d : drafts) {
    table.sites.push_back(std::move(d.site));
    table.origin.push_back(std::move(d.origin));
  }
  return table;
}

}  // namespace covmap::io::detail
