#include "job/audit_job.h"

#include <chrono>
#include <filesystem>
#include <new>
#include <utility>

#include "cleaning/map_cleaning.h"
#include "core/readable_numbers.h"
#include "io/atomic_file.h"
#include "io/input_error.h"
#include "io/output_plan.h"
#include "io/plausibility.h"
#include "voronoi/clip.h"
#include "voronoi/engine.h"

namespace covmap::job {
namespace {

using Say = std::function<void(const std::string&)>;

void check_outputs(const AuditRequest& r) {
  io::OutputPlan plan;
  plan.inputs = {r.inputs.map};
  if (!r.inputs.sensors.empty()) plan.inputs.push_back(r.inputs.sensors);
  plan.folder = r.outputs.folder;
  plan.folder_files = report::audit_report_file_names(r.outputs.format);
  plan.force = r.settings.force;
  io::check_output_plan(plan);
}

std::string file_size_words(const std::filesystem::path& file) {
  std::error_code size_error;
  const auto bytes = std::filesystem::file_size(file, size_error);
  return size_error ? std::string("size unknown") : fixed(bytes / 1e6, 1) + " MB";
}

AuditInputsRead read_inputs(const AuditRequest& r, const Say& say) {
  AuditInputsRead in;
  say("reading the map (" + file_size_words(r.inputs.map) + ")");
  in.map = gis::read_any_coverage_map(r.inputs.map, map_read_options(r), &in.source);
  if (!r.inputs.sensors.empty()) {
    gis::SensorReadOptions options = sensor_read_options(r);
    options.sensors.frame = in.map.frame.get();
    // A map without a frame is planar (--planar, or declared in covmap's own plane): so are its sensors.
    options.sensors.planar = options.sensors.planar || !in.map.frame;
    options.sensors.notes = &in.notes;
    in.reported = gis::read_any_sensors(r.inputs.sensors, options);
  }
  if (auto finding = io::lon_lat_looking(in.map)) in.implausible.push_back({AuditInputKind::kMap, *finding});
  if (auto finding = io::sensors_far_outside(in.map, in.reported))
    in.implausible.push_back({AuditInputKind::kSensors, *finding});
  return in;
}

const std::filesystem::path& file_of(const AuditRequest& r, AuditInputKind input) {
  return input == AuditInputKind::kSensors ? r.inputs.sensors : r.inputs.map;
}

// Findings stop the audit unless settings.force; with it they are warnings.
void refuse_implausible(const AuditRequest& r, const AuditInputsRead& in, const AuditJobHooks& hooks) {
  for (const AuditInputsRead::Doubt& doubt : in.implausible) {
    if (!r.settings.force) throw ImplausibleInputError(doubt.input, file_of(r, doubt.input), doubt.finding);
    if (hooks.warning) hooks.warning(file_of(r, doubt.input), doubt.finding);
  }
}

audit::AuditOptions audit_options(const AuditRequest& r, const Say& say) {
  audit::AuditOptions o;
  o.alpha = r.settings.alpha;
  o.cleaning.snap_distance = r.settings.snap;
  o.threads = r.settings.threads;
  o.progress = [say](const std::string& stage, double f) {
    say(stage + ", " + std::to_string(static_cast<int>(100 * f)) + " %");
  };
  return o;
}

void write_reports(const AuditRequest& r, const io::CoverageMap& map, const audit::AuditResult& result,
                   const audit::AuditOptions& options, const Say& say) {
  report::AuditReportContext context{result, map, r.inputs.map.string(), r.inputs.sensors.string(),
                                     r.settings.alpha, r.command_line, &options};
  context.render.basemap_url = r.outputs.basemap_url;
  context.render.full_precision = r.outputs.full_precision;
  io::ReportFolderWriter folder(r.outputs.folder, r.settings.force);
  report::write_audit_reports(context, r.outputs.format, folder, [&](const std::string& file) { say("writing " + file); });
  say("moving the reports into place");
  folder.commit();
}

AuditInputKind input_named(const AuditRequest* r, const std::string& file) {
  if (r == nullptr || file.empty()) return AuditInputKind::kNone;
  if (file == r->inputs.map.string()) return AuditInputKind::kMap;
  if (file == r->inputs.sensors.string()) return AuditInputKind::kSensors;
  if (file == r->inputs.raster_table.string()) return AuditInputKind::kRasterTable;
  return AuditInputKind::kNone;
}

}  // namespace

ImplausibleInputError::ImplausibleInputError(AuditInputKind in, std::filesystem::path f, const std::string& what)
    : std::runtime_error(f.string() + ": " + what), input(in), file(std::move(f)), finding(what) {}

AuditInputsRead read_audit_inputs(const AuditRequest& request) {
  validate(request);
  return read_inputs(request, [](const std::string&) {});
}

AuditedMap run_audit_job(const AuditRequest& r, const AuditJobHooks& hooks) {
  const Say say = hooks.progress ? hooks.progress : [](const std::string&) {};
  validate(r);
  check_outputs(r);
  const auto read_start = std::chrono::steady_clock::now();
  const AuditInputsRead in = read_inputs(r, say);
  if (hooks.note)
    for (const std::string& note : in.notes) hooks.note(note);
  const double read_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - read_start).count();
  refuse_implausible(r, in, hooks);
  say("map read (" + in.source.reader + "): " + std::to_string(in.map.cells.size()) + " cells, " +
      std::to_string(in.map.vertex_count) + " vertices" +
      (in.map.frame ? ", in " + in.map.frame->description() : std::string(", planar")));
  const audit::AuditOptions options = audit_options(r, say);
  AuditedMap audited{audit::audit(in.map.cells, in.reported, options), {}};
  // report.json's stage times start with reading the inputs (the reports' own writing comes after
  // report.json is made, so it is not among them).
  audited.result.timings.insert(audited.result.timings.begin(), {"reading map and sensors", read_seconds});
  audited.result.seconds += read_seconds;
  write_reports(r, in.map, audited.result, options, say);
  audited.counts = report::count_verdicts(audited.result.sensors);
  return audited;
}

AuditFailure describe_current_failure(const AuditRequest* request) {
  try {
    throw;
  } catch (const io::InputError& e) {
    return {FailureKind::kBadInput, e.what(), input_named(request, e.file), e.item()};
  } catch (const ImplausibleInputError& e) {
    return {FailureKind::kBadInput, e.what(), e.input, ""};
  } catch (const InvalidAuditRequest& e) {
    return {FailureKind::kBadInput, e.what(), AuditInputKind::kNone, ""};
  } catch (const io::OutputError& e) {
    return {FailureKind::kBadInput, e.what(), AuditInputKind::kNone, ""};
  } catch (const cleaning::SnapTooSmall& e) {
    return {FailureKind::kBadInput,
            std::string(e.what()) + "; give a larger --snap (about the map's staircase step, in map units)",
            AuditInputKind::kMap, ""};
  } catch (const voronoi::InvalidSites& e) {
    return {FailureKind::kBadInput, e.what(), AuditInputKind::kNone, ""};
  } catch (const voronoi::ClipTooLarge& e) {
    return {FailureKind::kBadInput, e.what(), AuditInputKind::kNone, ""};
  } catch (const audit::MapTooLarge& e) {
    return {FailureKind::kBadInput, e.what(), AuditInputKind::kMap, ""};
  } catch (const std::bad_alloc&) {
    return {FailureKind::kBadInput,
            "out of memory; the input is too large for this machine (see docs/RELIABILITY.md for the limits)",
            AuditInputKind::kNone, ""};
  } catch (const std::exception& e) {
    return {FailureKind::kInternal, std::string("internal error (please report it): ") + e.what(),
            AuditInputKind::kNone, ""};
  }
}

}  // namespace covmap::job
