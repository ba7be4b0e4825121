// Faces as sorted sets of sorted boundary cycles, to compare two tracings of one graph that may
// number their faces and start their cycles apart (faces by geometry against faces by labels).
#pragma once

#include <algorithm>
#include <utility>
#include <vector>

#include "core/diagram.h"

namespace covmap::testing {

inline std::vector<std::vector<std::vector<std::pair<int, bool>>>> canonical_faces(const Diagram& d) {
  std::vector<std::vector<std::vector<std::pair<int, bool>>>> out;
  for (const Face& f : d.faces) {
    std::vector<std::vector<std::pair<int, bool>>> cycles;
    for (const auto b : face_cycles(d, f)) {
      std::vector<std::pair<int, bool>> c;
      for (const HalfArc& h : b) c.emplace_back(h.arc, h.forward);
      std::sort(c.begin(), c.end());
      cycles.push_back(std::move(c));
    }
    std::sort(cycles.begin(), cycles.end());
    out.push_back(std::move(cycles));
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace covmap::testing
