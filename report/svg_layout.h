// Layout decisions of the SVG writer (internal to report/, declared here so tests can check them):
// the picture's width, where labels go, the scale bar, the dot colours. svg.h states the rules;
// the tunables live here, each in one place.
//
// Label placement works in picture pixels: x to the right, y down, (0, 0) the picture's top left.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/box.h"
#include "core/diagram.h"

namespace covmap::report::detail {

// ---- width (svg_size.cpp) ----
// The automatic width's range, and the median nearest-neighbour spacing it aims at, in pixels:
// 12 px leaves room between two default site dots (6 px across) at the median.
inline constexpr double kMinWidthPx = 800.0;
inline constexpr double kMaxWidthPx = 4000.0;
inline constexpr double kSpacingPx = 12.0;
// The median spacing is measured on at most this many sites (evenly taken through the list): the
// median of a sample of 1000 is within a few per cent of the whole list's, and it bounds the cost.
inline constexpr std::size_t kSpacingSample = 1000;

// The median over (sampled) sites of the distance to the nearest other site; coinciding sites are
// skipped. 0 when no site has another at a positive distance.
double median_nearest_spacing(std::span<const Site> sites);

// The width rule of svg.h for a picture of `view`: kSpacingPx / median spacing pixels per world
// unit, clamped to [kMinWidthPx, kMaxWidthPx]; kMinWidthPx when the spacing is unknown (0).
double automatic_width_px(std::span<const Site> sites, const Box& view);

// ---- labels (svg_labels.cpp) ----
// A label's box in ems of the font: the width of one character (a UTF-8 code point; 0.62 em is
// about the widest average of sans-serif text, digits are 0.56), the height above and below the
// baseline, and the halo (the white outline drawn round the text, 1/4 em wide, half outside).
inline constexpr double kCharWidthEm = 0.62;
inline constexpr double kAscentEm = 0.8;
inline constexpr double kDescentEm = 0.25;
inline constexpr double kHaloEm = 0.25;
// Distance between a site's dot and its label, in pixels.
inline constexpr double kLabelGapPx = 2.0;

struct LabelRequest {
  Point at;               // the site's centre, picture pixels
  double dot_radius = 0;  // pixels
  std::string_view text;
};

struct PlacedLabel {
  std::size_t request = 0;  // index into the requests
  Point baseline;           // start of the text's baseline (text-anchor start), picture pixels
};

struct LabelBox {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // picture pixels, x0 <= x1, y0 <= y1
};

// The box of `text` set at `baseline` in a font of `font_px` (the metric above).
LabelBox label_box(std::string_view text, Point baseline, double font_px);

// Places labels for `requests`, taken in the order given (the caller puts the most important
// first), by the rule of svg.h: at the first of four places around the dot whose box lies inside
// [0, width_px] x [0, height_px] and overlaps no placed box; none after `cap` are placed.
std::vector<PlacedLabel> place_labels(std::span<const LabelRequest> requests, double font_px, double width_px,
                                      double height_px, std::size_t cap);

// ---- scale bar (svg_scale_bar.cpp) ----
// The bar's length is the longest 1, 2 or 5 x 10^k not above this fraction of the view's width.
inline constexpr double kScaleBarFraction = 0.2;
// Its distance from the picture's left and bottom edges, in pixels.
inline constexpr double kScaleBarInsetPx = 12.0;

// The longest 1, 2 or 5 x 10^k that is <= at_most (at_most > 0 and finite).
double round_length(double at_most);

// "500", "0.02", "2000000": a round length for the bar's label, in fixed notation.
std::string round_length_text(double length);

// Writes <g class="scale-bar"> (outside the y-flipped group: coordinates are x and -y) for `view`,
// drawn at `scale` pixels per world unit, labelled in `units`.
void write_scale_bar(std::ostream& out, const Box& view, double scale, double font_px, const std::string& units);

// ---- colours (svg_colours.cpp) ----
// The darker colour of a site's dot, same hue as site_colour_for(id).
std::string site_dot_colour_for(std::string_view id);

// Text for XML content and attribute values (svg.cpp).
std::string xml_escape(std::string_view text);

}  // namespace covmap::report::detail
