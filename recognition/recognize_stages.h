// The stages of recognize() (recognize.cpp) and the plain data they pass between them. Internal to
// the recognition library: not a public header (recognition/CMakeLists.txt).
//
// In the order recognize() runs them:
//   input labels        input_sites.cpp        a copy of the input's sites and labels, if any
//   input preparation   input_preparation.cpp  clear the input's labels, the tolerance, arc ends
//   graph frame         graph_frame.cpp        the graph centred and scaled, and back
//   frame               frame.cpp              nodes on a clipped map's frame, the face outside it
//   start face          start_face.cpp         the face whose near nodes fix its site best
//   node constraints    node_constraint.cpp    going around a node: the fixed set of the inversions
//   free root           free_root.cpp          no node fixes a site: the root's region (§3)
//   candidates          candidates.cpp         the start face's candidate sites, polished
//   propagation         propagation.cpp        one candidate to every face, breadth first
//   verification        verification.cpp       every arc against the two sites it separates
//   disagreeing node    disagreeing_node.cpp   a failing graph's nodes against each other: the defect
//   position solve      position_solve.cpp     sites refined by least squares over all arcs
//   weight solve        weight_solve.cpp       log-weights by least squares over all arcs
//   site collection     site_collection.cpp    one site per face into the reconstruction's sites
//   MWVD check          mwvd_check.cpp         the input against the sites, the recomputed diagram
//                                              against the input (mwvd_check.h)
//   input sites         input_sites.cpp        the input's own sites against the reconstruction
#pragma once

#include <cmath>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "core/box.h"
#include "core/diagram.h"
#include "core/large_buffer.h"
#include "mobius/generalized_circle.h"
#include "mobius/node_constraint.h"
#include "recognition/recognize.h"
#include "voronoi/faces.h"

namespace covmap::recognition::stages {

// ---- Small geometry shared by the stages (distance_to and intersect: mobius/generalized_circle.h) ----

inline mobius::GeneralizedCircle curve_of(const Arc& a) {
  if (const auto* c = std::get_if<Circle>(&a.curve)) return mobius::GeneralizedCircle::from(*c);
  return mobius::GeneralizedCircle::from(std::get<Line>(a.curve));
}

inline int half_id(const HalfArc& h) { return 2 * h.arc + (h.forward ? 0 : 1); }


// ---- Data passed between the stages ----

// Why recognition ends with "no bisector graph": the reason, and the evidence when there is some.
struct Rejection {
  std::string reason;
  std::optional<RecognitionFailure> failure;
};

// The input's scale: the tolerance of every comparison is relative to its nodes' extent.
struct InputScale {
  bool clipped = false;  // some arc is a frame arc
  Box extent;
  double scale = 0.0;     // the extent's diagonal (a fallback length when the nodes coincide)
  double relative = 0.0;  // RecognitionOptions::relative_tolerance
  double tol = 0.0;       // relative · scale, plus the rounding of the input's coordinates
};

// The graph's own frame, z_frame = (z - origin) / unit (mobius::NodeFrame maps back): centred on
// its extent when that lies far from the origin, and scaled by a power of two to an extent near 1.
// In plane coordinates a graph near 1e7 loses ~14 digits in every generalized-circle form
// (|z|² ~ 1e14 beside radii ~1); in its frame it keeps them.
struct GraphFrame : mobius::NodeFrame {
  bool translated = false;
  mobius::Complex to_frame(mobius::Complex z) const { return (z - origin) / unit; }
};
// The input's node coordinates and curves while the graph is in its frame (only when translated:
// scaling by a power of two is undone exactly).
struct SavedGeometry {
  LargeVector<Node> nodes;
  LargeVector<Curve> curves;
};

// Per node: on the frame of a clipped map; per face: outside the frame (no site).
struct FrameMarks {
  LargeVector<char> on_frame;
  LargeVector<char> outside;
};

// The traced graph as every later stage reads it.
struct TracedGraph {
  const Diagram& g;
  // Per half-arc: its face, and the half-arc after it in the face's boundary cycle.
  const LargeVector<int>& face_of_half;
  const LargeVector<int>& next_half;
  const LargeVector<char>& on_frame;
  const LargeVector<char>& outside;
  double scale = 0.0;
  double tol = 0.0;
  double relative = 0.0;  // RecognitionOptions::relative_tolerance
  double unit = 1.0;      // the graph frame's unit: lengths in messages are multiplied by it
  // The tolerance for a point at p: tol plus `relative` times p's distance from the extent's box
  // (sites may lie far from the nodes — cocircular sites around one node — and are only as
  // accurate as their own size).
  Box extent;
  double tol_at(mobius::Complex p) const { return tol + relative * extent.distance_to({p.real(), p.imag()}); }
};

// The matrix tolerance of a node v whose frame unit is L: the graph's tolerance at v expressed in
// the node's frame (tol_at(v) / L: a node far outside the extent — nearly equal weights put some
// 1e10 out — is only as accurate as its own distance), between tolerance::kMatrixRounding and
// kMatrixCeiling.
double matrix_tolerance(const TracedGraph& t, mobius::Complex v, double L);

// Lemmas 5 and §4.4: going once around node v from face f, across every arc at v and back, maps
// f's site to itself. The composition of the inversions is an anti-Möbius map for an odd number
// of arcs (its fixed set: a circle — the solution circle — or at most two points) and a Möbius
// map for an even number (at most two fixed points, or no constraint when it is the identity).
// A node's constraint on the site of a face (mobius/node_constraint.h), in plane coordinates, with
// the node it comes from. An empty fixed set's gap says how far the node is from being a node of
// a bisector graph.
struct Constraint : mobius::NodeConstraint {
  int node = kNone;
};

// The face whose nodes give the most constraints, each node counted once per face (face -1 when
// none gives any).
struct StartFace {
  int face = -1;
  std::vector<Constraint> constraints;
};

// How far a point is from satisfying every constraint of the start face, and which constraint is
// farthest; the point that came closest is named when none satisfies all.
struct Violation {
  double amount = INFINITY;
  int constraint = -1;
  mobius::Complex at;
};

// The start face's candidate sites.
struct Candidates {
  std::vector<mobius::Complex> points;
  bool family = false;  // the sites form a family (a free root, or coinciding solution circles)
  std::optional<mobius::GeneralizedCircle> family_circle;  // the one solution circle of a family
  Violation closest;    // the candidate that came closest, for the failure when there is none
};

struct FaceSite {
  bool assigned = false;
  mobius::Complex position;
  double weight = 1.0;
};

// Per face, reused by every candidate: its site, whether the propagation reached it, and the
// breadth-first queue.
struct PropagationBuffers {
  explicit PropagationBuffers(int faces);
  LargeVector<FaceSite> site;
  LargeVector<char> reached;
  LargeVector<int> queue;
};

// ---- The stages ----

// Takes the input's labels off (sites, faces, the sites arcs name) and measures its scale.
InputScale prepare_input(Diagram& g, const RecognitionOptions& options);

// Arcs whose ends are not on their curves: malformed, and invisible to the inversions, which take
// each arc through its node (bisector_relation.h). Allowed: `in.tol` plus `in.relative` of the
// numbers that state the curve (their own rounding). The first such arc end, in arc order, with
// how many nodes are off and the worst of them in `residuals`.
std::optional<Rejection> arc_end_off_curve(const Diagram& g, const InputScale& in, ResidualSummary& residuals);

// The frame of a graph with this extent; the graph moved into it (its input geometry saved when
// translated), and back.
GraphFrame graph_frame(const Box& extent, double scale);
SavedGeometry to_frame(Diagram& g, const GraphFrame& frame);
void to_plane(Diagram& g, const GraphFrame& frame, SavedGeometry& saved);
InputScale scale_in_frame(const InputScale& in, const GraphFrame& frame);
// The reconstruction's sites, candidates, region and failure from frame to plane coordinates.
void to_plane(Reconstruction& r, const GraphFrame& frame);

FrameMarks frame_marks(const Diagram& g, const LargeVector<int>& face_of_half);

// The clip polygon of a clipped graph: its own if stated, else the frame arcs followed from node to
// node (counter-clockwise, as frame arcs keep the inside on their left).
std::vector<Point> clip_polygon_of(const Diagram& g);

// The constraint of the node where half-arc h_out (leaving it, on face f's boundary) starts;
// nullopt when the walk around the node meets a frame arc or an open end.
std::optional<Constraint> node_constraint(const TracedGraph& t, int f, int h_out);


StartFace start_face(const TracedGraph& t);

// No node fixes any site (paper 5, §3): the root's site ranges over a region, or nowhere.
std::variant<SiteRegion, Rejection> free_root_region(const TracedGraph& t, const Box& extent);

// Two solution circles that agree within the tolerance: one circle.
bool same_circle(const mobius::GeneralizedCircle& a, const mobius::GeneralizedCircle& b, const TracedGraph& t);

Candidates start_candidates(const TracedGraph& t, const std::vector<Constraint>& constraints,
                            const std::optional<SiteRegion>& free_root);

// Every arc's demand that its two sites lie on its two sides, pulled back to the site of face `root`
// through the inversions of a breadth-first spanning tree (paper 5, §3): generalized disks.
std::vector<mobius::GeneralizedCircle> pulled_back_bounds(const TracedGraph& t, int root);

// A one-parameter family on `circle` (the start face's one solution circle): the members in the
// middle of each piece of the circle inside every pulled-back bound, widest piece first; none when
// no member puts every site on its arcs' sides (family_arc.cpp).
std::vector<mobius::Complex> family_members(const TracedGraph& t, int start, const mobius::GeneralizedCircle& circle);

// The failure when the start face has no candidate.
Rejection no_common_point(const TracedGraph& t, int start, const std::vector<Constraint>& constraints,
                          const Violation& closest);

// Gauss-Newton on the distances to the solution circles among `cs`: an intersection of two
// circles alone can be ill-conditioned when they meet at a shallow angle.
mobius::Complex polish(mobius::Complex p, const std::vector<Constraint>& cs, double tol);


// Candidate p as the site of face `start`, propagated to every face reachable from it.
void propagate(const TracedGraph& t, int start, mobius::Complex p, PropagationBuffers& buffers);

// Every arc against its two sites (on its two sides, mirror images): the residual summary, and as
// the failure the failing arc worst against its allowance, with the counts. (recognize() names the
// node nearest the defect, disagreeing_node, once every candidate has failed.)
struct ArcVerification {
  ResidualSummary residuals;
  std::optional<RecognitionFailure> failure;
};
ArcVerification verify_arcs(const TracedGraph& t, const LargeVector<FaceSite>& site);

// The node nearest the defect of a graph that is no bisector graph, found with no site: the one
// whose solution sets miss the point the other nodes of its faces share (verification.cpp says
// how it is chosen); nullopt when every face agrees in itself.
std::optional<RecognitionFailure> disagreeing_node(const TracedGraph& t);

// Keeps the kWorstResiduals largest of `all` in `summary.worst`, largest first.
void keep_worst(std::vector<Residual> all, ResidualSummary& summary);

// The sites of all assigned faces refined by Gauss-Newton steps of least squares over every arc
// (each arc: its two sites are mirror images in it). A step whose correction exceeds
// tolerance::kLinearisation of the extent is not made.
// Both solves number their unknowns in `order` (the faces in breadth-first order, the propagation's
// queue): neighbouring faces get nearby numbers, and the iterations read memory nearly in order.
struct SolveOrder {
  explicit SolveOrder(const LargeVector<int>& faces_in_order, std::size_t faces);
  const LargeVector<int>& order;  // unknown -> face
  LargeVector<int> rank;          // face -> unknown (kNone: not an unknown)
};
void solve_positions(const TracedGraph& t, const SolveOrder& order, LargeVector<FaceSite>& site);

// The log-weights of all assigned faces by weighted least squares over every arc between two of
// them (each arc states log(w_right / w_left) from its two sites' positions), started from the
// ratios integrated along the breadth-first tree from the (refined) sites, so that errors do not
// accumulate along the tree.
void solve_weights(const TracedGraph& t, const SolveOrder& order, LargeVector<FaceSite>& site);

// The reconstruction from one site per face (sites, face_site). spread: per face, how well its
// arcs state its site (face_spreads, site_spread.h); faces whose sites agree within t.tol share
// one site, and so does an orphan face with the nearest at least as well stated within t.tol times
// its spread (weights within t.relative times it); a site is placed by its best-stated face.
Reconstruction collect_sites(const TracedGraph& t, const LargeVector<FaceSite>& site, const LargeVector<double>& spread,
                             double weight_snap);

// The input's sites and arc labels (input_sites.h), before prepare_input takes them off; nullopt
// when the input carries no sites.
std::optional<InputLabels> input_labels(const Diagram& g);

// The input's sites against the reconstruction of a bisector graph (input_sites.h); tol is a
// length (positions), tau relative (weights).
InputSitesComparison compare_input_sites(const InputLabels& in, const Reconstruction& r, double tol, double tau);

// Sets out.voronoi and out.voronoi_differences: is out.graph the MWVD of out.sites, judged at
// options.relative_tolerance of the input's scale (mwvd_check.h)?
void mwvd_check(Reconstruction& out, const InputScale& in, const RecognitionOptions& options);

}  // namespace covmap::recognition::stages
