#include "cli/cli_support.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <unistd.h>

#include "audit/audit.h"
#include "cleaning/map_cleaning.h"
#include "io/atomic_file.h"
#include "io/input_error.h"
#include "voronoi/clip.h"
#include "voronoi/engine.h"

namespace covmap::cli {
namespace {

// The number a user typed, or NaN when the text is not one whole finite number.
double parse_finite(const std::string& text) {
  if (text.empty()) return std::nan("");
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(text.c_str(), &end);
  if (*end != '\0' || errno == ERANGE || !std::isfinite(value)) return std::nan("");
  return value;
}

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
  } catch (const io::InputError& e) {
    return {e.what(), kBadInput};
  } catch (const io::OutputError& e) {
    return {e.what(), kBadInput};
  } catch (const cleaning::SnapTooSmall& e) {
    return {std::string(e.what()) + "; give a larger --snap (about the map's staircase step, in map units)", kBadInput};
  } catch (const voronoi::InvalidSites& e) {
    return {e.what(), kBadInput};
  } catch (const voronoi::ClipTooLarge& e) {
    return {e.what(), kBadInput};
  } catch (const audit::MapTooLarge& e) {
    return {e.what(), kBadInput};
  } catch (const std::bad_alloc&) {
    return {"out of memory; the input is too large for this machine (see docs/RELIABILITY.md for the limits)",
            kBadInput};
  } catch (const std::exception& e) {
    return {std::string("internal error (please report it): ") + e.what(), kInternal};
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
      [](std::string& text) -> std::string {
        const double v = parse_finite(text);
        return std::isfinite(v) && v > 0 ? "" : "must be a positive number (got '" + text + "')";
      },
      "POSITIVE");
}

CLI::Validator non_negative_number() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const double v = parse_finite(text);
        return std::isfinite(v) && v >= 0 ? "" : "must be a number ≥ 0 (got '" + text + "')";
      },
      "NUMBER ≥ 0");
}

CLI::Validator fraction() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const double v = parse_finite(text);
        return std::isfinite(v) && v > 0 && v < 1 ? "" : "must be a number between 0 and 1, such as 1e-7 (got '" + text + "')";
      },
      "0 < NUMBER < 1");
}

CLI::Validator whole_number_in(long long lowest, long long highest) {
  const std::string range = std::to_string(lowest) + "–" + std::to_string(highest);
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        char* end = nullptr;
        errno = 0;
        const long long v = text.empty() ? 0 : std::strtoll(text.c_str(), &end, 10);
        if (text.empty() || *end != '\0' || errno == ERANGE || v < lowest || v > highest)
          return "must be a whole number in " + range + " (got '" + text + "')";
        return "";
      },
      "INT in " + range);
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
