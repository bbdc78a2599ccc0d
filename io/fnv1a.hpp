#pragma once
// FNV-1a, 64 bits: a hash stable across builds and machines (std::hash is not), for noticing an edit or a
// corrupted byte, not an adversary. Sweep scene hashes (drivers/sweep.cpp) and checkpoint checksums
// (io/checkpoint.cpp).
#include <cstdint>
#include <string_view>

namespace granmc {

inline std::uint64_t fnv1a64(std::string_view bytes) noexcept {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (const char c : bytes) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001b3ULL;
  }
  return h;
}

}  // namespace granmc
