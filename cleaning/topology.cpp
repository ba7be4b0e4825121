#include "cleaning/topology.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "cleaning/tolerances.h"
#include "core/parallel.h"

namespace covmap::cleaning {
namespace {


// One ring's samples walked from a starting sample: offset o is sample (start + o) mod n, at an
// arc length that keeps increasing past the perimeter, so stretches never wrap.
struct Walk {
  const std::vector<Sample>& samples;
  std::size_t start = 0;
  double perimeter = 0.0;
  std::size_t n() const { return samples.size(); }
  const Sample& at(std::size_t o) const { return samples[(start + o) % n()]; }
  double s(std::size_t o) const {
    return at(o).s + perimeter * static_cast<double>((start + o) / n());
  }
};

struct Run {
  int label = kOutside;
  std::size_t first = 0, count = 0;  // offsets in the walk
  double begin = 0.0, end = 0.0;     // walk arc lengths of the label changes around it
  double length() const { return end - begin; }
};

// A junction candidate: where one ring's label changes, with the short runs there.
struct Zone {
  int ring = 0;
  std::vector<Point> points;
};

Point mean(const std::vector<Point>& points) {
  Point m{0.0, 0.0};
  for (const Point& p : points) m.x += p.x, m.y += p.y;
  const double n = static_cast<double>(std::max<std::size_t>(points.size(), 1));
  return {m.x / n, m.y / n};
}

// One chain of a ring's walk: samples [o_begin, o_end) at arc lengths [t_begin, t_end], bordering
// `label`, between two zones of the ring (kNone: none, as around a closed loop).
struct ChainSpan {
  std::size_t o_begin = 0, o_end = 0;
  double t_begin = 0.0, t_end = 0.0;
  int label = kOutside;
  int zone_from = kNone, zone_to = kNone;
  bool loop = false;  // the whole ring, all around
};

struct PendingChain {
  RawChain chain;
  int zone_from = kNone, zone_to = kNone;
};

// What one ring contributes: its junction candidates, its chains (zone ids counted from the ring's
// own first zone) and its repair counts. Rings are read independently, on the threads; their
// readings are then combined in ring order.
struct RingReading {
  std::vector<Zone> zones;
  std::vector<PendingChain> chains;
  std::size_t short_chains_dropped = 0;
  std::size_t gaps_closed = 0;
  std::size_t overlaps_resolved = 0;
  std::size_t seams = 0;
};

class UnionFind {
 public:
  explicit UnionFind(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  std::size_t find(std::size_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void unite(std::size_t a, std::size_t b) {
    a = find(a), b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);  // the smaller index is the root
  }

 private:
  std::vector<std::size_t> parent_;
};

// Reads one ring's samples into runs, zones and chains. Only reads the index: any number of rings
// may be read at once.
class RingReader {
 public:
  RingReader(const BoundaryIndex& index, double min_length) : index_(index), min_length_(min_length) {}

  RingReading read(int r, const std::vector<Sample>& samples) const;

 private:
  // Whether ring `own`'s run with this label yields a chain: frame runs always, boundaries from
  // the side of the smaller sensor index only.
  static bool reads(int own, int label) { return label == kOutside || (label >= 0 && own < label); }
  static void count_short_run(int own, int label, bool between_cells, RingReading& out);
  void add_chain(int r, const Walk& walk, const ChainSpan& span, RingReading& out) const;
  void frame_points(const BoundaryRing& ring, double t_begin, double t_end, bool loop, std::vector<Point>& out) const;

  const BoundaryIndex& index_;
  double min_length_;
};

// Combines the rings' readings in ring order, then merges zones into junctions and joins chains.
class Builder {
 public:
  Builder(const BoundaryIndex& index, double min_length) : index_(index), min_length_(min_length) {}

  void add(RingReading&& reading);
  Topology finish();

 private:
  void join_degree_two(std::vector<RawChain>& chains, std::size_t junctions);

  const BoundaryIndex& index_;
  double min_length_;
  std::vector<Zone> zones_;
  std::vector<PendingChain> pending_;
  Topology out_;
};

void RingReader::count_short_run(int own, int label, bool between_cells, RingReading& out) {
  if (label == kOutside) {
    // A little outside between two cells is a gap at a junction; on the frame, a frame piece too
    // short to keep.
    if (between_cells) ++out.gaps_closed;
    else ++out.short_chains_dropped;
  } else if (label >= 0 && own < label) {
    ++out.short_chains_dropped;
  }
}

void RingReader::frame_points(const BoundaryRing& ring, double t_begin, double t_end, bool loop,
                           std::vector<Point>& out) const {
  const std::size_t nv = ring.size();
  if (loop) {
    out.insert(out.end(), ring.points.begin(), ring.points.end());
    return;
  }
  const double perimeter = ring.perimeter();
  double base = std::floor(t_begin / perimeter) * perimeter;
  std::size_t v = static_cast<std::size_t>(
      std::upper_bound(ring.arc.begin(), ring.arc.begin() + static_cast<std::ptrdiff_t>(nv), t_begin - base) -
      ring.arc.begin());
  for (std::size_t guard = 0; guard <= nv; ++guard) {
    if (v == nv) v = 0, base += perimeter;
    if (base + ring.arc[v] >= t_end) break;
    out.push_back(ring.points[v]);
    ++v;
  }
}

void RingReader::add_chain(int r, const Walk& walk, const ChainSpan& span, RingReading& out) const {
  const int label = span.label;
  const BoundaryRing& ring = index_.rings()[r];
  const int own = ring.sensor;
  if (label == kSelf) {
    ++out.seams;
    return;
  }
  if (!reads(own, label)) return;
  PendingChain p;
  p.chain.sensor_a = own;
  p.chain.sensor_b = label == kOutside ? kNone : label;
  p.zone_from = span.zone_from;
  p.zone_to = span.zone_to;
  if (label == kOutside) {
    frame_points(ring, span.t_begin, span.t_end, span.loop, p.chain.points);
  } else {
    // Midpoints between the two copies: gaps and overlaps are split evenly.
    Contact previous = Contact::kTouching;
    for (std::size_t o = span.o_begin; o < span.o_end; ++o) {
      const Sample& s = walk.at(o);
      const double radius = (s.label == label ? 1.0 : tolerance::kRelabelRadius) * index_.snap();
      const Across a = index_.across_at(r, s.edge, s.p, label, radius);
      if (a.label != label) continue;
      p.chain.points.push_back({0.5 * (s.p.x + a.q.x), 0.5 * (s.p.y + a.q.y)});
      if (a.contact != previous) {
        if (a.contact == Contact::kGap) ++out.gaps_closed;
        if (a.contact == Contact::kOverlap) ++out.overlaps_resolved;
      }
      previous = a.contact;
    }
  }
  out.chains.push_back(std::move(p));
}

RingReading RingReader::read(int r, const std::vector<Sample>& samples) const {
  RingReading out;
  const BoundaryRing& ring = index_.rings()[r];
  const int own = ring.sensor;
  const std::size_t n = samples.size();
  if (n == 0) return out;
  std::size_t start = n;
  for (std::size_t k = 0; k < n && start == n; ++k)
    if (samples[k].label != samples[(k + n - 1) % n].label) start = k;
  const Walk walk{samples, start == n ? 0 : start, ring.perimeter()};

  if (start == n) {  // one neighbour all around: a closed loop (an island, or a lone cell's frame)
    const int label = samples[0].label;
    if (ring.perimeter() < min_length_) count_short_run(own, label, false, out);
    else add_chain(r, walk, {.o_end = n, .t_end = ring.perimeter(), .label = label, .loop = true}, out);
    return out;
  }

  std::vector<Run> runs;
  for (std::size_t o = 0; o < n; ++o) {
    if (o == 0 || walk.at(o).label != walk.at(o - 1).label) runs.push_back({walk.at(o).label, o, 0, 0.0, 0.0});
    ++runs.back().count;
  }
  const std::size_t m = runs.size();
  for (Run& run : runs) {
    const std::size_t o = run.first;
    const double before = o == 0 ? walk.s(n - 1) - walk.perimeter : walk.s(o - 1);
    const int label_before = o == 0 ? walk.at(n - 1).label : walk.at(o - 1).label;
    run.begin = locate_transition(index_, r, before, walk.s(o), label_before);
  }
  for (std::size_t j = 0; j < m; ++j) runs[j].end = j + 1 < m ? runs[j + 1].begin : runs[0].begin + walk.perimeter;

  std::vector<std::size_t> longs;
  for (std::size_t j = 0; j < m; ++j)
    if (runs[j].length() >= min_length_) longs.push_back(j);

  if (longs.empty()) {  // a cell too small for any boundary of its own: one junction
    Zone zone{r, {}};
    for (const Run& run : runs) {
      zone.points.push_back(ring.at(run.begin));
      count_short_run(own, run.label, false, out);
    }
    for (const Sample& s : samples) zone.points.push_back(s.p);
    out.zones.push_back(std::move(zone));
    return out;
  }

  // Zones between consecutive long runs (cyclically): dissolved when both runs have one label.
  const std::size_t q = longs.size();
  std::vector<int> zone_id(q, kNone);
  for (std::size_t z = 0; z < q; ++z) {
    const Run& before = runs[longs[z]];
    const Run& after = runs[longs[(z + 1) % q]];
    // Dissolved: the same neighbour on both sides, and nothing but outside (a gap) or the sensor
    // itself (a seam) in between. A third cell in between, however small, is a real contact.
    bool dissolve = before.label == after.label;
    for (std::size_t j = (longs[z] + 1) % m; j != longs[(z + 1) % q]; j = (j + 1) % m)
      if (runs[j].label >= 0) dissolve = false;
    const bool between_cells = before.label != kOutside && after.label != kOutside;
    Zone zone{r, {ring.at(before.end)}};
    for (std::size_t j = (longs[z] + 1) % m; j != longs[(z + 1) % q]; j = (j + 1) % m) {
      count_short_run(own, runs[j].label, between_cells, out);
      for (std::size_t o = runs[j].first; o < runs[j].first + runs[j].count; ++o) zone.points.push_back(walk.at(o).p);
    }
    zone.points.push_back(ring.at(after.begin));
    if (dissolve) continue;
    zone_id[z] = static_cast<int>(out.zones.size());
    out.zones.push_back(std::move(zone));
  }

  // Chains: from one kept zone to the next, through dissolved ones.
  const auto first_kept = std::find_if(zone_id.begin(), zone_id.end(), [](int id) { return id != kNone; });
  if (first_kept == zone_id.end()) {  // every zone dissolved: one boundary all around
    const Run& first = runs[longs[0]];
    add_chain(r, walk,
              {.o_begin = first.first, .o_end = first.first + n, .t_begin = first.begin,
               .t_end = first.begin + walk.perimeter, .label = first.label, .loop = true},
              out);
    return out;
  }
  const std::size_t z0 = static_cast<std::size_t>(first_kept - zone_id.begin());
  std::size_t z = z0;
  do {
    std::size_t next = (z + 1) % q;
    while (zone_id[next] == kNone) next = (next + 1) % q;
    const Run& first = runs[longs[(z + 1) % q]];
    const Run& last = runs[longs[next]];
    const bool wraps = longs[next] < longs[(z + 1) % q];
    const std::size_t o_end = last.first + last.count + (wraps ? n : 0);
    const double t_end = last.end + (wraps ? walk.perimeter : 0.0);
    add_chain(r, walk,
              {.o_begin = first.first, .o_end = o_end, .t_begin = first.begin, .t_end = t_end, .label = first.label,
               .zone_from = zone_id[z], .zone_to = zone_id[next]},
              out);
    z = next;
  } while (z != z0);
  return out;
}

void Builder::add(RingReading&& reading) {
  const int offset = static_cast<int>(zones_.size());
  for (Zone& zone : reading.zones) zones_.push_back(std::move(zone));
  for (PendingChain& p : reading.chains) {
    if (p.zone_from != kNone) p.zone_from += offset;
    if (p.zone_to != kNone) p.zone_to += offset;
    pending_.push_back(std::move(p));
  }
  out_.short_chains_dropped += reading.short_chains_dropped;
  out_.gaps_closed += reading.gaps_closed;
  out_.overlaps_resolved += reading.overlaps_resolved;
  out_.seams += reading.seams;
}

void Builder::join_degree_two(std::vector<RawChain>& chains, std::size_t junctions) {
  // A junction where exactly two pieces of one boundary meet (one arriving, one leaving) is no
  // junction: the pieces are joined. Repeated until no such junction is left.
  std::vector<char> alive(chains.size(), 1);
  bool changed = true;
  while (changed) {
    changed = false;
    std::vector<std::vector<std::size_t>> ends(junctions);
    for (std::size_t c = 0; c < chains.size(); ++c) {
      if (!alive[c]) continue;
      if (chains[c].from != kNone) ends[chains[c].from].push_back(c);
      if (chains[c].to != kNone) ends[chains[c].to].push_back(c);
    }
    std::vector<char> touched(chains.size(), 0);
    for (std::size_t j = 0; j < junctions; ++j) {
      if (ends[j].size() != 2) continue;
      std::size_t in = ends[j][0], out = ends[j][1];
      if (touched[in] || touched[out]) continue;
      RawChain& a = chains[in];
      RawChain& b = chains[out];
      if (a.sensor_a != b.sensor_a || a.sensor_b != b.sensor_b) continue;
      const int jj = static_cast<int>(j);
      if (in == out) {  // a loop through the junction: a closed loop
        a.from = a.to = kNone;
      } else {
        if (a.to != jj) std::swap(in, out);
        RawChain& arriving = chains[in];
        RawChain& leaving = chains[out];
        if (arriving.to != jj || leaving.from != jj) continue;  // both arrive or both leave: keep
        arriving.points.insert(arriving.points.end(), leaving.points.begin(), leaving.points.end());
        arriving.to = leaving.to;
        alive[out] = 0;
      }
      touched[in] = touched[out] = 1;
      ++out_.junctions_merged;
      changed = true;
    }
  }
  std::vector<RawChain> kept;
  for (std::size_t c = 0; c < chains.size(); ++c)
    if (alive[c]) kept.push_back(std::move(chains[c]));
  chains = std::move(kept);
}

Topology Builder::finish() {
  // Zones whose points come close are one junction.
  const double merge = tolerance::kJunctionMerge * index_.snap();
  std::vector<Point> points;
  std::vector<std::size_t> owner;
  for (std::size_t z = 0; z < zones_.size(); ++z)
    for (const Point& p : zones_[z].points) points.push_back(p), owner.push_back(z);
  UniformGrid grid(merge);
  for (std::size_t k = 0; k < points.size(); ++k) grid.add_point(static_cast<int>(k), points[k]);
  grid.finish();
  UnionFind sets(zones_.size());
  for (std::size_t k = 0; k < points.size(); ++k)
    grid.for_each_near(points[k], [&](int other) {
      const Point o = points[static_cast<std::size_t>(other)];
      if (std::hypot(o.x - points[k].x, o.y - points[k].y) <= merge) sets.unite(owner[k], owner[static_cast<std::size_t>(other)]);
    });

  // Junctions in order of their first zone; the position is the mean of the zones' positions.
  std::vector<int> junction_of(zones_.size(), kNone);
  std::vector<std::vector<std::size_t>> members;
  for (std::size_t z = 0; z < zones_.size(); ++z) {
    const std::size_t root = sets.find(z);
    if (junction_of[root] == kNone) {
      junction_of[root] = static_cast<int>(members.size());
      members.emplace_back();
    }
    junction_of[z] = junction_of[root];
    members[static_cast<std::size_t>(junction_of[z])].push_back(z);
  }
  std::vector<Point> junctions;
  for (const auto& group : members) {
    std::vector<Point> positions;
    std::vector<int> rings;
    for (std::size_t z : group) positions.push_back(mean(zones_[z].points)), rings.push_back(zones_[z].ring);
    junctions.push_back(mean(positions));
    std::sort(rings.begin(), rings.end());
    // One candidate per ring around a junction is expected; more are junctions merged into one.
    out_.junctions_merged += group.size() - static_cast<std::size_t>(std::unique(rings.begin(), rings.end()) - rings.begin());
  }

  std::vector<RawChain> chains;
  for (PendingChain& p : pending_) {
    RawChain c = std::move(p.chain);
    c.from = p.zone_from == kNone ? kNone : junction_of[static_cast<std::size_t>(p.zone_from)];
    c.to = p.zone_to == kNone ? kNone : junction_of[static_cast<std::size_t>(p.zone_to)];
    if (c.from != kNone && c.from == c.to) {
      // Both ends at one junction: a real loop through it, or a sliver between merged candidates.
      const Point j = junctions[static_cast<std::size_t>(c.from)];
      double reach = 0.0;
      for (const Point& q : c.points) reach = std::max(reach, std::hypot(q.x - j.x, q.y - j.y));
      if (reach < tolerance::kSelfLoopReach * min_length_) {
        ++out_.short_chains_dropped;
        continue;
      }
    }
    chains.push_back(std::move(c));
  }
  join_degree_two(chains, junctions.size());

  // Junctions no chain reaches (a tiny cell whose neighbours' boundary was joined across it).
  std::vector<int> renumber(junctions.size(), kNone);
  for (const RawChain& c : chains) {
    if (c.from != kNone) renumber[static_cast<std::size_t>(c.from)] = 0;
    if (c.to != kNone) renumber[static_cast<std::size_t>(c.to)] = 0;
  }
  for (std::size_t j = 0; j < junctions.size(); ++j)
    if (renumber[j] == 0) {
      renumber[j] = static_cast<int>(out_.junctions.size());
      out_.junctions.push_back(junctions[j]);
    }
  for (RawChain& c : chains) {
    if (c.from != kNone) c.from = renumber[static_cast<std::size_t>(c.from)];
    if (c.to != kNone) c.to = renumber[static_cast<std::size_t>(c.to)];
  }
  out_.chains = std::move(chains);
  return std::move(out_);
}

}  // namespace

Topology build_topology(const BoundaryIndex& index, double min_length, int threads) {
  const RingReader reader(index, min_length);
  Builder builder(index, min_length);
  // Sampling and reading a ring (a neighbour query per sample, then per sample of its chains and
  // per bisection step of its label changes) only read the index: a batch of rings is sampled and
  // read on the threads, each into its own slot, then the readings are combined in ring order, so
  // the result does not depend on the thread count. Batches bound the readings held at once.
  const std::size_t rings = index.rings().size();
  std::vector<RingReading> batch(tolerance::kSampledRingsBatch);
  for (std::size_t first = 0; first < rings; first += batch.size()) {
    const std::size_t count = std::min(batch.size(), rings - first);
    parallel_items(count, threads, [&](std::size_t k) {
      const int r = static_cast<int>(first + k);
      batch[k] = reader.read(r, sample_ring(index, r));
    });
    for (std::size_t k = 0; k < count; ++k) builder.add(std::move(batch[k]));
  }
  return builder.finish();
}

}  // namespace covmap::cleaning
