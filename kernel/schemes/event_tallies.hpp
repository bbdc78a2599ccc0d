#pragma once
// The counts of the time-step-free schemes: equal weights (schemes/event_scheme.hpp, 001 sec. 4) and weighted
// particles (schemes/swpm_scheme.hpp).
#include <cstdint>

namespace granmc {

struct EventTally {
  std::uint64_t candidates = 0;           // candidate pairs (real + fictitious collisions)
  std::uint64_t collisions = 0;           // real collisions
  std::uint64_t majorant_updates = 0;     // raises of U_max at steps 2.7 and 2.10
  std::uint64_t majorant_violations = 0;  // candidates with |v_i - v_j| above the U_max they were drawn with
};

struct SwpmTally {
  std::uint64_t candidates = 0;           // candidate pairs
  std::uint64_t collisions = 0;           // real collisions
  std::uint64_t transfers = 0;            // collisions of unequal weights (each adds a particle)
  std::uint64_t majorant_updates = 0;     // raises of U_max
  std::uint64_t majorant_violations = 0;  // candidates with |v_i - v_j| above the U_max they were drawn with
};

}  // namespace granmc
