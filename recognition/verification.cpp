// Verification in recognize(): every arc, independently and in parallel, against the two sites it
// separates: each on its own side, and the two mirror images in it. Every arc is measured, so the
// answer says how many disagree and which are worst, not only the first.
//
// The failure is the failing arc worst against its allowance; once every candidate has failed,
// recognize() names the node nearest the defect instead (disagreeing_node.cpp).
#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/parallel.h"
#include "mobius/bisector_relation.h"
#include "recognition/recognize_stages.h"

namespace covmap::recognition::stages {
namespace {

// Worse: larger against what the tolerance allows it (ties: the lower element index first).
bool larger(const Residual& a, const Residual& b) {
  const double ra = a.amount / a.allowed, rb = b.amount / b.allowed;
  return ra > rb || (ra == rb && a.index < b.index);
}

// One worker's share of the arcs: its worst residuals, how many arcs fail, and its worst failure.
struct ChunkResult {
  std::vector<Residual> worst;
  int failing = 0;
  std::optional<RecognitionFailure> worst_failure;   // measured: off by the most allowances
  double worst_ratio = 0.0;                          // its amount / allowance
  std::optional<RecognitionFailure> first_untraced;  // an arc with one face on both sides
  int unverified = 0;                                // arcs with a side tracing left open
};

void remember(ChunkResult& r, const Residual& x) {
  r.worst.push_back(x);
  if (r.worst.size() > 4 * ResidualSummary::kWorstResiduals) {
    std::nth_element(r.worst.begin(), r.worst.begin() + ResidualSummary::kWorstResiduals, r.worst.end(), larger);
    r.worst.resize(ResidualSummary::kWorstResiduals);
  }
}

// An arc failing by `amount`, `allowed` by the tolerance (0: untraced, kept only when it is the first).
void fail(ChunkResult& r, int arc, int face, mobius::Complex where, double amount, double allowed,
          const std::string& message) {
  ++r.failing;
  const bool untraced = !(allowed > 0);
  const double ratio = untraced ? 0.0 : amount / allowed;
  std::optional<RecognitionFailure>& kept = untraced ? r.first_untraced : r.worst_failure;
  if (kept && (untraced || !(ratio > r.worst_ratio))) return;
  if (!untraced) r.worst_ratio = ratio;
  RecognitionFailure f;
  f.arc = arc;
  f.face = face;
  f.x = where.real();
  f.y = where.imag();
  f.amount = amount;
  f.message = message;
  kept = std::move(f);
}

void verify_chunk(const TracedGraph& t, const LargeVector<FaceSite>& site, std::size_t b, std::size_t e, ChunkResult& r) {
  const Diagram& g = t.g;
  const LargeVector<int>& face_of_half = t.face_of_half;
  for (std::size_t a = b; a < e; ++a) {
    const Arc& arc = g.arcs[a];
    const int left = face_of_half[2 * a], right = face_of_half[2 * a + 1];
    if (arc.frame) continue;
    if (left == kNone || right == kNone) {
      ++r.unverified;  // tracing by geometry left a side open (nearly parallel rays meeting far out)
      continue;
    }
    if (left == right) {
      // One face on both sides: the arc separates no two sites.
      const int v = arc.from != kNone ? arc.from : arc.to;
      const mobius::Complex where = v != kNone ? mobius::Complex(g.nodes[v].x, g.nodes[v].y) : mobius::Complex(0.0, 0.0);
      std::ostringstream msg;
      msg << "arc " << a << " has face " << left << " on both sides";
      fail(r, static_cast<int>(a), left, where, 0.0, 0.0, msg.str());
      continue;
    }
    if (!site[left].assigned || !site[right].assigned) continue;
    const mobius::ArcBisector bis = mobius::arc_bisector(arc, g.nodes, site[left].position);
    // The face on the left must hold its site on that side: inside the disk when the arc runs
    // counter-clockwise, on the left of a line; the face on the right the other side.
    const bool left_is_inside = bis.line || arc.ccw;
    // The arc is taken through its node v; far from the graph (nodes of nearly tangent huge circles
    // lie hundreds of extents out) v and the curve are stated only to `relative` of that distance,
    // and so is the arc's mirror.
    const double stated = t.relative * t.extent.distance_to({bis.v.real(), bis.v.imag()});
    bool failed = false;
    for (const int f : {left, right}) {
      const mobius::Complex p = site[f].position;
      if (mobius::strictly_inside(bis, p) == (left_is_inside == (f == left))) continue;
      const double off = mobius::distance_to(curve_of(arc), p);
      const double allowed = t.tol_at(p) + stated;
      remember(r, {ResidualElement::kArc, static_cast<int>(a), p.real(), p.imag(), off, allowed});
      if (off > allowed && !failed) {
        failed = true;
        std::ostringstream msg;
        msg << "arc " << a << ": the site of face " << f << " lies on the wrong side of it (by " << t.unit * off << ")";
        fail(r, static_cast<int>(a), f, bis.v, off, allowed, msg.str());
      }
    }
    // The mirror residual divided by √|k| (k: the inversion's derivative, |k| = (w_r / w_l)², the
    // partner's weight ratio): the same whichever way the arc is read, so an arc from a heavy to a
    // light site does not amplify the heavy site's error into a false rejection.
    const mobius::WeightedPoint partner = mobius::partner_across(bis, {site[left].position, 1.0});
    const double stretch = partner.weight > 0 && std::isfinite(partner.weight) ? std::sqrt(partner.weight) : 1.0;
    const double off = std::abs(site[right].position - partner.position) / stretch;
    const double allowed = std::max(t.tol_at(partner.position), t.tol_at(site[right].position)) + stated;
    remember(r, {ResidualElement::kArc, static_cast<int>(a), partner.position.real(), partner.position.imag(), off, allowed});
    if (!(off <= allowed) && !failed) {
      std::ostringstream msg;
      msg << "arc " << a << ": the sites of faces " << left << " and " << right
          << " are not mirror images in it (off by " << t.unit * off << ")";
      fail(r, static_cast<int>(a), right, bis.v, off, allowed, msg.str());
    }
  }
}

}  // namespace

void keep_worst(std::vector<Residual> all, ResidualSummary& summary) {
  std::sort(all.begin(), all.end(), larger);
  // One entry per element: its largest residual.
  std::vector<Residual> kept;
  for (const Residual& x : all) {
    if (kept.size() == ResidualSummary::kWorstResiduals) break;
    if (std::none_of(kept.begin(), kept.end(), [&](const Residual& k) { return k.element == x.element && k.index == x.index; }))
      kept.push_back(x);
  }
  summary.worst = std::move(kept);
}

ArcVerification verify_arcs(const TracedGraph& t, const LargeVector<FaceSite>& site) {
  const int workers = worker_count(t.g.arcs.size());
  std::vector<ChunkResult> found(workers);
  parallel_chunks(t.g.arcs.size(), workers, [&](std::size_t b, std::size_t e, int w) { verify_chunk(t, site, b, e, found[w]); });
  ArcVerification out;
  out.residuals.tolerance = t.tol;
  std::vector<Residual> all;
  double worst_ratio = 0.0;
  for (ChunkResult& r : found) {
    out.residuals.arcs_beyond += r.failing;
    out.residuals.arcs_unverified += r.unverified;
    all.insert(all.end(), r.worst.begin(), r.worst.end());
    // The worst failing arc; ties: the earlier chunk, in arc order.
    if (r.worst_failure && (!out.failure || r.worst_ratio > worst_ratio))
      out.failure = std::move(r.worst_failure), worst_ratio = r.worst_ratio;
  }
  // An arc off by a length is the better evidence; untraced arcs only when there is none.
  for (ChunkResult& r : found)
    if (r.first_untraced && !out.failure) out.failure = std::move(r.first_untraced);
  keep_worst(std::move(all), out.residuals);
  if (!out.failure) return out;
  std::string message = std::to_string(out.residuals.arcs_beyond) +
                        " arc(s) disagree with the sites beyond the tolerance; the worst: " + out.failure->message;
  out.failure->arcs_beyond = out.residuals.arcs_beyond;
  out.failure->message = std::move(message);
  return out;
}

}  // namespace covmap::recognition::stages
