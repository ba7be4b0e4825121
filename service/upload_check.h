// covmap::service upload checks: an audit's inputs are read once when the job is submitted, with
// the same readers and plausibility rules as `covmap audit`, so that bad input is answered at once
// with 400 and never becomes a job (the job's own process reads them again to audit them).
#pragma once

#include <filesystem>

#include "service/audit_request.h"

namespace covmap::service {

// Throws ApiError kBadInput (where: "map: features[3] (sensor 'b')", "sensors:7: ...") for
// anything `covmap audit` would refuse with exit 2 before auditing: unreadable or malformed map or
// sensors, unusable CRS, plausibility findings unless request.force, more sensors than an audit
// takes.
void check_audit_inputs(const AuditRequest& request, const std::filesystem::path& map,
                        const std::filesystem::path& sensors);

}  // namespace covmap::service
