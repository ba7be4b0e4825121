// Verification in recognize(): every arc, independently and in parallel, against the two sites it
// separates: each on its own side, and the two mirror images in it.
#include <cmath>
#include <sstream>

#include "core/parallel.h"
#include "mobius/bisector_relation.h"
#include "recognition/recognize_stages.h"

namespace covmap::recognition::stages {
namespace {

RecognitionFailure arc_failure(int arc, int face, mobius::Complex where, double amount, std::string message) {
  RecognitionFailure f;
  f.arc = arc;
  f.face = face;
  f.x = where.real();
  f.y = where.imag();
  f.amount = amount;
  f.message = std::move(message);
  return f;
}

// The first failure of arcs [b, e) (in arc order), if any.
std::optional<RecognitionFailure> verify_arcs(const TracedGraph& t, const LargeVector<FaceSite>& site, double tol2,
                                              std::size_t b, std::size_t e) {
  const Diagram& g = t.g;
  const LargeVector<int>& face_of_half = t.face_of_half;
  const double tol = t.tol;
  for (std::size_t a = b; a < e; ++a) {
    const Arc& arc = g.arcs[a];
    const int left = face_of_half[2 * a], right = face_of_half[2 * a + 1];
    if (arc.frame || left == kNone || right == kNone || !site[left].assigned || !site[right].assigned) continue;
    const mobius::ArcBisector bis = mobius::arc_bisector(arc, g.nodes);
    // The face on the left must hold its site on that side: inside the disk when the arc runs
    // counter-clockwise, on the left of a line; the face on the right the other side.
    const bool left_is_inside = bis.line || arc.ccw;
    for (const int f : {left, right}) {
      const mobius::Complex p = site[f].position;
      if (mobius::strictly_inside(bis, p) == (left_is_inside == (f == left))) continue;
      const double off = mobius::distance_to(curve_of(arc), p);
      if (off > tol) {
        std::ostringstream msg;
        msg << "arc " << a << ": the site of face " << f << " lies on the wrong side of it";
        return arc_failure(static_cast<int>(a), f, p, off, msg.str());
      }
    }
    const mobius::WeightedPoint partner = mobius::partner_across(bis, {site[left].position, site[left].weight});
    const double off2 = std::norm(site[right].position - partner.position);
    if (!(off2 <= tol2)) {
      const double off = std::sqrt(off2);
      std::ostringstream msg;
      msg << "arc " << a << ": the sites of faces " << left << " and " << right
          << " are not mirror images in it (off by " << off << ")";
      return arc_failure(static_cast<int>(a), right, partner.position, off, msg.str());
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<RecognitionFailure> first_arc_failure(const TracedGraph& t, const LargeVector<FaceSite>& site) {
  const double tol2 = t.tol * t.tol;
  const Diagram& g = t.g;
  const int workers = worker_count(g.arcs.size());
  std::vector<std::optional<RecognitionFailure>> found(workers);
  parallel_chunks(g.arcs.size(), workers,
                  [&](std::size_t b, std::size_t e, int w) { found[w] = verify_arcs(t, site, tol2, b, e); });
  std::optional<RecognitionFailure> failure;
  for (auto& f : found)
    if (f && !failure) failure = std::move(f);
  return failure;
}

}  // namespace covmap::recognition::stages
