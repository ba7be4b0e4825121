// Why. Ceres' SPARSE_NORMAL_CHOLESKY factors JᵀJ with CHOLMOD's supernodal Cholesky. Debian's
// CHOLMOD (SuiteSparse 5) clears its workspace and zeroes each supernode inside OpenMP parallel
// loops whose thread count is compiled in (CHOLMOD_OMP_NUM_THREADS, 4), so OMP_NUM_THREADS does
// not reach them: every factorization forks and joins four threads per large enough supernode,
// on cores that the audit's own threads already use (the local re-solves factor on several), and
// a large audit spends a sizeable share of its CPU in the OpenMP runtime for loops that only write
// zeros and copy. Setting the runtime's maximum of active parallel levels to 0 makes each region a
// team of one, but the runtime still builds and ends a team per region, at nearly the same cost.
//
// How. A team of one is always a legal OpenMP execution (a runtime may give any region fewer
// threads than it asks for), so this file defines GOMP_parallel, the entry point GCC's OpenMP
// code calls for `#pragma omp parallel`, as running the region's body once on the calling thread:
// inside it omp_get_num_threads() is 1 and omp_get_thread_num() 0 (the runtime's answers outside
// any team), so each loop runs whole. The definition is linked into every executable that refines
// and exported to the shared libraries it loads, so CHOLMOD's calls bind to it rather than to
// libgomp's (the dynamic linker searches the executable first, as for malloc). No number changes:
// CHOLMOD's regions are element-wise loops without reductions, so an audit's report.json is the
// same byte for byte. CHOLMOD is the only library in covmap's processes that
// calls GOMP_parallel (checked with `nm -D` over `ldd build/cli/covmap`); a library that did would
// run its regions on one thread too, with the same results, only without the parallel speed-up.
// tests/fitting/serial_factorization_test.cpp checks that the process binds to this definition.
#include "fitting/serial_factorization.h"

#include <dlfcn.h>

extern "C" void GOMP_parallel(void (*body)(void*), void* data, unsigned /*num_threads*/, unsigned /*flags*/) {
  body(data);
}

namespace covmap::fitting::detail {

bool keep_sparse_factorization_serial() {
  // Fallback where the runtime's GOMP_parallel is reached anyway: no active parallel level, so its
  // regions get teams of one (set by every solving thread: the setting is per thread in some
  // runtimes). Looked up, not linked: covmap does not use OpenMP itself.
  using SetMaxActiveLevels = void (*)(int);
  static const auto set_max_active_levels =
      reinterpret_cast<SetMaxActiveLevels>(dlsym(RTLD_DEFAULT, "omp_set_max_active_levels"));
  if (set_max_active_levels) set_max_active_levels(0);
  static const bool bound_here = dlsym(RTLD_DEFAULT, "GOMP_parallel") == reinterpret_cast<void*>(&GOMP_parallel);
  return bound_here;
}

}  // namespace covmap::fitting::detail
