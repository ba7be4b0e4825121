// Dimension 2: all lifted sites lie in one plane (all weights equal — the ordinary Voronoi
// diagram — three sites, or w² affine in position). The power diagram is then a 2D power diagram
// of that plane extruded along its normal n: the power "vertex" of a triangle c is the line L_c
// through its in-plane power centre a_c with direction n, and the facet of an edge (i, j) is the
// strip between the lines of its two triangles (a half-plane on the hull). The facet walk is the
// same as in 3D (facet_walk.h), over the projective polygon (-n, a_c, +n, a_n), where +n and -n
// are points at infinity and a_c splits L_c into a lower and an upper half.
#include <numeric>

#include "voronoi/engine/edge_pattern.h"
#include "voronoi/engine/extractors.h"
#include "voronoi/engine/facet_walk.h"
#include "voronoi/engine/self_check.h"
#include "voronoi/engine/triple_node.h"

namespace covmap::voronoi::engine {
namespace {

using RT = SpatialTriangulation;
using Face = RT::Cell_handle;
using Vertex = RT::Vertex_handle;

struct FaceData {
  bool zero = false;            // a_c on the paraboloid
  EdgePattern half[2]{};        // lower (-n → a_c) and upper (a_c → +n)
  int node[2][2] = {{kNone, kNone}, {kNone, kNone}};
  int centre_node = kNone;
};

class PlanarExtractor {
 public:
  PlanarExtractor(const std::vector<Site>& sites, RT& rt, Diagram& out, BuildStats& stats)
      : sites_(sites), rt_(rt), out_(out), stats_(stats) {}

  void run() {
    int id = 0;
    // In dimension 2 the faces are the cells stored by the data structure (all_cells_* is 3D only).
    for (auto f = rt_.tds().raw_cells_begin(); f != rt_.tds().raw_cells_end(); ++f) {
      f->info() = id++;
      faces_.push_back(f);
    }
    data_.resize(faces_.size());
    uf_.resize(faces_.size());
    std::iota(uf_.begin(), uf_.end(), 0);
    // Faces whose sites are co-"circular" in the lifted plane share one power line: one set of
    // nodes, and the zero-width strip between them carries no arc.
    for_each_finite_edge([&](Face c, int i, int j) {
      Face n = c->neighbor(3 - i - j);
      if (infinite(c) || infinite(n)) return;
      const RawPoint far = n->vertex(n->index(c))->point().point();
      const auto pts = face_points(c);
      if (lifted::power_side(pts[0], pts[1], pts[2], far) == CGAL::ZERO)
        uf_[find(c->info())] = find(n->info());
    });
    for (std::size_t k = 0; k < faces_.size(); ++k)
      if (!infinite(faces_[k]) && find(static_cast<int>(k)) == static_cast<int>(k)) compute_face(k);
    for (std::size_t k = 0; k < faces_.size(); ++k)
      if (!infinite(faces_[k])) data_[k] = data_[find(static_cast<int>(k))];
    for_each_finite_edge([&](Face c, int i, int j) { walk_edge(c, i, j); });
  }

 private:
  const std::vector<Site>& sites_;
  RT& rt_;
  Diagram& out_;
  BuildStats& stats_;
  std::vector<Face> faces_;
  std::vector<FaceData> data_;
  std::vector<int> uf_;  // union-find over faces sharing one power line
  WalkScratch scratch_;
  const double extent_ = site_extent(sites_);

  // Every finite edge once, as (face, i, j), faces in id order, edges (0,1), (1,2), (2,0) of each,
  // each from the lower-id of its two faces. (CGAL's finite_edges picks the face by comparing
  // addresses, so the output's order would depend on where the allocator put the faces.)
  template <class F>
  void for_each_finite_edge(F&& f) {
    for (Face c : faces_)
      for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3;
        if (c->vertex(i) == rt_.infinite_vertex() || c->vertex(j) == rt_.infinite_vertex()) continue;
        if (c->neighbor(3 - i - j)->info() < c->info()) continue;
        f(c, i, j);
      }
  }

  int find(int f) {
    while (uf_[f] != f) f = uf_[f] = uf_[uf_[f]];
    return f;
  }

  // Triangulation_3::is_infinite(Cell) is for dimension 3 only.
  bool infinite(Face f) const { return f->has_vertex(rt_.infinite_vertex()); }

  std::array<RawPoint, 3> face_points(Face f) const {
    return {f->vertex(0)->point().point(), f->vertex(1)->point().point(),
            f->vertex(2)->point().point()};
  }

  template <class F>
  auto filtered(F&& f) {
    if (auto r = f(Approx{})) return *r;
    {
      CGAL::Protect_FPU_rounding<true> guard;
      if (auto r = f(Interval{})) return *r;
    }
    ++stats_.exact_fallbacks;
    return *f(Exact{});
  }

  struct FaceResult {
    bool zero;
    EdgePattern half[2]{};
  };

  void compute_face(std::size_t k) {
    Face f = faces_[k];
    const auto pts = face_points(f);
    const FaceResult r = filtered([&](auto tag) -> std::optional<FaceResult> {
      using NT = decltype(tag);
      const Homog<NT> n = lifted_normal<NT>(pts);
      const auto a = planar_power_centre<NT>(pts, n);
      if (!a) return std::nullopt;
      const auto z = is_zero_point(*a, false);
      const auto lo = edge_pattern_projective(negated(n), *a, true, false);
      const auto up = edge_pattern_projective(*a, n, false, true);
      if (!z || !lo || !up) return std::nullopt;
      return FaceResult{*z, {*lo, *up}};
    });
    FaceData& d = data_[k];
    d.zero = r.zero;
    d.half[0] = r.half[0];
    d.half[1] = r.half[1];
    // Both halves of the power line are travelled along the lifted normal n.
    const int sigma = travel_sign_planar(pts);
    for (int h = 0; h < 2; ++h)
      for (int q = 0; q < r.half[h].roots; ++q) {
        bool exact = false;
        out_.nodes.push_back(triple_node(pts, wanted_root(r.half[h], q, sigma), extent_, &exact));
        stats_.exact_nodes += exact;
        d.node[h][q] = static_cast<int>(out_.nodes.size()) - 1;
      }
    if (d.zero) {
      // A node of degree > 3 (rare): the power centre exactly, rounded once.
      const auto a = planar_power_centre<Exact>(pts, lifted_normal<Exact>(pts));
      const double w = CGAL::to_double(a->W);
      out_.nodes.push_back(Node{CGAL::to_double(a->X) / w, CGAL::to_double(a->Y) / w});
      d.centre_node = static_cast<int>(out_.nodes.size()) - 1;
    }
  }

  // Appends the tokens of one half of L_f, forwards (from its start) or backwards.
  void push_half(std::vector<Token>& tokens, Face f, int h, bool backwards) const {
    const FaceData& d = data_[f->info()];
    const EdgePattern& p = d.half[h];
    std::vector<Token> t;
    t.push_back({kNone, p.sign[0]});
    for (int r = 0; r < p.roots; ++r) {
      t.push_back({d.node[h][r], 0});
      t.push_back({kNone, p.sign[r + 1]});
    }
    if (backwards) std::reverse(t.begin(), t.end());
    tokens.insert(tokens.end(), t.begin(), t.end());
  }

  void walk_edge(Face c, int i0, int j0) {
    Vertex vi = c->vertex(i0), vj = c->vertex(j0);
    if (infinite(c)) {  // walk from the finite side of a hull edge
      c = c->neighbor(3 - i0 - j0);
      i0 = c->index(vi);
      j0 = c->index(vj);
    }
    const int k0 = 3 - i0 - j0;
    Face n = c->neighbor(k0);
    if (!infinite(n) && find(c->info()) == find(n->info())) return;  // zero-width strip
    const bool forward = j0 == (i0 + 1) % 3;  // (i, j, k) counter-clockwise around c's normal
    const auto pts = face_points(c);
    // Zero points at ±n (U when the plane is horizontal) and the infinite side of hull edges.
    struct Ends {
      bool plus_u, minus_u;
      std::optional<EdgePattern> to_out, from_out;
      bool out_u;
    };
    const bool hull = infinite(n);
    const Ends ends = filtered([&](auto tag) -> std::optional<Ends> {
      using NT = decltype(tag);
      const Homog<NT> nn = lifted_normal<NT>(pts);
      const auto pu = is_zero_point(nn, true), mu = is_zero_point(negated(nn), true);
      if (!pu || !mu) return std::nullopt;
      Ends e{*pu, *mu, EdgePattern{}, EdgePattern{}, false};
      if (hull) {
        // Outward in-plane direction: (c_j - c_i) × n', n' the normal making (i, j, k) ccw.
        const Homog<NT> np = forward ? nn : negated(nn);
        const Homog<NT> t = cross(lifted_difference<NT>(vi->point().point(), vj->point().point()), np);
        e.to_out = edge_pattern_projective(nn, t, true, true);
        e.from_out = edge_pattern_projective(t, negated(nn), true, true);
        const auto tu = is_zero_point(t, true);
        if (!e.to_out || !e.from_out || !tu) return std::nullopt;
        e.out_u = *tu;
      }
      return e;
    });
    std::vector<Token> tokens;
    auto zero = [&](bool is, int node) {
      if (is) tokens.push_back({node, 0});
    };
    zero(ends.minus_u, kInfinityNode);
    push_half(tokens, c, 0, false);
    zero(data_[c->info()].zero, data_[c->info()].centre_node);
    push_half(tokens, c, 1, false);
    zero(ends.plus_u, kInfinityNode);
    if (hull) {
      auto push_pattern = [&](const EdgePattern& p) {
        tokens.push_back({kNone, p.sign[0]});
        for (int r = 0; r < p.roots; ++r) {
          tokens.push_back({kInfinityNode, 0});  // a zero at infinity can only be U
          tokens.push_back({kNone, p.sign[r + 1]});
        }
      };
      push_pattern(*ends.to_out);
      zero(ends.out_u, kInfinityNode);
      push_pattern(*ends.from_out);
    } else {
      push_half(tokens, n, 1, true);
      zero(data_[n->info()].zero, data_[n->info()].centre_node);
      push_half(tokens, n, 0, true);
    }
    if (!forward) std::reverse(tokens.begin(), tokens.end());
    const WalkedFacet facet{
        .tokens = tokens, .si = site_of(vi), .sj = site_of(vj), .pi = vi->point().point(), .pj = vj->point().point()};
    emit_arcs(facet, scratch_, out_.arcs, [&] {
      if (vi->point().point().z() == vj->point().point().z()) return false;
      std::vector<RawPoint> link;
      for (Face f : {c, n})
        for (int k = 0; k < 3; ++k) {
          Vertex v = f->vertex(k);
          if (v != vi && v != vj && !rt_.is_infinite(v)) link.push_back(v->point().point());
        }
      return circle_centre_in_facet(vi->point().point(), vj->point().point(), link);
    });
  }
};

}  // namespace

void extract_planar(const std::vector<Site>& sites, SpatialTriangulation& rt, Diagram& out,
                    BuildStats& stats) {
  PlanarExtractor(sites, rt, out, stats).run();
}

}  // namespace covmap::voronoi::engine
