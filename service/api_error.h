// covmap::service errors: every error the API returns has one JSON shape,
//   {"error": {"code": "bad_input", "message": "...", "where": "map: features[3]"}}
// and the HTTP status that fits its code. Handlers throw ApiError; the server turns it (and any
// io::InputError, which is bad input by definition) into the response. Anything else that escapes
// a handler is a real internal error: 500 with code "internal".
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace covmap::service {

enum class ErrorCode {
  kBadInput,       // 400: the request or an uploaded file is malformed; `where` names the part
  kNotFound,       // 404: no such job, file or route
  kNotReady,       // 404: the job exists but has not produced that file (yet)
  kMethod,         // 405
  kConflict,       // 409: the job is not in a state that allows the request
  kTooLarge,       // 413: body or input over a limit
  kQueueFull,      // 503: too many jobs waiting; try again later
  kInternal,       // 500: a bug in covmap
};

std::string_view error_code_name(ErrorCode code);  // "bad_input", "not_found", ...
int http_status(ErrorCode code);

struct ApiError : std::runtime_error {
  ApiError(ErrorCode code, std::string message, std::string where = "")
      : std::runtime_error(std::move(message)), code(code), where(std::move(where)) {}
  ErrorCode code;
  std::string where;
};

// The JSON text of an error response.
std::string error_json(ErrorCode code, std::string_view message, std::string_view where);

}  // namespace covmap::service
