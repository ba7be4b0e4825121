// Model fit: maps drawn by other propagation models (tools/mapgen/propagation_model.h)
// with correctly reported sensors. Oracle: the generator's truth — every report is right (no gross
// errors), so any "inconsistent" is a sensor wrongly blamed, and the map was not drawn by the
// multiplicative model, so the audit must say so. The multiplicative map with gross errors is the
// control: it follows the model, and its gross errors must still be found.
#include <gtest/gtest.h>

#include "generated_map_audit.h"

namespace covmap {
namespace {

using namespace covmap::testing;

mapgen::CoverageMapOptions model_options(mapgen::PropagationModel model, std::uint64_t seed) {
  mapgen::CoverageMapOptions o = base_options(seed);
  o.bin_size_m = 100.0;
  o.errors.gross_fraction = 0.0;
  o.propagation.model = model;
  return o;
}

void expect_misfit_and_nobody_blamed(const audit::AuditResult& r) {
  EXPECT_TRUE(r.model_fit.misfit) << "ratio " << r.model_fit.ratio << ", reports' median p "
                                  << r.model_fit.reports_median_p.value_or(-1.0);
  for (const auto& s : r.sensors) {
    EXPECT_NE(s.verdict, audit::SensorVerdict::kInconsistent) << s.id << ": " << s.reason;
    // audit.h: χ² is set exactly for verdicts of the boundary fit, never left over from one undone.
    EXPECT_EQ(s.chi2.has_value(), s.basis == audit::VerdictBasis::kBoundaryFit) << s.id << ": " << s.reason;
  }
}

TEST(ModelMisfit, PerSensorExponentsAreReportedAndNobodyIsBlamed) {
  // The boundaries are still nearly circles (of other sensors): only the reports reveal the misfit.
  const AuditRun r = run(model_options(mapgen::PropagationModel::kExponents, 3), sensors(60, 3), 3.5);
  ASSERT_TRUE(r.result.model_fit.reports_median_p.has_value());
  EXPECT_LT(*r.result.model_fit.reports_median_p, 0.1);
  expect_misfit_and_nobody_blamed(r.result);
}

TEST(ModelMisfit, ShadowingIsReportedAndNobodyIsBlamed) {
  // Terrain: boundaries no circle follows.
  const AuditRun r = run(model_options(mapgen::PropagationModel::kShadowing, 4), sensors(60, 4), 3.5);
  EXPECT_GT(r.result.model_fit.ratio, 4.0);
  expect_misfit_and_nobody_blamed(r.result);
}

TEST(ModelMisfit, ExcessLossIsReportedAndNobodyIsBlamed) {
  mapgen::CoverageMapOptions o = model_options(mapgen::PropagationModel::kExcessLoss, 5);
  const AuditRun r = run(o, sensors(60, 5), 3.5);
  expect_misfit_and_nobody_blamed(r.result);
}

TEST(ModelMisfit, TheModelsOwnMapWithGrossErrorsIsNoMisfit) {
  mapgen::CoverageMapOptions o = model_options(mapgen::PropagationModel::kMultiplicative, 6);
  o.errors.gross_fraction = 0.2;
  const AuditRun r = run(o, sensors(60, 6), 3.5);
  EXPECT_FALSE(r.result.model_fit.misfit);
  EXPECT_LT(r.result.model_fit.ratio, 2.0);
  int gross = 0, found = 0;
  for (std::size_t k = 0; k < r.generated.truth.size(); ++k) {
    if (r.generated.reported[k].error.gross == mapgen::GrossErrorKind::kNone || r.generated.truth[k].bins < 100) continue;
    ++gross;
    for (const auto& s : r.result.sensors)
      if (s.id == r.generated.truth[k].id) found += s.verdict == audit::SensorVerdict::kInconsistent;
  }
  ASSERT_GE(gross, 5);
  EXPECT_EQ(found, gross);
}

}  // namespace
}  // namespace covmap
