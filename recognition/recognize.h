// covmap::recognition::recognize — is an arc graph a weighted bisector graph, and which weighted
// sites drew it? (seed paper 5, §4: degree-3 nodes, Lemmas 3-7.)
//
// Contract (this stage): the input is a planar circular-arc graph (Diagram nodes and arcs; any
// sites in it are not used, only compared with the reconstruction afterwards: input_sites.h). Faces are traced by geometry. When some face has at least three nodes
// of degree three, its site is the intersection of the nodes' solution circles (Lemma 5/6, at
// most two candidates); each candidate is propagated to every face by inversion across the arcs
// (Lemma 1), breadth first, and every arc is verified: the sites it separates must be each
// other's inversion in its circle (mirror image in its line) with the lighter site on the disk
// side. Nodes of any degree constrain the site of a face by the fixed set of the inversions around
// them (§4.4: a circle, at most two points, or nothing); when all constraints are one circle (faces
// with at most two nodes, §4.2) the sites form a family and one member is returned, marked so.
// When no node constrains any site (graphs of disjoint, possibly nested circles and lines, §3, or
// nodes whose inversions compose to the identity) every arc still demands that its two sites lie
// on its two sides; pulled back to one root face through the composed transforms, these demands
// are generalized disks, intersected by half-space intersection in 3D (feasible_region.h). The
// region is returned with a representative point, whose propagation is the reconstruction. Frame
// arcs of clipped maps bound faces but constrain nothing. An arc whose end nodes do not lie on its
// circle or line (beyond the tolerance) is rejected before anything else.
//
// Everything is computed in the graph's own frame (centred, scaled by a power of two), so the
// answer does not depend on where the graph sits or how large it is. After propagation the sites
// are refined by least squares over every arc (Gauss-Newton on the mirror relations) and the
// weights solved by least squares on every arc's log-weight ratio, so errors do not grow along
// the propagation tree. One tolerance, RecognitionOptions::relative_tolerance, governs every
// approximate decision; a graph rounded to d significant digits is accepted with a tolerance of
// ~10·10^-d. The answer counts the arcs and nodes beyond the tolerance and names the worst
// (Reconstruction::residuals), and names the first failure with its distance. Linear in the size
// of the graph per iteration of the solves (at most tolerance::kSolveIterations);
// docs/PERFORMANCE.md has times.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "recognition/compare.h"
#include "recognition/input_sites.h"
#include "mobius/generalized_circle.h"
#include "core/diagram.h"

namespace covmap::recognition {

struct RecognitionOptions {
  // THE tolerance, relative to the graph's extent (the diagonal of its nodes' box, measured in the
  // graph's own frame: centred and scaled, so recognition does not depend on where the graph
  // sits). It governs every approximate decision: how far an arc's end node may be off its curve
  // (the numbers that state a curve are trusted to this fraction of their own size, so a rounded
  // huge circle still passes through its ends), how far a site may be from where an arc says it
  // must be (plus the same fraction of the site's distance from the graph), and, expressed in each
  // node's frame, when a composed Möbius matrix is "proportional", "zero" or "the identity"
  // (tolerance::kMatrixRounding is the floor). Exact (double-precision) graphs need ~1e-9; a graph
  // written with d significant digits needs ~10^(1-d).
  double relative_tolerance = 1e-7;
  // Recompute the MWVD of the reconstructed sites with the engine and compare it with the input
  // (paper 5, §5): a bisector graph need not be the Voronoi diagram (e.g. a missing orphan face).
  // The comparison uses relative_tolerance too.
  bool voronoi_check = true;
  // Reconstructed weights that agree to this relative amount are made equal: weights reach faces
  // through chains of inversions and pick up rounding there, while equal weights are exactly what
  // turns bisectors into lines (a weight ratio of 1 + 1e-16 is a circle of radius 1e16).
  double weight_snap = 1e-12;
};

// One element of the graph and how far it is from agreeing with the reconstruction: an arc whose
// two sites are not mirror images in it (or a site on its wrong side), or a node off one of its
// arcs' curves. Lengths in the graph's coordinates.
enum class ResidualElement { kArc, kNode };
std::string_view to_string(ResidualElement element);
struct Residual {
  ResidualElement element = ResidualElement::kArc;
  int index = kNone;
  double x = 0.0, y = 0.0;  // where
  double amount = 0.0;      // by how much (a length)
  double allowed = 0.0;     // how much the tolerance allows this element (a length; see RecognitionOptions)
};

// Every arc and node measured against the reconstruction (or, when recognition fails, against the
// best attempt): how many exceed the tolerance, and the worst few — nearest to or farthest beyond
// what the tolerance allows them — first.
struct ResidualSummary {
  double tolerance = 0.0;    // the length relative_tolerance stands for in this graph
  int arcs_beyond = 0;       // arcs whose residual exceeds the tolerance
  int nodes_beyond = 0;      // nodes off an arc's curve beyond the tolerance
  // Arcs not measured because tracing the faces by geometry left one of their sides open (nearly
  // parallel rays of near-degenerate inputs meeting far out); an accepted graph says so.
  int arcs_unverified = 0;
  std::vector<Residual> worst;  // at most kWorstResiduals, largest amount / allowed first
  static constexpr std::size_t kWorstResiduals = 5;
};

struct RecognitionFailure {
  std::string message;
  int arc = kNone;
  int node = kNone;
  int face = kNone;
  double x = 0.0, y = 0.0;  // where
  double amount = 0.0;      // by how much (a length)
  // How many arcs and nodes disagree beyond the tolerance (Reconstruction::residuals names the
  // worst); the fields above describe the node nearest the defect when the graph's nodes point at
  // one, else the failing element found (docs/RECOGNITION.md, "Failures name what failed").
  int arcs_beyond = 0;
  int nodes_beyond = 0;
};

// Where the site of one face may lie when the graph does not fix it (paper 5, §3): inside every
// bound (the region where the form is negative). Any point of the region propagates to a valid
// reconstruction; `representative` is the one returned, `margin` its distance to the boundary.
struct SiteRegion {
  int face = kNone;
  std::vector<mobius::GeneralizedCircle> bounds;
  Point representative;
  double margin = 0.0;
};

// Wall-clock seconds of recognize()'s stages, for benchmarks and progress reports.
struct RecognitionTimings {
  double faces = 0.0;        // copying the input and tracing its faces by geometry
  double start = 0.0;        // node constraints of the start face and its candidates
  double propagate = 0.0;    // breadth-first propagation and verification of every candidate
  double sites = 0.0;        // weight snapping and merging of coinciding sites
  double voronoi_check = 0.0;
};

// Is the graph the MWVD of its reconstructed sites (paper 5, §5)? kUnknown: the check was not run,
// or the graph is no bisector graph.
enum class MwvdAnswer { kUnknown, kYes, kNo };
// "unknown", "yes", "no" (covmap.reconstruction/1 and the CLI's summary line).
std::string_view to_string(MwvdAnswer answer);
// The answer named `name` (as written by to_string); nullopt for any other text.
std::optional<MwvdAnswer> mwvd_answer_from_string(std::string_view name);

struct Reconstruction {
  bool bisector_graph = false;
  std::string reason;
  std::vector<Site> sites;  // weights normalised so that the largest is 1
  std::vector<int> face_site;        // per traced face of the input: index into sites
  std::vector<std::vector<Site>> candidates;  // when two solutions survive
  bool unique = true;  // false: the graph fixes the sites only up to a family (see region)
  std::optional<SiteRegion> region;  // set when the root site ranges over a 2D region (§3)
  std::optional<RecognitionFailure> failure;
  // The residual of every arc and node against the returned sites (accepted graphs: all within the
  // tolerance; rejected ones: against the candidate that came closest, when one was propagated).
  ResidualSummary residuals;
  // Whether the graph is the MWVD of the sites, and where the recomputed diagram differs from the
  // input when it is not.
  MwvdAnswer voronoi = MwvdAnswer::kUnknown;
  std::vector<Difference> voronoi_differences;
  // When the input carried sites (and is a bisector graph): do they agree with these (input_sites.h)?
  std::optional<InputSitesComparison> input_sites;
  Diagram graph;  // the input with its faces traced (face_site refers to these)
  RecognitionTimings timings;
};

// Takes the graph by value: callers done with theirs move it in (a graph of 10^6 faces is ~200 MB).
Reconstruction recognize(Diagram graph, const RecognitionOptions& options = {});

}  // namespace covmap::recognition
