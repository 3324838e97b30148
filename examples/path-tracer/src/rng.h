// Random numbers for the path tracer: a PCG32 generator (O'Neill's permuted congruential
// generator: a 64-bit LCG whose output is a permuted, rotated 32-bit slice of the state), one
// per pixel. Every pixel's stream is keyed by (seed, pixel), so an image is the same for the
// same --seed on any machine and thread count, and independent for another seed: what raygate's
// Monte Carlo image check needs from a tracer.
#pragma once

#include <cstdint>

namespace nff {

// SplitMix64's finaliser: spreads a key over all 64 bits, so neighbouring pixels and seeds get
// unrelated streams.
inline std::uint64_t mix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

// Mixed into every key; a tracer that changes it renders other (equally right) noise.
constexpr std::uint64_t kStreamSalt = 0x5EED0001ull;

class Rng {
 public:
  Rng(std::uint64_t seed, std::uint64_t pixel)
      : state_(0), increment_((mix64(pixel ^ kStreamSalt) << 1) | 1) {
    next_u32();
    state_ += mix64(seed + kStreamSalt);
    next_u32();
  }

  std::uint32_t next_u32() {
    const std::uint64_t old = state_;
    state_ = old * 6364136223846793005ull + increment_;
    const auto xorshifted = static_cast<std::uint32_t>(((old >> 18) ^ old) >> 27);
    const auto rotation = static_cast<std::uint32_t>(old >> 59);
    return (xorshifted >> rotation) | (xorshifted << ((32 - rotation) & 31));
  }

  // Uniform in [0, 1): the top 24 bits, so the result is exact in a float and never 1.
  double uniform() { return (next_u32() >> 8) * (1.0 / 16777216.0); }

 private:
  std::uint64_t state_;
  std::uint64_t increment_;
};

}  // namespace nff
