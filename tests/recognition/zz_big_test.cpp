#include <gtest/gtest.h>
#include <random>
#include <iostream>
#include <chrono>
#include "recognition/recognize.h"
#include "voronoi/engine.h"
namespace covmap::recognition {
TEST(ZZBig, Million) {
  const int n = std::getenv("BIGN") ? std::atoi(std::getenv("BIGN")) : 1000000;
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(0.0, 1.0), w(1.0, 2.0);
  std::vector<voronoi::Site> s;
  for (int i = 0; i < n; ++i) s.push_back({std::to_string(i), u(rng), u(rng), w(rng)});
  voronoi::Diagram d = voronoi::build_diagram(s);
  voronoi::Diagram g = d; g.sites.clear(); g.faces.clear();
  RecognitionOptions o; o.voronoi_check = false;
  auto t0 = std::chrono::steady_clock::now();
  Reconstruction r = recognize(g, o);
  auto t1 = std::chrono::steady_clock::now();
  std::cout << "time " << std::chrono::duration<double>(t1 - t0).count() << " bisector " << r.bisector_graph << " " << r.reason << "\n";
  if (r.failure) {
    auto& f = *r.failure;
    std::cout << "arc " << f.arc << " face " << f.face << " at " << f.x << "," << f.y << " amount " << f.amount << "\n";
    if (f.arc >= 0) {
      auto& a = d.arcs[f.arc];
      if (auto* c = std::get_if<voronoi::Circle>(&a.curve)) std::cout << "circle " << c->cx << "," << c->cy << " r " << c->r << "\n"; else std::cout << "line\n";
      std::cout << "sites L " << a.left_site << " (" << s[a.left_site].x << "," << s[a.left_site].y << "," << s[a.left_site].weight << ") R " << a.right_site << " (" << s[a.right_site].x << "," << s[a.right_site].y << "," << s[a.right_site].weight << ")\n";
      for (auto v : {a.from, a.to}) if (v >= 0) std::cout << "node " << d.nodes[v].x << "," << d.nodes[v].y << "\n";
    }
  }
}
}
