#include "cli/serve_command.h"

#include <pthread.h>
#include <signal.h>

#include <iostream>
#include <memory>
#include <thread>

#include "cli/cli_support.h"
#include "service/http_server.h"

namespace covmap::cli {

CLI::App* setup_serve(CLI::App& app, service::ServeOptions& o) {
  CLI::App* cmd = app.add_subcommand("serve", "Run the HTTP service: audits as jobs, quick operations, a web page at /");
  cmd->add_option("--host", o.host, "address to listen on (loopback by default: the service has no authentication)")
      ->capture_default_str();
  cmd->add_option("--port", o.port, "TCP port (0: any free one, printed at start)")->check(whole_number_in(0, 65535))->capture_default_str();
  cmd->add_option("--data", o.data_dir, "folder of the job store and the jobs' files (created if missing)")->capture_default_str();
  cmd->add_option("--workers", o.workers, "audits running at once, each in its own process")->check(whole_number_in(1, 64))->capture_default_str();
  cmd->add_option("--queue", o.queue_limit, "jobs waiting beyond which submissions get 503")->check(whole_number_in(1, 100000))->capture_default_str();
  cmd->add_option("--max-upload-mb", o.max_upload_mb, "largest request body (map + sensors), MiB")->check(whole_number_in(1, 4096))->capture_default_str();
  cmd->add_option("--job-cpu-seconds", o.job_cpu_seconds, "CPU time an audit may use before it is stopped")->check(whole_number_in(1, 1000000))->capture_default_str();
  cmd->add_option("--job-memory-mb", o.job_memory_mb, "memory (address space) an audit may use, MiB")->check(whole_number_in(64, 1 << 20))->capture_default_str();
  return cmd;
}

int run_serve(const service::ServeOptions& options) {
  return guarded([&]() {
    // SIGINT/SIGTERM are taken by one thread with sigwait, blocked everywhere else (threads
    // inherit the mask), so stopping is ordinary code rather than a signal handler.
    sigset_t stop_signals;
    sigemptyset(&stop_signals);
    sigaddset(&stop_signals, SIGINT);
    sigaddset(&stop_signals, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);
    std::unique_ptr<service::HttpServer> started;
    int port = 0;
    try {
      started = std::make_unique<service::HttpServer>(options);
      port = started->bind();
    } catch (const service::StartError& e) {
      std::cerr << "covmap: serve: " << e.what() << std::endl;
      return kBadInput;
    }
    service::HttpServer& server = *started;
    std::cout << "covmap serve: listening on http://" << options.host << ":" << port << "/ (data: "
              << options.data_dir.string() << ", " << options.workers << " worker" << (options.workers == 1 ? "" : "s") << ")";
    if (server.requeued_at_start() || server.failed_at_start())
      std::cout << "; after the last stop " << server.requeued_at_start() << " interrupted job(s) requeued, "
                << server.failed_at_start() << " failed";
    std::cout << std::endl;
    std::thread stopper([&] {
      int signal = 0;
      sigwait(&stop_signals, &signal);
      std::cerr << "covmap serve: stopping (signal " << signal << ")" << std::endl;
      server.stop();
    });
    const bool ok = server.run();
    if (!ok) {
      pthread_kill(stopper.native_handle(), SIGTERM);
    }
    stopper.join();
    return ok ? kOk : kBadInput;
  });
}

}  // namespace covmap::cli
