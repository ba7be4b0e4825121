// The synchronous operations as routes: POST /v1/diagram, /v1/check, /v1/recognize, /v1/compare.
#include "service/api_error.h"
#include "service/server_state.h"
#include "service/sync_operations.h"

namespace covmap::service::detail {

void add_sync_routes(HttpServer::State& s) {
  using Operation = std::string (*)(std::string_view);
  const std::pair<const char*, Operation> routes[] = {{"/v1/diagram", diagram_operation},
                                                      {"/v1/check", check_operation},
                                                      {"/v1/recognize", recognize_operation},
                                                      {"/v1/compare", compare_operation}};
  for (const auto& [path, operation] : routes) {
    add_route(s, "POST", path, guarded([&s, operation = operation](const httplib::Request& req, httplib::Response& res) {
      if (req.body.size() > (s.options.max_sync_mb << 20))
        throw ApiError(ErrorCode::kTooLarge,
                       "the body is over " + std::to_string(s.options.max_sync_mb) +
                           " MiB, the limit of synchronous operations: submit it as a job (POST /v1/audits) or use the "
                           "command line",
                       "body");
      if (req.body.empty()) throw ApiError(ErrorCode::kBadInput, "the body is empty", "body");
      send_json(res, 200, operation(req.body));
    }));
  }
}

}  // namespace covmap::service::detail
