// Site collection in recognize(): the reconstruction from one site per face. Weights equal up to
// rounding are made equal (see RecognitionOptions::weight_snap), faces whose sites coincide within
// `tol` (orphans) share one site, and weights are normalised to a largest of 1. Sites are numbered
// by their first face.
#include <algorithm>
#include <string>
#include <thread>
#include <utility>

#include "core/parallel.h"
#include "recognition/recognize_stages.h"

namespace covmap::recognition::stages {
namespace {

// A site's position keyed for the sweep in x.
struct Keyed {
  double x, y;
  int face;
  bool operator<(const Keyed& o) const { return x < o.x || (x == o.x && face < o.face); }
};

// Per face, its weight with weights equal up to weight_snap made equal.
void snap_weights(const LargeVector<FaceSite>& site, double weight_snap, LargeVector<double>& weight) {
  const int faces = static_cast<int>(site.size());
  LargeVector<std::pair<double, int>> order;
  order.reserve(faces);
  for (int f = 0; f < faces; ++f)
    if (site[f].assigned) order.emplace_back(site[f].weight, f);
  std::sort(order.begin(), order.end());  // (weight, face): no ties
  for (std::size_t k = 0; k < order.size(); ++k) {
    if (k > 0 && order[k].first - order[k - 1].first <= weight_snap * order[k].first) order[k].first = order[k - 1].first;
    weight[order[k].second] = order[k].first;
  }
}

// The assigned sites sorted by x (the positions travel with the sorted keys, so the sweep reads
// memory in order).
void sort_by_x(const LargeVector<FaceSite>& site, LargeVector<Keyed>& by_x) {
  const int faces = static_cast<int>(site.size());
  by_x.reserve(faces);
  for (int f = 0; f < faces; ++f)
    if (site[f].assigned) by_x.push_back({site[f].position.real(), site[f].position.imag(), f});
  std::sort(by_x.begin(), by_x.end());  // (x, face): no ties
}

// Coinciding sites through a sweep in x: each face joins the first earlier face (in face order)
// whose site lies within tol; a union over a window of width tol. Per face, the earliest face with
// the same site.
LargeVector<int> earliest_same_site(const LargeVector<Keyed>& by_x, int faces, double tol) {
  LargeVector<int> same_as(faces, kNone);
  const double tol2 = tol * tol;
  auto close = [&](const Keyed& a, const Keyed& b) { return (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) <= tol2; };
  for (std::size_t k = 0; k < by_x.size(); ++k) {
    const Keyed& p = by_x[k];
    int earliest = p.face;
    for (std::size_t j = k; j-- > 0;) {
      const Keyed& e = by_x[j];
      if (p.x - e.x > tol) break;
      if (close(e, p)) earliest = std::min(earliest, same_as[e.face] == kNone ? e.face : same_as[e.face]);
    }
    for (std::size_t j = k + 1; j < by_x.size(); ++j) {
      const Keyed& e = by_x[j];
      if (e.x - p.x > tol) break;
      if (e.face < earliest && close(e, p)) earliest = e.face;
    }
    same_as[p.face] = earliest;
  }
  return same_as;
}

}  // namespace

Reconstruction collect_sites(const LargeVector<FaceSite>& site, double tol, double weight_snap) {
  const int faces = static_cast<int>(site.size());
  // The two orders are independent: one worker each.
  LargeVector<double> weight(faces, 0.0);
  LargeVector<Keyed> by_x;
  if (worker_count(site.size()) > 1) {
    std::thread other([&] { sort_by_x(site, by_x); });
    snap_weights(site, weight_snap, weight);
    other.join();
  } else {
    snap_weights(site, weight_snap, weight);
    sort_by_x(site, by_x);
  }
  const LargeVector<int> same_as = earliest_same_site(by_x, faces, tol);
  double wmax = 0;
  for (int f = 0; f < faces; ++f) wmax = std::max(wmax, weight[f]);
  Reconstruction r;
  r.sites.reserve(by_x.size());  // at most one site per assigned face
  r.face_site.reserve(faces);
  advise_huge_pages(r.sites.data(), r.sites.capacity() * sizeof(Site));
  advise_huge_pages(r.face_site.data(), r.face_site.capacity() * sizeof(int));
  r.face_site.assign(faces, kNone);
  LargeVector<int> first_face;  // per site, the face it is numbered by
  first_face.reserve(by_x.size());
  for (int f = 0; f < faces; ++f) {
    if (!site[f].assigned) continue;
    const int first = same_as[f];
    if (first != f && r.face_site[first] != kNone) {
      r.face_site[f] = r.face_site[first];
      continue;
    }
    r.face_site[f] = static_cast<int>(first_face.size());
    first_face.push_back(f);
  }
  r.sites.resize(first_face.size());
  parallel_chunks(first_face.size(), worker_count(first_face.size()), [&](std::size_t b, std::size_t e, int) {
    for (std::size_t k = b; k < e; ++k) {
      const int f = first_face[k];
      r.sites[k] = {"s" + std::to_string(k), site[f].position.real(), site[f].position.imag(), weight[f] / wmax};
    }
  });
  return r;
}

}  // namespace covmap::recognition::stages
