// covmap::io::InputError — the one exception type for malformed input files.
//
// Contract: every reader in covmap::io reports bad input (unreadable file, bad syntax, bad values)
// by throwing InputError, never by returning partial data. The error names where the problem is so
// a person can fix the file without a debugger: the file, the line (1-based; 0 when the format has
// no useful line, e.g. a JSON value addressed by path), the item (a site, a JSON path) and what is
// wrong. Readers that validate many records collect every problem first and throw once, so a file
// with ten bad rows needs one edit cycle, not ten.
//
// what() reads like
//   sites.csv:7: site 'b': weight must be positive (got -1)
// and, for several problems,
//   sites.csv: 3 problems
//     sites.csv:7: site 'b': weight must be positive (got -1)
//     ...
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace covmap::io {

// One thing wrong with an input. Empty fields are left out of the rendered text.
struct InputProblem {
  int line = 0;          // 1-based line in the file, 0 if not applicable
  std::string item;      // what is wrong: "site 'b'", "sites[3] (site 'b')", "arcs[12].to"
  std::string message;   // how it is wrong: "weight must be positive (got -1)"
};

struct InputError : std::runtime_error {
  // How many problems what() spells out; the rest are counted ("... and 7 more").
  static constexpr std::size_t kMaxListed = 20;

  InputError(std::string file, int line, std::string item, std::string message);
  // problems must not be empty.
  InputError(std::string file, std::vector<InputProblem> problems);

  std::string file;                    // as the user named it; may be empty (e.g. a --clip spec)
  std::vector<InputProblem> problems;  // never empty; problems.front() is the first found

  int line() const { return problems.front().line; }
  const std::string& item() const { return problems.front().item; }
  const std::string& message() const { return problems.front().message; }
};

// "file:line: item: message" with the empty parts left out.
std::string format_problem(const std::string& file, const InputProblem& problem);

}  // namespace covmap::io
