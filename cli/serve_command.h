// covmap serve [--host 127.0.0.1] [--port 8080] [--data DIR] [--workers N] [--max-upload-mb M]:
// the HTTP service (service/http_server.h; the API in docs/openapi.json, the web page at /).
// Runs until SIGINT or SIGTERM, then stops: running audits are killed and run again at the next
// start. Exit 0 after such a stop; 2 for bad options or an address it cannot listen on.
#pragma once

#include <CLI/CLI.hpp>

#include "service/serve_options.h"

namespace covmap::cli {

CLI::App* setup_serve(CLI::App& app, service::ServeOptions& options);
int run_serve(const service::ServeOptions& options);

}  // namespace covmap::cli
