#include "service/api_error.h"

#include <nlohmann/json.hpp>

namespace covmap::service {

std::string_view error_code_name(ErrorCode code) {
  switch (code) {
    case ErrorCode::kBadInput: return "bad_input";
    case ErrorCode::kNotFound: return "not_found";
    case ErrorCode::kNotReady: return "not_ready";
    case ErrorCode::kMethod: return "method_not_allowed";
    case ErrorCode::kConflict: return "conflict";
    case ErrorCode::kTooLarge: return "too_large";
    case ErrorCode::kQueueFull: return "queue_full";
    case ErrorCode::kInternal: return "internal";
  }
  return "internal";
}

int http_status(ErrorCode code) {
  switch (code) {
    case ErrorCode::kBadInput: return 400;
    case ErrorCode::kNotFound:
    case ErrorCode::kNotReady: return 404;
    case ErrorCode::kMethod: return 405;
    case ErrorCode::kConflict: return 409;
    case ErrorCode::kTooLarge: return 413;
    case ErrorCode::kQueueFull: return 503;
    case ErrorCode::kInternal: return 500;
  }
  return 500;
}

std::string error_json(ErrorCode code, std::string_view message, std::string_view where) {
  nlohmann::json j = {{"error", {{"code", error_code_name(code)}, {"message", message}, {"where", where}}}};
  // Messages quote the user's input, which need not be UTF-8: replace bad bytes, never throw.
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace covmap::service
