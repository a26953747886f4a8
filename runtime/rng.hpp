// Deterministic random numbers for the model (rotational latency, seeded faults). xoshiro256**
// seeded through SplitMix64 (Blackman & Vigna, https://prng.di.unimi.it/); integer only, so the
// same seed gives the same draws on every compiler. Give each consumer its own stream (fork) so
// adding draws in one component never shifts another's.
#pragma once

#include <cstdint>
#include <string_view>

namespace vbim {

class Rng {
 public:
  explicit Rng(std::uint64_t seed) {
    std::uint64_t x = seed;
    for (auto& w : s_) w = splitmix(x);
  }
  // A child stream named by a label: independent of how many draws the parent made.
  Rng fork(std::string_view label) const {
    std::uint64_t h = 1469598103934665603ULL;  // FNV-1a over the label, mixed with the seed state
    for (char c : label) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ULL;
    return Rng(h ^ s_[0] ^ (s_[3] << 1));
  }
  std::uint64_t next() {
    const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
    const std::uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = rotl(s_[3], 45);
    return result;
  }
  // Uniform in [0, bound) without modulo bias (Lemire's multiply-shift with rejection).
  std::uint64_t below(std::uint64_t bound) {
    if (bound == 0) return 0;
    for (;;) {
      const unsigned __int128 m = static_cast<unsigned __int128>(next()) * bound;
      const auto low = static_cast<std::uint64_t>(m);
      if (low >= bound || low >= (0 - bound) % bound) return static_cast<std::uint64_t>(m >> 64);
    }
  }
  // True with probability num/den.
  bool chance(std::uint64_t num, std::uint64_t den) { return below(den) < num; }

 private:
  static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  static std::uint64_t splitmix(std::uint64_t& x) {
    std::uint64_t z = (x += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }
  std::uint64_t s_[4];
};

}  // namespace vbim
