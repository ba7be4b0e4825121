// Label placement for the SVG writer (svg.h, svg_layout.h): greedy, first fit among four places,
// never overlapping a placed label, never outside the picture.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "report/svg_layout.h"

namespace covmap::report::detail {
namespace {

// UTF-8 code points: every byte that does not continue a sequence (10xxxxxx) starts one.
std::size_t code_points(std::string_view text) {
  return static_cast<std::size_t>(
      std::count_if(text.begin(), text.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
}

// The advance of `text` in a font of font_px, by the metric of svg_layout.h.
double text_width(std::string_view text, double font_px) {
  return kCharWidthEm * font_px * static_cast<double>(code_points(text));
}

bool overlap(const LabelBox& a, const LabelBox& b) { return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1; }

// Placed boxes, bucketed by the square cells of a grid each box touches, so that a new box is
// tested only against boxes near it (10^4 labels would otherwise cost 10^8 tests).
class BoxGrid {
 public:
  explicit BoxGrid(double cell) : cell_(cell) {}

  bool is_free(const LabelBox& b) const {
    bool clear = true;
    for_cells(b, [&](std::uint64_t key) {
      const auto it = cells_.find(key);
      if (it == cells_.end()) return;
      for (const std::size_t k : it->second) clear = clear && !overlap(boxes_[k], b);
    });
    return clear;
  }

  void add(const LabelBox& b) {
    boxes_.push_back(b);
    for_cells(b, [&](std::uint64_t key) { cells_[key].push_back(boxes_.size() - 1); });
  }

 private:
  template <typename F>
  void for_cells(const LabelBox& b, F&& f) const {
    // Boxes lie inside the picture (checked before), so cell indices are small and non-negative.
    const auto lo_x = static_cast<std::uint64_t>(b.x0 / cell_), hi_x = static_cast<std::uint64_t>(b.x1 / cell_);
    const auto lo_y = static_cast<std::uint64_t>(b.y0 / cell_), hi_y = static_cast<std::uint64_t>(b.y1 / cell_);
    for (std::uint64_t x = lo_x; x <= hi_x; ++x)
      for (std::uint64_t y = lo_y; y <= hi_y; ++y) f(x << 32 | y);
  }

  double cell_;
  std::vector<LabelBox> boxes_;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> cells_;
};

// A grid cell a few labels wide: each box touches few cells, each cell holds few boxes.
constexpr double kGridCellEm = 8.0;

}  // namespace

LabelBox label_box(std::string_view text, Point baseline, double font_px) {
  const double halo = kHaloEm * font_px / 2;
  return {baseline.x - halo, baseline.y - kAscentEm * font_px - halo,
          baseline.x + text_width(text, font_px) + halo,
          baseline.y + kDescentEm * font_px + halo};
}

std::vector<PlacedLabel> place_labels(std::span<const LabelRequest> requests, double font_px, double width_px,
                                      double height_px, std::size_t cap) {
  std::vector<PlacedLabel> placed;
  if (font_px <= 0) return placed;
  BoxGrid grid(kGridCellEm * font_px);
  for (std::size_t i = 0; i < requests.size() && placed.size() < cap; ++i) {
    const LabelRequest& r = requests[i];
    const double width = text_width(r.text, font_px);
    const double gap = r.dot_radius + kLabelGapPx;
    // Above right (the usual place), below right, above left, below left.
    const Point places[] = {{r.at.x + gap, r.at.y - gap},
                            {r.at.x + gap, r.at.y + gap + kAscentEm * font_px},
                            {r.at.x - gap - width, r.at.y - gap},
                            {r.at.x - gap - width, r.at.y + gap + kAscentEm * font_px}};
    for (const Point& baseline : places) {
      const LabelBox b = label_box(r.text, baseline, font_px);
      if (!(b.x0 >= 0 && b.y0 >= 0 && b.x1 <= width_px && b.y1 <= height_px) || !grid.is_free(b)) continue;
      grid.add(b);
      placed.push_back({i, baseline});
      break;
    }
  }
  return placed;
}

}  // namespace covmap::report::detail
