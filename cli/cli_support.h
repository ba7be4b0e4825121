// Shared pieces of the covmap subcommands: exit codes and the error reporting every command uses.
#pragma once

#include <functional>
#include <string>

namespace covmap::cli {

// Exit status: 0 success; 1 the answer is "no" (violations or differences found); 2 bad input or
// usage; 3 not a bisector graph (recognize); 4 an internal error; 5 a kind of input not handled yet.
enum ExitCode : int { kOk = 0, kViolations = 1, kBadInput = 2, kNotBisectorGraph = 3, kInternal = 4 };

// Runs `body`, turning covmap's typed errors into a message on stderr and an exit code.
int guarded(const std::function<int()>& body);

}  // namespace covmap::cli
