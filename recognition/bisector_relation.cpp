#include "recognition/bisector_relation.h"

#include <cmath>

#include "recognition/mobius.h"

namespace covmap::recognition {

WeightedPoint partner_across(const GeneralizedCircle& bisector, const WeightedPoint& site) {
  const SpherePoint image = Mobius::inversion(bisector).apply(site.position);
  WeightedPoint out;
  out.position = image ? *image : Complex(INFINITY, INFINITY);
  if (bisector.is_line()) {
    out.weight = site.weight;
  } else {
    // w_j = w_i · |c - s_j| / r = w_i · r / |c - s_i|.
    const Complex c = *bisector.centre();
    const double r = *bisector.radius();
    out.weight = site.weight * r / std::abs(site.position - c);
  }
  return out;
}

}  // namespace covmap::recognition
