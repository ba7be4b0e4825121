// covmap::mapgen::RandomStream — reproducible random numbers for the map generator.
//
// Contract: the same (seed, stream) gives the same sequence on every platform and compiler. That
// rules out std::uniform_real_distribution and std::normal_distribution, whose algorithms the
// standard leaves to the library; only std::mt19937_64's output is fully specified, and the
// transforms below are written out. Independent streams (one per purpose: sensor errors, vertex
// jitter, random layouts) keep one option from shifting the randomness of another: adding jitter
// does not change which sensors get gross errors.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace covmap::mapgen {

// The purposes that draw random numbers; each gets its own stream for a given seed.
enum class RandomPurpose : std::uint64_t {
  kSensorErrors = 1,
  kVertexJitter = 2,
  kRandomLayout = 3,
  kTownLayout = 4,   // which window of a town list
  kPropagation = 5,  // per-sensor parameters of a non-multiplicative propagation model
};

class RandomStream {
 public:
  RandomStream(std::uint64_t seed, RandomPurpose purpose) : engine_(mix(seed, static_cast<std::uint64_t>(purpose))) {}

  // Uniform in [0, 1), 53 random bits.
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  // Uniform in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  // Standard normal (Box–Muller; one draw per call, the partner value is discarded for simplicity).
  double normal() {
    const double u = 1.0 - uniform();  // (0, 1]: log is finite
    return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * std::numbers::pi * uniform());
  }
  // Uniform integer in [0, n), n > 0, without modulo bias (rejection).
  std::uint64_t below(std::uint64_t n) {
    const std::uint64_t limit = UINT64_MAX - UINT64_MAX % n;
    std::uint64_t r = engine_();
    while (r >= limit) r = engine_();
    return r % n;
  }

 private:
  // splitmix64 of seed and purpose: nearby seeds give unrelated engine states.
  static std::uint64_t mix(std::uint64_t seed, std::uint64_t purpose) {
    std::uint64_t z = seed * 0x9E3779B97F4A7C15ULL + purpose * 0xD1B54A32D192ED03ULL;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }

  std::mt19937_64 engine_;
};

}  // namespace covmap::mapgen
