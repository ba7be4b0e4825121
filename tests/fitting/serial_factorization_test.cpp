// CHOLMOD's OpenMP regions run on the solving thread (fitting/serial_factorization.cpp): the
// process must bind GOMP_parallel to covmap's definition, which runs a region's body once, here.
#include <gtest/gtest.h>

#include <dlfcn.h>

#include <thread>

#include "fitting/serial_factorization.h"

extern "C" void GOMP_parallel(void (*body)(void*), void* data, unsigned num_threads, unsigned flags);

namespace covmap::fitting::detail {
namespace {

TEST(SerialFactorization, ProcessBindsTheRegionEntryToFitting) {
  // The test binary links Ceres and CHOLMOD as covmap does; CHOLMOD's reference must resolve here.
  ASSERT_NE(dlsym(RTLD_DEFAULT, "GOMP_parallel"), nullptr) << "GOMP_parallel is not exported";
  EXPECT_TRUE(keep_sparse_factorization_serial())
      << "the process resolves GOMP_parallel elsewhere: CHOLMOD would fork its own threads again";
}

TEST(SerialFactorization, RegionRunsOnceOnTheCallingThread) {
  struct Seen {
    int calls = 0;
    std::thread::id thread;
  } seen;
  GOMP_parallel(
      [](void* data) {
        auto* s = static_cast<Seen*>(data);
        ++s->calls;
        s->thread = std::this_thread::get_id();
      },
      &seen, 4, 0);
  EXPECT_EQ(seen.calls, 1);
  EXPECT_EQ(seen.thread, std::this_thread::get_id());
}

}  // namespace
}  // namespace covmap::fitting::detail
