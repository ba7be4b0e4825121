// The whole-list checks of the site readers (io/site_validation.h) against brute-force oracles, and
// the sites fast path on a list large enough that its tables are far past any small-size case:
// read back bit for bit as written and as the reference reader reads it, and repeats found however
// far apart they are (the id check's flat table, io/site_validation.cpp, and the fast path that
// fills the table itself, io/sites_json_fast.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/round_trip_numbers.h"
#include "diagram_samples.h"
#include "io/fast_readers.h"
#include "io/site_parsers.h"
#include "io/site_validation.h"
#include "io/text_util.h"
#include "io_test_util.h"

namespace covmap::io {
namespace {

using detail::find_repeated_ids;
using detail::find_repeated_positions;
using testing::input_error_from;
using testing::same;

using Pairs = std::vector<std::pair<std::size_t, std::size_t>>;

// Sites with ids and positions from small pools, so that repeats are many; every fifth is left out.
std::vector<Site> crowded_sites(std::size_t n, std::uint32_t seed) {
  std::mt19937 random(seed);
  std::uniform_int_distribution<int> pick(0, 40);
  const double coordinates[] = {0.0, -0.0, 1.0, 0.1 + 0.2, 0.3, -1e-300, 1e300};
  std::uniform_int_distribution<std::size_t> coordinate(0, std::size(coordinates) - 1);
  std::vector<Site> sites(n);
  for (auto& s : sites) {
    s.id = std::to_string(pick(random)) + (pick(random) % 2 ? "" : "x");
    s.x = coordinates[coordinate(random)];
    s.y = coordinates[coordinate(random)];
  }
  return sites;
}

const Site* included(const std::vector<Site>& sites, std::size_t i) { return i % 5 == 3 ? nullptr : &sites[i]; }

// The (site, first) pairs a check reports for the included sites, in the order reported.
using Check = void (*)(std::size_t, const detail::SiteAt&, const detail::Repeat&);
Pairs reported(Check check, const std::vector<Site>& sites) {
  Pairs found;
  check(
      sites.size(), [&](std::size_t i) { return included(sites, i); },
      [&](std::size_t i, std::size_t first) { found.emplace_back(i, first); });
  return found;
}

TEST(SiteChecks, RepeatedIdsAreThoseABruteForceFindsInFileOrder) {
  for (const std::uint32_t seed : {1u, 2u, 3u}) {
    const auto sites = crowded_sites(3000, seed);
    const Pairs found = reported(find_repeated_ids, sites);
    Pairs expected;
    std::map<std::string, std::size_t> first;
    for (std::size_t i = 0; i < sites.size(); ++i) {
      if (!included(sites, i)) continue;
      const auto [it, inserted] = first.emplace(sites[i].id, i);
      if (!inserted) expected.emplace_back(i, it->second);
    }
    EXPECT_GT(expected.size(), 2000u);  // the pools are small: most sites repeat an id
    EXPECT_EQ(found, expected) << "seed " << seed;
  }
}

TEST(SiteChecks, RepeatedPositionsAreThoseABruteForceFindsWithZeroAndMinusZeroAlike) {
  for (const std::uint32_t seed : {1u, 2u, 3u}) {
    const auto sites = crowded_sites(1500, seed);
    Pairs found = reported(find_repeated_positions, sites);
    std::sort(found.begin(), found.end());  // reported in no particular order
    Pairs expected;
    for (std::size_t i = 0; i < sites.size(); ++i) {
      if (!included(sites, i)) continue;
      for (std::size_t j = 0; j < i; ++j) {
        if (included(sites, j) && sites[j].x == sites[i].x && sites[j].y == sites[i].y) {
          expected.emplace_back(i, j);
          break;
        }
      }
    }
    EXPECT_GT(expected.size(), 1000u);
    EXPECT_EQ(found, expected) << "seed " << seed;
  }
}

// 10^5 distinct sites with ids of both kinds (strings and integers), some names, and doubles of
// every magnitude.
std::vector<Site> many_sites() {
  std::mt19937_64 random(16);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-300, 300);
  std::vector<Site> sites(100'000);
  for (std::size_t i = 0; i < sites.size(); ++i) {
    Site& s = sites[i];
    s.id = i % 3 == 0 ? std::to_string(i) : "site-" + std::to_string(i);
    s.x = std::ldexp(unit(random), exponent(random));
    s.y = unit(random) * 1e5;
    s.weight = std::ldexp(1.0 + unit(random) * 0.5, exponent(random) / 10);
    if (i % 7 == 0) s.name = "mast \"" + std::to_string(i) + "\" \xC3\xA9";
  }
  return sites;
}

std::string sites_json(const std::vector<Site>& sites) {
  std::ostringstream out;
  write_sites_json(sites, out);
  return out.str();
}

void expect_same_sites(const std::vector<Site>& a, const std::vector<Site>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_TRUE(a[i].id == b[i].id && a[i].name == b[i].name && same(a[i].x, b[i].x) && same(a[i].y, b[i].y) &&
                same(a[i].weight, b[i].weight))
        << "site " << i;
  }
}

TEST(SiteChecks, LargeListTakesTheFastPathAndReadsBackAsWrittenAndAsTheReferenceReadsIt) {
  const auto sites = many_sites();
  const std::string text = sites_json(sites);
  const auto fast = detail::parse_sites_json_fast(text);
  ASSERT_TRUE(fast.has_value());
  expect_same_sites(fast->sites, sites);
  const SiteTable reference = detail::parse_sites_json(text, "s.json");
  expect_same_sites(fast->sites, reference.sites);
  EXPECT_EQ(fast->origin, reference.origin);
  EXPECT_EQ(fast->origin.back(), "sites[99999]");
}

TEST(SiteChecks, LargeListWithRepeatsFarApartMissesAndTheReferenceNamesEachPair) {
  auto sites = many_sites();
  sites.back().id = sites[7].id;  // "site-7"
  sites[60'001].x = sites[31].x;  // the position of sites[31]
  sites[60'001].y = sites[31].y;
  const std::string text = sites_json(sites);
  EXPECT_FALSE(detail::parse_sites_json_fast(text).has_value());
  const auto e = input_error_from([&] { parse_sites(text, "s.json"); });
  ASSERT_EQ(e.problems.size(), 2u);
  EXPECT_EQ(format_problem(e.file, e.problems[0]),
            "s.json: sites[60001] (site 'site-60001'): same position (" + round_trip_number(sites[31].x) + ", " +
                round_trip_number(sites[31].y) + ") as site 'site-31' (sites[31])");
  EXPECT_EQ(format_problem(e.file, e.problems[1]),
            "s.json: sites[99999] (site 'site-7'): duplicate id; first used by site 'site-7' (sites[7])");
}

}  // namespace
}  // namespace covmap::io
