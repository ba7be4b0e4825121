#include "io/segment_sweep.h"

#include <algorithm>
#include <cassert>
#include <cstdint>
#include <limits>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

#include "core/orientation.h"

namespace covmap::io::detail {
namespace {

bool same(Point p, Point q) { return p.x == q.x && p.y == q.y; }
bool lex_less(Point p, Point q) { return p.x < q.x || (p.x == q.x && p.y < q.y); }

struct Event {
  Point at;
  std::uint32_t segment = 0;
  bool insertion = false;  // false: the segment's right end (removal)
};

bool event_before(const Event& e, const Event& f) {
  if (!same(e.at, f.at)) return lex_less(e.at, f.at);
  if (e.insertion != f.insertion) return !e.insertion;  // removals first
  return e.segment < f.segment;
}

// The status order just after the current event point (see the header). Only called by std::set
// with the segment being inserted, which starts at `at`, as one of the two arguments.
class Below {
 public:
  // `segments` have their ends in sweep order: a < b lexicographically.
  Below(const std::vector<Segment>& segments, const Point& at) : segments_(&segments), at_(&at) {}

  bool operator()(std::uint32_t i, std::uint32_t j) const { return order(i, j) < 0; }

 private:
  // +1 when `at` lies above segment k (k is below the event point), -1 below, 0 when k contains
  // it (k is active, so "on its line" is "on it").
  int side(std::uint32_t k) const {
    const Segment& s = (*segments_)[k];
    if (same(s.a, *at_)) return 0;
    return orientation(s.a, s.b, *at_);
  }

  // -1 when i is below j just after the event point, +1 above, 0 for the same segment.
  int order(std::uint32_t i, std::uint32_t j) const {
    if (i == j) return 0;
    const int si = side(i), sj = side(j);
    if (si == 0 && sj == 0) {
      // Both through the event point: by direction out of it (counter-clockwise is above), then
      // collinear overlapping segments by index.
      const int turn = orientation(*at_, (*segments_)[i].b, (*segments_)[j].b);
      if (turn != 0) return -turn;
      return i < j ? -1 : 1;
    }
    if (si == 0) return sj > 0 ? 1 : -1;  // j below the point i goes through: i is above j
    if (sj == 0) return si > 0 ? -1 : 1;
    // Neither contains the event point, so neither is being inserted: std::set never asks. On
    // opposite sides of the point the answer is still plain; on the same side it would need the
    // height of both at x = at.x, which this comparator does not compute.
    assert(si != sj && "status comparison between two segments that both miss the event point");
    return si > sj ? -1 : 1;
  }

  const std::vector<Segment>* segments_;
  const Point* at_;
};

}  // namespace

std::optional<SegmentPair> find_adjacent_pair(std::vector<Segment> segments,
                                              const std::function<bool(std::size_t, std::size_t)>& accept) {
  if (segments.size() >= (std::size_t{1} << 31)) throw std::length_error("find_adjacent_pair: too many segments");
  std::vector<Event> events;
  events.reserve(2 * segments.size());
  for (std::size_t k = 0; k < segments.size(); ++k) {
    Segment& s = segments[k];
    if (same(s.a, s.b)) continue;
    if (lex_less(s.b, s.a)) std::swap(s.a, s.b);  // from here on, a is the left end
    const auto id = static_cast<std::uint32_t>(k);
    events.push_back({s.a, id, true});
    events.push_back({s.b, id, false});
  }
  std::sort(events.begin(), events.end(), event_before);

  Point at{};
  using Status = std::set<std::uint32_t, Below>;
  Status status(Below(segments, at));
  std::vector<Status::iterator> where(segments.size(), status.end());

  const auto test = [&](Status::iterator lower, Status::iterator upper) -> std::optional<SegmentPair> {
    const std::size_t i = std::min(*lower, *upper), j = std::max(*lower, *upper);
    if (accept(i, j)) return SegmentPair{i, j};
    return std::nullopt;
  };
  for (const Event& event : events) {
    at = event.at;
    if (!event.insertion) {
      const auto next = status.erase(where[event.segment]);
      if (next != status.begin() && next != status.end()) {
        if (auto found = test(std::prev(next), next)) return found;
      }
      continue;
    }
    const auto [it, inserted] = status.insert(event.segment);
    assert(inserted);  // distinct segments never compare equal
    where[event.segment] = it;
    if (it != status.begin()) {
      if (auto found = test(std::prev(it), it)) return found;
    }
    if (const auto next = std::next(it); next != status.end()) {
      if (auto found = test(it, next)) return found;
    }
  }
  return std::nullopt;
}

}  // namespace covmap::io::detail
