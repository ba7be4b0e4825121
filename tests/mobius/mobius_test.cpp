// Möbius machinery against closed forms: the Apollonius circle of two weighted sites (the formula
// of docs/NUMERICS.md, 'Apollonius centre', computed here independently), direct point-by-point
// evaluation of compositions, and the defining property of a fixed set.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "mobius/bisector_relation.h"
#include "mobius/mobius.h"

namespace covmap::mobius {
namespace {

struct Apollonius {
  Complex centre;
  double radius;
};

// c = s_i + w_i² (s_j - s_i) / ((w_i - w_j)(w_i + w_j)), r = w_i w_j |s_j - s_i| / |w_i² - w_j²|.
Apollonius apollonius(Complex si, double wi, Complex sj, double wj) {
  const double k = wi * wi / ((wi - wj) * (wi + wj));
  return {si + k * (sj - si), wi * wj * std::abs(sj - si) / std::abs((wi - wj) * (wi + wj))};
}

Complex random_point(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  return {u(rng), u(rng)};
}

TEST(Mobius, InversionInApolloniusCircleSwapsTheSites) {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> w(0.5, 3.0);
  for (int trial = 0; trial < 500; ++trial) {
    const Complex si = random_point(rng), sj = random_point(rng);
    const double wi = w(rng), wj = w(rng);
    if (std::abs(wi - wj) < 1e-3) continue;
    const Apollonius a = apollonius(si, wi, sj, wj);
    const GeneralizedCircle c = GeneralizedCircle::circle(a.centre, a.radius);
    const SpherePoint image = Mobius::inversion(c).apply(si);
    ASSERT_TRUE(image.has_value());
    EXPECT_LT(std::abs(*image - sj), 1e-9 * (1 + a.radius));
    const WeightedPoint p = partner_across(c, {si, wi});
    EXPECT_NEAR(p.weight / wi, wj / wi, 1e-9 * wj / wi);
  }
}

TEST(Mobius, ReflectionInBisectorLineSwapsEqualWeightSites) {
  std::mt19937_64 rng(2);
  for (int trial = 0; trial < 200; ++trial) {
    const Complex si = random_point(rng), sj = random_point(rng);
    const Complex mid = 0.5 * (si + sj), dir = (sj - si) * Complex(0, 1);
    const GeneralizedCircle line = GeneralizedCircle::line(mid, dir);
    const WeightedPoint p = partner_across(line, {si, 2.0});
    EXPECT_LT(std::abs(p.position - sj), 1e-12);
    EXPECT_EQ(p.weight, 2.0);
  }
}

TEST(Mobius, InversionFixesItsCirclePointwiseAndSwapsCentreAndInfinity) {
  const GeneralizedCircle c = GeneralizedCircle::circle({0.3, -0.2}, 1.7);
  const Mobius m = Mobius::inversion(c);
  for (int k = 0; k < 12; ++k) {
    const Complex z = Complex(0.3, -0.2) + std::polar(1.7, 0.5 * k);
    EXPECT_LT(std::abs(*m.apply(z) - z), 1e-12);
  }
  EXPECT_FALSE(m.apply(Complex(0.3, -0.2)).has_value());
  EXPECT_LT(std::abs(*m.apply(SpherePoint{}) - Complex(0.3, -0.2)), 1e-15);
}

Mobius random_map(std::mt19937_64& rng, bool conjugated) {
  return Mobius(random_point(rng), random_point(rng), random_point(rng), random_point(rng),
                conjugated);
}

TEST(Mobius, CompositionInverseAndCircleImagesAgreeWithPointwiseEvaluation) {
  std::mt19937_64 rng(3);
  for (int trial = 0; trial < 300; ++trial) {
    const Mobius f = random_map(rng, trial % 2 == 0), g = random_map(rng, trial % 3 == 0);
    const Complex z = random_point(rng);
    const SpherePoint direct = f.apply(g.apply(z));
    const SpherePoint composed = f.after(g).apply(z);
    ASSERT_TRUE(direct && composed);
    EXPECT_LT(std::abs(*direct - *composed), 1e-9 * (1 + std::abs(*direct)));
    const SpherePoint back = f.inverse().apply(f.apply(z));
    ASSERT_TRUE(back);
    EXPECT_LT(std::abs(*back - z), 1e-8);
    // Points of a circle map onto the image circle (value relative to the form's size).
    const GeneralizedCircle c = GeneralizedCircle::circle(random_point(rng), 0.4 + trial * 1e-3);
    const GeneralizedCircle image = f.apply(c);
    const double scale = std::abs(image.A) + std::abs(image.B) + std::abs(image.C);
    for (int k = 0; k < 6; ++k) {
      const Complex p = *c.centre() + std::polar(*c.radius(), 1.1 * k);
      const SpherePoint q = f.apply(p);
      ASSERT_TRUE(q);
      EXPECT_LT(std::abs(image.value(*q)) / (scale * (1 + std::norm(*q))), 1e-9);
    }
  }
}

// Lemma 5: at a node where the bisectors of three sites meet, the composition of the three
// inversions is an anti-Möbius map whose fixed set is a circle through the node containing s_i.
TEST(Mobius, SolutionCircleOfThreeBisectorsContainsTheSite) {
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> w(0.5, 3.0);
  int tested = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const Complex s[3] = {random_point(rng), random_point(rng), random_point(rng)};
    const double ws[3] = {w(rng), w(rng), w(rng)};
    if (std::abs(ws[0] - ws[1]) < 0.05 || std::abs(ws[1] - ws[2]) < 0.05 ||
        std::abs(ws[0] - ws[2]) < 0.05)
      continue;
    auto bis = [&](int i, int j) {
      const Apollonius a = apollonius(s[i], ws[i], s[j], ws[j]);
      return GeneralizedCircle::circle(a.centre, a.radius);
    };
    // s_i → (across b(i,k)) s_k → (across b(j,k)) s_j → (across b(i,j)) s_i.
    const Mobius h =
        Mobius::inversion(bis(0, 1)).after(Mobius::inversion(bis(1, 2))).after(Mobius::inversion(bis(0, 2)));
    ASSERT_TRUE(h.conjugated());
    // The fixed-point equation is complex; for three bisectors of one node its real and imaginary
    // parts are proportional (one may vanish): a single circle. Both must vanish at s_i.
    const auto forms = h.fixed_set_forms();
    const double norm0 = std::abs(forms[0].A) + std::abs(forms[0].B) + std::abs(forms[0].C);
    const double norm1 = std::abs(forms[1].A) + std::abs(forms[1].B) + std::abs(forms[1].C);
    const double scale = std::max(norm0, norm1);
    ASSERT_GT(scale, 0);
    for (const GeneralizedCircle& f : forms) EXPECT_LT(std::abs(f.value(s[0])) / scale, 1e-8);
    const GeneralizedCircle& circle = norm0 >= norm1 ? forms[0] : forms[1];
    // It is a real circle through s_0 (and, in the paper's normalisation, through the node).
    EXPECT_TRUE(circle.is_line() || circle.radius().has_value());
    ++tested;
  }
  EXPECT_GT(tested, 100);
}

}  // namespace
}  // namespace covmap::mobius
