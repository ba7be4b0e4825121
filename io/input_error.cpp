#include "io/input_error.h"

#include <algorithm>
#include <cctype>
#include <string_view>
#include <unordered_map>
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

// Messages that differ only in their numbers ("position 0 (7.6e152, ...)" on every feature).
std::string shape_of(const std::string& message) {
  std::string shape;
  for (std::size_t i = 0; i < message.size(); ++i) {
    if (!std::isdigit(static_cast<unsigned char>(message[i]))) {
      shape += message[i];
      continue;
    }
    shape += '#';
    while (i + 1 < message.size() && std::isdigit(static_cast<unsigned char>(message[i + 1]))) ++i;
  }
  return shape;
}

// The same mistake on many items (one mistake repeated on every feature) is one line: the first
// item where it happened and how many more share it, messages compared with their numbers left
// out. Groups keep the order of first occurrence.
std::string render(const std::string& file, const std::vector<InputProblem>& problems) {
  if (problems.empty()) return file.empty() ? "invalid input" : file + ": invalid input";
  if (problems.size() == 1) return format_problem(file, problems.front());
  std::vector<std::pair<std::size_t, std::size_t>> groups;  // (first problem, count)
  std::unordered_map<std::string, std::size_t> group_of;
  for (std::size_t i = 0; i < problems.size(); ++i) {
    const auto [it, inserted] = group_of.emplace(shape_of(problems[i].message), groups.size());
    if (inserted) groups.emplace_back(i, 0);
    ++groups[it->second].second;
  }
  std::string out = (file.empty() ? "input" : file) + ": " + std::to_string(problems.size()) + " problems";
  const std::size_t listed = std::min(groups.size(), InputError::kMaxListed);
  for (std::size_t g = 0; g < listed; ++g) {
    InputProblem first = problems[groups[g].first];
    if (groups[g].second > 1) {  // appended piecewise: GCC 12 false -Wrestrict (PR 105651)
      if (!first.item.empty()) first.item += ' ';
      first.item += "(and ";
      first.item += std::to_string(groups[g].second - 1);
      first.item += " more like it)";
    }
    out += "\n  " + format_problem(file, first);
  }
  if (listed < groups.size()) out += "\n  ... and " + std::to_string(groups.size() - listed) + " more kinds of problem";
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
