// The verdict on one sensor of an audit: a closed set, so that adding a verdict is a compile error
// wherever it is not handled (reports, counts, exit codes).
#pragma once

#include <optional>
#include <string_view>

namespace covmap::audit {

enum class SensorVerdict {
  kUnreported,    // the map has a cell for it, but it was not reported: nothing to judge
  kConsistent,    // the report agrees with the map within the combined uncertainty
  kInconsistent,  // the map is explained significantly better by the reconstruction (verdict.h)
  kUndetermined,  // reported, but the map does not determine the sensor well enough to judge it
  kNotInMap,      // reported, but no cell of the map names it
  kModelMisfit,   // reported, but the map around it does not follow the model: not judged (model_fit.h)
};

inline constexpr SensorVerdict kAllSensorVerdicts[] = {SensorVerdict::kUnreported, SensorVerdict::kConsistent,
                                                       SensorVerdict::kInconsistent, SensorVerdict::kUndetermined,
                                                       SensorVerdict::kNotInMap, SensorVerdict::kModelMisfit};

// What a verdict rests on: the χ² test of the boundary fit, the sensor's mapped cell
// (audit/cell_evidence.h: where the boundaries do not pin it down), the predicted cell of a sensor
// absent from the map, or the model fit (model_misfit); kNone for unreported sensors and for
// sensors nothing could judge.
enum class VerdictBasis { kNone, kBoundaryFit, kCell, kPrediction, kModelFit };

inline constexpr VerdictBasis kAllVerdictBases[] = {VerdictBasis::kNone, VerdictBasis::kBoundaryFit, VerdictBasis::kCell,
                                                    VerdictBasis::kPrediction, VerdictBasis::kModelFit};

// "none", "boundary_fit", "cell", "prediction", "model_fit" (report.json writes null for "none").
std::string_view to_string(VerdictBasis b);

// The names used in report.json and sensors.geojson: "unreported", "consistent", "inconsistent",
// "undetermined", "not_in_map", "model_misfit". (The reports write null instead of "unreported".)
std::string_view to_string(SensorVerdict v);
// The verdict named `name` (as written by to_string); nullopt for any other text.
std::optional<SensorVerdict> sensor_verdict_from_string(std::string_view name);

}  // namespace covmap::audit
