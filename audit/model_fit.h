// Model fit: how well the multiplicative model explains the map, measured against the
// noise the map itself carries. Internal to the audit library.
//
// Every boundary chain has two fits: its own free circle or line (cleaning, three parameters per
// chain, blind to any model) and the model's bisector of the two refined sensors (three parameters
// per sensor, shared by all its boundaries). The free fit's residuals are the map's own noise:
// staircase, rounding, jitter, whatever a smooth curve cannot follow. Where the map follows the
// model, the model's residuals are of the same size (the model is a special case of free curves
// with fewer parameters); where it does not (per-sensor path-loss exponents, additive offsets,
// terrain), the boundaries are still smooth curves, but no set of sensors draws them all, and the
// model's residuals grow beyond the free ones. The ratio of their mean squares, pooled over a
// sensor's boundaries, is an F-like statistic of nested models: ~1 under the model whatever the
// bin size, jitter or rounding, since both fits see the same noise.
#pragma once

#include <vector>

#include "audit/audit.h"
#include "cleaning/map_cleaning.h"
#include "fitting/refine.h"

namespace covmap::audit::stages {

struct ModelFitResult {
  ModelFit map;                        // the whole map
  std::vector<double> sensor_ratio;    // per map sensor; NaN with fewer than kMisfitMinSamples samples
};

// samples and residuals: the refinement's (residuals in map units, one per sample; empty when the
// refinement did not run, and the fit is then unknown). bin: the map's bin size (its floor of noise).
ModelFitResult model_fit(const cleaning::CleanedMap& cleaned, std::span<const fitting::BoundarySample> samples,
                         std::span<const double> residuals, std::span<const double> sensor_area, double bin,
                         const AuditOptions& options);

// Sets each map sensor's model_fit_ratio and, for a reported sensor above the threshold, the
// verdict model_misfit with its reason (whatever the boundary fit said: where the model does not
// hold, its consistent and inconsistent are both unfounded).
void apply_model_fit(const ModelFitResult& fit, const AuditOptions& options, std::vector<SensorAudit>& sensors);

// The reports against the map (ModelFit (2)): the median χ² tail probability over all sensors the
// boundary fit judged, and per such sensor over its neighbours (sensors sharing a boundary, itself
// excluded: a gross error is a lone outlier among right neighbours, a region the model does not
// draw has most of them off). A sensor whose neighbours' median is below kMisfitPValue becomes
// model_misfit. Then sets fit.misfit_sensors, misfit_area_share and misfit over both statistics.
void apply_report_fit(std::span<const fitting::BoundarySample> samples, std::span<const double> sensor_area,
                      const AuditOptions& options, ModelFit& fit, std::vector<SensorAudit>& sensors);

}  // namespace covmap::audit::stages
