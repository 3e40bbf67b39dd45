// Seeded pseudo-random generator (house style 6: every random draw comes from an explicitly
// seeded local generator). xoshiro256** seeded through splitmix64; the integer and real
// draws below are implemented here (not std:: distributions, whose output differs between
// standard libraries), so the same seed gives the same stream on every platform.
#pragma once

#include <cstdint>

namespace rearm {

class Rng {
 public:
  explicit Rng(std::uint64_t seed);

  // Raw 64 random bits.
  std::uint64_t next();
  // Uniform integer in [lo, hi] (inclusive); lo <= hi required. Unbiased (rejection).
  std::int64_t uniform_int(std::int64_t lo, std::int64_t hi);
  // Uniform index in [0, n); n > 0 required.
  std::uint64_t index(std::uint64_t n);
  // Uniform real in [0, 1) with 53 random bits.
  double uniform01();
  // Uniform real in [lo, hi).
  double uniform(double lo, double hi);
  // True with probability p.
  bool bernoulli(double p);
  // A generator for a derived stream, e.g. one per trial: independent of how many draws
  // this one has made so far only through `stream`.
  static Rng derive(std::uint64_t seed, std::uint64_t stream);

 private:
  std::uint64_t s_[4];
};

}  // namespace rearm
