// The scale bar of the SVG pictures (svg.h, svg_layout.h): a round length in the lower left corner.
#include <cmath>
#include <cstdio>
#include <ostream>

#include "report/svg_geometry.h"
#include "report/svg_layout.h"

namespace covmap::report::detail {
namespace {

// The bar's stroke and the white casing under it, in pixels; the end ticks are half an em tall.
constexpr double kBarStrokePx = 1.5;
constexpr double kBarCasingPx = 4.0;

}  // namespace

double round_length(double at_most) {
  double power = std::pow(10.0, std::floor(std::log10(at_most)));
  // log10 may round across a power of ten; settle so that power <= at_most < 10 power.
  if (power > at_most) power /= 10;
  if (10 * power <= at_most) power *= 10;
  for (const double step : {5.0, 2.0}) {
    if (step * power <= at_most) return step * power;
  }
  return power;
}

std::string round_length_text(double length) {
  // Fixed notation with as many decimals as a length below 1 needs (0.02: two), none from 1 up.
  const int decimals = length >= 1 ? 0 : static_cast<int>(std::ceil(-std::log10(length) - 1e-9));
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, length);
  return buffer;
}

void write_scale_bar(std::ostream& out, const Box& view, double scale, double font_px, const std::string& units) {
  const double length = round_length(kScaleBarFraction * view.width());
  // Picture pixels to the file's coordinates (world x, world y negated; see write_svg).
  const double x0 = view.xmin + kScaleBarInsetPx / scale, x1 = x0 + length;
  const double y = -view.ymin - kScaleBarInsetPx / scale;
  const double tick = font_px / 2 / scale;
  const std::string bar = "M" + svg_number(x0) + " " + svg_number(y - tick) + " V" + svg_number(y) + " H" +
                          svg_number(x1) + " V" + svg_number(y - tick);
  // A white casing under the black bar keeps it visible on any face colour.
  out << "<g class=\"scale-bar\" fill=\"none\" stroke-linecap=\"square\">\n"
      << "<path stroke=\"#ffffff\" stroke-width=\"" << svg_number(kBarCasingPx / scale) << "\" d=\"" << bar << "\"/>\n"
      << "<path class=\"scale-bar-line\" stroke=\"#000000\" stroke-width=\"" << svg_number(kBarStrokePx / scale) << "\" d=\""
      << bar << "\" data-length=\"" << svg_number(length) << "\"/>\n"
      << "<text x=\"" << svg_number(x0) << "\" y=\"" << svg_number(y - tick - font_px / 4 / scale)
      << "\" font-family=\"sans-serif\" font-size=\"" << svg_number(font_px / scale) << "\" fill=\"#000000\" stroke=\"#ffffff\" stroke-width=\""
      << svg_number(font_px / 4 / scale) << "\" paint-order=\"stroke\">" << xml_escape(round_length_text(length) + " " + units)
      << "</text>\n</g>\n";
}

}  // namespace covmap::report::detail
