// Shared pieces of the covmap subcommands: exit codes and the error reporting every command uses.
#pragma once

#include <functional>
#include <string>

namespace covmap::cli {

// Exit status: 0 success; 1 the answer is "no" (violations found); 2 bad input or usage;
// 3 reserved for "not a bisector graph" (recognition); 4 an internal error.
enum ExitCode : int { kOk = 0, kViolations = 1, kBadInput = 2, kInternal = 4 };

// Runs `body`, turning covmap's typed errors into a message on stderr and an exit code.
int guarded(const std::function<int()>& body);

}  // namespace covmap::cli
