// Helpers for asserting on CheckReports.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "check/check.h"

namespace covmap::check::testing {

// The first reported violation of kind, if any.
inline std::optional<Violation> first_of(const CheckReport& r, ViolationKind kind) {
  for (const Violation& v : r.violations)
    if (v.kind == kind) return v;
  return std::nullopt;
}

inline bool near(const Violation& v, double x, double y, double tol) {
  return std::hypot(v.x - x, v.y - y) <= tol;
}

// Prints the report when an expectation about it fails.
inline ::testing::AssertionResult is_ok(const CheckReport& r) {
  if (r.ok()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << r.brief();
}

}  // namespace covmap::check::testing
