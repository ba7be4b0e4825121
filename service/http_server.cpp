#include "service/http_server.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "io/input_error.h"
#include "service/api_error.h"
#include "service/job_files.h"
#include "service/server_state.h"

namespace covmap::service {
namespace detail {

void send_json(httplib::Response& res, int status, const std::string& json) {
  res.status = status;
  res.set_content(json, "application/json");
}

httplib::Server::Handler guarded(Handler handler) {
  return [handler = std::move(handler)](const httplib::Request& req, httplib::Response& res) {
    try {
      handler(req, res);
    } catch (const ApiError& e) {
      send_json(res, http_status(e.code), error_json(e.code, e.what(), e.where));
    } catch (const io::InputError& e) {
      send_json(res, 400, error_json(ErrorCode::kBadInput, e.what(), e.problems.empty() ? "" : e.problems.front().item));
    } catch (const std::exception& e) {
      send_json(res, 500, error_json(ErrorCode::kInternal, e.what(), ""));
    }
  };
}

void add_route(HttpServer::State& state, const std::string& method, const std::string& path, httplib::Server::Handler handler) {
  state.routes.push_back({method, path});
  std::string pattern;
  for (std::size_t i = 0; i < path.size(); ++i) {
    if (path[i] == '{') {
      pattern += "([^/]+)";
      i = path.find('}', i);
    } else {
      pattern += path[i];
    }
  }
  if (method == "GET") state.http.Get(pattern, std::move(handler));
  else if (method == "POST") state.http.Post(pattern, std::move(handler));
  else if (method == "DELETE") state.http.Delete(pattern, std::move(handler));
  else throw std::logic_error("add_route: method " + method);
}

}  // namespace detail

namespace {

// httplib's own answers (no route, body too large) in the API's JSON shape.
void json_error_pages(HttpServer::State& s) {
  s.http.set_error_handler([&s](const httplib::Request& req, httplib::Response& res) {
    if (!res.body.empty()) return;
    ErrorCode code = ErrorCode::kNotFound;
    std::string message = "no route " + req.method + " " + req.path + " (the API is described at /openapi.json)";
    if (res.status == 413) {
      code = ErrorCode::kTooLarge;
      message = "the request is larger than the server's limit of " + std::to_string(s.options.max_upload_mb) +
                " MiB (covmap serve --max-upload-mb)";
    } else if (res.status == 405) {
      code = ErrorCode::kMethod;
      message = req.method + " is not allowed on " + req.path;
    } else if (res.status != 404) {
      code = res.status >= 500 ? ErrorCode::kInternal : ErrorCode::kBadInput;
      message = "HTTP " + std::to_string(res.status);
    }
    res.set_content(error_json(code, message, ""), "application/json");
  });
}

// One server per data folder: an exclusive lock on DATA/serve.lock, held (and released by the
// kernel, whatever way the process ends) for the server's life.
int lock_data_folder(const std::filesystem::path& data) {
  const std::string file = (data / "serve.lock").string();
  const int fd = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) throw StartError("data folder " + data.string() + ": cannot open " + file + ": " + std::strerror(errno));
  if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd);
    throw StartError("another covmap serve uses the data folder " + data.string() + "; stop it, or give this one another --data");
  }
  return fd;
}

}  // namespace

HttpServer::HttpServer(const ServeOptions& options) : state_(std::make_unique<State>()) {
  std::string why;
  if (!options.is_valid(&why)) throw std::invalid_argument(why);
  state_->options = options;
  std::error_code made;
  std::filesystem::create_directories(options.data_dir / "jobs", made);
  if (made) throw StartError("data folder " + options.data_dir.string() + ": " + made.message());
  state_->lock_fd = lock_data_folder(options.data_dir);
  try {
    state_->store = std::make_unique<JobStore>(JobStore::open(job_store_file(options.data_dir)));
  } catch (const std::runtime_error& e) {
    ::close(state_->lock_fd);
    throw StartError(e.what());
  }
  state_->recovered = state_->store->recover_interrupted(options.max_attempts, now_ms());
  state_->http.set_payload_max_length(options.max_upload_mb << 20);
  // SO_REUSEADDR only: httplib's default adds SO_REUSEPORT, with which a second server binds the
  // same port and quietly takes half the requests instead of being refused.
  state_->http.set_socket_options([](socket_t sock) {
    int yes = 1;
    setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  });
  state_->http.new_task_queue = [] { return new httplib::ThreadPool(8); };
  json_error_pages(*state_);
  detail::add_audit_routes(*state_);
  detail::add_sync_routes(*state_);
  detail::add_page_routes(*state_);
  state_->runner = std::make_unique<JobRunner>(*state_->store, options);
}

HttpServer::~HttpServer() {
  state_->http.stop();
  state_->runner.reset();  // kills running audits; their jobs are requeued at the next start
  state_->store.reset();
  if (state_->lock_fd >= 0) ::close(state_->lock_fd);
}

int HttpServer::bind() {
  const int port = state_->options.port == 0 ? state_->http.bind_to_any_port(state_->options.host)
                                              : (state_->http.bind_to_port(state_->options.host, state_->options.port)
                                                     ? state_->options.port
                                                     : -1);
  if (port < 0)
    throw StartError("cannot listen on " + state_->options.host + ":" + std::to_string(state_->options.port) +
                             " (in use, or not an address of this machine)");
  return port;
}

bool HttpServer::run() { return state_->http.listen_after_bind(); }

void HttpServer::stop() { state_->http.stop(); }

std::vector<Route> HttpServer::routes() const { return state_->routes; }

std::size_t HttpServer::requeued_at_start() const { return state_->recovered.requeued.size(); }
std::size_t HttpServer::failed_at_start() const { return state_->recovered.failed.size(); }

}  // namespace covmap::service
