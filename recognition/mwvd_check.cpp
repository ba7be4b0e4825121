// The MWVD check of recognize() (paper 5, §5): a bisector graph need not be the Voronoi diagram of
// its sites (e.g. a missing orphan face); the diagram of the reconstructed sites is recomputed and
// compared with the input.
#include "recognition/compare.h"
#include "recognition/recognize_stages.h"
#include "voronoi/clip.h"
#include "voronoi/engine.h"

namespace covmap::recognition::stages {

void mwvd_check(Reconstruction& out, bool clipped, const RecognitionOptions& options) {
  const Diagram& g = out.graph;
  // The sites must be distinct for a Voronoi diagram; coinciding sites already answer "no".
  try {
    Diagram recomputed = voronoi::build_diagram(out.sites);
    if (clipped) recomputed = voronoi::clip_diagram(recomputed, clip_polygon_of(g));
    CompareOptions co;
    co.relative_tolerance = options.relative_tolerance;
    const Comparison c = compare_graphs(g, recomputed, co);
    out.voronoi = c.equal() ? MwvdAnswer::kYes : MwvdAnswer::kNo;
    out.voronoi_differences = c.differences;
  } catch (const voronoi::InvalidSites& e) {
    out.voronoi = MwvdAnswer::kNo;
    out.voronoi_differences.push_back({DifferenceKind::NodeOnlyInA, kNone, 0, 0, e.what()});
  }
}

}  // namespace covmap::recognition::stages
