// The reference covmap.arcgraph/1 reader (nlohmann's DOM; the source of every error message) and
// parse_diagram_json, which tries the fast path first (io/fast_readers.h). The writer is in
// diagram_json_write.cpp.
#include "io/diagram_json.h"

#include <cmath>

#include "core/round_trip_numbers.h"
#include "io/fast_readers.h"
#include "io/input_error.h"
#include "io/input_limits.h"
#include "io/json_fields.h"
#include "io/polygon_check.h"
#include "io/site_parsers.h"
#include "io/text_util.h"

namespace covmap::io {
namespace {

using detail::FieldError;
using detail::Json;

struct Reader {
  const Json& root;
  const std::string& file;
  bool unlabelled = false;  // an arc graph without sites: arcs' "sites" are optional and ignored
  Diagram diagram;

  const Json& array_member(std::string_view key) {
    const Json& value = detail::member(root, key, "");
    detail::expect_array(value, std::string(key));
    return value;
  }

  void read_nodes() {
    const Json& nodes = array_member("nodes");
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      const std::string at = detail::element_path("nodes", i);
      diagram.nodes.push_back({detail::finite_number(detail::member(nodes[i], "x", at), at + ".x"),
                               detail::finite_number(detail::member(nodes[i], "y", at), at + ".y")});
    }
  }

  Curve read_curve(const Json& arc, const std::string& at, bool& ccw) {
    const Json* circle = detail::optional_member(arc, "circle");
    const Json* line = detail::optional_member(arc, "line");
    if ((circle != nullptr) == (line != nullptr)) {
      throw FieldError(at, circle ? "has both \"circle\" and \"line\"; an arc lies on exactly one curve"
                                  : "needs a \"circle\" or a \"line\"");
    }
    const auto number = [&](const Json& object, const std::string& path, const char* key) {
      return detail::finite_number(detail::member(object, key, path), detail::member_path(path, key));
    };
    if (circle) {
      const std::string cat = at + ".circle";
      Circle c{number(*circle, cat, "cx"), number(*circle, cat, "cy"), number(*circle, cat, "r")};
      if (!(c.r > 0)) throw FieldError(cat + ".r", "radius must be positive (got " + round_trip_number(c.r) + ")");
      ccw = detail::boolean(detail::member(*circle, "ccw", cat), cat + ".ccw");
      return c;
    }
    const std::string lat = at + ".line";
    Line l{number(*line, lat, "x"), number(*line, lat, "y"), number(*line, lat, "dx"), number(*line, lat, "dy")};
    if (l.dx == 0 && l.dy == 0) throw FieldError(lat, "direction (dx, dy) must not be zero");
    ccw = true;  // not meaningful for lines; the default keeps round trips exact
    return l;
  }

  void read_arcs() {
    const Json& arcs = array_member("arcs");
    const std::size_t nodes = diagram.nodes.size(), sites = diagram.sites.size();
    for (std::size_t i = 0; i < arcs.size(); ++i) {
      const std::string at = detail::element_path("arcs", i);
      const Json& a = arcs[i];
      detail::expect_object(a, at);
      Arc arc;
      arc.from = detail::index(detail::member(a, "from", at), at + ".from", nodes, "node", true);
      arc.to = detail::index(detail::member(a, "to", at), at + ".to", nodes, "node", true);
      arc.curve = read_curve(a, at, arc.ccw);
      if (std::holds_alternative<Circle>(arc.curve) && (arc.from == kNone) != (arc.to == kNone)) {
        throw FieldError(at, "a circle arc has both ends or neither (a full circle); only line arcs reach infinity");
      }
      if (unlabelled) {
        if (const Json* frame = detail::optional_member(a, "frame")) arc.frame = detail::boolean(*frame, at + ".frame");
        diagram.arcs.push_back(std::move(arc));
        continue;
      }
      const Json& pair = detail::member(a, "sites", at);
      if (!pair.is_array() || pair.size() != 2) {
        throw FieldError(at + ".sites", "must be [left, right] (got " + detail::describe(pair) + ")");
      }
      arc.left_site = detail::index(pair[0], at + ".sites[0]", sites, "site", true);
      arc.right_site = detail::index(pair[1], at + ".sites[1]", sites, "site", true);
      if (const Json* frame = detail::optional_member(a, "frame")) arc.frame = detail::boolean(*frame, at + ".frame");
      const int named = (arc.left_site != kNone) + (arc.right_site != kNone);
      if (arc.frame && named != 1) {
        throw FieldError(at + ".sites", "a frame arc names the site inside the frame and null outside");
      }
      if (!arc.frame && (named != 2 || arc.left_site == arc.right_site)) {
        throw FieldError(at + ".sites", "a bisector arc separates two different sites (add \"frame\":true for a frame arc)");
      }
      diagram.arcs.push_back(std::move(arc));
    }
  }

  void read_faces() {
    const Json* faces = detail::optional_member(root, "faces");
    if (!faces) return;
    detail::expect_array(*faces, "faces");
    for (std::size_t i = 0; i < faces->size(); ++i) {
      const std::string at = detail::element_path("faces", i);
      const Json& f = (*faces)[i];
      Face face;
      face.site = detail::index(detail::member(f, "site", at), at + ".site", diagram.sites.size(), "site", false);
      face.bounded = detail::boolean(detail::member(f, "bounded", at), at + ".bounded");
      face.orphan = detail::boolean(detail::member(f, "orphan", at), at + ".orphan");
      add_face(diagram, face);
      const Json& cycles = detail::member(f, "boundaries", at);
      const std::string cat = at + ".boundaries";
      detail::expect_array(cycles, cat);
      for (std::size_t c = 0; c < cycles.size(); ++c) {
        const std::string cyc = detail::element_path(cat, c);
        detail::expect_array(cycles[c], cyc);
        if (cycles[c].empty()) throw FieldError(cyc, "a boundary cycle must not be empty");
        std::vector<HalfArc> cycle;
        for (std::size_t k = 0; k < cycles[c].size(); ++k) {
          const std::string step = detail::element_path(cyc, k);
          const Json& h = cycles[c][k];
          if (!h.is_array() || h.size() != 2) throw FieldError(step, "must be [arc, forward] (got " + detail::describe(h) + ")");
          cycle.push_back({detail::index(h[0], step + "[0]", diagram.arcs.size(), "arc", false),
                           detail::boolean(h[1], step + "[1]")});
        }
        add_cycle(diagram, cycle);
      }
    }
  }

  void read_clip() {
    const Json* clip = detail::optional_member(root, "clip");
    if (!clip) return;
    detail::expect_array(*clip, "clip");
    for (std::size_t i = 0; i < clip->size(); ++i) {
      const std::string at = detail::element_path("clip", i);
      const Json& p = (*clip)[i];
      if (!p.is_array() || p.size() != 2) throw FieldError(at, "must be [x, y] (got " + detail::describe(p) + ")");
      diagram.clip.push_back({detail::finite_number(p[0], at + "[0]"), detail::finite_number(p[1], at + "[1]")});
    }
    if (diagram.clip.empty()) return;  // empty means "not clipped"
    if (const auto defect = polygon_defect(diagram.clip)) throw FieldError("clip", *defect);
    if (ring_orientation(diagram.clip) < 0) throw FieldError("clip", "must be counter-clockwise");
  }
};

}  // namespace

namespace detail {

Diagram parse_diagram_json_reference(std::string_view text, const std::string& file, ArcLabels labels) {
  const Json root = detail::parse_json(text, file);
  detail::check_format_tag(root, "covmap.arcgraph/1", file);
  if (labels == ArcLabels::kOptional) {
    const auto sites = root.find("sites");
    const bool carried = sites != root.end() && !(sites->is_array() && sites->empty());
    labels = carried ? ArcLabels::kOptional : ArcLabels::kIgnored;
  }
  Reader reader{root, file, labels == ArcLabels::kIgnored, {}};
  if (labels != ArcLabels::kIgnored) {
    const auto sites = root.find("sites");
    if (sites == root.end()) throw InputError(file, 0, "sites", "missing");
    reader.diagram.sites = detail::sites_from_json(*sites, "sites", file).sites;
  }
  try {
    reader.read_nodes();
    reader.read_arcs();
    if (labels == ArcLabels::kRequired) reader.read_faces();
    reader.read_clip();
  } catch (const FieldError& e) {
    throw InputError(file, 0, e.path, e.message);
  }
  const Diagram& d = reader.diagram;
  if (d.sites.size() > kMaxSites || d.nodes.size() + d.arcs.size() > kMaxGraphItems)
    throw InputError(file, 0, "", std::to_string(d.sites.size()) + " sites, " + std::to_string(d.nodes.size()) +
                                      " nodes and " + std::to_string(d.arcs.size()) + " arcs; covmap takes at most " +
                                      std::to_string(kMaxSites) + " sites and " + std::to_string(kMaxGraphItems) +
                                      " nodes and arcs together (docs/RELIABILITY.md)");
  return std::move(reader.diagram);
}

}  // namespace detail

Diagram parse_diagram_json(std::string_view text, const std::string& file, ArcLabels labels) {
  if (auto fast = detail::parse_diagram_json_fast(text, labels)) return std::move(*fast);
  return detail::parse_diagram_json_reference(text, file, labels);
}

Diagram read_diagram_json(const std::filesystem::path& path, ArcLabels labels) {
  return parse_diagram_json(detail::read_text_file(path), path.string(), labels);
}

}  // namespace covmap::io
