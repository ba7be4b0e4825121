#include "io/site_validation.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string_view>

#include "core/large_buffer.h"
#include "core/round_trip_numbers.h"
#include "io/text_util.h"

namespace covmap::io::detail {

std::string site_label(const SiteDraft& draft) {
  const std::string id = draft.site.id.empty() ? "" : "site " + quote_id(draft.site.id);
  if (draft.line > 0) return id.empty() ? "row" : id;
  return id.empty() ? draft.origin : draft.origin + " (" + id + ")";
}

bool site_values_valid(const Site& s) {
  return std::isfinite(s.x) && std::isfinite(s.y) && std::isfinite(s.weight) && s.weight > 0;
}

void check_site_values(SiteDraft& draft) {
  const auto& s = draft.site;
  if (!std::isfinite(s.x)) draft.problems.push_back("x must be finite (got " + round_trip_number(s.x) + ")");
  if (!std::isfinite(s.y)) draft.problems.push_back("y must be finite (got " + round_trip_number(s.y) + ")");
  if (!std::isfinite(s.weight)) {
    draft.problems.push_back("weight must be finite (got " + round_trip_number(s.weight) + ")");
  } else if (!(s.weight > 0)) {
    draft.problems.push_back("weight must be positive (got " + round_trip_number(s.weight) + ")");
  }
}

namespace {

// "site 'a' (line 4)" / "site 'a' (sites[0])": how a message refers to the other site of a pair.
std::string reference(const SiteDraft& other) { return "site " + quote_id(other.site.id) + " (" + other.origin + ")"; }

// The first key of each value, in a flat open-addressing table (linear probing, at most half
// full), with no allocation per key: a node-based map (std::unordered_map) allocates a node per
// key and takes a cache miss for the bucket, the node and its cached hash on every probe once the
// nodes outgrow the cache, which on large inputs dominates reading the sites.
// Each slot holds the upper half of a key's hash and its index + 1 (0: empty), so a probe only
// looks at the key itself when the halves agree. Keys are inserted in increasing index order, so
// the index kept for a value is that of its first key.
class FirstOfEqualKeys {
 public:
  explicit FirstOfEqualKeys(std::size_t keys) {
    if (keys >= std::numeric_limits<std::uint32_t>::max()) throw std::length_error("FirstOfEqualKeys: too many keys");
    const std::size_t size = std::bit_ceil(std::max<std::size_t>(2 * keys, 16));
    slots_.reserve(size);
    advise_huge_pages(slots_.data(), size * sizeof(std::uint64_t));  // core/large_buffer.h
    slots_.resize(size);
    mask_ = size - 1;
  }

  // The first index whose key equals key `index` (same_key_as(j): key j equals it), recording
  // `index` as the first when there is none; then it returns `index` itself.
  template <class SameKeyAs>
  std::size_t first(std::uint64_t hash, std::size_t index, SameKeyAs&& same_key_as) {
    const std::uint64_t tag = hash >> 32;  // the lower half places the key, the upper half is kept
    for (std::size_t s = hash & mask_;; s = (s + 1) & mask_) {
      const std::uint64_t slot = slots_[s];
      if (slot == 0) {
        slots_[s] = tag << 32 | (index + 1);
        return index;
      }
      const std::size_t other = (slot & 0xffff'ffff) - 1;
      if (slot >> 32 == tag && same_key_as(other)) return other;
    }
  }

 private:
  std::vector<std::uint64_t> slots_;
  std::size_t mask_ = 0;
};

}  // namespace

void find_repeated_ids(std::size_t count, const SiteAt& site, const Repeat& repeat) {
  // Views into the sites' own ids (no copies: a million sites would be a million strings more).
  FirstOfEqualKeys first(count);
  for (std::size_t i = 0; i < count; ++i) {
    const Site* s = site(i);
    if (!s) continue;
    const std::string_view id = s->id;
    const std::size_t j = first.first(std::hash<std::string_view>{}(id), i, [&](std::size_t k) { return site(k)->id == id; });
    if (j != i) repeat(i, j);
  }
}

void find_repeated_positions(std::size_t count, const SiteAt& site, const Repeat& repeat) {
  // Exact equality only: nearly coincident sites are legal input, and deciding how near is too near
  // belongs to the engine's tolerances, not to the file reader. Sorted rather than hashed: a sort
  // stays n log n whatever the coordinates, where a hash of numbers a file chooses can be made to
  // collide.
  struct Position {
    double x, y;
    std::size_t index;  // the tie-break keeps file order within a position: the first is reported against
    auto operator<=>(const Position&) const = default;
  };
  // Sorted as compact records, not as indices into the sites (whose scattered reads made this the
  // slowest part of reading a million sites).
  std::vector<Position> order;
  order.reserve(count);
  advise_huge_pages(order.data(), order.capacity() * sizeof(Position));
  for (std::size_t i = 0; i < count; ++i) {
    if (const Site* s = site(i)) order.push_back({s->x, s->y, i});
  }
  std::sort(order.begin(), order.end());
  std::size_t run_start = 0;  // first site (in sorted order) at the current position
  for (std::size_t k = 1; k < order.size(); ++k) {
    if (order[k].x != order[run_start].x || order[k].y != order[run_start].y) {
      run_start = k;
      continue;
    }
    repeat(order[k].index, order[run_start].index);
  }
}

namespace {

void check_unique_ids(std::vector<SiteDraft>& drafts) {
  // Drafts with no id have it reported as missing already.
  find_repeated_ids(
      drafts.size(), [&](std::size_t i) { return drafts[i].site.id.empty() ? nullptr : &drafts[i].site; },
      [&](std::size_t i, std::size_t first) {
        drafts[i].problems.push_back("duplicate id; first used by " + reference(drafts[first]));
      });
}

void check_unique_positions(std::vector<SiteDraft>& drafts) {
  find_repeated_positions(
      drafts.size(), [&](std::size_t i) { return drafts[i].usable() ? &drafts[i].site : nullptr; },
      [&](std::size_t i, std::size_t first) {
        const auto& s = drafts[i].site;
        drafts[i].problems.push_back("same position (" + round_trip_number(s.x) + ", " + round_trip_number(s.y) + ") as " +
                                     reference(drafts[first]));
      });
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
