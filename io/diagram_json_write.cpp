// write_diagram_json (io/diagram_json.h): the arc graph streamed token by token through JsonOut,
// with no JSON document in memory (issue 16). The layout is the one documented in FORMATS.md: one
// element per line, so a diff shows which arc changed.
#include <cmath>
#include <ostream>
#include <stdexcept>

#include "io/diagram_json.h"
#include "io/diagram_json_write.h"
#include "io/json_fields.h"
#include "io/json_number.h"
#include "io/json_out.h"
#include "io/site_parsers.h"
#include "io/text_util.h"

namespace covmap::io {
namespace {

using detail::JsonOut;

// JSON has no NaN or infinity. The first non-finite number in member order is named with its
// path; paths are only made for it, not for every number written.
void check(double v, const char* array, std::size_t i, const char* member) {
  if (std::isfinite(v)) return;
  throw std::invalid_argument("write_diagram_json: " + detail::element_path(array, i) + member + " is " +
                              detail::format_number(v) + "; JSON cannot represent it");
}

// A string that is not UTF-8 would make the file invalid JSON (the readers refuse such ids, but a
// Diagram can be made in code).
void check_text(const std::string& text, std::size_t i, const char* member) {
  if (detail::valid_json_text(text)) return;
  throw std::invalid_argument("write_diagram_json: " + detail::element_path("sites", i) + member +
                              " is not valid UTF-8; JSON text must be");
}

void check_writable(const Diagram& d) {
  for (std::size_t i = 0; i < d.sites.size(); ++i) {
    check_text(d.sites[i].id, i, ".id");
    check(d.sites[i].x, "sites", i, ".x");
    check(d.sites[i].y, "sites", i, ".y");
    check(d.sites[i].weight, "sites", i, ".weight");
    check_text(d.sites[i].name, i, ".name");
  }
  for (std::size_t i = 0; i < d.nodes.size(); ++i) {
    check(d.nodes[i].x, "nodes", i, ".x");
    check(d.nodes[i].y, "nodes", i, ".y");
  }
  for (std::size_t i = 0; i < d.arcs.size(); ++i) {
    if (const auto* c = std::get_if<Circle>(&d.arcs[i].curve)) {
      check(c->cx, "arcs", i, ".circle.cx");
      check(c->cy, "arcs", i, ".circle.cy");
      check(c->r, "arcs", i, ".circle.r");
    } else {
      const auto& l = std::get<Line>(d.arcs[i].curve);
      check(l.x, "arcs", i, ".line.x");
      check(l.y, "arcs", i, ".line.y");
      check(l.dx, "arcs", i, ".line.dx");
      check(l.dy, "arcs", i, ".line.dy");
    }
  }
  for (std::size_t i = 0; i < d.clip.size(); ++i) {
    check(d.clip[i].x, "clip", i, "[0]");
    check(d.clip[i].y, "clip", i, "[1]");
  }
}

void write_node(JsonOut& out, const Node& n) {
  out.raw("{\"x\":");
  out.number(n.x);
  out.raw(",\"y\":");
  out.number(n.y);
  out.raw("}");
}

void write_arc(JsonOut& out, const Arc& arc) {
  out.raw("{\"from\":");
  out.index_or_null(arc.from);
  out.raw(",\"to\":");
  out.index_or_null(arc.to);
  if (const auto* c = std::get_if<Circle>(&arc.curve)) {
    out.raw(",\"circle\":{\"cx\":");
    out.number(c->cx);
    out.raw(",\"cy\":");
    out.number(c->cy);
    out.raw(",\"r\":");
    out.number(c->r);
    out.raw(arc.ccw ? ",\"ccw\":true}" : ",\"ccw\":false}");
  } else {
    const auto& l = std::get<Line>(arc.curve);
    out.raw(",\"line\":{\"x\":");
    out.number(l.x);
    out.raw(",\"y\":");
    out.number(l.y);
    out.raw(",\"dx\":");
    out.number(l.dx);
    out.raw(",\"dy\":");
    out.number(l.dy);
    out.raw("}");
  }
  out.raw(",\"sites\":[");
  out.index_or_null(arc.left_site);
  out.raw(",");
  out.index_or_null(arc.right_site);
  out.raw(arc.frame ? "],\"frame\":true}" : "]}");
}

void write_face(JsonOut& out, const Diagram& d, const Face& face) {
  out.raw("{\"site\":");
  out.index_or_null(face.site);
  out.raw(face.bounded ? ",\"bounded\":true" : ",\"bounded\":false");
  out.raw(face.orphan ? ",\"orphan\":true" : ",\"orphan\":false");
  out.raw(",\"boundaries\":[");
  bool first_cycle = true;
  for (const auto cycle : face_cycles(d, face)) {
    out.raw(first_cycle ? "[" : ",[");
    first_cycle = false;
    bool first_step = true;
    for (const auto& half : cycle) {
      out.raw(first_step ? "[" : ",[");
      first_step = false;
      out.integer(half.arc);
      out.raw(half.forward ? ",true]" : ",false]");
    }
    out.raw("]");
  }
  out.raw("]}");
}

void write_clip_point(JsonOut& out, const Point& p) {
  out.raw("[");
  out.number(p.x);
  out.raw(",");
  out.number(p.y);
  out.raw("]");
}

// `"name":[` + one element per line + `]`.
template <class Element, class WriteElement>
void write_array(JsonOut& out, std::string_view name, const std::vector<Element>& items, WriteElement&& write,
                 bool last) {
  out.raw("\"");
  out.raw(name);
  out.raw("\":[");
  for (std::size_t i = 0; i < items.size(); ++i) {
    out.raw(i == 0 ? "\n  " : ",\n  ");
    write(items[i]);
  }
  out.raw(items.empty() ? "]" : "\n]");
  out.raw(last ? "\n" : ",\n");
}

// Longest spellings: an int index ("-2147483648") and the member names and punctuation of one
// element of each array, rounded up (the exact layout is in the write_* functions above).
constexpr std::size_t kIndexChars = 11;
constexpr std::size_t kNumberChars = kMaxJsonNumberChars;
constexpr std::size_t kElementText = 128;  // punctuation and names of any one element, and its ",\n  "
constexpr std::size_t kDocumentText = 256;  // the format line and the five array openings and closings

std::size_t string_bound(const std::string& text) { return 2 + 6 * text.size(); }

void write_document(JsonOut& out, const Diagram& d) {
  out.raw("{\"format\":\"covmap.arcgraph/1\",\n");
  write_array(out, "sites", d.sites, [&](const Site& s) { detail::write_site_json(out, s); }, false);
  write_array(out, "nodes", d.nodes, [&](const Node& n) { write_node(out, n); }, false);
  write_array(out, "arcs", d.arcs, [&](const Arc& a) { write_arc(out, a); }, false);
  write_array(out, "faces", d.faces, [&](const Face& f) { write_face(out, d, f); }, false);
  write_array(out, "clip", d.clip, [&](const Point& p) { write_clip_point(out, p); }, true);
  out.raw("}\n");
  out.flush();
}

}  // namespace

namespace detail {

std::size_t diagram_json_size_bound(const Diagram& d) {
  std::size_t bytes = kDocumentText;
  for (const Site& s : d.sites) bytes += kElementText + 3 * kNumberChars + string_bound(s.id) + string_bound(s.name);
  bytes += d.nodes.size() * (kElementText + 2 * kNumberChars);
  bytes += d.arcs.size() * (kElementText + 4 * kNumberChars + 4 * kIndexChars);
  // A face: its own text, then per cycle "[", "]" and a comma, per step "[arc,false]" and a comma.
  bytes += d.faces.size() * (kElementText + kIndexChars) + d.cycles.size() * 3 + d.half_arcs.size() * (kIndexChars + 9);
  bytes += d.clip.size() * (kElementText + 2 * kNumberChars);
  return bytes;
}

}  // namespace detail

void write_diagram_json(const Diagram& d, std::ostream& stream) {
  // A non-finite number or a non-UTF-8 string anywhere throws before the first byte is written (the
  // caller's stream then holds nothing half-made).
  check_writable(d);
  JsonOut out(stream);
  write_document(out, d);
}

std::string diagram_json_text(const Diagram& d) {
  check_writable(d);
  std::string text;
  text.reserve(detail::diagram_json_size_bound(d));
  JsonOut out(text);
  write_document(out, d);
  return text;
}

}  // namespace covmap::io
