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
// circle or line (beyond the tolerance) is rejected before anything else. The answer names the arc
// and the distance when it fails. Linear in the size of the graph; docs/PERFORMANCE.md has times
// (10^6 faces in about 2 s).
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
  // Relative to the diameter of the graph's nodes: how far a propagated site may be from where an
  // arc says it must be. Exact (double-precision) graphs need ~1e-9; noisy maps use issue 4's
  // tolerant path instead.
  double relative_tolerance = 1e-7;
  // Recompute the MWVD of the reconstructed sites with the engine and compare it with the input
  // (paper 5, §5): a bisector graph need not be the Voronoi diagram (e.g. a missing orphan face).
  bool voronoi_check = true;
  // Relative to the largest entry of a composed 2×2 Möbius matrix: entries smaller than this are
  // zero, when deciding whether going around a node is the identity (no constraint), has one or
  // two fixed points, or fixes a whole circle.
  double matrix_tolerance = 1e-9;
  // Reconstructed weights that agree to this relative amount are made equal: weights reach faces
  // through chains of inversions and pick up rounding there, while equal weights are exactly what
  // turns bisectors into lines (a weight ratio of 1 + 1e-16 is a circle of radius 1e16).
  double weight_snap = 1e-12;
};

struct RecognitionFailure {
  std::string message;
  int arc = kNone;
  int node = kNone;
  int face = kNone;
  double x = 0.0, y = 0.0;  // where
  double amount = 0.0;      // by how much (a length)
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
