// A sensor as its operator reported it: the one type io reads (io/reported_sensors.h), the audit
// judges (audit/audit.h) and the reports print.
#pragma once

#include <optional>
#include <string>

#include "core/diagram.h"

namespace covmap {

struct ReportedSensor {
  std::string id;
  std::string name;                        // a human name as read ("Zollikofen"); empty when absent
  Point position;                          // planar map units (metres; projected if geographic)
  std::optional<double> lon, lat;          // as read, for geographic input
  std::optional<double> weight;            // as read, or derived from the power and alpha
  std::optional<double> tx_power_dbm;      // as read
  std::optional<double> position_sigma_m;  // stated precision, if given
  std::optional<double> power_sigma_db;
  std::string origin;                      // where it was read: "line 7", "features[3]", "sites[3]"
};

}  // namespace covmap
