// covmap::service HTTP server: `covmap serve`'s API (docs/openapi.json) over cpp-httplib.
//
//   POST   /v1/audits                  multipart: map (file), sensors (file, optional), options (JSON)
//   GET    /v1/audits                  jobs, newest first (?limit=N, default 100)
//   GET    /v1/audits/{id}             one job: status, progress, stage, error, summary
//   GET    /v1/audits/{id}/{file}      report.json, report.html, sensors/shifts/diagram.geojson or audit.gpkg
//   DELETE /v1/audits/{id}             cancel a queued or running job; delete a finished one with its files
//   POST   /v1/diagram | check | recognize | compare   synchronous operations (service/sync_operations.h)
//   GET    /openapi.json, GET /        the API document; the web page
//
// Contract: every error is the JSON of service/api_error.h with its status; bad input never
// leaves a job or a file behind (uploads are read before the job is stored, and removed when
// refused). On start the job store recovers jobs a previous server left running
// (JobStore::recover_interrupted). The handlers run on cpp-httplib's thread pool; audits run in
// processes of their own (service/job_runner.h).
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "service/serve_options.h"

namespace covmap::service {

// Why a server cannot start, for the person starting it: the address is taken, the data folder
// cannot be used, or another server uses it. `covmap serve` exits 2 with the message.
struct StartError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Route {
  std::string method;  // "GET", "POST", "DELETE"
  std::string path;    // "/v1/audits/{id}"
  bool operator==(const Route&) const = default;
};

class HttpServer {
 public:
  // Opens (or creates) the data folder, takes its lock (one server per data folder: recovery takes
  // every running job for interrupted), opens its job store and recovers interrupted jobs. Throws
  // StartError if it cannot (std::invalid_argument for invalid options).
  explicit HttpServer(const ServeOptions& options);
  ~HttpServer();
  HttpServer(const HttpServer&) = delete;
  HttpServer& operator=(const HttpServer&) = delete;

  // Binds the listening socket (options.port, or a free one if 0) and returns the port; throws
  // StartError when the address is taken or not available.
  int bind();
  // Serves until stop(); returns false if the server could not listen.
  bool run();
  // Stops serving (from any thread or a signal-handling thread); running audits are killed and
  // requeued at the next start.
  void stop();

  // Every route the server answers, as (method, path in docs/openapi.json's spelling).
  std::vector<Route> routes() const;

  // What the store recovered at start, for the start-up message.
  std::size_t requeued_at_start() const;
  std::size_t failed_at_start() const;

  // What the handlers share; defined in service/server_state.h (internal), opaque here.
  struct State;

 private:
  std::unique_ptr<State> state_;
};

}  // namespace covmap::service
