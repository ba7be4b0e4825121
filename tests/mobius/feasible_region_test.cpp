// feasible_region against a brute-force oracle: a fine grid over the window finds the deepest point
// of the intersection of random generalized disks; the half-space intersection must say "empty"
// exactly when the grid finds no point deeper than its own spacing can hide, and its
// representative must lie inside every disk (checked with plain distances, not the library's).
#include <gtest/gtest.h>


#include <cmath>
#include <random>

#include "mobius/feasible_region.h"

namespace covmap::mobius {
namespace {

struct Disk {
  bool line = false;
  Complex c;     // centre, or a point of the line
  double r = 0;  // radius (circles)
  Complex d;     // direction (lines; the region is on its left)
  bool inside = true;
};

GeneralizedCircle form(const Disk& k) {
  if (k.line) return GeneralizedCircle::line(k.c, k.d);
  GeneralizedCircle g = GeneralizedCircle::circle(k.c, k.r);
  if (!k.inside) g = {-g.A, -g.B, -g.C};
  return g;
}

// Plain geometry, independent of GeneralizedCircle: how deep z is inside the disk.
double depth(const Disk& k, Complex z) {
  if (k.line) {
    const Complex u = k.d / std::abs(k.d);
    return std::imag(std::conj(u) * (z - k.c));  // left of the direction is positive
  }
  const double inside = k.r - std::abs(z - k.c);
  return k.inside ? inside : -inside;
}

double deepest_on_grid(const std::vector<Disk>& disks, int n, Complex* where) {
  double best = -INFINITY;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const Complex z(-1.0 + 2.0 * i / n, -1.0 + 2.0 * j / n);
      double m = 1.0 - std::max(std::abs(z.real()), std::abs(z.imag()));
      for (const Disk& k : disks) m = std::min(m, depth(k, z));
      if (m > best) best = m, *where = z;
    }
  return best;
}

TEST(FeasibleRegion, AgreesWithAGridOracleOnRandomDisks) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0), radius(0.1, 1.2), angle(0.0, 6.283185307179586);
  std::bernoulli_distribution coin(0.5), rare(0.15);
  const int grid = 300;
  const double spacing = 2.0 / grid;
  int nonempty = 0, empty = 0, near_deepest = 0;
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<Disk> disks;
    const int m = 1 + trial % 7;
    for (int k = 0; k < m; ++k) {
      Disk d;
      d.line = rare(rng);
      d.c = Complex(u(rng), u(rng));
      d.r = radius(rng);
      d.d = std::polar(1.0, angle(rng));
      d.inside = coin(rng);
      disks.push_back(d);
    }
    std::vector<GeneralizedCircle> forms;
    for (const Disk& d : disks) forms.push_back(form(d));
    const FeasibleRegion fr = feasible_region(forms, {0.0, 0.0}, 1.0);
    Complex at;
    const double oracle = deepest_on_grid(disks, grid, &at);
    if (oracle > 2 * spacing) {
      EXPECT_FALSE(fr.empty) << "trial " << trial << ": the grid finds depth " << oracle << " at " << at;
    }
    if (!fr.empty) {
      ++nonempty;
      double m = 1.0 - std::max(std::abs(fr.representative.real()), std::abs(fr.representative.imag()));
      for (const Disk& d : disks) m = std::min(m, depth(d, fr.representative));
      EXPECT_GT(m, 0.0) << "trial " << trial << ": the representative is outside a disk";
      EXPECT_NEAR(m, fr.margin, 1e-9) << "trial " << trial;
      // The deepest point (recognition puts a free root's representative at the deepest point of
      // its region): no grid point is deeper by more than the grid's resolution; and never far
      // below.
      EXPECT_GT(m, 0.05 * oracle) << "trial " << trial;
      near_deepest += m >= oracle - 2 * spacing;
    } else {
      ++empty;
      EXPECT_LT(oracle, 2 * spacing) << "trial " << trial;
    }
  }
  EXPECT_GT(nonempty, 50);
  EXPECT_GT(empty, 20);
  EXPECT_EQ(near_deepest, nonempty) << "representatives short of the deepest point by more than the grid's resolution";
}

// Window scaling: the same configuration far from the origin and a million times larger.
TEST(FeasibleRegion, IsScaleAndTranslationInvariant) {
  const Complex offset(3e6, -7e6);
  const double s = 1e6;
  std::vector<GeneralizedCircle> forms{GeneralizedCircle::circle(offset + s * Complex(0.2, 0.1), 0.5 * s),
                                       [&] {
                                         GeneralizedCircle g = GeneralizedCircle::circle(offset + s * Complex(0.4, 0.1), 0.2 * s);
                                         return GeneralizedCircle{-g.A, -g.B, -g.C};
                                       }()};
  const FeasibleRegion fr = feasible_region(forms, offset, s);
  ASSERT_FALSE(fr.empty);
  const Complex z = fr.representative;
  EXPECT_LT(std::abs(z - (offset + s * Complex(0.2, 0.1))), 0.5 * s);
  EXPECT_GT(std::abs(z - (offset + s * Complex(0.4, 0.1))), 0.2 * s);
  EXPECT_GT(fr.margin, 1e-3 * s);
}

TEST(FeasibleRegion, DisjointDisksHaveNoCommonPoint) {
  std::vector<GeneralizedCircle> forms{GeneralizedCircle::circle({-0.5, 0}, 0.3),
                                       GeneralizedCircle::circle({0.5, 0}, 0.3)};
  EXPECT_TRUE(feasible_region(forms, {0, 0}, 1.0).empty);
}

TEST(FeasibleRegion, RejectsADegenerateForm) {
  std::vector<GeneralizedCircle> forms{GeneralizedCircle{0.0, {0.0, 0.0}, 1.0}};
  EXPECT_THROW(feasible_region(forms, {0, 0}, 1.0), std::invalid_argument);
  EXPECT_THROW(feasible_region({}, {0, 0}, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace covmap::mobius
