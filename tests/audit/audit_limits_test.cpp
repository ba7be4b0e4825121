// An audit too large to finish in reasonable time is refused at once, not left to run for minutes
// in silence (10⁶ tiny features).
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "audit/audit.h"
#include "audit/tolerances.h"

namespace covmap::audit {
namespace {

std::vector<CoverageCell> unit_square_cells(std::size_t n) {
  std::vector<CoverageCell> cells(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = static_cast<double>(i % 1000), y = static_cast<double>(i / 1000);
    cells[i].sensor = "s" + std::to_string(i);
    cells[i].feature = static_cast<int>(i);
    cells[i].polygons.push_back({{{x, y}, {x + 1, y}, {x + 1, y + 1}, {x, y + 1}}, {}});
  }
  return cells;
}

TEST(AuditLimits, TooManySensorsAreRefusedBeforeAnyWork) {
  const auto cells = unit_square_cells(kMaxSensors + 1);
  AuditOptions options;
  bool any_progress = false;
  options.progress = [&](const std::string&, double) { any_progress = true; };
  try {
    audit(cells, {}, options);
    FAIL() << "an oversized map was audited";
  } catch (const MapTooLarge& e) {
    EXPECT_NE(std::string(e.what()).find("split the map into regions"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(any_progress);  // refused before the first stage began
}

}  // namespace
}  // namespace covmap::audit
