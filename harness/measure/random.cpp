#include "measure/random.h"

#include <stdexcept>

namespace raygate {
namespace {

constexpr std::uint64_t rotate_left(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

}  // namespace

std::uint64_t splitmix64_next(std::uint64_t& state) {
  state += 0x9e3779b97f4a7c15ULL;
  std::uint64_t z = state;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

Xoshiro256::Xoshiro256(std::uint64_t seed) {
  // splitmix64 never yields four zero words in a row, so the all-zero state (a fixed point of
  // xoshiro) cannot occur.
  for (std::uint64_t& word : state_) word = splitmix64_next(seed);
}

std::uint64_t Xoshiro256::next() {
  const std::uint64_t result = rotate_left(state_[1] * 5, 7) * 9;
  const std::uint64_t shifted = state_[1] << 17;
  state_[2] ^= state_[0];
  state_[3] ^= state_[1];
  state_[1] ^= state_[2];
  state_[0] ^= state_[3];
  state_[2] ^= shifted;
  state_[3] = rotate_left(state_[3], 45);
  return result;
}

std::uint64_t Xoshiro256::uniform_below(std::uint64_t bound) {
  if (bound == 0) throw std::invalid_argument("uniform_below: bound must be positive");
  // (2^64 - bound) mod bound == 2^64 mod bound: the count of low outputs to reject.
  const std::uint64_t reject_below = (0 - bound) % bound;
  for (;;) {
    const std::uint64_t x = next();
    if (x >= reject_below) return x % bound;
  }
}

double Xoshiro256::uniform_unit() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

}  // namespace raygate
