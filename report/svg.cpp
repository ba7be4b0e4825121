#include "report/svg.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>
#include <stdexcept>

#include <numeric>
#include <vector>

#include "report/svg_geometry.h"
#include "report/svg_layout.h"

namespace covmap::report {
namespace {

using detail::svg_number;
using detail::xml_escape;

Box bounding_box(const auto& points) {
  Box b{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
        -std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  for (const auto& p : points) {
    b.xmin = std::min(b.xmin, p.x);
    b.ymin = std::min(b.ymin, p.y);
    b.xmax = std::max(b.xmax, p.x);
    b.ymax = std::max(b.ymax, p.y);
  }
  return b;
}

Box view_box(const Diagram& d, const SvgOptions& o) {
  if (o.view) return {(*o.view)[0], (*o.view)[1], (*o.view)[2], (*o.view)[3]};
  Box b = !d.clip.empty() ? bounding_box(d.clip) : !d.sites.empty() ? bounding_box(d.sites) : bounding_box(d.nodes);
  if (!(b.xmin <= b.xmax)) b = {0, 0, 0, 0};  // nothing to frame
  // A single site, or sites on a horizontal or vertical line, still needs a two-dimensional view.
  double extent = std::max(b.width(), b.height());
  if (extent == 0) extent = std::max(1.0, std::max(std::abs(b.xmin), std::abs(b.ymin)));
  const double pad = o.margin * extent;
  const double grow_x = (extent - b.width()) / 2 * (b.width() == 0 ? 1 : 0);
  const double grow_y = (extent - b.height()) / 2 * (b.height() == 0 ? 1 : 0);
  return {b.xmin - pad - grow_x, b.ymin - pad - grow_y, b.xmax + pad + grow_x, b.ymax + pad + grow_y};
}

// How the picture maps the world: pixels per world unit, and the picture's size.
struct Frame {
  Box view;
  Box far;
  double scale = 1.0;  // pixels per world unit
  double width_px = 0.0;
  double height_px = 0.0;
  Point pixel(double x, double y) const { return {(x - view.xmin) * scale, (view.ymax - y) * scale}; }
};

// The attributes of a stroke `pixels` wide (svg.h: world units unless non_scaling_stroke).
std::string stroke_width(const SvgOptions& o, const Frame& f, double pixels) {
  return o.non_scaling_stroke ? "stroke-width=\"" + svg_number(pixels) + "\" vector-effect=\"non-scaling-stroke\""
                              : "stroke-width=\"" + svg_number(pixels / f.scale) + "\"";
}

// What a label says: the site's name, else its id.
const std::string& label_text(const Site& s) { return s.name.empty() ? s.id : s.name; }

// "north (North mast)": the id, and the name when there is one.
std::string id_and_name(const Site& s) { return s.id + (s.name.empty() ? "" : " (" + s.name + ")"); }

void write_faces(const Diagram& d, const Frame& f, std::ostream& out) {
  out << "<g class=\"faces\" fill-rule=\"evenodd\" stroke=\"none\">\n";
  for (const auto& face : d.faces) {
    const bool known = face.site >= 0 && static_cast<std::size_t>(face.site) < d.sites.size();
    const std::string name = known ? xml_escape(id_and_name(d.sites[face.site])) : "?";
    out << "<path class=\"face" << (face.orphan ? " orphan" : "") << "\" fill=\""
        << (known ? site_colour_for(d.sites[face.site].id) : "#dddddd") << "\" d=\"" << detail::face_path(d, face, f.far)
        << "\"><title>site " << name << (face.orphan ? " (orphan face)" : "") << "</title></path>\n";
  }
  out << "</g>\n";
}

void write_arcs(const Diagram& d, const SvgOptions& o, const Frame& f, std::ostream& out) {
  out << "<g class=\"arcs\" fill=\"none\" stroke=\"#333333\" stroke-linecap=\"round\">\n";
  for (std::size_t i = 0; i < d.arcs.size(); ++i) {
    const bool frame = d.arcs[i].frame;
    out << "<path" << (frame ? " class=\"frame\" stroke=\"#000000\" " : " ")
        << stroke_width(o, f, frame ? o.frame_width_px : o.arc_width_px) << " d=\""
        << detail::arc_path(d, static_cast<int>(i), f.far) << "\"/>\n";
  }
  out << "</g>\n";
}

// A site's dot radius in pixels: area proportional to weight reads naturally; capped at 4 times
// the lightest's radius so that one heavy site cannot hide the map.
double dot_radius_px(const Site& s, double lightest, const SvgOptions& o) {
  return o.site_radius_px * (lightest > 0 ? std::clamp(std::sqrt(s.weight / lightest), 1.0, 4.0) : 1.0);
}

double lightest_weight(const Diagram& d) {
  double lightest = std::numeric_limits<double>::infinity();
  for (const auto& s : d.sites) lightest = std::min(lightest, s.weight);
  return lightest;
}

void write_nodes_and_sites(const Diagram& d, const SvgOptions& o, const Frame& f, std::ostream& out) {
  if (o.show_nodes && !d.nodes.empty()) {
    out << "<g class=\"nodes\" fill=\"#333333\">\n";
    for (const auto& n : d.nodes)
      out << "<circle cx=\"" << svg_number(n.x) << "\" cy=\"" << svg_number(n.y) << "\" r=\""
          << svg_number(o.node_radius_px / f.scale) << "\"/>\n";
    out << "</g>\n";
  }
  if (!o.show_sites || d.sites.empty()) return;
  const double lightest = lightest_weight(d);
  out << "<g class=\"sites\" stroke=\"#ffffff\">\n";
  for (const auto& s : d.sites) {
    out << "<circle cx=\"" << svg_number(s.x) << "\" cy=\"" << svg_number(s.y) << "\" r=\""
        << svg_number(dot_radius_px(s, lightest, o) / f.scale) << "\" fill=\"" << detail::site_dot_colour_for(s.id)
        << "\" " << stroke_width(o, f, 1.0) << "><title>" << xml_escape(id_and_name(s)) << " (weight "
        << svg_number(s.weight) << ")</title></circle>\n";
  }
  out << "</g>\n";
}

// Labels sit outside the flipped group, or the text would be upside down: (x, y) is written (x, -y).
void write_labels(const Diagram& d, const SvgOptions& o, const Frame& f, std::ostream& out) {
  if (!o.show_sites || d.sites.empty() || o.max_labels == 0) return;
  // Heaviest first (svg.h), ties in input order.
  std::vector<std::size_t> order(d.sites.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return d.sites[a].weight > d.sites[b].weight; });
  const double lightest = lightest_weight(d);
  std::vector<detail::LabelRequest> requests;
  requests.reserve(order.size());
  for (const std::size_t i : order) {
    const Site& s = d.sites[i];
    requests.push_back({f.pixel(s.x, s.y), dot_radius_px(s, lightest, o), label_text(s)});
  }
  const auto placed = detail::place_labels(requests, o.font_px, f.width_px, f.height_px, o.max_labels);
  out << "<g class=\"labels\" font-family=\"sans-serif\" font-size=\"" << svg_number(o.font_px / f.scale)
      << "\" fill=\"#111111\" stroke=\"#ffffff\" stroke-width=\"" << svg_number(detail::kHaloEm * o.font_px / f.scale)
      << "\" paint-order=\"stroke\">\n";
  for (const auto& p : placed) {
    out << "<text x=\"" << svg_number(f.view.xmin + p.baseline.x / f.scale) << "\" y=\""
        << svg_number(p.baseline.y / f.scale - f.view.ymax) << "\">" << xml_escape(requests[p.request].text)
        << "</text>\n";
  }
  out << "</g>\n";
}

}  // namespace

bool SvgOptions::is_valid(std::string* why) const {
  const auto fail = [&](const char* reason) {
    if (why) *why = reason;
    return false;
  };
  if (width_px && (!(*width_px > 0) || !std::isfinite(*width_px))) return fail("width_px must be positive and finite");
  if (!(margin >= 0) || !std::isfinite(margin)) return fail("margin must be non-negative and finite");
  if (view) {
    const auto& v = *view;
    if (!std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); })) return fail("view must be finite");
    if (!(v[0] < v[2]) || !(v[1] < v[3])) return fail("view must be {xmin, ymin, xmax, ymax} with min < max");
  }
  for (const double px : {arc_width_px, frame_width_px, node_radius_px, site_radius_px, font_px}) {
    if (!(px >= 0) || !std::isfinite(px)) return fail("sizes in pixels must be non-negative and finite");
  }
  return true;
}

void write_svg(const Diagram& d, std::ostream& out, const SvgOptions& o) {
  if (std::string why; !o.is_valid(&why)) throw std::invalid_argument("write_svg: " + why);
  Frame f;
  f.view = view_box(d, o);
  f.far = detail::far_box(d, f.view);
  f.width_px = o.width_px ? *o.width_px : detail::automatic_width_px(d.sites, f.view);
  f.scale = f.width_px / f.view.width();
  f.height_px = f.view.height() * f.scale;
  const Box& view = f.view;

  // The viewBox is in world units with y negated, so world point (x, y) sits at (x, -y); the
  // scale(1,-1) group below lets everything inside use world coordinates directly.
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << svg_number(f.width_px) << "\" height=\""
      << svg_number(f.height_px) << "\" viewBox=\"" << svg_number(view.xmin) << ' ' << svg_number(-view.ymax) << ' '
      << svg_number(view.width()) << ' ' << svg_number(view.height()) << "\">\n"
      << "<title>covmap diagram: " << d.sites.size() << " sites, " << d.nodes.size() << " nodes, " << d.arcs.size()
      << " arcs, " << d.faces.size() << " faces</title>\n";
  if (!o.background.empty()) {
    out << "<rect x=\"" << svg_number(view.xmin) << "\" y=\"" << svg_number(-view.ymax) << "\" width=\""
        << svg_number(view.width()) << "\" height=\"" << svg_number(view.height()) << "\" fill=\""
        << xml_escape(o.background) << "\"/>\n";
  }
  out << "<g transform=\"scale(1,-1)\">\n";
  if (o.fill_faces && !d.faces.empty()) write_faces(d, f, out);
  write_arcs(d, o, f, out);
  write_nodes_and_sites(d, o, f, out);
  out << "</g>\n";
  write_labels(d, o, f, out);
  if (o.show_scale_bar) detail::write_scale_bar(out, view, f.scale, o.font_px, o.units);
  out << "</svg>\n";
}

namespace detail {

// Control characters other than tab, newline and carriage return are not allowed in XML 1.0 at
// all, so they become '?'.
std::string xml_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r') out += '?';
        else out += c;
    }
  }
  return out;
}

}  // namespace detail
}  // namespace covmap::report
