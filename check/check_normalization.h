// Diagrams whose numbers sit near the ends of the double range, checked at a better scale.
//
// The checker squares lengths and divides by weights: coordinates beyond ~1e150 overflow, below
// ~1e-150 (denormal) underflow, and weights of 1e-320 turn every weighted distance into infinity.
// The MWVD does not change when every length, or every weight, is multiplied by one number, and a
// power of two changes no mantissa, so such a diagram is checked scaled by powers of two and the
// report's positions and lengths are scaled back. Everything else is checked as it is.
#pragma once

#include "core/diagram.h"
#include "check/check.h"

namespace covmap::check::detail {

struct Normalization {
  int length_exponent = 0;  // lengths were multiplied by 2^length_exponent
  int weight_exponent = 0;  // weights were multiplied by 2^weight_exponent
  bool needed() const { return length_exponent != 0 || weight_exponent != 0; }
};

// The powers of two that bring the sites' extent and the largest weight near 1, or none when both
// are comfortably inside the range the checks are written for.
Normalization normalization_for(const Diagram& d);

// d with every length (sites, nodes, curves, clip) and every weight scaled.
Diagram normalized(const Diagram& d, const Normalization& n);

// Positions, scale and eps of a report made on the normalized diagram, in the input's units.
void scale_back(CheckReport& report, const Normalization& n);

}  // namespace covmap::check::detail
