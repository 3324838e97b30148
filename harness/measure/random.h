// A small, fully specified pseudo-random generator for the bootstrap. The standard library's
// engines are specified but its distributions are not (std::uniform_int_distribution may give
// different numbers under libstdc++ and libc++), and a CI gate must give the same confidence
// interval for the same samples on every machine. So both the engine (xoshiro256**, seeded
// through splitmix64) and the integer draw (rejection sampling) are written out here.
#pragma once

#include <array>
#include <cstdint>

namespace raygate {

// One splitmix64 step: advances `state` and returns the next output. Used to expand a single
// 64-bit seed into xoshiro's 256-bit state (the seeding its authors recommend).
std::uint64_t splitmix64_next(std::uint64_t& state);

// xoshiro256** (Blackman and Vigna): fast, 2^256 - 1 period, good statistical quality.
class Xoshiro256 {
 public:
  explicit Xoshiro256(std::uint64_t seed);

  std::uint64_t next();

  // Uniform integer in [0, bound), bound > 0, without modulo bias: outputs below 2^64 mod bound
  // are rejected so that every residue has exactly the same number of preimages.
  std::uint64_t uniform_below(std::uint64_t bound);

  // Uniform double in [0, 1) from the top 53 bits.
  double uniform_unit();

 private:
  std::array<std::uint64_t, 4> state_{};
};

}  // namespace raygate
