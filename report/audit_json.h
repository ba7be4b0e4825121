// JSON building blocks shared by the audit writers (internal to report/): numbers that are never
// written as NaN or infinity, and output that survives ids which are not UTF-8.
#pragma once

#include <iosfwd>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "audit/sensor_verdict.h"

namespace covmap::report::detail {

// Members keep the order they were written in, so a person reading a report finds "format" first.
using OrderedJson = nlohmann::ordered_json;

// The number, or null when it is NaN or infinite (JSON has neither).
OrderedJson number_or_null(double value);
// The number, or null when absent, NaN or infinite.
OrderedJson number_or_null(const std::optional<double>& value);

// A sensor's human name, or null when it has none (the reports never write an empty name).
OrderedJson name_or_null(const std::string& name);

// A verdict as the reports write it: its name, or null for a sensor that was not reported.
OrderedJson verdict_json(audit::SensorVerdict verdict);

// Writes `value` and a newline. indent < 0: one line. Bytes that are not UTF-8 in strings become
// U+FFFD instead of making the whole report fail.
void write_json(const OrderedJson& value, std::ostream& out, int indent);

}  // namespace covmap::report::detail
