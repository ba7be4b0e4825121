// Fuzz target: the covmap.sites/1 reader (io/sites_io.h, parse_sites with SitesFormat::kJson).
#include "checks.h"
#include "io/input_error.h"
#include "io/sites_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace covmap;
  try {
    const io::SiteTable table = io::parse_sites(fuzz::as_text(data, size), "fuzz.json", io::SitesFormat::kJson);
    fuzz::check_sites(table.sites);
    fuzz::require(table.origin.size() == table.sites.size(), "sites: one origin per site");
  } catch (const io::InputError&) {
  }
  return 0;
}
