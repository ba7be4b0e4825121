// covmap::report SVG rendering: a picture of a Diagram for people.
//
// What is drawn, bottom to top: a background; each face filled with its site's colour (one <path>
// per face, fill-rule evenodd so holes stay empty; circle arcs as true elliptical-arc commands);
// every arc stroked (frame arcs heavier); nodes as small dots; sites as dots whose radius grows
// with weight; labels; a scale bar. World y points up (a transform flips it) and path coordinates
// are world coordinates. Sizes are given in pixels of the picture at its nominal width and
// converted to world units, which every renderer understands; with non_scaling_stroke the stroke
// widths are instead left in screen pixels for zooming in a browser.
//
// The view is options.view if set, else the clip polygon's bounding box if the diagram is clipped,
// else the sites' bounding box, widened by options.margin. Unbounded faces and rays are cut outside
// the view (svg_geometry.h explains how). A diagram without faces (a graph from another tool) is
// drawn as arcs only.
//
// Width: options.width_px if set. Otherwise chosen from the data so that the median distance from
// a site to its nearest neighbour is kSpacingPx (12) pixels, clamped to kMinWidthPx..kMaxWidthPx
// (800..4000), so small site sets get the minimum and very large ones the maximum (svg_layout.h
// has the constants and the sampling). The height follows the view's aspect ratio.
//
// Labels: a site is labelled with its name, or its id when it has none. Sites are taken heaviest
// first (heavier sites own larger regions; ties in input order), and each label is put at the first
// of four places around its dot (above right, below right, above left, below left) where its box
// lies inside the picture and overlaps no label already placed; a label with no such place is left
// out, as is every label after options.max_labels. A label's box, in pixels: 0.62 em per character
// (UTF-8 code point) wide, from 0.8 em above the baseline to 0.25 em below, widened on every side
// by half the white halo drawn round the text (font_px / 8). Sparse sites therefore get every
// label, dense areas some, never a pile.
//
// Scale bar (show_scale_bar): in the lower left corner, a bar 1, 2 or 5 x 10^k world units long,
// the longest such length not above a fifth of the view's width, labelled "<length> <units>".
// Diagram files carry no unit, so `units` defaults to "units"; a caller that knows them (planar
// metres: "m") says so.
//
// Colours: a site's colour is a function of its id alone (site_colour_for), so the same site has
// the same colour in every picture whatever the order of the sites: `diagram` and `recognize` of
// one input (the audit report's map can use it too). Ids and names are XML-escaped. Throws
// std::invalid_argument if options are invalid; does not validate the diagram beyond what drawing
// needs (indices must be in range).
#pragma once

#include <array>
#include <cstddef>
#include <iosfwd>
#include <optional>
#include <string>
#include <string_view>

#include "core/diagram.h"

namespace covmap::report {

struct SvgOptions {
  // Width of the picture in pixels; unset: chosen from the sites' spacing (see above).
  std::optional<double> width_px;
  // Extra space around the automatic view, as a fraction of its larger extent, on each side.
  double margin = 0.08;
  // World window {xmin, ymin, xmax, ymax}; unset: automatic (see above). Margin is not added.
  std::optional<std::array<double, 4>> view;
  // Fill the faces; off draws only the arc graph.
  bool fill_faces = true;
  bool show_nodes = true;
  bool show_sites = true;
  // Labels (names, else ids) placed without overlap (see above); at most this many, to bound the
  // file's size. 0: no labels.
  std::size_t max_labels = 2000;
  // A scale bar labelled in `units` (see above).
  bool show_scale_bar = true;
  std::string units = "units";
  // Keep stroke widths constant while zooming (vector-effect: non-scaling-stroke). Off by default:
  // librsvg (rsvg-convert, ImageMagick, GNOME viewers) ignores vector-effect and would draw the
  // widths in world units, so that a 1 px stroke could cover the whole picture.
  bool non_scaling_stroke = false;
  // Stroke width of bisector arcs and of frame arcs, in pixels.
  double arc_width_px = 1.0;
  double frame_width_px = 2.0;
  // Radius of node dots; radius of the lightest site's dot (heavier: x sqrt(weight ratio), up to 4x).
  double node_radius_px = 1.8;
  double site_radius_px = 3.0;
  double font_px = 11.0;
  // Background colour (any SVG colour); empty for transparent.
  std::string background = "#ffffff";

  // True if every field is usable; otherwise false, with the reason in *why if why is not null.
  bool is_valid(std::string* why = nullptr) const;
};

void write_svg(const Diagram& diagram, std::ostream& out, const SvgOptions& options = {});

// The fill colour ("#rrggbb") of the site with this id, in every picture covmap draws. An id that
// is an integer in canonical decimal form ("17", "-3", not "017") has hue n x 137.5 degrees (the
// golden angle), so consecutive numbers get well separated hues; any other id gets the hue of a
// hash of its text, spread the same way.
std::string site_colour_for(std::string_view id);

// The fill colour of the integer i: site_colour_for(std::to_string(i)). For renderers that number
// their sites and have no ids (prefer site_colour_for where there is an id).
std::string site_colour(std::size_t i);

}  // namespace covmap::report
