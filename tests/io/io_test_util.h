// Helpers shared by the io tests: a scratch directory, file text, and catching InputError.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <utility>

#include "io/input_error.h"
#include "io/local_projection.h"
#include "io/map_frame.h"
#include "tests/support/temp_dir.h"

namespace covmap::io::testing {

// A frame standing for a map in its own projected CRS: the plane of a transverse Mercator about
// another point, with the kind a PROJ frame has (gis/ makes the real ones; io sees only the
// interface). Its forward/inverse are LocalProjection's, an oracle independent of the reader.
class ProjectedForTest final : public MapFrame {
 public:
  explicit ProjectedForTest(LocalProjection p) : p_(p) {}
  FrameKind kind() const override { return FrameKind::kProjectedCrs; }
  Point forward(double lon, double lat) const override { return p_.forward(lon, lat); }
  LonLat inverse(Point p) const override { return p_.inverse(p); }
  double point_scale_at(Point p) const override { return p_.point_scale_at(p); }
  LonLat reference() const override { return p_.reference(); }
  std::string description() const override { return "test CRS"; }
  std::string crs_wkt() const override { return "TEST"; }
  std::string crs_code() const override { return "TEST:1"; }

 private:
  LocalProjection p_;
};

using covmap::testing::read_text;
using covmap::testing::TempDir;

// Runs f, which must throw InputError, and returns the error for inspection.
inline InputError input_error_from(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "expected an InputError";
  return InputError("", 0, "", "no error was thrown");
}

// Every single-byte deletion, replacement and insertion of `text`; counts the variants the fast
// path took, so a test can make sure both outcomes were exercised.
template <class Agrees>
inline std::pair<int, int> mutate_all(const std::string& text, Agrees&& agrees) {
  static constexpr char kBytes[] = {'"', ',', ':', '[', ']', '{', '}', '0', '1', '-', '.', 'e', ' ', 'n', '\\', '\x01'};
  int taken = 0, missed = 0;
  const auto run = [&](const std::string& variant) { (agrees(variant) ? taken : missed) += 1; };
  for (std::size_t i = 0; i < text.size(); ++i) {
    run(text.substr(0, i) + text.substr(i + 1));
    for (const char c : kBytes) {
      if (c != text[i]) run(text.substr(0, i) + c + text.substr(i + 1));
      run(text.substr(0, i) + c + text.substr(i));
    }
  }
  return {taken, missed};
}

}  // namespace covmap::io::testing
