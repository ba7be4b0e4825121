// What the HTTP handlers share (internal to service/): the options, the job store, the runner.
#pragma once

#include <httplib.h>

#include <functional>
#include <memory>

#include "service/http_server.h"
#include "service/job_runner.h"
#include "service/job_store.h"

namespace covmap::service {

struct HttpServer::State {
  ServeOptions options;
  std::unique_ptr<JobStore> store;
  std::unique_ptr<JobRunner> runner;
  httplib::Server http;
  RecoveryReport recovered;
  std::vector<Route> routes;  // every route added, as the API document names it
  int lock_fd = -1;           // the data folder's lock (DATA/serve.lock), held while the server lives
};

namespace detail {

using Handler = std::function<void(const httplib::Request&, httplib::Response&)>;

// The handler with every error turned into the API's JSON error response.
httplib::Server::Handler guarded(Handler handler);

void add_audit_routes(HttpServer::State& state);
void add_sync_routes(HttpServer::State& state);
void add_page_routes(HttpServer::State& state);

void send_json(httplib::Response& res, int status, const std::string& json);

// Adds a route to the server and to the list the API document is checked against: `method` "GET",
// "POST" or "DELETE"; `path` as in docs/openapi.json ("/v1/audits/{id}"); parameters in braces
// match one path segment each (and reach the handler as req.matches[1], [2], ...).
void add_route(HttpServer::State& state, const std::string& method, const std::string& path, httplib::Server::Handler handler);

}  // namespace detail
}  // namespace covmap::service
