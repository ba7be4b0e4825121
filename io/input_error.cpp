#include "io/input_error.h"

#include <algorithm>
#include <utility>

namespace covmap::io {

std::string format_problem(const std::string& file, const InputProblem& problem) {
  std::string out = file;
  if (problem.line > 0) out += (out.empty() ? "line " : ":") + std::to_string(problem.line);
  if (!problem.item.empty()) out += (out.empty() ? "" : ": ") + problem.item;
  out += (out.empty() ? "" : ": ") + problem.message;
  return out;
}

namespace {

std::string render(const std::string& file, const std::vector<InputProblem>& problems) {
  if (problems.empty()) return file.empty() ? "invalid input" : file + ": invalid input";
  if (problems.size() == 1) return format_problem(file, problems.front());
  std::string out = (file.empty() ? "input" : file) + ": " + std::to_string(problems.size()) + " problems";
  const std::size_t listed = std::min(problems.size(), InputError::kMaxListed);
  for (std::size_t i = 0; i < listed; ++i) out += "\n  " + format_problem(file, problems[i]);
  if (listed < problems.size()) out += "\n  ... and " + std::to_string(problems.size() - listed) + " more";
  return out;
}

}  // namespace

InputError::InputError(std::string file_name, int line, std::string item, std::string message)
    : InputError(std::move(file_name), std::vector<InputProblem>{{line, std::move(item), std::move(message)}}) {}

InputError::InputError(std::string file_name, std::vector<InputProblem> all)
    : std::runtime_error(render(file_name, all)), file(std::move(file_name)), problems(std::move(all)) {
  // An InputError without a problem would make line()/item() undefined; keep the invariant here.
  if (problems.empty()) problems.push_back({0, "", "invalid input"});
}

}  // namespace covmap::io
