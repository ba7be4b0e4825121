// disagreeing_node() in recognize(): the node nearest the defect of a graph that is no bisector
// graph, found with no site.
//
// A rejected graph's failure should name the element nearest the defect, not the first failing
// arc: a site propagated through a moved node or a removed arc is wrong everywhere beyond it, so
// the failing arcs spread over the whole graph and the first in arc order can be anywhere. The
// graph's nodes, though, can be tested without any site: every node fixes the sites of its faces
// to a solution set (recognize_stages.h, Constraint), and in a bisector graph the solution sets of
// a face's nodes share the face's site. Per face, the point most of its nodes' sets share is found,
// and the nodes whose sets miss it disagree; the node named is the one that disagrees for the most
// faces (a moved node spoils its own solution sets and those of its arcs' other ends for every
// face around them; a removed arc leaves two nodes of degree two, wrong for both their faces),
// then for the largest share of its faces, then the one with the most disagreeing neighbours (the
// centre of the cluster), then the one that misses by the most allowances. When every face agrees
// in itself (the defect lies between faces) there is none, and verify_arcs names the failing arc
// worst against its allowance.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <tuple>
#include <unordered_map>

#include "core/parallel.h"
#include "recognition/recognize_stages.h"

namespace covmap::recognition::stages {
namespace {

// The solution sets of face f's nodes (each node once; nodes on the frame or of frame arcs say
// nothing about the site).
std::vector<Constraint> face_constraints(const TracedGraph& t, int f) {
  std::vector<Constraint> found;
  for (const auto cycle : face_cycles(t.g, f))
    for (const HalfArc& h : cycle) {
      const Arc& arc = t.g.arcs[h.arc];
      const int v = h.forward ? arc.from : arc.to;  // h leaves v
      if (v == kNone || arc.frame || t.on_frame[v]) continue;
      if (std::any_of(found.begin(), found.end(), [&](const Constraint& c) { return c.node == v; })) continue;
      if (auto c = node_constraint(t, f, half_id(h)); c && !c->any) {
        c->node = v;
        found.push_back(std::move(*c));
      }
    }
  return found;
}

// How far p is from constraint c's solution set, less what the node's own accuracy allows (a node
// far outside the extent is only as accurate as its distance from it; candidates.cpp reads the
// start face's nodes the same way).
double miss(const TracedGraph& t, const Constraint& c, mobius::Complex p) {
  double off = INFINITY;
  if (c.is_circle) off = mobius::distance_to(c.circle, p);
  for (const mobius::Complex& q : c.points) off = std::min(off, std::abs(q - p));
  const Node& at = t.g.nodes[c.node];
  return std::max(0.0, off - t.relative * t.extent.distance_to({at.x, at.y}));
}

// A node's solution set for a face against the point most of the face's nodes' sets share.
struct NodeVerdict {
  int node = kNone;
  int face = kNone;
  double amount = 0.0;  // its miss (a length)
  double ratio = 0.0;   // the miss against what the tolerance allows there (> 1: it disagrees)
};

// Candidate sites of a face are taken from pairs among kConsensusNodes of its nodes spread evenly
// along its boundary, so that the work stays linear in the face's size. A defect spoils a run of
// consecutive nodes of a face: a moved node and the other ends of its arcs, up to five when bending
// its arcs changes how the faces around it are traced (seen in negative_test.cpp); of twelve
// sampled nodes such a run leaves at least seven sound ones (a face of k ≤ 12 nodes: k − 5).
constexpr std::size_t kConsensusNodes = 12;

// The point on which most of face f's node constraints agree (fixed points and pairwise
// intersections of the solution sets tried), and every node's miss of it. Nothing when the face
// has fewer than three nodes or no point has two of them.
void face_verdicts(const TracedGraph& t, int f, std::vector<NodeVerdict>& out) {
  const std::vector<Constraint> cs = face_constraints(t, f);
  if (cs.size() < 3) return;  // two solution sets (nearly) always share a point: no evidence
  std::vector<mobius::Complex> points;
  const std::size_t stride = (cs.size() + kConsensusNodes - 1) / kConsensusNodes;
  for (std::size_t i = 0; i < cs.size(); i += stride) {
    points.insert(points.end(), cs[i].points.begin(), cs[i].points.end());
    for (std::size_t j = i + stride; j < cs.size() && cs[i].is_circle; j += stride)
      if (cs[j].is_circle)
        for (const mobius::Complex& p : mobius::intersect(cs[i].circle, cs[j].circle)) points.push_back(p);
  }
  int best_count = 0;
  double best_total = INFINITY;
  mobius::Complex best;
  for (const mobius::Complex& p : points) {
    if (!std::isfinite(p.real()) || !std::isfinite(p.imag())) continue;
    int count = 0;
    double total = 0.0;
    for (const Constraint& c : cs) {
      const double off = miss(t, c, p);
      count += off <= t.tol_at(p);
      total += off;
    }
    if (count > best_count || (count == best_count && total < best_total))
      best_count = count, best_total = total, best = p;
  }
  if (best_count < 2) return;
  for (const Constraint& c : cs) {
    const double off = miss(t, c, best);
    out.push_back({c.node, f, off, off / t.tol_at(best)});
  }
}

}  // namespace

// The node the graph's own nodes point at, with no site (the file's header says how it is chosen).
// None when every face agrees in itself (the defect lies between faces). Run only when a
// candidate fails; it costs about what that candidate's propagation did.
std::optional<RecognitionFailure> disagreeing_node(const TracedGraph& t) {
  const std::size_t faces = t.g.faces.size();
  const int workers = worker_count(faces);
  std::vector<std::vector<NodeVerdict>> found(workers);
  parallel_chunks(faces, workers, [&](std::size_t b, std::size_t e, int w) {
    for (std::size_t f = b; f < e; ++f)
      if (!t.outside[f]) face_verdicts(t, static_cast<int>(f), found[w]);
  });
  // Per node: the faces it was tested for, those it disagrees for, and its worst miss.
  struct Tally {
    int tested = 0, disagrees = 0;
    int neighbours = 0;  // disagreeing nodes one arc away
    NodeVerdict worst;
  };
  std::unordered_map<int, Tally> tally;
  for (const auto& chunk : found)
    for (const NodeVerdict& x : chunk) {
      Tally& n = tally[x.node];
      ++n.tested;
      if (!(x.ratio > 1.0)) continue;
      ++n.disagrees;
      if (x.ratio > n.worst.ratio || (x.ratio == n.worst.ratio && x.face < n.worst.face)) n.worst = x;
    }
  auto disagrees = [&](int v) {
    const auto it = tally.find(v);
    return it != tally.end() && it->second.disagrees > 0;
  };
  // A moved node spoils its own solution sets and those of its arcs' other ends: the centre of the
  // cluster is the one whose neighbours all disagree.
  for (const Arc& a : t.g.arcs)
    if (a.from != kNone && a.to != kNone && a.from != a.to && disagrees(a.from) && disagrees(a.to))
      ++tally[a.from].neighbours, ++tally[a.to].neighbours;
  // For the most faces (a sound node of a face the defect spoils disagrees for that face only),
  // then for the largest share of its faces, then the centre of the cluster, then the largest
  // miss; ties: the lower index.
  auto rank = [](const Tally& n) {
    const double share = static_cast<double>(n.disagrees) / n.tested;
    return std::tuple(n.disagrees, share, n.neighbours, n.worst.ratio, -n.worst.node);
  };
  const Tally* pick = nullptr;
  for (const auto& [node, n] : tally)
    if (n.disagrees > 0 && (!pick || rank(n) > rank(*pick))) pick = &n;
  if (!pick) return std::nullopt;
  const int pick_votes = pick->disagrees;
  const NodeVerdict& o = pick->worst;
  RecognitionFailure f;
  f.node = o.node;
  f.face = o.face;
  f.x = t.g.nodes[o.node].x;
  f.y = t.g.nodes[o.node].y;
  f.amount = o.amount;
  std::ostringstream msg;
  msg << "node " << o.node << " disagrees with the other nodes of " << pick_votes
      << " face(s) around it: its solution set for face " << o.face << " misses the point they share by "
      << t.unit * o.amount;
  f.message = msg.str();
  return f;
}

}  // namespace covmap::recognition::stages
