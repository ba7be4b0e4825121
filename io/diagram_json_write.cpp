// write_diagram_json (io/diagram_json.h): the arc graph written token by token through JsonOut,
// with no JSON document in memory, in pieces of a few hundred elements rendered on the
// machine's cores and written in order (io/ordered_pieces.h). The layout is the one documented in
// FORMATS.md: one element per line, so a diff shows which arc changed.
#include <algorithm>
#include <cmath>
#include <ostream>
#include <stdexcept>
#include <vector>

#include "core/large_buffer.h"

#include "io/diagram_json.h"
#include "io/diagram_json_write.h"
#include "io/json_fields.h"
#include "core/round_trip_numbers.h"
#include "io/json_out.h"
#include "io/ordered_pieces.h"
#include "io/site_parsers.h"
#include "io/text_util.h"

namespace covmap::io {
namespace {

using detail::JsonOut;
using namespace std::string_view_literals;  // "..."sv: a literal's length without strlen

// JSON has no NaN or infinity. The first non-finite number in member order is named with its
// path; paths are only made for it, not for every number written.
void check(double v, const char* array, std::size_t i, const char* member) {
  if (std::isfinite(v)) return;
  throw std::invalid_argument("write_diagram_json: " + detail::element_path(array, i) + member + " is " +
                              round_trip_number(v) + "; JSON cannot represent it");
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
    out.raw(arc.ccw ? ",\"ccw\":true}"sv : ",\"ccw\":false}"sv);
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
  out.raw(arc.frame ? "],\"frame\":true}"sv : "]}"sv);
}

void write_face(JsonOut& out, const Diagram& d, const Face& face) {
  out.raw("{\"site\":");
  out.index_or_null(face.site);
  out.raw(face.bounded ? ",\"bounded\":true"sv : ",\"bounded\":false"sv);
  out.raw(face.orphan ? ",\"orphan\":true"sv : ",\"orphan\":false"sv);
  out.raw(",\"boundaries\":[");
  bool first_cycle = true;
  for (const auto cycle : face_cycles(d, face)) {
    out.raw(first_cycle ? "["sv : ",["sv);
    first_cycle = false;
    bool first_step = true;
    for (const auto& half : cycle) {
      out.raw(first_step ? "["sv : ",["sv);
      first_step = false;
      out.integer(half.arc);
      out.raw(half.forward ? ",true]"sv : ",false]"sv);
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

// Longest spellings: an int index ("-2147483648") and the member names and punctuation of one
// element of each array, rounded up (the exact layout is in the write_* functions above).
constexpr std::size_t kIndexChars = 11;
constexpr std::size_t kNumberChars = kMaxJsonNumberChars;
constexpr std::size_t kElementText = 128;  // punctuation and names of any one element, and its ",\n  "
constexpr std::size_t kDocumentText = 256;  // the format line and the five array openings and closings

std::size_t string_bound(const std::string& text) { return 2 + 6 * text.size(); }

// The document's five arrays, in file order; each is `"name":[` + one element per line + `]`.
enum class Section { kSites, kNodes, kArcs, kFaces, kClip };
constexpr Section kSections[] = {Section::kSites, Section::kNodes, Section::kArcs, Section::kFaces, Section::kClip};

const char* section_name(Section s) {
  switch (s) {
    case Section::kSites: return "sites";
    case Section::kNodes: return "nodes";
    case Section::kArcs: return "arcs";
    case Section::kFaces: return "faces";
    case Section::kClip: return "clip";
  }
  return "";
}

std::size_t section_size(const Diagram& d, Section s) {
  switch (s) {
    case Section::kSites: return d.sites.size();
    case Section::kNodes: return d.nodes.size();
    case Section::kArcs: return d.arcs.size();
    case Section::kFaces: return d.faces.size();
    case Section::kClip: return d.clip.size();
  }
  return 0;
}

// At least the length of the section's elements as written.
std::size_t section_bound(const Diagram& d, Section s) {
  switch (s) {
    case Section::kSites: {
      std::size_t bytes = 0;
      for (const Site& site : d.sites) bytes += kElementText + 3 * kNumberChars + string_bound(site.id) + string_bound(site.name);
      return bytes;
    }
    case Section::kNodes: return d.nodes.size() * (kElementText + 2 * kNumberChars);
    case Section::kArcs: return d.arcs.size() * (kElementText + 4 * kNumberChars + 4 * kIndexChars);
    // A face: its own text, then per cycle "[", "]" and a comma, per step "[arc,false]" and a comma.
    case Section::kFaces:
      return d.faces.size() * (kElementText + kIndexChars) + d.cycles.size() * 3 + d.half_arcs.size() * (kIndexChars + 9);
    case Section::kClip: return d.clip.size() * (kElementText + 2 * kNumberChars);
  }
  return 0;
}

void write_element(JsonOut& out, const Diagram& d, Section s, std::size_t i) {
  switch (s) {
    case Section::kSites: detail::write_site_json(out, d.sites[i]); return;
    case Section::kNodes: write_node(out, d.nodes[i]); return;
    case Section::kArcs: write_arc(out, d.arcs[i]); return;
    case Section::kFaces: write_face(out, d, d.faces[i]); return;
    case Section::kClip: write_clip_point(out, d.clip[i]); return;
  }
}

// One piece of the text: elements [begin, end) of a section, with the section's opening when it
// starts it (and the document's when it is the first) and its closing when it ends it. The pieces of
// all sections, in order, are the document.
struct Piece {
  Section section = Section::kSites;
  std::size_t begin = 0, end = 0;
};

std::vector<Piece> plan_pieces(const Diagram& d, std::size_t piece_bytes) {
  std::vector<Piece> pieces;
  for (const Section s : kSections) {
    const std::size_t n = section_size(d, s);
    // Elements per piece from the section's average bound; an empty section is one piece too.
    const std::size_t bound = section_bound(d, s);
    const std::size_t per_piece = bound <= piece_bytes ? std::max<std::size_t>(n, 1) : std::max<std::size_t>(1, n * piece_bytes / bound);
    std::size_t begin = 0;
    do {
      const std::size_t end = std::min(n, begin + per_piece);
      pieces.push_back({s, begin, end});
      begin = end;
    } while (begin < n);
  }
  return pieces;
}

void write_piece(JsonOut& out, const Diagram& d, const Piece& piece) {
  const std::size_t n = section_size(d, piece.section);
  if (piece.begin == 0) {
    if (piece.section == Section::kSites) out.raw("{\"format\":\"covmap.arcgraph/1\",\n");
    out.raw("\"");
    out.raw(section_name(piece.section));
    out.raw("\":[");
  }
  for (std::size_t i = piece.begin; i < piece.end; ++i) {
    out.raw(i == 0 ? "\n  "sv : ",\n  "sv);
    write_element(out, d, piece.section, i);
  }
  if (piece.end == n) {
    out.raw(n == 0 ? "]" : "\n]");
    out.raw(piece.section == Section::kClip ? "\n}\n" : ",\n");
  }
  out.flush();
}

}  // namespace

namespace detail {

std::size_t diagram_json_size_bound(const Diagram& d) {
  std::size_t bytes = kDocumentText;
  for (const Section s : kSections) bytes += section_bound(d, s);
  return bytes;
}

void render_diagram_json(const Diagram& d, const DiagramTextPieces& options,
                         const std::function<void(std::string_view)>& emit) {
  const std::vector<Piece> pieces = plan_pieces(d, std::max<std::size_t>(options.piece_bytes, 1));
  OrderedPieces threads;
  threads.threads = options.threads > 0 ? options.threads : rendering_threads(diagram_json_size_bound(d));
  threads.window = 4 * static_cast<std::size_t>(threads.threads);
  render_pieces_in_order(
      pieces.size(), threads,
      [&](std::size_t j, std::string& text) {
        JsonOut out(text);
        write_piece(out, d, pieces[j]);
      },
      emit);
}

}  // namespace detail

void write_diagram_json(const Diagram& d, std::ostream& stream) {
  // A non-finite number or a non-UTF-8 string anywhere throws before the first byte is written (the
  // caller's stream then holds nothing half-made).
  check_writable(d);
  detail::render_diagram_json(d, {}, [&stream](std::string_view piece) {
    stream.write(piece.data(), static_cast<std::streamsize>(piece.size()));
  });
}

std::string diagram_json_text(const Diagram& d) {
  check_writable(d);
  std::string text;
  text.reserve(detail::diagram_json_size_bound(d));
  // In huge pages where the system has them: a fresh 4 KiB page costs a fault (core/large_buffer.h),
  // and faulting in a large graph's text page by page would take longer than formatting it.
  advise_huge_pages(text.data(), text.capacity());
  detail::render_diagram_json(d, {}, [&text](std::string_view piece) { text.append(piece); });
  return text;
}

}  // namespace covmap::io
