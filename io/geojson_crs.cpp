#include "io/geojson_crs.h"

#include <algorithm>
#include <cctype>
#include <set>
#include <stdexcept>

namespace covmap::io::detail {
namespace {

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

// WGS84 lon/lat spellings: the last ':'- or '/'-separated token is CRS84 (OGC), or it is 4326 and
// the name mentions EPSG ("EPSG:4326", "urn:ogc:def:crs:EPSG::4326",
// "http://www.opengis.net/def/crs/EPSG/0/4326").
bool names_wgs84(const std::string& name) {
  std::vector<std::string> tokens(1);
  for (const char c : lower(name)) {
    if (c == ':' || c == '/') tokens.emplace_back();
    else tokens.back() += c;
  }
  if (tokens.back() == "crs84") return true;
  return tokens.back() == "4326" && std::find(tokens.begin(), tokens.end(), "epsg") != tokens.end();
}

// The declared system's name: {"type":"name","properties":{"name":N}} gives N,
// {"type":"EPSG","properties":{"code":C}} (pre-2008 drafts) gives "EPSG:C", a link gives
// "link <href>"; anything else is named by its JSON text so a message can quote it.
std::string crs_name(const Json& crs) {
  const Json* type = optional_member(crs, "type");
  const Json* properties = optional_member(crs, "properties");
  if (type && type->is_string() && properties && properties->is_object()) {
    const auto& kind = type->get_ref<const std::string&>();
    if (kind == "name") {
      if (const Json* name = optional_member(*properties, "name"); name && name->is_string()) return name->get<std::string>();
    } else if (kind == "EPSG") {
      if (const Json* code = optional_member(*properties, "code"); code && code->is_number_integer()) return "EPSG:" + code->dump();
    } else if (kind == "link") {
      if (const Json* href = optional_member(*properties, "href"); href && href->is_string()) return "link " + href->get<std::string>();
    }
  }
  std::string text = crs.dump();
  if (text.size() > 80) text = text.substr(0, 77) + "...";
  return text;
}

std::string quoted(const std::string& text) { return "\"" + text + "\""; }

}  // namespace

void CrsDeclarations::add(const Json& object, const std::string& path) {
  const Json* crs = optional_member(object, "crs");
  if (!crs || crs->is_null()) return;
  CrsDeclaration d;
  d.path = member_path(path, "crs");
  d.name = crs_name(*crs);
  d.wgs84 = names_wgs84(d.name);
  declared_.push_back(std::move(d));
}

void CrsDeclarations::add_text(std::string_view crs, const std::string& path) {
  Json owner = Json::object();
  owner["crs"] = Json::parse(crs.begin(), crs.end());
  add(owner, path);
}

std::optional<std::string> CrsDeclarations::foreign_top_level() const {
  if (declared_.empty() || declared_.front().path != "crs" || declared_.front().wgs84) return std::nullopt;
  return declared_.front().name;
}

TopLevelCrs resolve_top_level(const CrsDeclarations& declarations, const CrsResolver& resolve, bool planar) {
  TopLevelCrs out;
  const std::optional<std::string> name = declarations.foreign_top_level();
  if (name && *name == kPlaneCrsName) {
    out.plane = true;
    return out;
  }
  if (!resolve || !name) return out;
  try {
    out.frame = resolve(*name);
  } catch (const std::invalid_argument& e) {
    // With --planar the user vouches for planar coordinates, and a name that is no CRS covmap can
    // use ("covmap:local-plane-metres", a planning tool's own) is only a label.
    if (!planar) out.problems.push_back({0, "crs", e.what()});
    return out;
  }
  if (planar) {
    out.frame = nullptr;
    out.problems.push_back({0, "crs",
                            "declares coordinate reference system " + quoted(*name) +
                                ", and covmap uses it: drop --planar (it is only for data without a CRS)"});
  }
  return out;
}

std::vector<InputProblem> CrsDeclarations::problems(bool any_system) const {
  std::vector<InputProblem> out;
  if (declared_.empty()) return out;
  const CrsDeclaration& first = declared_.front();
  std::set<std::string> reported_foreign;
  std::set<std::string> reported_mixed;
  for (const auto& d : declared_) {
    if (!any_system && !d.wgs84 && reported_foreign.insert(d.key()).second) {
      out.push_back({0, d.path,
                     "declares coordinate reference system " + quoted(d.name) +
                         ", but covmap reads GeoJSON as WGS84 longitude/latitude (RFC 7946); reproject the file to "
                         "WGS84, or use --planar if its coordinates are planar metres"});
    }
    if (d.key() != first.key() && reported_mixed.insert(d.key()).second) {
      out.push_back({0, d.path,
                     "declares coordinate reference system " + quoted(d.name) + " but " + first.path + " declares " +
                         quoted(first.name) + "; one file must use one coordinate reference system"});
    }
  }
  return out;
}

}  // namespace covmap::io::detail
