#include "cli/cli_support.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <unistd.h>

#include "core/typed_numbers.h"
#include "io/input_error.h"
#include "job/audit_job.h"

namespace covmap::cli {
namespace {

int say(const std::string& message, int code) {
  std::cerr << "covmap: " << message << "\n";
  return code;
}

std::string subcommand_list(const CLI::App& app) {
  std::string names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    names += (names.empty() ? "" : ", ") + sub->get_name();
  return names;
}

}  // namespace

Failure current_failure() {
  try {
    throw;
  } catch (const job::ImplausibleInputError& e) {
    // The job leaves the way to force it to the shell: here, a flag.
    return {io::InputError(e.file.string(), 0, "", e.finding + " (pass --force to audit anyway)").what(), kBadInput};
  } catch (const std::exception&) {
    const job::AuditFailure failure = job::describe_current_failure();
    return {failure.message, failure.kind == job::FailureKind::kBadInput ? kBadInput : kInternal};
  }
}

int guarded(const std::function<int()>& body) {
  try {
    return body();
  } catch (const std::exception&) {
    const Failure failure = current_failure();
    return say(failure.message, failure.code);
  }
}

int exit_for_parse_error(const CLI::App& app, const CLI::ParseError& error, int argc, char** argv) {
  if (error.get_exit_code() == 0) return app.exit(error);  // --help, --version: printed, success
  const bool no_subcommand = app.get_subcommands().empty();
  if (no_subcommand && argc < 2)
    return say("no subcommand given; use one of: " + subcommand_list(app) + " (covmap --help)", kBadInput);
  if (no_subcommand && argv[1][0] != '-')
    return say("unknown subcommand '" + std::string(argv[1]) + "'; use one of: " + subcommand_list(app) +
                   " (covmap --help)",
               kBadInput);
  const std::string where = no_subcommand ? "" : app.get_subcommands().front()->get_name() + ": ";
  return say(where + error.what() + " (covmap " + (no_subcommand ? "" : app.get_subcommands().front()->get_name() + " ") +
                 "--help)",
             kBadInput);
}

CLI::Validator positive_number() {
  return CLI::Validator(
      [](std::string& text) { return positive_number_problem(text); },
      "POSITIVE");
}

CLI::Validator non_negative_number() {
  return CLI::Validator(
      [](std::string& text) { return non_negative_number_problem(text); },
      "NUMBER ≥ 0");
}

CLI::Validator fraction() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const std::optional<double> v = parse_finite_number(text);
        return v && *v > 0 && *v < 1 ? "" : "must be a number between 0 and 1, such as 1e-7 (got '" + text + "')";
      },
      "0 < NUMBER < 1");
}

CLI::Validator whole_number_in(long long lowest, long long highest) {
  return CLI::Validator([=](std::string& text) { return whole_number_problem(text, lowest, highest); },
                        "INT in " + std::to_string(lowest) + "–" + std::to_string(highest));
}

CLI::Validator input_file() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        std::error_code ec;
        const std::filesystem::file_status status = std::filesystem::status(text, ec);
        if (!std::filesystem::exists(status)) return "cannot read '" + text + "': no such file";
        if (std::filesystem::is_directory(status)) return "cannot read '" + text + "': it is a folder, not a file";
        if (::access(text.c_str(), R_OK) != 0) return "cannot read '" + text + "': " + std::strerror(errno);
        return "";
      },
      "FILE");
}

}  // namespace covmap::cli
