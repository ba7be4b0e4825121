// Dimension 3. For two sites i, j adjacent in the regular triangulation, their power facet Q is a
// convex polygon (possibly unbounded) in the plane of equal power; the paraboloid cuts that plane
// in a conic ∂D projecting onto the bisector of i and j (D = {g > 0}). The MWVD arcs of (i, j) are
// exactly ∂D ∩ Q. D and Q are convex, so one walk around ∂Q lists the crossing points in the same
// cyclic order as ∂D does, and the piece of ∂D between two consecutive crossings lies inside Q
// exactly when the stretch of ∂Q between them lies outside D. Arcs come from the walk alone: no
// angular sorting of algebraic points and no tolerance. The walk is projective: rays end at
// points at infinity, and for equal weights (vertical facets) the conic touches the line at
// infinity at the vertical direction U, where unbounded arcs end.
//
// The triangulation is read once into flat arrays (per cell its four vertex ids and four
// neighbour ids) and released: every later pass, the edge walks included, reads those arrays only.
// Vertices are numbered by their sites' Morton (Z-order) rank, with their points stored in that
// order, and cells are stored by the rank of their first vertex, so that neighbours and their
// points are near in memory; CGAL's order scatters cells (most neighbours lie far apart) and the
// walks would wait on memory. The cells' numbers and their vertex
// order are canonical (flat_triangulation.h): a function of the complex, not of the order CGAL
// inserted the sites in. They decide everything here that orders the output or a construction:
// which cell of a facet computes its pattern (the lower-numbered), how nodes are numbered (in cell
// order), the order of a node's three sites (the cell's), where each edge's walk starts (its
// lowest-numbered finite cell, at the edge's vertex indices there, which also say which site of
// its arcs is the left one), and the order of the arcs (the edges' starting cells). The walks
// turn around each edge as CGAL's cell circulator does (Triangulation_utils_3::next_around_edge:
// the flat cells keep CGAL's orientation). So the diagram does not depend on the insertion order
// (tests/voronoi/engine_insertion_order_test.cpp).
#include <algorithm>
#include <cmath>
#include <numeric>
#include <type_traits>

#include "voronoi/engine/edge_pattern.h"
#include "voronoi/engine/extractors.h"
#include "voronoi/engine/facet_walk.h"
#include "voronoi/engine/flat_triangulation.h"
#include "voronoi/engine/readable_arcs.h"
#include "voronoi/engine/self_check.h"
#include "voronoi/engine/triple_node.h"
#include "core/large_buffer.h"
#include "core/parallel.h"
#include "voronoi/tolerances.h"

namespace covmap::voronoi::engine {
namespace {

// Per cell: its power vertex (finite cells) or outward ray direction (infinite cells), the values
// and error bounds of a Homog<Approx>. No member has an initializer, so allocating the array
// touches no page: compute_cells writes every entry, on all cores (a fresh page costs a fault and
// its zeroing, which on one core before the loop would be a noticeable part of a build).
struct CellData {
  double value[4];
  double error[4];
  bool valid;  // usable (else recompute with intervals or exactly when needed)

  void set(const Homog<Approx>& p) {
    const Approx* c[4] = {&p.X, &p.Y, &p.Z, &p.W};
    for (int k = 0; k < 4; ++k) value[k] = c[k]->v, error[k] = c[k]->e;
    valid = true;
  }
  Homog<Approx> get() const {
    return {{value[0], error[0]}, {value[1], error[1]}, {value[2], error[2]}, {value[3], error[3]}};
  }
};
static_assert(std::is_trivially_default_constructible_v<CellData>);

class SpatialExtractor {
 public:
  SpatialExtractor(const std::vector<Site>& sites, FlatTriangulation& flat, Diagram& out, BuildStats& stats)
      : sites_(sites), flat_(flat), out_(out), stats_(stats) {}

  void run() {
    extent_ = site_extent(sites_);
    compute_cells();
    compute_facets();
    merge_shared_line_nodes();
    release_before_walks();
    walk_all_edges();
  }

  // Arcs are mended (engine/readable_arcs.h) after all walks: they only read the nodes.
  std::vector<ArcMend> mends_;
  double extent_ = 0;

 private:
  const std::vector<Site>& sites_;
  FlatTriangulation& flat_;  // moved into the arrays below
  Diagram& out_;
  BuildStats& stats_;

  LargeVector<FlatCell> cells_;  // in canonical order (see the top of the file)
  LargeVector<RawPoint> points_;  // per vertex id, its site's (x, y, w)
  LargeVector<int> vertex_site_;  // per vertex id, its site
  LargeVector<CellData> data_;
  LargeVector<std::uint8_t> flags_;
  LargeVector<EdgePattern> facet_;  // 4 per cell, oriented from the cell towards its neighbour
  // Per facet entry, the node id of its first interior zero point in the numbering cell's order
  // (kInfinityNode at infinity): the facet's nodes have consecutive ids (facet_node()).
  LargeVector<int> facet_first_;
  LargeVector<int> node_rep_;       // per root node, the node it was merged into; empty if none was
  LargeVector<int> uf_;             // union-find on cells sharing one power vertex on the paraboloid
  LargeVector<int> vertex_node_;    // node id of a zero vertex, by union-find root
  std::vector<std::pair<int, int>> zero_nodes_;  // (cell, node) of the finite zero-vertex cells, by cell
  // Large buffers, sized without being written: every entry is written as its node is placed, on
  // all cores (std::vectors would be zero-filled on one core first, through 4 KiB page faults).
  LargeVector<std::array<int, 3>> node_facet_;  // per root node: the sites of its facet
  LargeVector<AlongLine> node_root_;            // per root node: which root of its facet's line
  int workers_ = 1;

  static int local_edge(int i, int j) {
    if (i > j) std::swap(i, j);
    return i == 0 ? j - 1 : i == 1 ? j + 1 : 5;  // (0,1..3) → 0..2, (1,2..3) → 3..4, (2,3) → 5
  }

  int find(int c) {
    while (uf_[c] != c) c = uf_[c] = uf_[uf_[c]];
    return c;
  }

  bool infinite(int c) const { return flags_[c] & kInfiniteCell; }
  bool zero(int c) const { return flags_[c] & kZeroVertex; }

  // The site of a vertex as the triangulation stores it: (x, y, w), the same doubles.
  RawPoint raw(int vertex) const { return points_[vertex]; }

  // Index in cell c of vertex `site` / of neighbour n (c->index(v), c->index(n) in CGAL).
  int index_of_vertex(int c, int v) const {
    const std::array<int, 4>& s = cells_[c].vertex;
    return s[0] == v ? 0 : s[1] == v ? 1 : s[2] == v ? 2 : 3;
  }
  int index_of_neighbor(int c, int n) const {
    const std::array<int, 4>& s = cells_[c].neighbor;
    return s[0] == n ? 0 : s[1] == n ? 1 : s[2] == n ? 2 : 3;
  }
  // The vertex of c's neighbour across facet f that is not on that facet.
  int site_beyond(int c, int f) const {
    const int n = cells_[c].neighbor[f];
    return cells_[n].vertex[index_of_neighbor(n, c)];
  }

  // The finite facet of an infinite cell, and the far vertex of the finite cell behind it.
  void ray_sites(int c, std::array<RawPoint, 3>& tri, RawPoint& away) const {
    const int inf = index_of_vertex(c, kInfiniteVertex);
    for (int k = 0, m = 0; k < 4; ++k)
      if (k != inf) tri[m++] = raw(cells_[c].vertex[k]);
    away = raw(site_beyond(c, inf));
  }

  template <class NT>
  std::optional<Homog<NT>> cell_point(int c) const {
    if (infinite(c)) {
      std::array<RawPoint, 3> tri;
      RawPoint away;
      ray_sites(c, tri, away);
      return power_ray_direction<NT>(tri, away);
    }
    std::array<RawPoint, 4> s;
    for (int k = 0; k < 4; ++k) s[k] = raw(cells_[c].vertex[k]);
    return power_vertex<NT>(s);
  }

  void copy_triangulation() {
    FlatTriangulation flat = std::move(flat_);
    cells_ = std::move(flat.cells);
    points_ = std::move(flat.points);
    vertex_site_ = std::move(flat.vertex_site);
    flags_ = std::move(flat.flags);
  }

  void compute_cells() {
    copy_triangulation();
    // Sized without touching a page; every entry is written below, on all cores.
    data_.resize(cells_.size());
    uf_.resize(cells_.size());
    vertex_node_.resize(cells_.size());
    out_.nodes.reserve(2 * sites_.size());
    advise_huge_pages(out_.nodes.data(), out_.nodes.capacity() * sizeof(Node));  // zeroed by one thread
    workers_ = worker_count(cells_.size());
    std::vector<std::size_t> fallbacks(workers_, 0);
    parallel_chunks(cells_.size(), workers_, [&](std::size_t begin, std::size_t end, int w) {
      for (std::size_t k = begin; k < end; ++k) {
        uf_[k] = static_cast<int>(k);
        vertex_node_[k] = kNone;
        CellData& d = data_[k];
        const int c = static_cast<int>(k);
        const bool inf = infinite(c);
        std::optional<bool> zero;
        d.valid = false;
        if (auto p = cell_point<Approx>(c)) {
          d.set(*p);
          zero = is_zero_point(*p, inf);
        }
        if (!zero) {
          CGAL::Protect_FPU_rounding<true> guard;
          if (auto p = cell_point<Interval>(c)) zero = is_zero_point(*p, inf);
        }
        if (!zero) {
          ++fallbacks[w];
          zero = is_zero_point(*cell_point<Exact>(c), inf);
        }
        if (*zero) flags_[k] |= kZeroVertex;
      }
    });
    for (std::size_t f : fallbacks) stats_.exact_fallbacks += f;
  }

  template <class NT>
  std::optional<EdgePattern> facet_pattern(int a, int b) const {
    std::optional<Homog<NT>> pa, pb;
    if constexpr (std::is_same_v<NT, Approx>) {
      if (!data_[a].valid || !data_[b].valid) return std::nullopt;
      pa = data_[a].get();
      pb = data_[b].get();
    } else {
      pa = cell_point<NT>(a);
      pb = cell_point<NT>(b);
      if (!pa || !pb) return std::nullopt;
    }
    return edge_pattern_projective(*pa, *pb, infinite(a), infinite(b));
  }

  void compute_facets() {
    facet_.resize(4 * cells_.size());  // no page touched: pass 1 writes every entry
    // Per cell, what pass 2 has to do for the cell: the nodes it numbers (bits 0-6) and whether
    // any of its facet entries gets a first node at all (kWritesFacets: also those at infinity,
    // which number none). Written in pass 1 by the worker computing the cell's patterns, so that
    // pass 2 counts from one byte per cell and skips the cells with nothing to do, instead of
    // reading four facet entries and their neighbours' ids.
    constexpr std::uint8_t kWritesFacets = 0x80;
    LargeVector<std::uint8_t> todo(cells_.size());
    // Pass 1, in parallel: the crossing pattern of every facet, from its lower-id cell (each facet
    // entry pair is written by exactly one worker). Unions of cells sharing a vertex are rare and
    // applied afterwards.
    struct Union {
      int cell, facet, neighbor;
    };
    std::vector<std::vector<Union>> unions(workers_);
    std::vector<std::size_t> fallbacks(workers_, 0);
    parallel_chunks(cells_.size(), workers_, [&](std::size_t begin, std::size_t end, int w) {
      for (std::size_t k = begin; k < end; ++k) {
        const int c = static_cast<int>(k);
        std::uint8_t cell_todo = 0;
        for (int f = 0; f < 4; ++f) {
          const int nk = cells_[k].neighbor[f];
          if (nk < c) continue;
          std::optional<EdgePattern> p = facet_pattern<Approx>(c, nk);
          if (!p) {
            CGAL::Protect_FPU_rounding<true> guard;
            p = facet_pattern<Interval>(c, nk);
          }
          if (!p) {
            ++fallbacks[w];
            p = facet_pattern<Exact>(c, nk);
          }
          const int mirror = index_of_neighbor(nk, c);
          EdgePattern& fwd = facet_[4 * k + f];
          EdgePattern& bwd = facet_[4 * nk + mirror];
          fwd = *p;
          bwd = *p;
          std::reverse(bwd.sign, bwd.sign + p->roots + 1);
          if (p->empty && zero(c) && zero(nk))
            unions[w].push_back({c, f, nk});
          if (!p->empty && p->roots > 0) {
            cell_todo |= kWritesFacets;
            // On an edge at infinity (between two directions) the only possible zero is U: no node.
            if (!(infinite(c) && infinite(nk))) cell_todo += static_cast<std::uint8_t>(p->roots);
          }
        }
        todo[k] = cell_todo;
      }
    });
    for (std::size_t f : fallbacks) stats_.exact_fallbacks += f;
    // The approximate vertices (72 bytes a cell) are not read again: their
    // block goes back to the system rather than to core/large_buffer.h's cache, where it would stay
    // resident through the walks, the peak of the build. The node ids are allocated only now.
    LargeVector<CellData>().swap(data_);
    release_large_buffers();
    facet_first_.resize(4 * cells_.size());  // filled on all cores: its pages are fresh
    parallel_chunks(cells_.size(), workers_, [&](std::size_t begin, std::size_t end, int) {
      std::fill(facet_first_.begin() + 4 * begin, facet_first_.begin() + 4 * end, kNone);
    });
    // Applied in cell order, so that each class has the same root whichever worker found its
    // unions: its vertex is rounded from that cell's homogeneous coordinates.
    std::vector<Union> all;
    for (const auto& list : unions) all.insert(all.end(), list.begin(), list.end());
    std::sort(all.begin(), all.end(),
              [](const Union& a, const Union& b) { return a.cell != b.cell ? a.cell < b.cell : a.facet < b.facet; });
    for (const Union& u : all) uf_[find(u.cell)] = find(u.neighbor);
    // Pass 2: the crossing nodes are numbered in cell order, facet by facet, and placed. In
    // parallel over contiguous ranges of cells: each worker first counts the nodes of its
    // range, so that it knows where its numbers start, then numbers and places them (each facet
    // is handled by the worker holding its lower-id cell). The numbers are those of one
    // sequential pass.
    std::vector<int> first_node(workers_ + 1, 0);
    parallel_chunks(cells_.size(), workers_, [&](std::size_t begin, std::size_t end, int w) {
      int count = 0;
      for (std::size_t o = begin; o < end; ++o) count += todo[o] & ~kWritesFacets;
      first_node[w + 1] = count;
    });
    first_node[0] = static_cast<int>(out_.nodes.size());
    std::partial_sum(first_node.begin(), first_node.end(), first_node.begin());
    out_.nodes.resize(first_node[workers_]);
    node_facet_.resize(first_node[workers_]);
    node_root_.resize(first_node[workers_]);
    std::vector<std::size_t> exact_nodes(workers_, 0);
    parallel_chunks(cells_.size(), workers_, [&](std::size_t begin, std::size_t end, int w) {
      int next = first_node[w];
      for (std::size_t o = begin; o < end; ++o) {
        if (!todo[o]) continue;
        const int c = static_cast<int>(o);
        for (int f = 0; f < 4; ++f) {
          const int nk = cells_[c].neighbor[f];
          const EdgePattern& p = facet_[4 * c + f];
          if (nk < c || p.empty || p.roots == 0) continue;
          const bool at_infinity = infinite(c) && infinite(nk);
          const int first = at_infinity ? kInfinityNode : next;
          facet_first_[4 * c + f] = first;
          facet_first_[4 * nk + index_of_neighbor(nk, c)] = first;
          if (!at_infinity)
            for (int r = 0; r < p.roots; ++r) place_root_node(c, f, r, next++, exact_nodes[w]);
        }
      }
    });
    for (std::size_t e : exact_nodes) stats_.exact_nodes += e;
    // Zero vertices get their nodes now, so the walks only read.
    for (std::size_t k = 0; k < cells_.size(); ++k)
      if (zero(static_cast<int>(k))) vertex_zero_node(static_cast<int>(k));
    for (std::size_t k = 0; k < cells_.size(); ++k) {
      const int c = static_cast<int>(k);
      if (zero(c) && !infinite(c)) zero_nodes_.push_back({c, vertex_node_[find(c)]});
    }
  }

  // The node of the r-th interior zero point of facet entry (c, f), in c's order along it.
  int facet_node(int c, int f, int r) const {
    const int first = facet_first_[4 * c + f];
    if (first == kInfinityNode) return kInfinityNode;
    const int nk = cells_[c].neighbor[f];
    const int node = first + (c < nk ? r : facet_[4 * c + f].roots - 1 - r);
    return node_rep_.empty() ? node : node_rep_[node];
  }

  // The node of a zero vertex (kInfinityNode for U), once compute_facets has numbered them.
  int zero_node(int c) const {
    if (infinite(c)) return kInfinityNode;
    return std::lower_bound(zero_nodes_.begin(), zero_nodes_.end(), std::pair<int, int>(c, kNone))->second;
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
    // Sweep over nodes sorted by x: candidates are within `cell` in both coordinates. Each entry
    // carries its x, so neither the sort nor the sweep's test looks the node up. std::sort makes
    // the same moves for the same comparisons whatever the element, so ties in x (grids) come out
    // in the order an index array sorted by x got: the same unions, the same representatives.
    struct ByX {
      double x;
      int node;
    };
    LargeVector<ByX> order;
    order.reserve(n);
    const auto finite_nodes_in_index_order = [&] {
      order.clear();
      for (std::size_t i = 0; i < n; ++i)
        if (std::isfinite(out_.nodes[i].x) && std::isfinite(out_.nodes[i].y))
          order.push_back({out_.nodes[i].x, static_cast<int>(i)});
    };
    // Without ties in x the sorted order is unique, and the two-thread sort finds it; with ties
    // (grids) std::sort runs again on the unsorted order, for the order of ties described above.
    const auto by_x = [](const ByX& a, const ByX& b) { return a.x < b.x; };
    finite_nodes_in_index_order();
    parallel_sort(order.begin(), order.end(), by_x);
    if (std::adjacent_find(order.begin(), order.end(), [](const ByX& a, const ByX& b) { return a.x == b.x; }) !=
        order.end()) {
      finite_nodes_in_index_order();
      std::sort(order.begin(), order.end(), by_x);
    }
    std::vector<int> parent(n);
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&](int x) {
      while (parent[x] != x) x = parent[x] = parent[parent[x]];
      return x;
    };
    bool merged = false;
    for (std::size_t a = 0; a < order.size(); ++a) {
      const int i = order[a].node;
      const Node& p = out_.nodes[i];
      for (std::size_t b = a + 1; b < order.size(); ++b) {
        if (order[b].x - p.x > cell) break;
        const int j = order[b].node;
        const Node& q = out_.nodes[j];
        if (std::fabs(q.y - p.y) > cell) continue;
        if (node_facet_[j] == node_facet_[i]) continue;  // two crossings of one line
        if (find(j) != find(i) && same_crossing(i, j)) {
          parent[find(i)] = find(j);
          merged = true;
        }
      }
    }
    if (!merged) return;
    node_rep_.resize(n);
    for (std::size_t i = 0; i < n; ++i) node_rep_[i] = find(static_cast<int>(i));
  }

  void place_root_node(int cell, int f, int r, int node, std::size_t& exact_nodes) {
    const EdgePattern& p = facet_[4 * cell + f];
    std::array<int, 3> tri;
    std::array<RawPoint, 3> points;
    for (int k = 0, m = 0; k < 4; ++k)
      if (k != f) {
        tri[m] = vertex_site_[cells_[cell].vertex[k]];
        points[m] = raw(cells_[cell].vertex[k]);
        ++m;
      }
    // The travel from c's power vertex to n's leaves c (its fourth site falls behind) or, when c is
    // infinite, reaches the finite cell n from infinity.
    const bool c_finite = !infinite(cell);
    const RawPoint away = raw(c_finite ? cells_[cell].vertex[f] : site_beyond(cell, f));
    const int sigma = travel_sign(points, away, c_finite);
    bool exact = false;
    const AlongLine which = wanted_root(p, r, sigma);
    out_.nodes[node] = triple_node(points, which, extent_, &exact);
    exact_nodes += exact;
    node_facet_[node] = tri;
    node_root_[node] = which;
  }

  int vertex_zero_node(int cell) {
    if (infinite(cell)) return kInfinityNode;
    const int root = find(cell);
    if (vertex_node_[root] != kNone) return vertex_node_[root];
    auto v = cell_point<Exact>(root);
    const double w = CGAL::to_double(v->W);
    out_.nodes.push_back(Node{CGAL::to_double(v->X) / w, CGAL::to_double(v->Y) / w});
    return vertex_node_[root] = static_cast<int>(out_.nodes.size()) - 1;
  }

  // True when the ring turns counter-clockwise around c_j - c_i. Cells are positively oriented, so
  // orientation(c_i, c_j, c_prev, c_next) is the parity of that vertex permutation.
  bool circulates_ccw(int c, int ii, int ij, int next) const {
    const int prev_third = index_of_neighbor(c, next);  // the vertex off the facet shared with `next`
    const int next_third = 6 - ii - ij - prev_third;
    const int perm[4] = {ii, ij, prev_third, next_third};
    int inversions = 0;
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) inversions += perm[a] > perm[b];
    return inversions % 2 == 0;
  }

  // The walks read neither the CGAL-to-flat map nor the union-find of zero vertices (each has its
  // node in zero_nodes_ by now) nor the merge's data; released so that the walks' output can take
  // their place.
  void release_before_walks() {
    LargeVector<std::array<int, 3>>().swap(node_facet_);
    LargeVector<AlongLine>().swap(node_root_);
    LargeVector<int>().swap(uf_);
    LargeVector<int>().swap(vertex_node_);
    release_large_buffers();
  }

  // Each triangulation edge is walked once, from its finite cell L of lowest number, around
  // (vertex i, vertex j) of L, i < j. Workers take contiguous ranges of cells and scan them in
  // increasing order; a worker meeting an edge not yet marked in its own marks circulates it and
  // marks it in every cell of the ring. The cell where a worker first meets an edge is L exactly
  // when L lies in its range (a finite cell of the ring earlier in the range would have marked the
  // edge), and only then does it walk the edge, there and then: exactly one worker walks each edge,
  // without shared state. Each worker's walks come in increasing order of (L, local_edge(i, j)),
  // and the workers' ranges follow each other, so the arcs are in their order (the edges' in cell
  // order) when the workers' lists are put end to end.
  struct WalkState {
    LargeVector<std::uint8_t> done;  // per cell, bit local_edge(i, j)
    std::vector<int> ring;
    std::vector<Token> tokens;
    WalkScratch scratch;
    LargeVector<Arc> arcs;  // large buffers: they reuse the blocks released by earlier stages
    LargeVector<ArcMend> mends;  // one per arc
    std::vector<RawPoint> link;
  };

  void walk_all_edges() {
    std::vector<WalkState> states(workers_);
    parallel_chunks(cells_.size(), workers_, [&](std::size_t begin, std::size_t end, int w) {
      WalkState& st = states[w];
      st.done.assign(cells_.size(), 0);
      st.arcs.reserve(3 * sites_.size() / workers_ + 16);
      st.mends.reserve(3 * sites_.size() / workers_ + 16);
      for (std::size_t k = begin; k < end; ++k) {
        const int c = static_cast<int>(k);
        if (infinite(c)) continue;
        for (int i = 0; i < 4; ++i)
          for (int j = i + 1; j < 4; ++j) {
            if (st.done[k] & (1u << local_edge(i, j))) continue;
            const int vi = cells_[c].vertex[i], vj = cells_[c].vertex[j];
            if (circulate(st, c, vi, vj) == c) walk_ring(st, vi, vj);
          }
      }
    });
    // Nothing but the walks' output is read from here on: the triangulation's arrays go back to the
    // system before the arcs are gathered, the peak of the build.
    for (WalkState& st : states) LargeVector<std::uint8_t>().swap(st.done);
    release_walk_input();
    gather_arcs(states);
    apply_mends(out_, mends_);
  }

  void release_walk_input() {
    LargeVector<FlatCell>().swap(cells_);
    LargeVector<RawPoint>().swap(points_);
    LargeVector<int>().swap(vertex_site_);
    LargeVector<std::uint8_t>().swap(flags_);
    LargeVector<EdgePattern>().swap(facet_);
    LargeVector<int>().swap(facet_first_);
    LargeVector<int>().swap(node_rep_);
    release_large_buffers();
  }

  // Puts the workers' arcs into the diagram, worker after worker (walk_all_edges: that is their
  // order): each worker's arcs copied on all cores into one fresh array, advised as huge pages
  // before it is first touched, and its buffers returned to the system at once, so the arcs are
  // held at most once plus one worker's share. Appending worker by worker and permuting in place
  // by swaps would run on one core through 4 KiB page faults.
  void gather_arcs(std::vector<WalkState>& states) {
    const std::size_t start = out_.arcs.size();
    std::size_t total = start;
    std::vector<std::size_t> base(states.size());
    for (std::size_t w = 0; w < states.size(); ++w) {
      base[w] = total;
      total += states[w].arcs.size();
    }
    out_.arcs.reserve(total);
    advise_huge_pages(out_.arcs.data() + start, (total - start) * sizeof(Arc));
    out_.arcs.resize(total);
    mends_.assign(total, ArcMend::kNone);
    for (std::size_t w = 0; w < states.size(); ++w) {
      WalkState& st = states[w];
      const std::size_t to = base[w];
      parallel_chunks(st.arcs.size(), worker_count(st.arcs.size()), [&](std::size_t begin, std::size_t end, int) {
        std::copy(st.arcs.begin() + begin, st.arcs.begin() + end, out_.arcs.begin() + to + begin);
        std::copy(st.mends.begin() + begin, st.mends.begin() + end, mends_.begin() + to + begin);
      });
      LargeVector<Arc>().swap(st.arcs);
      LargeVector<ArcMend>().swap(st.mends);
      release_large_buffers();
    }
  }

  // The cells around the edge (vi, vj) of cell c0, in the order of CGAL's cell circulator
  // incident_cells(c0, index of vi, index of vj), each marked as done for this edge; returns the
  // finite one of lowest number (c0 is finite).
  int circulate(WalkState& st, int c0, int vi, int vj) const {
    std::vector<int>& ring = st.ring;
    ring.clear();
    int lowest = c0;
    int c = c0;
    do {
      if (!infinite(c) && c < lowest) lowest = c;  // walks start finite
      ring.push_back(c);
      const int ii = index_of_vertex(c, vi), ij = index_of_vertex(c, vj);
      st.done[c] |= static_cast<std::uint8_t>(1u << local_edge(ii, ij));
      c = cells_[c].neighbor[CGAL::Triangulation_utils_3::next_around_edge(ii, ij)];
    } while (c != c0);
    return lowest;
  }

  // The walk around the facet of (vi, vj) whose cells st.ring lists, from its first cell.
  void walk_ring(WalkState& st, int vi, int vj) {
    const std::vector<int>& ring = st.ring;
    const std::size_t m = ring.size();
    bool ccw = true;
    for (std::size_t p = 0; p < m; ++p) {
      if (infinite(ring[p])) continue;
      ccw = circulates_ccw(ring[p], index_of_vertex(ring[p], vi), index_of_vertex(ring[p], vj), ring[(p + 1) % m]);
      break;
    }
    std::vector<Token>& tokens = st.tokens;
    tokens.clear();
    for (std::size_t p = 0; p < m; ++p) {
      const int c = ring[p];
      const int f = index_of_neighbor(c, ring[(p + 1) % m]);
      if (zero(c)) tokens.push_back({zero_node(c), 0});
      const EdgePattern& pat = facet_[4 * c + f];
      if (pat.empty) continue;
      tokens.push_back({kNone, pat.sign[0]});
      for (int r = 0; r < pat.roots; ++r) {
        tokens.push_back({facet_node(c, f, r), 0});
        tokens.push_back({kNone, pat.sign[r + 1]});
      }
    }
    if (!ccw) std::reverse(tokens.begin(), tokens.end());
    bool have_link = false;  // the link is needed rarely: gathered on first use
    // Each link vertex once: the one a cell shares with the next cell of the ring (its readers
    // take a minimum or an "all"; listing each vertex twice only doubled their work).
    auto link = [&]() -> const std::vector<RawPoint>& {
      if (!have_link) {
        st.link.clear();
        for (std::size_t p = 0; p < m; ++p) {
          const int c = ring[p];
          const int off = index_of_neighbor(c, ring[(p + 1) % m]);  // the vertex off that facet
          const int v = cells_[c].vertex[6 - index_of_vertex(c, vi) - index_of_vertex(c, vj) - off];
          if (v != kInfiniteVertex) st.link.push_back(raw(v));
        }
        have_link = true;
      }
      return st.link;
    };
    const std::size_t first = st.arcs.size();
    emit_arcs({.tokens = tokens, .si = vertex_site_[vi], .sj = vertex_site_[vj], .pi = raw(vi), .pj = raw(vj)},
              st.scratch, st.arcs, [&] {
                if (raw(vi).z() == raw(vj).z()) return false;  // U would show
                return circle_centre_in_facet(raw(vi), raw(vj), link());
              });
    for (std::size_t k = first; k < st.arcs.size(); ++k)
      st.mends.push_back(ends_within_rounding(st.arcs[k], out_.nodes, sites_, extent_)
                             ? arc_mend(st.arcs[k], out_.nodes, sites_, st.scratch.zeros, link(), extent_)
                             : ArcMend::kNone);
  }
};

}  // namespace

void extract_spatial(const std::vector<Site>& sites, FlatTriangulation flat, Diagram& out, BuildStats& stats) {
  SpatialExtractor(sites, flat, out, stats).run();
}

}  // namespace covmap::voronoi::engine
