// Helpers shared by the io tests: a scratch directory, file text, and catching InputError.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <utility>

#include "io/input_error.h"
#include "io/local_projection.h"
#include "io/map_frame.h"

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


// A fresh directory under the system temp dir, removed with everything in it at the end of the test.
class TempDir {
 public:
  TempDir() {
    std::random_device random;
    path_ = std::filesystem::temp_directory_path() / ("covmap-io-test-" + std::to_string(random()) + std::to_string(random()));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

  // Writes `text` to a file in the directory and returns its path.
  std::filesystem::path write(const std::string& name, const std::string& text) const {
    const auto file = path_ / name;
    std::filesystem::create_directories(file.parent_path());
    std::ofstream(file, std::ios::binary) << text;
    return file;
  }

 private:
  std::filesystem::path path_;
};

inline std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

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
