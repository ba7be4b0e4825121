// covmap::io SVG rendering: a picture of a Diagram for people.
//
// What is drawn, bottom to top: a background; each face filled with its site's colour (one <path>
// per face, fill-rule evenodd so holes stay empty; circle arcs as true elliptical-arc commands);
// every arc stroked (frame arcs heavier); nodes as small dots; sites as dots whose radius grows
// with weight; site ids as labels when there are few sites. World y points up (a transform flips
// it) and path coordinates are world coordinates. Sizes are given in pixels of the picture at its
// nominal width and converted to world units, which every renderer understands; with
// non_scaling_stroke the stroke widths are instead left in screen pixels for zooming in a browser.
//
// The view is options.view if set, else the clip polygon's bounding box if the diagram is clipped,
// else the sites' bounding box, widened by options.margin. Unbounded faces and rays are cut outside
// the view (svg_geometry.h explains how). A diagram without faces (a graph from another tool) is
// drawn as arcs only.
//
// Colours: site i gets hue i * 137.5 degrees (the golden angle), so neighbours in the input order
// get well separated hues. Ids are XML-escaped. Throws std::invalid_argument if options are
// invalid; does not validate the diagram beyond what drawing needs (indices must be in range).
#pragma once

#include <array>
#include <cstddef>
#include <iosfwd>
#include <optional>
#include <string>

#include "core/diagram.h"

namespace covmap::report {

struct SvgOptions {
  // Width of the picture in pixels; the height follows the view's aspect ratio.
  double width_px = 800.0;
  // Extra space around the automatic view, as a fraction of its larger extent, on each side.
  double margin = 0.08;
  // World window {xmin, ymin, xmax, ymax}; unset: automatic (see above). Margin is not added.
  std::optional<std::array<double, 4>> view;
  // Fill the faces; off draws only the arc graph.
  bool fill_faces = true;
  bool show_nodes = true;
  bool show_sites = true;
  // Site ids are written next to the sites when there are at most this many sites.
  std::size_t max_labels = 200;
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

// The fill colour of site i ("#rrggbb"), also used by other renderers for consistency.
std::string site_colour(std::size_t i);

}  // namespace covmap::report
