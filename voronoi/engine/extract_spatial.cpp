// Dimension 3. For two sites i, j adjacent in the regular triangulation, their power facet Q is a
// convex polygon (possibly unbounded) in the plane of equal power; the paraboloid cuts that plane
// in a conic ∂D projecting onto the bisector of i and j (D = {g > 0}). The MWVD arcs of (i, j) are
// exactly ∂D ∩ Q. D and Q are convex, so one walk around ∂Q lists the crossing points in the same
// cyclic order as ∂D does, and the piece of ∂D between two consecutive crossings lies inside Q
// exactly when the stretch of ∂Q between them lies outside D. Arcs come from the walk alone: no
// angular sorting of algebraic points and no tolerance. The walk is projective: rays end at
// points at infinity, and for equal weights (vertical facets) the conic touches the line at
// infinity at the vertical direction U, where unbounded arcs end.
#include <algorithm>
#include <cmath>
#include <numeric>

#include "voronoi/engine/edge_pattern.h"
#include "voronoi/engine/extractors.h"
#include "voronoi/engine/facet_walk.h"
#include "voronoi/engine/readable_arcs.h"
#include "voronoi/engine/self_check.h"
#include "voronoi/engine/triple_node.h"
#include "core/parallel.h"
#include "voronoi/tolerances.h"

namespace covmap::voronoi::engine {
namespace {

using RT = RegularTriangulation;
using Cell = RT::Cell_handle;
using Vertex = RT::Vertex_handle;

// Per cell: its power vertex (finite cells) or outward ray direction (infinite cells).
struct CellData {
  Homog<Approx> v{};
  bool valid = false;    // v usable (else recompute with intervals or exactly when needed)
  bool zero = false;     // the vertex is a zero point: on the paraboloid, or the direction U
  bool infinite = false;
};

class SpatialExtractor {
 public:
  SpatialExtractor(const std::vector<Site>& sites, RT& rt, Diagram& out, BuildStats& stats)
      : sites_(sites), rt_(rt), out_(out), stats_(stats) {}

  void run() {
    extent_ = site_extent(sites_);
    compute_cells();
    compute_facets();
    merge_shared_line_nodes();
    walk_all_edges();
  }

  // Arcs are mended (engine/readable_arcs.h) after all walks: they only read the nodes.
  std::vector<ArcMend> mends_;
  double extent_ = 0;

 private:
  const std::vector<Site>& sites_;
  RT& rt_;
  Diagram& out_;
  BuildStats& stats_;

  std::vector<Cell> cells_;
  std::vector<CellData> data_;
  std::vector<EdgePattern> facet_;  // 4 per cell, oriented from the cell towards its neighbour
  std::vector<int> facet_node_;     // 2 per facet entry: node ids of its interior zero points
  std::vector<int> uf_;             // union-find: cells sharing one power vertex on the paraboloid
  std::vector<int> vertex_node_;    // node id of a zero vertex, by union-find root
  std::vector<std::array<int, 3>> node_facet_;  // per root node: the sites of its facet
  std::vector<AlongLine> node_root_;            // per root node: which root of its facet's line
  int workers_ = 1;

  static int local_edge(int i, int j) {
    if (i > j) std::swap(i, j);
    return i == 0 ? j - 1 : i == 1 ? j + 1 : 5;  // (0,1..3) → 0..2, (1,2..3) → 3..4, (2,3) → 5
  }

  int find(int c) {
    while (uf_[c] != c) c = uf_[c] = uf_[uf_[c]];
    return c;
  }

  // The finite facet of an infinite cell, and the far vertex of the finite cell behind it.
  void ray_sites(Cell c, std::array<RawPoint, 3>& tri, RawPoint& away) const {
    const int inf = c->index(rt_.infinite_vertex());
    for (int k = 0, m = 0; k < 4; ++k)
      if (k != inf) tri[m++] = c->vertex(k)->point().point();
    Cell n = c->neighbor(inf);
    away = n->vertex(n->index(c))->point().point();
  }

  template <class NT>
  std::optional<Homog<NT>> cell_point(Cell c) const {
    if (rt_.is_infinite(c)) {
      std::array<RawPoint, 3> tri;
      RawPoint away;
      ray_sites(c, tri, away);
      return power_ray_direction<NT>(tri, away);
    }
    std::array<RawPoint, 4> s;
    for (int k = 0; k < 4; ++k) s[k] = c->vertex(k)->point().point();
    return power_vertex<NT>(s);
  }

  void compute_cells() {
    int id = 0;
    for (auto c = rt_.all_cells_begin(); c != rt_.all_cells_end(); ++c) {
      c->info() = id++;
      cells_.push_back(c);
    }
    data_.resize(cells_.size());
    uf_.resize(cells_.size());
    std::iota(uf_.begin(), uf_.end(), 0);
    vertex_node_.assign(cells_.size(), kNone);
    out_.nodes.reserve(2 * sites_.size());
    workers_ = worker_count(cells_.size());
    std::vector<std::size_t> fallbacks(workers_, 0);
    parallel_chunks(cells_.size(), workers_, [&](std::size_t begin, std::size_t end, int w) {
      for (std::size_t k = begin; k < end; ++k) {
        CellData& d = data_[k];
        d.infinite = rt_.is_infinite(cells_[k]);
        std::optional<bool> zero;
        if (auto p = cell_point<Approx>(cells_[k])) {
          d.v = *p;
          d.valid = true;
          zero = is_zero_point(*p, d.infinite);
        }
        if (!zero) {
          CGAL::Protect_FPU_rounding<true> guard;
          if (auto p = cell_point<Interval>(cells_[k])) zero = is_zero_point(*p, d.infinite);
        }
        if (!zero) {
          ++fallbacks[w];
          zero = is_zero_point(*cell_point<Exact>(cells_[k]), d.infinite);
        }
        d.zero = *zero;
      }
    });
    for (std::size_t f : fallbacks) stats_.exact_fallbacks += f;
  }

  template <class NT>
  std::optional<EdgePattern> facet_pattern(Cell a, Cell b) const {
    std::optional<Homog<NT>> pa, pb;
    if constexpr (std::is_same_v<NT, Approx>) {
      if (!data_[a->info()].valid || !data_[b->info()].valid) return std::nullopt;
      pa = data_[a->info()].v;
      pb = data_[b->info()].v;
    } else {
      pa = cell_point<NT>(a);
      pb = cell_point<NT>(b);
      if (!pa || !pb) return std::nullopt;
    }
    return edge_pattern_projective(*pa, *pb, data_[a->info()].infinite, data_[b->info()].infinite);
  }

  void compute_facets() {
    facet_.assign(4 * cells_.size(), EdgePattern{});
    facet_node_.assign(8 * cells_.size(), kNone);
    // Pass 1, in parallel: the crossing pattern of every facet, from its lower-id cell (each facet
    // entry pair is written by exactly one worker). Unions of cells sharing a vertex are rare and
    // applied afterwards.
    std::vector<std::vector<std::pair<int, int>>> unions(workers_);
    std::vector<std::size_t> fallbacks(workers_, 0);
    parallel_chunks(cells_.size(), workers_, [&](std::size_t begin, std::size_t end, int w) {
      for (std::size_t k = begin; k < end; ++k) {
        Cell c = cells_[k];
        for (int f = 0; f < 4; ++f) {
          Cell n = c->neighbor(f);
          const int nk = n->info();
          if (nk < static_cast<int>(k)) continue;
          std::optional<EdgePattern> p = facet_pattern<Approx>(c, n);
          if (!p) {
            CGAL::Protect_FPU_rounding<true> guard;
            p = facet_pattern<Interval>(c, n);
          }
          if (!p) {
            ++fallbacks[w];
            p = facet_pattern<Exact>(c, n);
          }
          const int mirror = n->index(c);
          EdgePattern& fwd = facet_[4 * k + f];
          EdgePattern& bwd = facet_[4 * nk + mirror];
          fwd = *p;
          bwd = *p;
          std::reverse(bwd.sign, bwd.sign + p->roots + 1);
          if (p->empty && data_[k].zero && data_[nk].zero)
            unions[w].emplace_back(static_cast<int>(k), nk);
        }
      }
    });
    for (std::size_t f : fallbacks) stats_.exact_fallbacks += f;
    for (const auto& list : unions)
      for (auto [a, b] : list) uf_[find(a)] = find(b);
    // Pass 2: number the crossing nodes in a fixed order, then place them in parallel.
    struct Job {
      int cell, facet, root, node;
    };
    std::vector<Job> jobs;
    int next = static_cast<int>(out_.nodes.size());
    for (std::size_t k = 0; k < cells_.size(); ++k) {
      Cell c = cells_[k];
      for (int f = 0; f < 4; ++f) {
        Cell n = c->neighbor(f);
        const int nk = n->info();
        if (nk < static_cast<int>(k)) continue;
        const EdgePattern& p = facet_[4 * k + f];
        if (p.empty || p.roots == 0) continue;
        // On an edge at infinity (between two directions) the only possible zero is U.
        const bool at_infinity = data_[k].infinite && data_[nk].infinite;
        const int mirror = n->index(c);
        for (int r = 0; r < p.roots; ++r) {
          int node = kInfinityNode;
          if (!at_infinity) {
            node = next++;
            jobs.push_back({static_cast<int>(k), f, r, node});
          }
          facet_node_[2 * (4 * k + f) + r] = node;
          facet_node_[2 * (4 * nk + mirror) + (p.roots - 1 - r)] = node;
        }
      }
    }
    out_.nodes.resize(next);
    node_facet_.resize(next);
    node_root_.resize(next);
    const int node_workers = worker_count(jobs.size());
    std::vector<std::size_t> exact_nodes(node_workers, 0);
    parallel_chunks(jobs.size(), node_workers, [&](std::size_t begin, std::size_t end, int w) {
      for (std::size_t j = begin; j < end; ++j)
        place_root_node(jobs[j].cell, jobs[j].facet, jobs[j].root, jobs[j].node, exact_nodes[w]);
    });
    for (std::size_t e : exact_nodes) stats_.exact_nodes += e;
    // Zero vertices get their nodes now, so the walks only read.
    for (std::size_t k = 0; k < cells_.size(); ++k)
      if (data_[k].zero) vertex_zero_node(static_cast<int>(k));
  }

  // Facets whose lifted sites are coplanar and co-circular share one power line, so each of its
  // crossings with the paraboloid is found once per facet. Candidates are nearby root nodes; they
  // are merged only when exact predicates confirm the shared line and the same one of its two
  // crossings (they may be closer than rounding: internally tangent bisectors moved by an ulp).
  bool same_crossing(int i, int j) const {
    const std::array<int, 3>& a = node_facet_[i];
    const std::array<int, 3>& b = node_facet_[j];
    auto raw = [&](int s) {
      return RawPoint(sites_[s].x, sites_[s].y, sites_[s].weight);
    };
    for (int t : b) {
      if (t == a[0] || t == a[1] || t == a[2]) continue;
      if (lifted::orientation(raw(a[0]), raw(a[1]), raw(a[2]), raw(t)) != CGAL::ZERO) return false;
      if (lifted::power_side(raw(a[0]), raw(a[1]), raw(a[2]), raw(t)) != CGAL::ZERO) return false;
    }
    return same_root({raw(a[0]), raw(a[1]), raw(a[2])}, node_root_[i], {raw(b[0]), raw(b[1]), raw(b[2])},
                     node_root_[j]);
  }

  void merge_shared_line_nodes() {
    const std::size_t n = node_facet_.size();
    if (n < 2) return;
    double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
    for (const Site& s : sites_) {
      xmin = std::min(xmin, s.x), xmax = std::max(xmax, s.x);
      ymin = std::min(ymin, s.y), ymax = std::max(ymax, s.y);
    }
    const double cell =
        tolerance::kNodeMergeCandidate * std::max(std::hypot(xmax - xmin, ymax - ymin), 1e-300);
    // Sweep over nodes sorted by x: candidates are within `cell` in both coordinates.
    std::vector<int> order;
    order.reserve(n);
    for (std::size_t i = 0; i < n; ++i)
      if (std::isfinite(out_.nodes[i].x) && std::isfinite(out_.nodes[i].y))
        order.push_back(static_cast<int>(i));
    std::sort(order.begin(), order.end(),
              [&](int a, int b) { return out_.nodes[a].x < out_.nodes[b].x; });
    std::vector<int> parent(n);
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&](int x) {
      while (parent[x] != x) x = parent[x] = parent[parent[x]];
      return x;
    };
    bool merged = false;
    for (std::size_t a = 0; a < order.size(); ++a) {
      const int i = order[a];
      const Node& p = out_.nodes[i];
      for (std::size_t b = a + 1; b < order.size(); ++b) {
        const int j = order[b];
        const Node& q = out_.nodes[j];
        if (q.x - p.x > cell) break;
        if (std::fabs(q.y - p.y) > cell) continue;
        if (node_facet_[j] == node_facet_[i]) continue;  // two crossings of one line
        if (find(j) != find(i) && same_crossing(i, j)) {
          parent[find(i)] = find(j);
          merged = true;
        }
      }
    }
    if (!merged) return;
    for (int& node : facet_node_)
      if (node >= 0) node = find(node);
  }

  void place_root_node(int cell, int f, int r, int node, std::size_t& exact_nodes) {
    Cell c = cells_[cell];
    Cell n = c->neighbor(f);
    const EdgePattern& p = facet_[4 * cell + f];
    std::array<int, 3> tri;
    std::array<RawPoint, 3> raw;
    for (int k = 0, m = 0; k < 4; ++k)
      if (k != f) {
        tri[m] = site_of(c->vertex(k));
        raw[m++] = c->vertex(k)->point().point();
      }
    // The travel from c's power vertex to n's leaves c (its fourth site falls behind) or, when c is
    // infinite, reaches the finite cell n from infinity.
    const bool c_finite = !data_[cell].infinite;
    const RawPoint away = c_finite ? c->vertex(f)->point().point() : n->vertex(n->index(c))->point().point();
    const int sigma = travel_sign(raw, away, c_finite);
    bool exact = false;
    const AlongLine which = wanted_root(p, r, sigma);
    out_.nodes[node] = triple_node(raw, which, extent_, &exact);
    exact_nodes += exact;
    node_facet_[node] = tri;
    node_root_[node] = which;
  }

  int vertex_zero_node(int cell) {
    if (data_[cell].infinite) return kInfinityNode;
    const int root = find(cell);
    if (vertex_node_[root] != kNone) return vertex_node_[root];
    auto v = cell_point<Exact>(cells_[root]);
    const double w = CGAL::to_double(v->W);
    out_.nodes.push_back(Node{CGAL::to_double(v->X) / w, CGAL::to_double(v->Y) / w});
    return vertex_node_[root] = static_cast<int>(out_.nodes.size()) - 1;
  }

  // True when the circulator turns counter-clockwise around c_j - c_i. Cells are positively
  // oriented, so orientation(c_i, c_j, c_prev, c_next) is the parity of that vertex permutation.
  static bool circulates_ccw(Cell c, int ii, int ij, Cell next) {
    const int prev_third = c->index(next);  // the vertex off the facet shared with `next`
    const int next_third = 6 - ii - ij - prev_third;
    const int perm[4] = {ii, ij, prev_third, next_third};
    int inversions = 0;
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) inversions += perm[a] > perm[b];
    return inversions % 2 == 0;
  }

  // Each triangulation edge is walked once. Workers take contiguous ranges of cells; a worker meeting
  // an edge not yet marked in its own marks circulates it, marks it in every cell of the ring, and
  // walks it only if the ring's lowest-id finite cell is in its range — so exactly one worker walks each
  // edge, without shared state (CGAL's finite_edges iterator would circulate every edge too).
  struct WalkState {
    std::vector<std::uint8_t> done;  // per cell, bit local_edge(i, j)
    std::vector<Cell> ring;
    std::vector<Token> tokens;
    WalkScratch scratch;
    std::vector<Arc> arcs;
    std::vector<ArcMend> mends;  // one per arc
    std::vector<RawPoint> link;
  };

  void walk_all_edges() {
    std::vector<WalkState> states(workers_);
    parallel_chunks(cells_.size(), workers_, [&](std::size_t begin, std::size_t end, int w) {
      WalkState& st = states[w];
      st.done.assign(cells_.size(), 0);
      st.arcs.reserve(3 * sites_.size() / workers_ + 16);
      for (std::size_t k = begin; k < end; ++k) {
        Cell c = cells_[k];
        if (data_[k].infinite) continue;
        for (int i = 0; i < 4; ++i)
          for (int j = i + 1; j < 4; ++j)
            if (!(st.done[k] & (1u << local_edge(i, j)))) walk_edge(st, c, i, j, begin, end);
      }
    });
    std::size_t total = out_.arcs.size();
    for (const WalkState& st : states) total += st.arcs.size();
    out_.arcs.reserve(total);
    mends_.assign(out_.arcs.size(), ArcMend::kNone);
    for (WalkState& st : states) {
      out_.arcs.insert(out_.arcs.end(), st.arcs.begin(), st.arcs.end());
      mends_.insert(mends_.end(), st.mends.begin(), st.mends.end());
    }
    apply_mends(out_, mends_);
  }

  void walk_edge(WalkState& st, Cell c0, int i0, int j0, std::size_t begin, std::size_t end) {
    Vertex vi = c0->vertex(i0), vj = c0->vertex(j0);
    std::vector<Cell>& ring = st.ring;
    ring.clear();
    auto circ = rt_.incident_cells(c0, i0, j0), done = circ;
    int lowest = c0->info();
    do {
      ring.push_back(circ);
      Cell c = circ;
      if (!data_[c->info()].infinite) lowest = std::min(lowest, c->info());  // walks start finite
      st.done[c->info()] |= static_cast<std::uint8_t>(1u << local_edge(c->index(vi), c->index(vj)));
    } while (++circ != done);
    if (lowest < static_cast<int>(begin) || lowest >= static_cast<int>(end)) return;
    const std::size_t m = ring.size();
    bool ccw = true;
    for (std::size_t p = 0; p < m; ++p) {
      if (rt_.is_infinite(ring[p])) continue;
      ccw = circulates_ccw(ring[p], ring[p]->index(vi), ring[p]->index(vj), ring[(p + 1) % m]);
      break;
    }
    std::vector<Token>& tokens = st.tokens;
    tokens.clear();
    for (std::size_t p = 0; p < m; ++p) {
      Cell c = ring[p];
      const int f = c->index(ring[(p + 1) % m]);
      if (data_[c->info()].zero) tokens.push_back({vertex_zero_node(c->info()), 0});
      const EdgePattern& pat = facet_[4 * c->info() + f];
      if (pat.empty) continue;
      tokens.push_back({kNone, pat.sign[0]});
      for (int r = 0; r < pat.roots; ++r) {
        tokens.push_back({facet_node_[2 * (4 * c->info() + f) + r], 0});
        tokens.push_back({kNone, pat.sign[r + 1]});
      }
    }
    if (!ccw) std::reverse(tokens.begin(), tokens.end());
    bool have_link = false;  // the link is needed rarely: gathered on first use
    auto link = [&]() -> const std::vector<RawPoint>& {
      if (!have_link) {
        st.link.clear();
        for (Cell c : ring)
          for (int k = 0; k < 4; ++k) {
            Vertex v = c->vertex(k);
            if (v != vi && v != vj && !rt_.is_infinite(v)) st.link.push_back(v->point().point());
          }
        have_link = true;
      }
      return st.link;
    };
    const std::size_t first = st.arcs.size();
    emit_arcs(tokens, st.scratch, site_of(vi), site_of(vj), sites_, st.arcs, [&] {
      if (vi->point().point().z() == vj->point().point().z()) return false;  // U would show
      return circle_centre_in_facet(vi->point().point(), vj->point().point(), link());
    });
    for (std::size_t k = first; k < st.arcs.size(); ++k)
      st.mends.push_back(ends_within_rounding(st.arcs[k], out_.nodes, sites_, extent_)
                             ? arc_mend(st.arcs[k], out_.nodes, sites_, st.scratch.zeros, link(), extent_)
                             : ArcMend::kNone);
  }
};

}  // namespace

void extract_spatial(const std::vector<Site>& sites, RegularTriangulation& rt, Diagram& out,
                     BuildStats& stats) {
  SpatialExtractor(sites, rt, out, stats).run();
}

}  // namespace covmap::voronoi::engine
