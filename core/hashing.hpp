// Deterministic hashing for seeded sampling (docs/algorithm.md §16): every random choice of the
// oracle and the carving is a function of a seed and an id, never of threads or call order.
#pragma once
#include <cstdint>

namespace mc {

// SplitMix64 (Steele, Lea, Flood 2014): a bijective 64-bit mixer; consecutive inputs give
// independent-looking outputs.
inline uint64_t splitmix64(uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

// The top 53 bits of a hash as a double in [0, 1).
inline double unit_double(uint64_t x) { return static_cast<double>(x >> 11) * 0x1.0p-53; }

}  // namespace mc
