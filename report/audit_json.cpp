#include "report/audit_json.h"

#include <cmath>
#include <ostream>

namespace covmap::report::detail {

OrderedJson verdict_json(audit::SensorVerdict verdict) {
  if (verdict == audit::SensorVerdict::kUnreported) return nullptr;
  return std::string(audit::to_string(verdict));
}

OrderedJson name_or_null(const std::string& name) { return name.empty() ? OrderedJson() : OrderedJson(name); }

OrderedJson number_or_null(double value) { return std::isfinite(value) ? OrderedJson(value) : OrderedJson(); }

OrderedJson number_or_null(const std::optional<double>& value) {
  return value ? number_or_null(*value) : OrderedJson();
}

void write_json(const OrderedJson& value, std::ostream& out, int indent) {
  // nlohmann writes doubles in the shortest form that reads back to the same bits (Grisu2 with a
  // round-trip guarantee), which is the covmap convention (docs/FORMATS.md).
  out << value.dump(indent, ' ', false, OrderedJson::error_handler_t::replace) << '\n';
}

}  // namespace covmap::report::detail
