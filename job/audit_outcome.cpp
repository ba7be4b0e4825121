#include "job/audit_outcome.h"

#include <nlohmann/json.hpp>

#include <stdexcept>

namespace covmap::job {
namespace {

using Json = nlohmann::json;

constexpr const char* kOutcomeFormat = "covmap.audit-outcome/1";

FailureKind failure_kind_from_name(std::string_view name) {
  for (const FailureKind k : {FailureKind::kBadInput, FailureKind::kInternal})
    if (failure_kind_name(k) == name) return k;
  throw std::invalid_argument("unknown failure kind '" + std::string(name) + "'");
}

AuditInputKind input_kind_from_name(std::string_view name) {
  for (const AuditInputKind k : {AuditInputKind::kNone, AuditInputKind::kMap, AuditInputKind::kSensors, AuditInputKind::kRasterTable})
    if (input_kind_name(k) == name) return k;
  throw std::invalid_argument("unknown input '" + std::string(name) + "'");
}

std::string string_member(const Json& j, const char* name) {
  if (!j.contains(name) || !j[name].is_string()) throw std::invalid_argument(std::string(name) + " must be a string");
  return j[name].get<std::string>();
}

}  // namespace

bool operator==(const AuditOutcome& a, const AuditOutcome& b) {
  if (a.done != b.done || a.summary_json != b.summary_json || a.failure.has_value() != b.failure.has_value()) return false;
  if (!a.failure) return true;
  const AuditFailure& x = *a.failure;
  const AuditFailure& y = *b.failure;
  return x.kind == y.kind && x.message == y.message && x.input == y.input && x.item == y.item;
}

std::string_view failure_kind_name(FailureKind kind) {
  switch (kind) {
    case FailureKind::kBadInput: return "bad_input";
    case FailureKind::kInternal: return "internal";
  }
  return "internal";
}

std::string_view input_kind_name(AuditInputKind input) {
  switch (input) {
    case AuditInputKind::kNone: return "";
    case AuditInputKind::kMap: return "map";
    case AuditInputKind::kSensors: return "sensors";
    case AuditInputKind::kRasterTable: return "raster_table";
  }
  return "";
}

AuditOutcome done_outcome(const AuditedMap& audited) {
  AuditOutcome o;
  o.done = true;
  // Canonical text (members sorted), so that the record reads back to an equal outcome.
  o.summary_json = Json::parse(report::verdict_counts_json(audited.counts)).dump();
  return o;
}

AuditOutcome failed_outcome(AuditFailure failure) {
  AuditOutcome o;
  o.failure = std::move(failure);
  return o;
}

std::string outcome_json(const AuditOutcome& o) {
  Json j = {{"format", kOutcomeFormat}, {"status", o.done ? "done" : "failed"}};
  if (o.done) j["summary"] = o.summary_json.empty() ? Json(nullptr) : Json::parse(o.summary_json);
  if (o.failure)
    j["failure"] = {{"kind", failure_kind_name(o.failure->kind)},
                    {"message", o.failure->message},
                    {"input", input_kind_name(o.failure->input)},
                    {"item", o.failure->item}};
  return j.dump(-1, ' ', false, Json::error_handler_t::replace);
}

AuditOutcome outcome_from_json(std::string_view text) {
  const Json j = Json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object() || j.value("format", "") != kOutcomeFormat)
    throw std::invalid_argument(std::string("not a ") + kOutcomeFormat + " record");
  AuditOutcome o;
  const std::string status = string_member(j, "status");
  if (status != "done" && status != "failed") throw std::invalid_argument("status must be done or failed");
  o.done = status == "done";
  if (o.done && j.contains("summary") && !j["summary"].is_null()) o.summary_json = j["summary"].dump();
  if (j.contains("failure")) {
    const Json& f = j["failure"];
    if (!f.is_object()) throw std::invalid_argument("failure must be an object");
    o.failure = AuditFailure{failure_kind_from_name(string_member(f, "kind")), string_member(f, "message"),
                             input_kind_from_name(string_member(f, "input")), string_member(f, "item")};
  }
  return o;
}

}  // namespace covmap::job
