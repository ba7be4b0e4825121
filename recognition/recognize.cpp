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

}  // namespace

Reconstruction recognize(Diagram input, const RecognitionOptions& options) {
  Reconstruction out;
  LapTimer timer;
  out.graph = std::move(input);
  Diagram& g = out.graph;
  const std::optional<InputLabels> labels = input_labels(g);  // prepare_input takes them off
  const InputScale in = prepare_input(g, options);
  if (auto off = arc_end_off_curve(g, in.tol)) return rejected(std::move(out), std::move(*off));
  voronoi::FaceIndex face_index;
  voronoi::trace_faces(g, voronoi::FaceLabels::kGeometry, &face_index);
  out.timings.faces = timer.lap();
  const FrameMarks frame = frame_marks(g, face_index.face_of_half);
  const TracedGraph traced{g, face_index.face_of_half, face_index.next_half, frame.on_frame, frame.outside, in.scale, in.tol};

  // The start face and its candidate sites: fixed by its nodes, or (no node fixes any site) free.
  StartFace start = start_face(traced, options.matrix_tolerance);
  std::optional<SiteRegion> free_root;
  if (start.face < 0 || start.constraints.empty()) {
    auto root = free_root_region(traced, in.extent);
    if (auto* no = std::get_if<Rejection>(&root)) return rejected(std::move(out), std::move(*no));
    free_root = std::move(std::get<SiteRegion>(root));
    start.face = free_root->face;
  }
  const Candidates candidates = start_candidates(start.constraints, free_root, in.tol, in.scale, options.matrix_tolerance);
  const LargeVector<char> at_degenerate_node = faces_at_degenerate_nodes(g, face_index);
  if (candidates.points.empty())
    return rejected(std::move(out), no_common_point(g, start.face, start.constraints, candidates.closest));
  out.timings.start = timer.lap();

  // Each candidate propagated to every face, every arc verified, the survivors' sites collected.
  std::vector<Reconstruction> solutions;
  std::optional<RecognitionFailure> last_failure;
  PropagationBuffers buffers(static_cast<int>(g.faces.size()));
  for (const mobius::Complex& p : candidates.points) {
    propagate(traced, at_degenerate_node, options.matrix_tolerance, start.face, p, buffers);
    std::optional<RecognitionFailure> failure = first_arc_failure(traced, buffers.site);
    out.timings.propagate += timer.lap();
    if (failure) {
      last_failure = failure;
      continue;
    }
    solutions.push_back(collect_sites(buffers.site, in.tol, options.weight_snap));
    out.timings.sites += timer.lap();
  }
  if (solutions.empty()) {
    std::string reason = last_failure ? last_failure->message : "no candidate survived";
    return rejected(std::move(out), Rejection{std::move(reason), last_failure});
  }
  accept(out, solutions, candidates.family, free_root);

  if (options.voronoi_check) {
    mwvd_check(out, in, options);
    out.timings.voronoi_check = timer.lap();
  }
  if (labels) out.input_sites = compare_input_sites(*labels, out, in.tol, options.relative_tolerance);
  return out;
}

}  // namespace covmap::recognition
