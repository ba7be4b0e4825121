// Shared pieces of the covmap subcommands: the exit-code contract, the error reporting every
// command uses, and the checks of option values.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>
#include <string>

namespace covmap::cli {

// The contract (README, "Exit codes"): 0 success; 1 findings (violations, differences, and for
// `audit --fail-on-inconsistent` inconsistent sensors); 2 usage or input errors, including missing
// or unreadable inputs, bad option values and outputs that cannot or may not be written; 3 not a
// bisector graph (recognize); 4 internal errors only (a bug in covmap: please report it).
enum ExitCode : int { kOk = 0, kFindings = 1, kBadInput = 2, kNotBisectorGraph = 3, kInternal = 4 };

// Runs `body`, turning covmap's typed errors into a message on stderr and an exit code: the errors
// that describe the user's input or outputs (job::describe_current_failure says which) and running
// out of memory exit kBadInput; anything else is a bug and exits kInternal.
int guarded(const std::function<int()>& body);

// What the exception being handled means for the user, as guarded() reports it: the message
// (without the "covmap: " prefix) and kBadInput or kInternal. Call it only inside a catch block;
// an exception that is not a std::exception is rethrown. `covmap audit` on several maps uses it to
// report a failed map and go on with the next.
struct Failure {
  std::string message;
  ExitCode code = kInternal;
};
Failure current_failure();

// Maps a command-line parse error onto the contract: help and --version exit 0 after printing;
// everything else prints one "covmap: ..." message (naming the unknown subcommand and listing the
// right ones where that is the problem) and exits kBadInput.
int exit_for_parse_error(const CLI::App& app, const CLI::ParseError& error, int argc, char** argv);

// Option value checks with messages for people ("must be a positive number (got 0)"). Each takes
// the text as typed, so "nan", "inf" and "1e999" are refused before any conversion.
CLI::Validator positive_number();
CLI::Validator non_negative_number();
// A number strictly between 0 and 1 (relative tolerances).
CLI::Validator fraction();
CLI::Validator whole_number_in(long long lowest, long long highest);
// An existing, readable file (not a folder).
CLI::Validator input_file();

}  // namespace covmap::cli
