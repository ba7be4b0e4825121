#include "service/audit_request.h"

#include "job/audit_request_json.h"
#include "report/audit_report.h"
#include "service/api_error.h"

namespace covmap::service {

job::AuditRequest parse_audit_request(std::string_view options_json) {
  job::AuditRequest request;
  try {
    job::read_options_json(options_json, request);
  } catch (const job::OptionsError& e) {
    throw ApiError(ErrorCode::kBadInput, e.message, e.member.empty() ? "options" : "options." + e.member);
  }
  return request;
}

std::vector<std::string> report_files(const job::AuditRequest& request) {
  return report::audit_report_file_names(request.outputs.format);
}

}  // namespace covmap::service
