// covmap::job: one audit from its files to its report folder — read the map and sensors, check
// their plausibility, audit, write the reports — as `covmap audit` runs it and as the service's
// job process runs it. The shells only say the outcome their way (exit codes and stderr, or the
// job's state and an HTTP error).
//
// Contract
//  - run_audit_job: validates the request (job/audit_request.h), checks the output plan
//    (io/output_plan.h) before anything is read, reads the inputs, refuses implausible inputs
//    unless settings.force (ImplausibleInputError; with force each finding goes to hooks.warning),
//    audits, and writes the report folder all or nothing. Throws the typed errors of the readers,
//    the output plan and the audit (describe_current_failure() classifies them); anything else is a
//    bug.
//  - read_audit_inputs: the reading and the plausibility findings alone, for a check of uploads
//    before any job exists; it throws what run_audit_job throws while reading.
//  - describe_current_failure: inside a catch block, what the exception being handled means for
//    the user (bad input or output, or a bug), with which input it is about; rethrows anything that
//    is not a std::exception.
#pragma once

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "audit/audit.h"
#include "core/reported_sensor.h"
#include "gis/map_reader.h"
#include "io/coverage_map.h"
#include "job/audit_request.h"
#include "report/audit_report.h"

namespace covmap::job {

// What a job tells its caller while it runs; any of them may be empty.
struct AuditJobHooks {
  std::function<void(const std::string& what)> progress;  // "reading the map (0.2 MB)", "refining, 40 %"
  std::function<void(const std::string& what)> note;      // which reading a file got where there was a choice
  // A plausibility finding passed over because of settings.force.
  std::function<void(const std::filesystem::path& file, const std::string& finding)> warning;
};

struct AuditedMap {
  audit::AuditResult result;
  report::AuditVerdictCounts counts;
};

AuditedMap run_audit_job(const AuditRequest& request, const AuditJobHooks& hooks = {});

// Which of the request's inputs a finding or failure is about.
enum class AuditInputKind { kNone, kMap, kSensors, kRasterTable };

// A plausibility finding that stops the audit without settings.force ("the map's x/y look like
// lon/lat degrees ..."). Each shell says how to force it.
struct ImplausibleInputError : std::runtime_error {
  ImplausibleInputError(AuditInputKind input, std::filesystem::path file, const std::string& finding);
  AuditInputKind input;
  std::filesystem::path file;
  std::string finding;
};

struct AuditInputsRead {
  io::CoverageMap map;
  std::vector<ReportedSensor> reported;
  gis::MapSource source;
  std::vector<std::string> notes;  // which reading the sensors file got, where there was a choice
  struct Doubt {
    AuditInputKind input = AuditInputKind::kMap;
    std::string finding;
  };
  std::vector<Doubt> implausible;  // plausibility findings (io/plausibility.h), none refused here
};

AuditInputsRead read_audit_inputs(const AuditRequest& request);

// What went wrong, for the user: bad input or an output that may not be written (kBadInput), or a
// bug (kInternal).
enum class FailureKind { kBadInput, kInternal };
struct AuditFailure {
  FailureKind kind = FailureKind::kInternal;
  std::string message;  // without any program prefix; names the file and item where known
  AuditInputKind input = AuditInputKind::kNone;  // which input, when the error names one
  std::string item;     // the first problem's item ("features[3] (sensor 'b')"), when known
};
AuditFailure describe_current_failure(const AuditRequest* request = nullptr);

}  // namespace covmap::job
