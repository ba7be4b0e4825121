// The job API: POST/GET/DELETE /v1/audits (service/http_server.h).
#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>

#include "service/api_error.h"
#include "service/audit_request.h"
#include "service/job_files.h"
#include "service/server_state.h"
#include "service/upload_check.h"

namespace covmap::service::detail {
namespace {

using Json = nlohmann::json;

constexpr std::size_t kDefaultListLimit = 100;
constexpr std::size_t kMaxListLimit = 10'000;

Json job_json(const Job& job) {
  Json j = {{"id", job.id},
            {"status", job_status_name(job.status)},
            {"progress", job.progress},
            {"stage", job.stage},
            {"map", job.map_name},
            {"sensors", job.sensors_name.empty() ? Json(nullptr) : Json(job.sensors_name)},
            {"created_ms", job.created_ms},
            {"started_ms", job.started_ms ? Json(job.started_ms) : Json(nullptr)},
            {"finished_ms", job.finished_ms ? Json(job.finished_ms) : Json(nullptr)},
            {"attempts", job.attempts}};
  j["error"] = job.error ? Json{{"code", job.error->code}, {"message", job.error->message}, {"where", job.error->where}}
                         : Json(nullptr);
  const Json summary = job.summary_json.empty() ? Json(nullptr) : Json::parse(job.summary_json, nullptr, false);
  j["summary"] = summary.is_discarded() ? Json(nullptr) : summary;
  Json files = Json::object();
  if (job.status == JobStatus::kDone)
    for (const std::string& name : report_files(parse_audit_request(job.options_json)))
      files[name] = "/v1/audits/" + job.id + "/" + name;
  j["files"] = files;
  return j;
}

std::string dump(const Json& j) { return j.dump(-1, ' ', false, Json::error_handler_t::replace); }

// The job named by the path, or 404. The id is checked before it becomes part of any path.
Job job_of(HttpServer::State& s, const std::string& id) {
  if (!is_valid_job_id(id)) throw ApiError(ErrorCode::kNotFound, "no job '" + id.substr(0, 64) + "': a job id is 32 hex digits", "id");
  std::optional<Job> job = s.store->get(id);
  if (!job) throw ApiError(ErrorCode::kNotFound, "no job " + id, "id");
  return *job;
}

void write_upload(const std::filesystem::path& path, const std::string& content) {
  std::ofstream out(path, std::ios::binary);
  out.write(content.data(), static_cast<std::streamsize>(content.size()));
  if (!out.flush()) throw std::runtime_error("cannot write " + path.string());
}

// One map of a submission as a job not yet stored: its folder written and its inputs checked.
// Throws (having removed the folder) if the inputs are refused; `label` names the map in messages
// of a batch ("map[2]").
Job prepare_job(HttpServer::State& s, const httplib::MultipartFormData& map_part, const httplib::MultipartFormData* sensors,
                const std::string& options_json, job::AuditRequest request, const std::string& label) {
  Job job;
  job.id = new_job_id();
  job.options_json = options_json;
  job.map_name = safe_upload_name(map_part.filename, "map");
  if (sensors) job.sensors_name = safe_upload_name(sensors->filename, "sensors");
  if (job.sensors_name == job.map_name) job.sensors_name = "sensors_" + job.sensors_name;
  const JobFiles files = job_files(s.options.data_dir, job.id);
  try {
    std::filesystem::create_directories(files.input_dir());
    write_upload(files.input_dir() / job.map_name, map_part.content);
    if (sensors) write_upload(files.input_dir() / job.sensors_name, sensors->content);
    request.inputs.map = files.input_dir() / job.map_name;
    if (sensors) request.inputs.sensors = files.input_dir() / job.sensors_name;
    check_audit_inputs(request);
  } catch (ApiError& e) {
    std::error_code ignored;
    std::filesystem::remove_all(files.dir, ignored);
    if (label != "map" && e.where.rfind("map", 0) == 0) e.where = label + " (" + job.map_name + ")" + e.where.substr(3);
    throw;
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove_all(files.dir, ignored);
    throw;
  }
  return job;
}

// POST /v1/audits: one job per map part (several map parts make a batch sharing the sensors and
// options); every map is checked before any job is stored, so a refused batch leaves nothing.
void submit(HttpServer::State& s, const httplib::Request& req, httplib::Response& res) {
  if (!req.is_multipart_form_data())
    throw ApiError(ErrorCode::kBadInput, "send multipart/form-data with the parts map (a file), sensors (a file, optional) and options (JSON, optional)", "body");
  std::vector<const httplib::MultipartFormData*> maps;
  for (auto [at, end] = req.files.equal_range("map"); at != end; ++at) maps.push_back(&at->second);
  if (maps.empty() || std::any_of(maps.begin(), maps.end(), [](const auto* m) { return m->content.empty(); }))
    throw ApiError(ErrorCode::kBadInput, "missing the part map: the coverage map file (several map parts make a batch)", "map");
  if (s.store->count_with_status(JobStatus::kQueued) + maps.size() > s.options.queue_limit)
    throw ApiError(ErrorCode::kQueueFull, std::to_string(s.options.queue_limit) + " jobs may wait at once; try again later", "");
  const std::string options_json = req.has_file("options") ? req.get_file_value("options").content : "";
  const job::AuditRequest request = parse_audit_request(options_json);
  const httplib::MultipartFormData* sensors =
      req.has_file("sensors") && !req.get_file_value("sensors").content.empty() ? &req.files.find("sensors")->second : nullptr;
  std::vector<Job> jobs;
  try {
    for (std::size_t i = 0; i < maps.size(); ++i)
      jobs.push_back(prepare_job(s, *maps[i], sensors, options_json, request,
                                 maps.size() == 1 ? "map" : "map[" + std::to_string(i) + "]"));
    for (Job& job : jobs) {
      job.created_ms = now_ms();
      s.store->insert(job);
    }
  } catch (...) {
    for (const Job& job : jobs) {
      s.store->remove(job.id);
      std::error_code ignored;
      std::filesystem::remove_all(job_files(s.options.data_dir, job.id).dir, ignored);
    }
    throw;
  }
  s.runner->wake();
  if (jobs.size() == 1) {
    res.set_header("Location", "/v1/audits/" + jobs.front().id);
    send_json(res, 202, dump(job_json(jobs.front())));
    return;
  }
  Json batch = Json::array();
  for (const Job& job : jobs) batch.push_back(job_json(job));
  send_json(res, 202, dump(Json{{"jobs", batch}}));
}

std::string content_type(const std::string& file) {
  if (file.ends_with(".html")) return "text/html; charset=utf-8";
  if (file.ends_with(".geojson")) return "application/geo+json";
  if (file.ends_with(".gpkg")) return "application/geopackage+sqlite3";
  return "application/json";
}

void serve_file(HttpServer::State& s, const Job& job, const std::string& file, httplib::Response& res) {
  const std::vector<std::string> names = report_files(parse_audit_request(job.options_json));
  if (std::find(names.begin(), names.end(), file) == names.end())
    throw ApiError(ErrorCode::kNotFound, "a job of this format has no file '" + file.substr(0, 64) + "'", "file");
  if (job.status != JobStatus::kDone)
    throw ApiError(ErrorCode::kNotReady, "the job is " + std::string(job_status_name(job.status)) + ": " + file + " exists only once it is done", "file");
  std::ifstream in(job_files(s.options.data_dir, job.id).output_dir() / file, std::ios::binary);
  if (!in) throw ApiError(ErrorCode::kNotFound, file + " is missing from the job's folder", "file");
  std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  res.status = 200;
  res.set_content(std::move(content), content_type(file).c_str());
}

void remove_job(HttpServer::State& s, const Job& job, httplib::Response& res) {
  if (!is_finished(job.status)) {
    s.store->cancel(job.id, now_ms());
    s.runner->cancel_running(job.id);
    send_json(res, 200, dump(Json{{"id", job.id}, {"status", "cancelled"}}));
    return;
  }
  s.store->remove(job.id);
  std::error_code ignored;
  std::filesystem::remove_all(job_files(s.options.data_dir, job.id).dir, ignored);
  send_json(res, 200, dump(Json{{"id", job.id}, {"deleted", true}}));
}

std::size_t list_limit(const httplib::Request& req) {
  if (!req.has_param("limit")) return kDefaultListLimit;
  const std::string text = req.get_param_value("limit");
  std::size_t limit = 0;
  try {
    std::size_t used = 0;
    limit = std::stoul(text, &used);
    if (used != text.size()) throw std::invalid_argument(text);
  } catch (const std::exception&) {
    throw ApiError(ErrorCode::kBadInput, "limit must be a whole number (got '" + text.substr(0, 32) + "')", "limit");
  }
  if (limit < 1 || limit > kMaxListLimit)
    throw ApiError(ErrorCode::kBadInput, "limit must be in 1-" + std::to_string(kMaxListLimit), "limit");
  return limit;
}

}  // namespace

void add_audit_routes(HttpServer::State& s) {
  add_route(s, "POST", "/v1/audits", guarded([&s](const httplib::Request& req, httplib::Response& res) { submit(s, req, res); }));
  add_route(s, "GET", "/v1/audits", guarded([&s](const httplib::Request& req, httplib::Response& res) {
    Json jobs = Json::array();
    for (const Job& job : s.store->list(list_limit(req))) jobs.push_back(job_json(job));
    send_json(res, 200, dump(Json{{"jobs", jobs}}));
  }));
  add_route(s, "GET", "/v1/audits/{id}", guarded([&s](const httplib::Request& req, httplib::Response& res) {
    send_json(res, 200, dump(job_json(job_of(s, req.matches[1]))));
  }));
  add_route(s, "GET", "/v1/audits/{id}/{file}", guarded([&s](const httplib::Request& req, httplib::Response& res) {
    serve_file(s, job_of(s, req.matches[1]), req.matches[2], res);
  }));
  add_route(s, "DELETE", "/v1/audits/{id}", guarded([&s](const httplib::Request& req, httplib::Response& res) {
    remove_job(s, job_of(s, req.matches[1]), res);
  }));
}

}  // namespace covmap::service::detail
