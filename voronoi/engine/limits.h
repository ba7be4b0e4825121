// The engine's supported input range (docs/ENGINE.md, "Supported input"). Sites outside it are
// refused by find_invalid_sites / build_diagram with InvalidSites before any work, each named with
// the limit it breaks. The limits come from the arithmetic, not from tests:
//  - The node construction (engine/triple_node.h) rounds coefficients that are products of up to
//    eight weights and four coordinate differences (e.g. B² ~ w⁸ d⁴), and the lifted predicates'
//    double filter carries an underflow slack of 2⁻¹⁰⁰⁰ per operation (engine/exact_sign.h). After
//    the power-of-two scaling (largest weight and largest |coordinate| in [0.5, 1)), a weight ratio
//    up to 2⁴⁰ and differences down to 2⁻⁶⁰ of the extent (itself at least 2⁻²⁷ of the largest
//    |coordinate|, below) keep every such product above 2⁻⁷⁰⁰: normal doubles, far above the slack.
//  - A light site among heavy ones owns a disk of radius about (its distance to them) × (weight
//    ratio)⁻¹. At a ratio of 2⁴⁰ that is still 2¹² ulps of coordinates of the extent's size, so its
//    circle and which side is which can be written; at 2⁵⁰ it is a few ulps and the checker found
//    the sides swapped.
//  - A node near the sites is written with the ulp of the largest coordinate, 2⁻⁵² of it. For that
//    to stay below 1e-8 of the sites' extent (100 times under the checker's tolerance), the sites
//    may lie at most 2²⁶ ≈ 6.7e7 extents from the origin. (Sites at 1e15 spread over 1e3 would be
//    written with nodes 0.125 apart: the checker would find no arc where the regions meet.)
//  - Every bisector must be wider than kBisectorUlps units in the last place of its own
//    coordinates: a circle whose radius is a few ulps of its centre, or a line between two sites a
//    few ulps apart, cannot be written so that its sides are told apart (two sites one ulp apart
//    with weights 1 and 1.5 give a circle of radius 1.2 ulps, whose sides the checker finds
//    swapped). Which pairs share a bisector is only known after the triangulation, so this limit
//    is enforced after construction, naming both sites, and costs one pass over the arcs.
//  - Near zero, doubles are denormal: the finest step is 2^-1074 whatever the value. For node
//    coordinates to be written to 2^-74 of the extent (far below the self-check's 1e-9), the
//    extent must be at least 2^kMinExtentExponent (sites at multiples of 5e-324 would be written
//    with nodes of one or two bits).
#pragma once

namespace covmap::voronoi::limits {

// Largest weight / smallest weight ≤ 2^kWeightRatioExponent (≈ 1.1e12).
inline constexpr int kWeightRatioExponent = 40;
// max(|x|, |y|) of every site ≤ 2^kOffsetExponent × the diagonal of the sites' bounding box.
inline constexpr int kOffsetExponent = 26;
// Distance between any two sites ≥ 2^-kSeparationExponent × that diagonal (≈ 8.7e-19).
inline constexpr int kSeparationExponent = 60;
// A bisector circle's radius (or, for equal weights, the distance between the two sites) must be at
// least this many units in the last place of the largest of its coordinates: the rounding the
// self-check and the independent checker allow any written number (64 ulps), so a narrower
// bisector could not be judged at all. (Disks of a thousand ulps or so are written and judged
// correctly.)
inline constexpr double kBisectorUlps = 64.0;
// The diagonal of the sites' bounding box must be at least 2^kMinExtentExponent (≈ 9.3e-302).
inline constexpr int kMinExtentExponent = -1000;

}  // namespace covmap::voronoi::limits
