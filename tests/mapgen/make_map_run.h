// Runs covmap-make-map in-process for the tests: the arguments parsed as the program parses them,
// stdout swallowed, stderr (or the parse error) into *error.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tools/mapgen/make_map_command.h"

namespace covmap::mapgen::testing {

// The command's exit status, or -1 when the arguments do not parse.
inline int run_make_map_args(std::vector<std::string> args, std::string* error = nullptr) {
  CLI::App app;
  MakeMapOptions options;
  setup_make_map(app, options);
  args.insert(args.begin(), "covmap-make-map");
  std::vector<const char*> argv;
  for (const auto& a : args) argv.push_back(a.c_str());
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
  } catch (const CLI::ParseError& e) {
    if (error) *error = e.what();
    return -1;
  }
  ::testing::internal::CaptureStderr();
  ::testing::internal::CaptureStdout();
  const int status = run_make_map(options);
  const std::string err = ::testing::internal::GetCapturedStderr();
  (void)::testing::internal::GetCapturedStdout();
  if (error) *error = err;
  return status;
}

}  // namespace covmap::mapgen::testing
