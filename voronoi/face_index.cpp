// The face index of trace_faces(): per half-arc, the face it bounds and its successor in that face's
// boundary cycle (kNone for half-arcs on no closed cycle).
#include "voronoi/face_tracing.h"

namespace covmap::voronoi::tracing {

void fill_face_index(FaceIndex& index, LargeVector<int> next_half, const LargeVector<int>& cycle_of_half,
                     const LargeVector<int>& face_of_cycle) {
  const int halves = static_cast<int>(next_half.size());
  index.face_of_half.assign(halves, kNone);
  index.next_half = std::move(next_half);
  for (int h = 0; h < halves; ++h) {
    if (cycle_of_half[h] < 0) index.next_half[h] = kNone;
    else index.face_of_half[h] = face_of_cycle[cycle_of_half[h]];
  }
}

}  // namespace covmap::voronoi::tracing
