#include "audit/sensor_verdict.h"

namespace covmap::audit {

std::string_view to_string(SensorVerdict v) {
  switch (v) {
    case SensorVerdict::kUnreported: return "unreported";
    case SensorVerdict::kConsistent: return "consistent";
    case SensorVerdict::kInconsistent: return "inconsistent";
    case SensorVerdict::kUndetermined: return "undetermined";
    case SensorVerdict::kNotInMap: return "not_in_map";
    case SensorVerdict::kModelMisfit: return "model_misfit";
  }
  return "unreported";  // unreachable: every enumerator is handled above
}

std::string_view to_string(VerdictBasis b) {
  switch (b) {
    case VerdictBasis::kNone: return "none";
    case VerdictBasis::kBoundaryFit: return "boundary_fit";
    case VerdictBasis::kCell: return "cell";
    case VerdictBasis::kPrediction: return "prediction";
    case VerdictBasis::kModelFit: return "model_fit";
  }
  return "none";  // unreachable: every enumerator is handled above
}

std::optional<SensorVerdict> sensor_verdict_from_string(std::string_view name) {
  for (SensorVerdict v : kAllSensorVerdicts)
    if (to_string(v) == name) return v;
  return std::nullopt;
}

}  // namespace covmap::audit
