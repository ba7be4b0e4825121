// covmap::job audit requests as JSON, both ways.
//
//  - The options object a person sends (the service's `options` part), by the options' names:
//      {"alpha": 3.5, "planar": true, "sensor_property": "cell", "format": "gpkg"}
//    read_options_json() reads it into a request: members and types are checked here, values by
//    the one validator (job/audit_request.h), so a value is refused with the command line's words.
//    Accepted members: kServiceOptions (not threads, which the service's limits decide, nor the
//    files, which are uploads). Rejected with OptionsError naming the member: text that is not a
//    JSON object, an unknown member (the message lists the known ones), a wrong type, a bad value.
//  - The whole request (inputs, settings, outputs, command line), as a job's process receives it:
//    request_json() writes it, request_from_json() reads it back to an equal request (every
//    number exactly), and refuses anything else with OptionsError.
#pragma once

#include <array>
#include <stdexcept>
#include <string>
#include <string_view>

#include "job/audit_request.h"

namespace covmap::job {

inline constexpr std::array<AuditOption, 12> kServiceOptions = {
    AuditOption::kAlpha,     AuditOption::kPlanar,      AuditOption::kFullPrecision, AuditOption::kForce,
    AuditOption::kSensorProperty, AuditOption::kLayer,  AuditOption::kSensorCrs,     AuditOption::kSensorLayer,
    AuditOption::kBasemap,   AuditOption::kSnap,        AuditOption::kBand,          AuditOption::kFormat};

// A member of the options object that cannot be taken: `member` is its name ("" for the whole).
struct OptionsError : std::invalid_argument {
  OptionsError(std::string member, std::string message);
  std::string member;
  std::string message;  // what() without the member's name
};

// Reads the options object into `request` (empty or blank text: nothing changes).
void read_options_json(std::string_view text, AuditRequest& request);

std::string request_json(const AuditRequest& request);
AuditRequest request_from_json(std::string_view text);

}  // namespace covmap::job
