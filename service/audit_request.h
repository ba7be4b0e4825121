// covmap::service audit requests: the `options` part of POST /v1/audits — the audit's options by
// their names, as JSON — read into the job library's one request type (job/audit_request.h) with
// its one validator, so the service refuses what `covmap audit` refuses, in the same words.
//
//   {"alpha": 3.5, "planar": true, "sensor_property": "cell", "format": "gpkg"}
//
// Accepted members: job::kServiceOptions (docs/openapi.json lists them too). Rejected with ApiError
// kBadInput whose `where` names the member ("options.alpha"): anything that is not a JSON object, an
// unknown member (the message lists the known ones), a value of the wrong type or out of range.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "job/audit_request.h"

namespace covmap::service {

// The options part read into a request (empty text: all defaults); inputs and outputs unset.
job::AuditRequest parse_audit_request(std::string_view options_json);

// The report files a finished job serves under /v1/audits/{id}/NAME: those the audit writes for
// the request's format.
std::vector<std::string> report_files(const job::AuditRequest& request);

}  // namespace covmap::service
