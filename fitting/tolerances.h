// Every fixed numerical threshold of the fitting library, in one place. (What a user may set — the
// robust loss and its scale, the iteration limit — lives in RefineOptions with its documentation.)
#pragma once

namespace covmap::fitting::tolerance {

// Boundary residual: the gradient norm |∇f| it divides by is floored at this fraction of its
// largest possible value (1 + w_a/w_b, in the units of residuals.h). On a bisector |∇f| is never
// zero for distinct sites; it vanishes only off the bisector, on the line through both sites and
// outside them, with equal weights — a gross outlier. The floor keeps that residual finite (the
// robust loss then discounts it) and changes the residual of a sample on or near an equal-weight
// bisector only when the sample is farther than ~5e8 site separations from the sites.
inline constexpr double kGradientFloor = 1e-9;

// Solver stopping rules (ceres::Solver::Options). Relative cost change 1e-10 leaves the parameters
// within ~1e-5·√m of their own σ from the optimum (m samples), far below the noise; with exact
// samples the cost falls to rounding level before the test can trigger. The relative step test is
// tighter than Ceres' default (1e-8) so that near-exact data reproduce the sites to ~1e-10 of their
// spread; the gradient test is Ceres' own, max |x − Π(x − g)| in parameter units, and set so it
// never stops a well-posed problem early.
inline constexpr double kFunctionTolerance = 1e-10;
inline constexpr double kParameterTolerance = 1e-12;
inline constexpr double kGradientTolerance = 1e-16;

// Covariance, rank deficiency (fitting/covariance.h). When the sparse QR of the Jacobian reports a
// rank deficiency, J'J (or a site's block of it) is scaled to a unit diagonal and eigen-decomposed;
// eigenvalues below this fraction of the largest span the (near) null space, i.e. parameter
// combinations the data determine no better than 1e-6 of the best-determined one.
inline constexpr double kNullEigenvalue = 1e-12;

// A site whose parameters carry more than this share (squared components, summed over the null
// space) of the null vectors is "undetermined": its uncertainty is reported unavailable and it is
// held fixed while the other sites' covariance is computed. Exactly undetermined parameters have
// shares near 1; eigenvector rounding leaves ~1e-12 on the others.
inline constexpr double kNullSpaceShare = 1e-6;

// The dense eigen-decomposition of the whole J'J is only attempted up to this many free parameters
// (about a second); larger problems rely on the per-site test alone and report the uncertainties
// of sites they cannot clear unavailable.
inline constexpr int kMaxDenseDiagnosisParameters = 1500;

// The estimated noise variance factor is floored here (exact samples give ~1e-30 after rounding):
// the covariance problem divides sample residuals by its square root.
inline constexpr double kMinVarianceFactor = 1e-40;

// How far (in log weight, from its starting value) the refinement may move a weight: 30 is a
// factor of 1e13, far beyond any real pair of sensors, but it stops a diverging start before the
// weight underflows and the residuals turn into NaN.
inline constexpr double kLogWeightExcursion = 30.0;

// A sensor's 3×3 information block (local_uncertainty.h) is singular when its smallest eigenvalue
// is below this fraction of its largest: the sensor is then reported undetermined.
inline constexpr double kLocalInformationConditioning = 1e-12;

}  // namespace covmap::fitting::tolerance
