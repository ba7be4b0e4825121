// Pass 3: every arc is on the bisector of its two sites, with the sides the right way round, and no
// third site is closer anywhere along it. Frame arcs: only the ownership of their inner site.
#include <algorithm>
#include <cmath>

#include "check/check_internal.h"

namespace covmap::check::detail {
namespace {

// Compares the arc's curve with the closed form of the bisector when both are of the same kind.
// A circle for equal weights, or a line for unequal ones, is left to the samples: with weights a
// few ulps apart the bisector is a circle so large that a line is an honest rounding of it.
bool curve_matches_bisector(CheckContext& c, int a, const ArcPath& path, const Site& si,
                            const Site& sj) {
  const double ex = sj.x - si.x, ey = sj.y - si.y;
  const double spacing = std::hypot(ex, ey);
  Violation ids;
  ids.arc = a;
  const Point where = path.at(sample_parameters(path, 1, c.region, c.scale).front());
  if (path.circle && si.weight != sj.weight) {
    // Apollonius circle, written as a correction to s_i with the difference of squares factored.
    const double k = si.weight * si.weight / ((si.weight - sj.weight) * (si.weight + sj.weight));
    const double cx = si.x + k * ex, cy = si.y + k * ey;
    const double r = si.weight * sj.weight * spacing /
                     std::abs((si.weight - sj.weight) * (si.weight + sj.weight));
    // Centre and radius of a huge circle are only known relative to its size.
    const double tol = c.eps + c.options.relative_tolerance * r;
    const double dc = std::hypot(path.centre.x - cx, path.centre.y - cy);
    const double dr = std::abs(path.radius - r);
    if (dc > tol || dr > tol) {
      c.add(ViolationKind::ArcNotOnBisector, where,
            strf("arc %d: circle (%.17g, %.17g) r=%.17g is not the bisector of sites %d and %d, "
                 "(%.17g, %.17g) r=%.17g",
                 a, path.centre.x, path.centre.y, path.radius, c.d.arcs[a].left_site,
                 c.d.arcs[a].right_site, cx, cy, r),
            ids);
      return false;
    }
  } else if (!path.circle && si.weight == sj.weight && spacing > 0.0) {
    const Point mid{0.5 * (si.x + sj.x), 0.5 * (si.y + sj.y)};
    const double off =
        std::abs(path.ux * (mid.y - path.origin.y) - path.uy * (mid.x - path.origin.x));
    const double tilt = std::abs(path.ux * ex + path.uy * ey) / spacing;  // cosine to the site axis
    if (off > c.eps || tilt * c.scale > c.eps) {
      c.add(ViolationKind::ArcNotOnBisector, where,
            strf("arc %d: line misses the perpendicular bisector of sites %d and %d (offset %.3g, "
                 "tilt %.3g)",
                 a, c.d.arcs[a].left_site, c.d.arcs[a].right_site, off, tilt),
            ids);
      return false;
    }
  }
  return true;
}

// Reports a site closer than `claimed` at p; true if one was found.
bool report_closer_site(CheckContext& c, int a, Point p, int claimed, int other) {
  bool found = false;
  const Site& own = c.d.sites[claimed];
  const double tol = c.tol(CheckContext::magnitude(p));
  c.owners.for_each_closer(
      p, CheckContext::closer_bound(weighted_distance(p, own)), [&](int k, double) {
        if (k == claimed || k == other) return true;
        const double off = bisector_offset(p, c.d.sites[k], own);
        if (off >= -tol) return true;
        Violation ids;
        ids.arc = a;
        ids.site = k;
        c.add(ViolationKind::ArcSiteCloser, p,
              strf("arc %d: site %d is closer than the arc's site %d (by %.3g as a length)", a, k,
                   claimed, -off),
              ids);
        found = true;
        return false;
      });
  return found;
}

void check_bisector_arc(CheckContext& c, int a, const ArcPath& path) {
  const Arc& arc = c.d.arcs[a];
  const Site& left = c.d.sites[arc.left_site];
  const Site& right = c.d.sites[arc.right_site];
  if (!curve_matches_bisector(c, a, path, left, right)) return;
  bool off_reported = false, side_reported = false, closer_reported = false;
  Violation ids;
  ids.arc = a;
  for (const double s : sample_parameters(path, c.options.samples_per_arc, c.region, c.scale)) {
    const Point p = path.at(s);
    if (!c.in_clip(p)) continue;
    ++c.report.arc_samples_checked;
    const double off = bisector_offset(p, left, right);
    const double tol = c.tol(std::max(CheckContext::magnitude(p), representation_magnitude(path)));
    if (std::abs(off) > tol) {
      if (!off_reported)
        c.add(ViolationKind::ArcNotOnBisector, p,
              strf("arc %d: sample is %.3g off the bisector of sites %d and %d (tolerance %.3g)", a,
                   off, arc.left_site, arc.right_site, tol),
              ids);
      off_reported = true;
      continue;  // side and ownership tests assume the sample is on the bisector
    }
    if (!side_reported) {
      // Probe both sides far enough that an arc within eps of the bisector cannot fool them, but
      // within half a radius so a small circle's probe stays on its own side of the circle.
      double h = c.options.side_probe_factor * tol;
      if (path.circle) h = std::min(h, 0.5 * path.radius);
      const Point t = path.tangent(s);
      const Point to_left{p.x - h * t.y, p.y + h * t.x};
      const Point to_right{p.x + h * t.y, p.y - h * t.x};
      if (!(bisector_offset(to_left, left, right) < 0.0 &&
            bisector_offset(to_right, left, right) > 0.0)) {
        c.add(ViolationKind::ArcSidesSwapped, p,
              strf("arc %d: site %d is not the closer one on the arc's left (site %d is)", a,
                   arc.left_site, arc.right_site),
              ids);
        side_reported = true;
      }
    }
    if (!closer_reported) {
      const bool left_closer = off <= 0.0;
      closer_reported = left_closer ? report_closer_site(c, a, p, arc.left_site, arc.right_site)
                                    : report_closer_site(c, a, p, arc.right_site, arc.left_site);
    }
  }
}

void check_frame_arc(CheckContext& c, int a, const ArcPath& path) {
  const Arc& arc = c.d.arcs[a];
  const int inner = arc.left_site != kNone ? arc.left_site : arc.right_site;
  for (const double s : sample_parameters(path, c.options.samples_per_arc, c.region, c.scale)) {
    const Point p = path.at(s);
    ++c.report.arc_samples_checked;
    if (report_closer_site(c, a, p, inner, kNone)) return;
  }
}

}  // namespace

void check_arcs(CheckContext& c) {
  for (int a = 0; a < static_cast<int>(c.d.arcs.size()); ++a) {
    if (!c.paths[a]) continue;
    if (c.d.arcs[a].frame) {
      check_frame_arc(c, a, *c.paths[a]);
    } else {
      check_bisector_arc(c, a, *c.paths[a]);
    }
  }
}

}  // namespace covmap::check::detail
