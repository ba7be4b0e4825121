// The fast path of the covmap.arcgraph/1 reader (io/fast_readers.h): the same rules as the
// reference reader in diagram_json.cpp, checked while scanning; any doubt is a miss.
#include "io/fast_readers.h"
#include "io/input_limits.h"
#include "io/polygon_check.h"

namespace covmap::io::detail {
namespace {

int index_or_null(JsonScan& scan, std::size_t count) { return scan.null() ? kNone : scan.index(count); }

Circle scan_circle(JsonScan& scan, bool& ccw) {
  enum : unsigned { kCx = 1, kCy = 2, kR = 4, kCcw = 8, kAll = 15 };
  Circle c;
  unsigned seen = 0;
  scan.open('{');
  for (bool first = true; scan.next('}', first);) {
    const std::string_view key = scan.key();
    if (key == "cx") first_time(seen, kCx), c.cx = scan.number();
    else if (key == "cy") first_time(seen, kCy), c.cy = scan.number();
    else if (key == "r") first_time(seen, kR), c.r = scan.number();
    else if (key == "ccw") first_time(seen, kCcw), ccw = scan.boolean();
    else scan.skip_value();
  }
  if (seen != kAll || !(c.r > 0)) throw FastPathMiss{};
  return c;
}

Line scan_line(JsonScan& scan) {
  enum : unsigned { kX = 1, kY = 2, kDx = 4, kDy = 8, kAll = 15 };
  Line l;
  unsigned seen = 0;
  scan.open('{');
  for (bool first = true; scan.next('}', first);) {
    const std::string_view key = scan.key();
    if (key == "x") first_time(seen, kX), l.x = scan.number();
    else if (key == "y") first_time(seen, kY), l.y = scan.number();
    else if (key == "dx") first_time(seen, kDx), l.dx = scan.number();
    else if (key == "dy") first_time(seen, kDy), l.dy = scan.number();
    else scan.skip_value();
  }
  if (seen != kAll || (l.dx == 0 && l.dy == 0)) throw FastPathMiss{};
  return l;
}

// Exactly two elements, each an index below `count` or null.
void scan_pair(JsonScan& scan, std::size_t count, int& left, int& right) {
  scan.open('[');
  bool first = true;
  if (!scan.next(']', first)) throw FastPathMiss{};
  left = index_or_null(scan, count);
  if (!scan.next(']', first)) throw FastPathMiss{};
  right = index_or_null(scan, count);
  if (scan.next(']', first)) throw FastPathMiss{};
}

class GraphScan {
 public:
  GraphScan(std::string_view text, ArcLabels labels) : scan_(text), requested_(labels), labels_(labels) {}

  Diagram run() {
    scan_.open('{');
    for (bool first = true; scan_.next('}', first);) member(scan_.key());
    scan_.expect_end();
    if (!(seen_ & kFormat) || !(seen_ & kNodes) || !(seen_ & kArcs)) throw FastPathMiss{};
    if (labels_ == ArcLabels::kRequired && !(seen_ & kSites)) throw FastPathMiss{};
    const Diagram& d = diagram_;
    if (d.sites.size() > kMaxSites || d.nodes.size() + d.arcs.size() > kMaxGraphItems) throw FastPathMiss{};
    return std::move(diagram_);
  }

 private:
  enum Member : unsigned { kFormat = 1, kSites = 2, kNodes = 4, kArcs = 8, kFaces = 16, kClip = 32 };

  void member(std::string_view key) {
    if (key == "format") {
      first_time(seen_, kFormat);
      expect_string(scan_, "covmap.arcgraph/1");
    } else if (key == "sites") {
      first_time(seen_, kSites);
      sites();
    } else if (key == "nodes") {
      first_time(seen_, kNodes);
      nodes();
    } else if (key == "arcs") {
      first_time(seen_, kArcs);
      arcs();
    } else if (key == "faces" && labels_ == ArcLabels::kRequired) {
      first_time(seen_, kFaces);
      faces();
    } else if (key == "clip") {
      first_time(seen_, kClip);
      clip();
    } else {
      scan_.skip_value();  // unknown, or ignored in this mode
    }
  }

  void sites() {
    if (requested_ == ArcLabels::kIgnored) return scan_.skip_value();
    // Labels are read by the arcs; arcs already read cannot take them any more.
    if (seen_ & kArcs) throw FastPathMiss{};
    SiteTable table = scan_sites(scan_);
    // kOptional: an empty list means an arc graph without sites.
    if (table.sites.empty() && labels_ == ArcLabels::kOptional) {
      labels_ = ArcLabels::kIgnored;
      return;
    }
    check_sites_or_miss(table);
    diagram_.sites = std::move(table.sites);
  }

  void nodes() {
    enum : unsigned { kX = 1, kY = 2, kAll = 3 };
    scan_.open('[');
    for (bool first = true; scan_.next(']', first);) {
      Node n;
      unsigned seen = 0;
      scan_.open('{');
      for (bool first_member = true; scan_.next('}', first_member);) {
        const std::string_view key = scan_.key();
        if (key == "x") first_time(seen, kX), n.x = scan_.number();
        else if (key == "y") first_time(seen, kY), n.y = scan_.number();
        else scan_.skip_value();
      }
      if (seen != kAll) throw FastPathMiss{};
      diagram_.nodes.push_back(n);
    }
  }

  void arcs() {
    if (!(seen_ & kNodes)) throw FastPathMiss{};
    // Without "sites" so far, a kOptional graph is unlabelled (sites arriving later will miss).
    if (labels_ == ArcLabels::kOptional && !(seen_ & kSites)) labels_ = ArcLabels::kIgnored;
    if (labels_ == ArcLabels::kRequired && !(seen_ & kSites)) throw FastPathMiss{};
    scan_.open('[');
    for (bool first = true; scan_.next(']', first);) diagram_.arcs.push_back(arc());
  }

  Arc arc() {
    enum : unsigned { kFrom = 1, kTo = 2, kCircle = 4, kLine = 8, kPair = 16, kFrame = 32 };
    const bool labelled = labels_ != ArcLabels::kIgnored;
    Arc arc;
    unsigned seen = 0;
    scan_.open('{');
    for (bool first = true; scan_.next('}', first);) {
      const std::string_view key = scan_.key();
      if (key == "from") first_time(seen, kFrom), arc.from = index_or_null(scan_, diagram_.nodes.size());
      else if (key == "to") first_time(seen, kTo), arc.to = index_or_null(scan_, diagram_.nodes.size());
      else if (key == "circle") first_time(seen, kCircle), arc.curve = scan_circle(scan_, arc.ccw);
      else if (key == "line") first_time(seen, kLine), arc.curve = scan_line(scan_), arc.ccw = true;
      else if (key == "frame") first_time(seen, kFrame), arc.frame = scan_.boolean();
      else if (key == "sites" && labelled) first_time(seen, kPair), scan_pair(scan_, diagram_.sites.size(), arc.left_site, arc.right_site);
      else scan_.skip_value();
    }
    if (!(seen & kFrom) || !(seen & kTo) || !(seen & kCircle) == !(seen & kLine)) throw FastPathMiss{};
    if ((seen & kCircle) && (arc.from == kNone) != (arc.to == kNone)) throw FastPathMiss{};
    if (!labelled) return arc;
    const int named = (arc.left_site != kNone) + (arc.right_site != kNone);
    if (!(seen & kPair) || (arc.frame && named != 1) || (!arc.frame && (named != 2 || arc.left_site == arc.right_site)))
      throw FastPathMiss{};
    return arc;
  }

  void faces() {
    if (!(seen_ & kArcs)) throw FastPathMiss{};
    scan_.open('[');
    for (bool first = true; scan_.next(']', first);) face();
  }

  void face() {
    enum : unsigned { kSite = 1, kBounded = 2, kOrphan = 4, kBoundaries = 8, kAll = 15 };
    // The face goes in first so that its cycles can follow it as they are read (core/diagram.h).
    add_face(diagram_, Face{});
    Face header;
    unsigned seen = 0;
    scan_.open('{');
    for (bool first = true; scan_.next('}', first);) {
      const std::string_view key = scan_.key();
      if (key == "site") first_time(seen, kSite), header.site = scan_.index(diagram_.sites.size());
      else if (key == "bounded") first_time(seen, kBounded), header.bounded = scan_.boolean();
      else if (key == "orphan") first_time(seen, kOrphan), header.orphan = scan_.boolean();
      else if (key == "boundaries") first_time(seen, kBoundaries), boundaries();
      else scan_.skip_value();
    }
    if (seen != kAll) throw FastPathMiss{};
    Face& f = diagram_.faces.back();
    f.site = header.site;
    f.bounded = header.bounded;
    f.orphan = header.orphan;
  }

  void boundaries() {
    scan_.open('[');
    for (bool first = true; scan_.next(']', first);) {
      cycle_.clear();
      scan_.open('[');
      for (bool first_step = true; scan_.next(']', first_step);) {
        HalfArc half;
        scan_.open('[');
        bool element = true;
        if (!scan_.next(']', element)) throw FastPathMiss{};
        half.arc = scan_.index(diagram_.arcs.size());
        if (!scan_.next(']', element)) throw FastPathMiss{};
        half.forward = scan_.boolean();
        if (scan_.next(']', element)) throw FastPathMiss{};
        cycle_.push_back(half);
      }
      if (cycle_.empty()) throw FastPathMiss{};
      add_cycle(diagram_, cycle_);
    }
  }

  void clip() {
    scan_.open('[');
    for (bool first = true; scan_.next(']', first);) diagram_.clip.push_back(scan_number_pair(scan_, false));
    if (diagram_.clip.empty()) return;  // empty means "not clipped"
    if (polygon_defect(diagram_.clip) || ring_orientation(diagram_.clip) < 0) throw FastPathMiss{};
  }

  JsonScan scan_;
  const ArcLabels requested_;
  ArcLabels labels_;  // requested_, except that kOptional becomes kIgnored without sites
  Diagram diagram_;
  unsigned seen_ = 0;
  std::vector<HalfArc> cycle_;  // the cycle being read, reused
};

}  // namespace

std::optional<Diagram> parse_diagram_json_fast(std::string_view text, ArcLabels labels) {
  try {
    return GraphScan(text, labels).run();
  } catch (const FastPathMiss&) {
    return std::nullopt;
  }
}

}  // namespace covmap::io::detail
