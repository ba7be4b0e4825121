#include "report/svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <ostream>
#include <stdexcept>

#include "report/svg_geometry.h"

namespace covmap::report {
namespace {

using detail::svg_number;

// The golden angle in degrees: successive multiples never come close to repeating a hue.
constexpr double kGoldenAngle = 137.50776405003785;

std::string hex_colour(double hue_degrees, double saturation, double lightness) {
  // HSL to RGB (CSS Color 3 algorithm); hex because SVG 1.1 viewers need not understand hsl().
  const auto channel = [&](double n) {
    const double k = std::fmod(n + hue_degrees / 30.0, 12.0);
    const double a = saturation * std::min(lightness, 1 - lightness);
    return lightness - a * std::max(-1.0, std::min({k - 3, 9 - k, 1.0}));
  };
  char buffer[8];
  std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", static_cast<int>(std::lround(channel(0) * 255)),
                static_cast<int>(std::lround(channel(8) * 255)), static_cast<int>(std::lround(channel(4) * 255)));
  return buffer;
}

std::string dot_colour(std::size_t i) { return hex_colour(std::fmod(i * kGoldenAngle, 360.0), 0.6, 0.35); }

// Text for XML content and attribute values. Control characters other than tab, newline and
// carriage return are not allowed in XML 1.0 at all, so they become '?'.
std::string xml_escape(const std::string& text) {
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

}  // namespace

std::string site_colour(std::size_t i) { return hex_colour(std::fmod(i * kGoldenAngle, 360.0), 0.55, 0.80); }

bool SvgOptions::is_valid(std::string* why) const {
  const auto fail = [&](const char* reason) {
    if (why) *why = reason;
    return false;
  };
  if (!(width_px > 0) || !std::isfinite(width_px)) return fail("width_px must be positive and finite");
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
  const Box view = view_box(d, o);
  const Box far = detail::far_box(d, view);
  const double scale = o.width_px / view.width();  // pixels per world unit
  const double height_px = view.height() * scale;
  const auto px = [&](double pixels) { return svg_number(pixels / scale); };  // pixels -> world units
  const auto stroke_width = [&](double pixels) {
    return o.non_scaling_stroke ? "stroke-width=\"" + svg_number(pixels) + "\" vector-effect=\"non-scaling-stroke\""
                                : "stroke-width=\"" + px(pixels) + "\"";
  };

  // The viewBox is in world units with y negated, so world point (x, y) sits at (x, -y); the
  // scale(1,-1) group below lets everything inside use world coordinates directly.
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << svg_number(o.width_px) << "\" height=\""
      << svg_number(height_px) << "\" viewBox=\"" << svg_number(view.xmin) << ' ' << svg_number(-view.ymax) << ' '
      << svg_number(view.width()) << ' ' << svg_number(view.height()) << "\">\n"
      << "<title>covmap diagram: " << d.sites.size() << " sites, " << d.nodes.size() << " nodes, " << d.arcs.size()
      << " arcs, " << d.faces.size() << " faces</title>\n";
  if (!o.background.empty()) {
    out << "<rect x=\"" << svg_number(view.xmin) << "\" y=\"" << svg_number(-view.ymax) << "\" width=\""
        << svg_number(view.width()) << "\" height=\"" << svg_number(view.height()) << "\" fill=\""
        << xml_escape(o.background) << "\"/>\n";
  }
  out << "<g transform=\"scale(1,-1)\">\n";

  if (o.fill_faces && !d.faces.empty()) {
    out << "<g class=\"faces\" fill-rule=\"evenodd\" stroke=\"none\">\n";
    for (const auto& face : d.faces) {
      const bool known = face.site >= 0 && static_cast<std::size_t>(face.site) < d.sites.size();
      const std::string name = known ? xml_escape(d.sites[face.site].id) : "?";
      out << "<path class=\"face" << (face.orphan ? " orphan" : "") << "\" fill=\""
          << (known ? site_colour(face.site) : "#dddddd") << "\" d=\"" << detail::face_path(d, face, far)
          << "\"><title>site " << name << (face.orphan ? " (orphan face)" : "") << "</title></path>\n";
    }
    out << "</g>\n";
  }

  out << "<g class=\"arcs\" fill=\"none\" stroke=\"#333333\" stroke-linecap=\"round\">\n";
  for (std::size_t i = 0; i < d.arcs.size(); ++i) {
    const bool frame = d.arcs[i].frame;
    out << "<path" << (frame ? " class=\"frame\" stroke=\"#000000\" " : " ")
        << stroke_width(frame ? o.frame_width_px : o.arc_width_px) << " d=\"" << detail::arc_path(d, static_cast<int>(i), far)
        << "\"/>\n";
  }
  out << "</g>\n";

  if (o.show_nodes && !d.nodes.empty()) {
    out << "<g class=\"nodes\" fill=\"#333333\">\n";
    for (const auto& n : d.nodes) {
      out << "<circle cx=\"" << svg_number(n.x) << "\" cy=\"" << svg_number(n.y) << "\" r=\"" << px(o.node_radius_px)
          << "\"/>\n";
    }
    out << "</g>\n";
  }

  if (o.show_sites && !d.sites.empty()) {
    double lightest = std::numeric_limits<double>::infinity();
    for (const auto& s : d.sites) lightest = std::min(lightest, s.weight);
    out << "<g class=\"sites\" stroke=\"#ffffff\">\n";
    for (std::size_t i = 0; i < d.sites.size(); ++i) {
      const auto& s = d.sites[i];
      // Area proportional to weight reads naturally; capped so one heavy site cannot hide the map.
      const double grow = lightest > 0 ? std::clamp(std::sqrt(s.weight / lightest), 1.0, 4.0) : 1.0;
      out << "<circle cx=\"" << svg_number(s.x) << "\" cy=\"" << svg_number(s.y) << "\" r=\""
          << px(o.site_radius_px * grow) << "\" fill=\"" << dot_colour(i) << "\" " << stroke_width(1.0) << "><title>" << xml_escape(s.id) << " (weight "
          << svg_number(s.weight) << ")</title></circle>\n";
    }
    out << "</g>\n";
  }
  out << "</g>\n";

  // Labels sit outside the flipped group, or the text would be upside down.
  if (o.show_sites && !d.sites.empty() && d.sites.size() <= o.max_labels) {
    out << "<g class=\"labels\" font-family=\"sans-serif\" font-size=\"" << px(o.font_px)
        << "\" fill=\"#111111\" stroke=\"#ffffff\" stroke-width=\"" << px(o.font_px / 4)
        << "\" paint-order=\"stroke\">\n";
    for (const auto& s : d.sites) {
      out << "<text x=\"" << svg_number(s.x + (o.site_radius_px + 2) / scale) << "\" y=\""
          << svg_number(-s.y - (o.site_radius_px + 2) / scale) << "\">" << xml_escape(s.id) << "</text>\n";
    }
    out << "</g>\n";
  }
  out << "</svg>\n";
}

}  // namespace covmap::report
