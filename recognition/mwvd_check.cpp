// The MWVD check of recognize() (paper 5, §5): a bisector graph need not be the Voronoi diagram of
// its sites (e.g. a missing orphan face). The input is judged against the reconstructed sites, and
// the diagram the engine recomputes from them against the input (mwvd_check.h says how).
#include "recognition/mwvd_check.h"

#include <algorithm>
#include <cmath>

#include "recognition/recognize_stages.h"
#include "recognition/site_spread.h"
#include "voronoi/clip.h"
#include "voronoi/engine.h"

namespace covmap::recognition {

double arc_site_spread(const Arc& arc, Point centre, double scale, Point line_read_at) {
  if (arc.frame || !(scale > 0)) return 1.0;
  return std::max(1.0, mwvd::stated_size(arc, centre, line_read_at) / scale);
}

namespace mwvd {

std::vector<ArcSites> arc_sites(const Diagram& g, const std::vector<int>& face_site) {
  std::vector<ArcSites> out(g.arcs.size());
  for (std::size_t f = 0; f < g.faces.size() && f < face_site.size(); ++f)
    for (const auto cycle : face_cycles(g, static_cast<int>(f)))
      for (const HalfArc& h : cycle) (h.forward ? out[h.arc].left : out[h.arc].right) = face_site[f];
  return out;
}

std::vector<double> site_spreads(const Diagram& g, const std::vector<ArcSites>& labels, std::size_t sites, Point centre,
                                 double scale) {
  // Its best-stated arc fixes a site (site_spread.h).
  std::vector<double> spread(sites, INFINITY);
  for (std::size_t a = 0; a < g.arcs.size(); ++a) {
    if (g.arcs[a].frame) continue;
    const Line* line = std::get_if<Line>(&g.arcs[a].curve);  // the input's numbers: no lever
    const double s = arc_site_spread(g.arcs[a], centre, scale, line ? Point{line->x, line->y} : centre);
    for (int k : {labels[a].left, labels[a].right})
      if (k != kNone) spread[k] = std::min(spread[k], s);
  }
  for (double& s : spread)
    if (!std::isfinite(s)) s = 1.0;
  return spread;
}

}  // namespace mwvd

namespace stages {

void mwvd_check(Reconstruction& out, const InputScale& in, const RecognitionOptions& options) {
  const Diagram& g = out.graph;
  const std::vector<mwvd::ArcSites> labels = mwvd::arc_sites(g, out.face_site);
  const Point centre = in.extent.centre();
  mwvd::Allowance allowance{options.relative_tolerance, in.scale, centre, out.sites,
                            mwvd::site_spreads(g, labels, out.sites.size(), centre, in.scale)};
  for (double sp : allowance.spread) allowance.widest_spread = std::max(allowance.widest_spread, sp);
  const WeightedSiteIndex index(out.sites);
  double smallest_weight = INFINITY;
  for (const Site& s : out.sites) smallest_weight = std::min(smallest_weight, s.weight);
  const mwvd::Sites sites{out.sites, index, smallest_weight};
  std::vector<Difference> differences = mwvd::input_against_sites(g, labels, sites, allowance);
  // The sites must be distinct for a Voronoi diagram; coinciding sites already answer "no".
  try {
    Diagram recomputed = voronoi::build_diagram(out.sites);
    if (in.clipped) recomputed = voronoi::clip_diagram(recomputed, clip_polygon_of(g));
    std::vector<Difference> missing = mwvd::recomputed_against_input(recomputed, g, labels, sites, allowance);
    differences.insert(differences.begin(), missing.begin(), missing.end());
  } catch (const voronoi::InvalidSites& e) {
    differences.insert(differences.begin(), {DifferenceKind::NodeOnlyInA, kNone, 0, 0, e.what()});
  } catch (const voronoi::EngineFailure& e) {
    // The engine refuses to draw these sites (it fails rather than write a diagram its own
    // self-check rejects: integer grids reconstructed to an ulp off). Without the recomputed
    // diagram a missing face cannot be ruled out: the input's own differences still say "no",
    // and none leave the answer unknown, with the reason — never a "no" without evidence.
    if (differences.empty()) {
      out.voronoi = MwvdAnswer::kUnknown;
      out.reason += std::string("; the MWVD check is undecided: the engine could not draw the reconstructed sites (") +
                    e.what() + ")";
      return;
    }
  }
  out.voronoi = differences.empty() ? MwvdAnswer::kYes : MwvdAnswer::kNo;
  out.voronoi_differences = std::move(differences);
}

}  // namespace stages
}  // namespace covmap::recognition
