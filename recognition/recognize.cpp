// recognize(): the driver over its stages (recognize_stages.h names them and the files that hold
// them). Each stage either hands its result to the next or ends recognition with a rejection.
#include "recognition/recognize.h"

#include <chrono>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "recognition/recognize_stages.h"
#include "recognition/site_spread.h"

namespace covmap::recognition {
namespace {

using namespace stages;

// Seconds since the previous lap (or since construction).
class LapTimer {
 public:
  double lap() {
    const Clock::time_point now = Clock::now();
    const double s = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    return s;
  }

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point last_ = Clock::now();
};

// A rejection names the element nearest the defect when the graph's nodes can find it among
// themselves (disagreeing_node.cpp): the start face's closest miss and the worst failing arc can lie
// anywhere beyond a moved node or a removed arc. Run only once every candidate has failed.
Rejection at_the_defect(const TracedGraph& t, Rejection why) {
  std::optional<RecognitionFailure> local = disagreeing_node(t);
  if (!local) return why;
  why.reason += "; nearest the defect: " + local->message;
  if (why.failure) local->arcs_beyond = why.failure->arcs_beyond, local->nodes_beyond = why.failure->nodes_beyond;
  local->message = why.reason;
  why.failure = std::move(local);
  return why;
}

Reconstruction rejected(Reconstruction out, Rejection why) {
  out.bisector_graph = false;
  out.reason = std::move(why.reason);
  out.failure = std::move(why.failure);
  return out;
}

// The first solution is the answer; all of them are candidates when two survive.
void accept(Reconstruction& out, std::vector<Reconstruction>& solutions, bool family,
            const std::optional<SiteRegion>& free_root) {
  out.bisector_graph = true;
  out.unique = !family;
  if (solutions.size() > 1 && !family)
    for (const auto& s : solutions) out.candidates.push_back(s.sites);
  out.sites = std::move(solutions.front().sites);
  out.face_site = std::move(solutions.front().face_site);
  out.region = free_root;
  out.reason = free_root ? "every arc separates mirror-image sites; no node fixes the sites: the site of face " +
                               std::to_string(free_root->face) + " may lie anywhere in a region (see region), this is one choice"
               : family  ? "every arc separates mirror-image sites; the sites are not unique (a "
                           "one-parameter family along a solution circle): this is one of them"
                         : "every arc separates mirror-image sites";
}

// Recognition proper, in the graph's frame: everything from the traced faces to the accepted sites.
Reconstruction recognize_in_frame(Reconstruction out, const InputScale& in, const RecognitionOptions& options,
                                  const GraphFrame& frame, LapTimer& timer) {
  Diagram& g = out.graph;
  voronoi::FaceIndex face_index;
  voronoi::trace_faces(g, voronoi::FaceLabels::kGeometry, &face_index);
  out.timings.faces = timer.lap();
  const FrameMarks marks = frame_marks(g, face_index.face_of_half);
  const TracedGraph traced{g,         face_index.face_of_half, face_index.next_half, marks.on_frame, marks.outside,
                           in.scale,  in.tol,                  in.relative,          frame.unit,     in.extent};

  // The start face and its candidate sites: fixed by its nodes, or (no node fixes any site) free.
  StartFace start = start_face(traced);
  std::optional<SiteRegion> free_root;
  if (start.face < 0 || start.constraints.empty()) {
    auto root = free_root_region(traced, in.extent);
    if (auto* no = std::get_if<Rejection>(&root)) return rejected(std::move(out), std::move(*no));
    free_root = std::move(std::get<SiteRegion>(root));
    start.face = free_root->face;
  }
  Candidates candidates = start_candidates(traced, start.constraints, free_root);
  if (candidates.family_circle) {
    // The members in the middle of the allowed pieces of the circle first; the fixed samples after
    // them only guard against a bound spoiled by rounding along a deep tree.
    std::vector<mobius::Complex> members = family_members(traced, start.face, *candidates.family_circle);
    members.insert(members.end(), candidates.points.begin(), candidates.points.end());
    candidates.points = std::move(members);
  }
  if (candidates.points.empty())
    return rejected(std::move(out), at_the_defect(traced, no_common_point(traced, start.face, start.constraints, candidates.closest)));
  out.timings.start = timer.lap();

  // Each candidate propagated to every face, every arc verified, the survivors' weights solved over
  // all arcs and their sites collected.
  std::vector<Reconstruction> solutions;
  std::optional<ArcVerification> closest;
  PropagationBuffers buffers(static_cast<int>(g.faces.size()));
  const LargeVector<double> spread =
      face_spreads(g, face_index.face_of_half, in.extent.centre(), in.scale);
  for (const mobius::Complex& p : candidates.points) {
    propagate(traced, start.face, p, buffers);
    const SolveOrder order(buffers.queue, g.faces.size());
    solve_positions(traced, order, buffers.site);
    ArcVerification verified = verify_arcs(traced, buffers.site);
    out.timings.propagate += timer.lap();
    if (verified.failure) {
      if (!closest || verified.residuals.arcs_beyond < closest->residuals.arcs_beyond) closest = std::move(verified);
      continue;
    }
    solve_weights(traced, order, buffers.site);
    solutions.push_back(collect_sites(traced, buffers.site, spread, options.weight_snap));
    solutions.back().residuals = std::move(verified.residuals);
    out.timings.sites += timer.lap();
  }
  if (solutions.empty()) {
    std::string reason = closest ? closest->failure->message : "no candidate survived";
    if (closest) out.residuals = std::move(closest->residuals);
    return rejected(std::move(out), at_the_defect(traced, Rejection{std::move(reason), closest ? closest->failure : std::nullopt}));
  }
  out.residuals = solutions.front().residuals;
  accept(out, solutions, candidates.family, free_root);
  if (out.residuals.arcs_unverified > 0)
    out.reason = "every arc between two traced faces separates mirror-image sites; " +
                 std::to_string(out.residuals.arcs_unverified) +
                 " arc(s) not verified: tracing the faces by geometry left a side of them open";
  return out;
}

}  // namespace

std::string_view to_string(ResidualElement element) {
  switch (element) {
    case ResidualElement::kArc: return "arc";
    case ResidualElement::kNode: return "node";
  }
  return "?";
}

Reconstruction recognize(Diagram input, const RecognitionOptions& options) {
  Reconstruction out;
  LapTimer timer;
  out.graph = std::move(input);
  const std::optional<InputLabels> labels = input_labels(out.graph);  // prepare_input takes them off
  const InputScale plane = prepare_input(out.graph, options);
  if (auto off = arc_end_off_curve(out.graph, plane, out.residuals)) return rejected(std::move(out), std::move(*off));

  // Into the graph's frame for the geometry, and back for the answer and the MWVD check.
  const GraphFrame frame = graph_frame(plane.extent, plane.scale);
  SavedGeometry saved = to_frame(out.graph, frame);
  out = recognize_in_frame(std::move(out), scale_in_frame(plane, frame), options, frame, timer);
  to_plane(out.graph, frame, saved);
  to_plane(out, frame);
  if (out.bisector_graph && options.voronoi_check) {
    mwvd_check(out, plane, options);
    out.timings.voronoi_check = timer.lap();
  }
  if (labels) out.input_sites = compare_input_sites(*labels, out, plane.tol, options.relative_tolerance);
  return out;
}

}  // namespace covmap::recognition
