// covmap::service upload checks: an audit's inputs are read once when the job is submitted, by the
// job library's own reading and validator (job/audit_job.h), so that bad input is answered at once
// with 400 and never becomes a job (the job's own process reads them again to audit them).
#pragma once

#include <filesystem>
#include <string>

#include "io/input_error.h"
#include "job/audit_request.h"
#include "service/api_error.h"

namespace covmap::service {

// Throws ApiError kBadInput (where: "options.alpha", "map: features[3] (sensor 'b')",
// "sensors:7: ...") for anything the audit would refuse before auditing: a request the validator
// refuses, unreadable or malformed map or sensors, unusable CRS, plausibility findings unless
// settings.force, more sensors than an audit takes. `request` names the uploaded files.
void check_audit_inputs(const job::AuditRequest& request);

// A message about an upload as the API says it: the files' paths on the server replaced by the
// parts' names ("map", "sensors"), which are what the user knows them as.
std::string without_server_paths(std::string message, const job::AuditRequest& request);

// An InputError about the upload `part` as an ApiError whose `where` names the part and the item.
ApiError as_bad_input(const io::InputError& e, const std::string& part, const job::AuditRequest& request);

}  // namespace covmap::service
