#pragma once
// The counts of the time-step-free scheme (schemes/event_scheme.hpp, 001 sec. 4).
#include <cstdint>

namespace granmc {

struct EventTally {
  std::uint64_t candidates = 0;           // candidate pairs (real + fictitious collisions)
  std::uint64_t collisions = 0;           // real collisions
  std::uint64_t majorant_updates = 0;     // raises of U_max at steps 2.7 and 2.10
  std::uint64_t majorant_violations = 0;  // candidates with |v_i - v_j| above the U_max they were drawn with
};

}  // namespace granmc
