#include "service/upload_check.h"

#include "job/audit_job.h"

namespace covmap::service {
namespace {

std::string part_of(const io::InputError& e, const job::AuditRequest& r) {
  // A problem the map's reading finds names the map; any other, once there are sensors, is theirs.
  return e.file == r.inputs.map.string() || r.inputs.sensors.empty() ? "map" : "sensors";
}

}  // namespace

std::string without_server_paths(std::string message, const job::AuditRequest& r) {
  const std::pair<std::string, std::string> parts[] = {{r.inputs.map.string(), "map"}, {r.inputs.sensors.string(), "sensors"}};
  for (const auto& [path, part] : parts) {
    if (path.empty()) continue;
    for (std::size_t at; (at = message.find(path)) != std::string::npos;) message.replace(at, path.size(), part);
  }
  return message;
}

ApiError as_bad_input(const io::InputError& e, const std::string& part, const job::AuditRequest& r) {
  std::string where = part;
  if (!e.problems.empty() && !e.problems.front().item.empty()) where += ": " + e.problems.front().item;
  return ApiError(ErrorCode::kBadInput, without_server_paths(e.what(), r), where);
}

void check_audit_inputs(const job::AuditRequest& request) {
  job::AuditInputsRead in;
  try {
    in = job::read_audit_inputs(request);
  } catch (const job::InvalidAuditRequest& e) {
    throw ApiError(ErrorCode::kBadInput, e.problem.message, "options." + std::string(job::option_name(e.problem.option)));
  } catch (const io::InputError& e) {
    throw as_bad_input(e, part_of(e, request), request);
  }
  if (request.settings.force) return;
  for (const auto& doubt : in.implausible)
    throw ApiError(ErrorCode::kBadInput, doubt.finding + " (set the option force to audit anyway)",
                   doubt.input == job::AuditInputKind::kSensors ? "sensors" : "map");
}

}  // namespace covmap::service
