// covmap::Diagram — the plain data type every covmap algorithm reads or writes.
//
// Contract: a Diagram is a planar circular-arc graph over a list of weighted sites. It holds no
// algorithm state; engines fill it, checkers and writers read it. Every arc lies on the
// multiplicatively weighted bisector of its two sites (an Apollonius circle, or a straight line for
// equal weights), except frame arcs, which follow a clipping boundary and have a kNone site on
// their outer side. Indices are plain ints into the vectors below; kNone marks "no such thing"
// (an unbounded end, the outside of the frame).
#pragma once

#include <array>
#include <cstddef>
#include <initializer_list>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

namespace covmap {

inline constexpr int kNone = -1;

struct Point {
  double x = 0.0;
  double y = 0.0;
};

// A sensor: distance to it is Euclidean distance divided by weight.
struct Site {
  std::string id;
  double x = 0.0;
  double y = 0.0;
  double weight = 1.0;
};

struct Node {
  double x = 0.0;
  double y = 0.0;
};

struct Circle {
  double cx = 0.0;
  double cy = 0.0;
  double r = 0.0;
};

// The line through (x, y) with direction (dx, dy); arcs on it run along +d.
struct Line {
  double x = 0.0;
  double y = 0.0;
  double dx = 1.0;
  double dy = 0.0;
};

using Curve = std::variant<Circle, Line>;

// One arc of the graph. Circle arcs run from -> to counter-clockwise around the centre when ccw is
// true (clockwise otherwise); from == to == kNone is the full circle. Line arcs run along +d; a
// kNone end is at infinity (both kNone: the whole line). left_site / right_site are the sites on
// the left and right of the arc's direction of travel; a frame arc has kNone on the outer side.
struct Arc {
  int from = kNone;
  int to = kNone;
  Curve curve = Circle{};
  bool ccw = true;
  int left_site = kNone;
  int right_site = kNone;
  bool frame = false;  // true: part of the clipping boundary, not a bisector
};

// An arc traversed in a face boundary: forward = from -> to.
struct HalfArc {
  int arc = kNone;
  bool forward = true;
};

// The boundary cycles of one face, read like a vector of cycles (each a span of half-arcs).
// Plain data in use, with one twist for size: the half-arcs of faces traced together live in one
// array that those faces share read-only (a million faces would otherwise cost two million small
// allocations, costing more in page faults than the tracing itself). A face copies its own cycles
// out before it is changed (push_back, mutable_cycle), so faces behave as values.
class FaceBoundaries {
 public:
  using Cycle = std::span<const HalfArc>;
  using Pool = std::shared_ptr<std::vector<HalfArc>>;

  FaceBoundaries() = default;
  FaceBoundaries(std::initializer_list<std::vector<HalfArc>> cycles) {
    for (const auto& c : cycles) push_back(c);
  }

  std::size_t size() const { return ranges_.size(); }
  bool empty() const { return ranges_.empty(); }
  Cycle operator[](std::size_t k) const { return {pool_->data() + ranges_[k].begin, ranges_[k].end - ranges_[k].begin}; }
  Cycle front() const { return (*this)[0]; }
  Cycle back() const { return (*this)[size() - 1]; }

  class const_iterator {
   public:
    using value_type = Cycle;
    using difference_type = std::ptrdiff_t;
    const_iterator() = default;
    const_iterator(const FaceBoundaries* b, std::size_t k) : b_(b), k_(k) {}
    Cycle operator*() const { return (*b_)[k_]; }
    const_iterator& operator++() {
      ++k_;
      return *this;
    }
    const_iterator operator++(int) {
      const_iterator old = *this;
      ++k_;
      return old;
    }
    bool operator==(const const_iterator& o) const { return k_ == o.k_; }

   private:
    const FaceBoundaries* b_ = nullptr;
    std::size_t k_ = 0;
  };
  const_iterator begin() const { return {this, 0}; }
  const_iterator end() const { return {this, size()}; }

  // Appends a copy of `cycle` (which may be one of this face's own cycles).
  void push_back(Cycle cycle) {
    const std::vector<HalfArc> copy(cycle.begin(), cycle.end());  // before make_own moves the storage
    make_own();
    ranges_.push_back({pool_->size(), pool_->size() + copy.size()});
    pool_->insert(pool_->end(), copy.begin(), copy.end());
  }
  void push_back(const std::vector<HalfArc>& cycle) { push_back(Cycle(cycle)); }
  // Appends [begin, end) of a shared pool (face tracing): no copy when this face already refers to
  // that pool or to none.
  void push_back_shared(const Pool& pool, std::size_t begin, std::size_t end) {
    if (pool_ && pool_ != pool) {
      push_back(Cycle(pool->data() + begin, end - begin));
      return;
    }
    pool_ = pool;
    ranges_.push_back({begin, end});
  }
  // Cycle k, writable (copies this face's cycles out of a shared pool first).
  std::span<HalfArc> mutable_cycle(std::size_t k) {
    make_own();
    return {pool_->data() + ranges_[k].begin, ranges_[k].end - ranges_[k].begin};
  }

 private:
  struct Range {
    std::size_t begin = 0, end = 0;
  };
  // Ranges of up to two cycles (a face and one hole) are stored inline.
  class Ranges {
   public:
    std::size_t size() const { return n_; }
    bool empty() const { return n_ == 0; }
    const Range& operator[](std::size_t k) const { return k < 2 ? inline_[k] : more_[k - 2]; }
    void push_back(Range r) {
      if (n_ < 2) inline_[n_] = r;
      else more_.push_back(r);
      ++n_;
    }

   private:
    std::array<Range, 2> inline_{};
    std::vector<Range> more_;
    std::size_t n_ = 0;
  };

  // Afterwards this face alone refers to a pool holding exactly its own cycles.
  void make_own() {
    if (pool_ && pool_.use_count() == 1) return;
    auto own = std::make_shared<std::vector<HalfArc>>();
    Ranges moved;
    for (std::size_t k = 0; k < ranges_.size(); ++k) {
      const Cycle c = (*this)[k];
      moved.push_back({own->size(), own->size() + c.size()});
      own->insert(own->end(), c.begin(), c.end());
    }
    pool_ = std::move(own);
    ranges_ = std::move(moved);
  }

  Pool pool_;
  Ranges ranges_;
};

// A connected component of one site's region. Each boundary is a closed cycle of half-arcs with the
// face on its left; for unbounded faces a cycle may pass through infinity (between an arc whose end
// is kNone and the next arc, whose start is kNone). The first boundary is the outer one for
// bounded faces; further boundaries are holes. An orphan face does not contain its own site.
struct Face {
  int site = kNone;
  bool bounded = true;
  bool orphan = false;
  FaceBoundaries boundaries;
};

struct Diagram {
  std::vector<Site> sites;
  std::vector<Node> nodes;
  std::vector<Arc> arcs;
  std::vector<Face> faces;
  // The clipping polygon (counter-clockwise) when the diagram was clipped, else empty.
  std::vector<Point> clip;
};

}  // namespace covmap
