#pragma once
// Every purpose a random number is drawn for, in one place (HOOMD's RNGIdentifiers.h). A Philox block
// is addressed by key = (seed, replica) and counter = (index, step, purpose, sub), never by the thread
// that draws it, so results do not depend on the thread count. Add new purposes at the end: changing a
// value changes every result drawn with it.
#include <cstdint>

namespace granmc {

enum class RngPurpose : std::uint16_t {
  initial_velocity = 1,  // sub = species, step = 0, index = particle
  collision_pair = 2,    // sub = 0, step = time step, index = 2 s and 2 s + 1 for candidate s of the step
  intruder_event = 3,    // sub = 0, step = event, index = 0 (waiting time, side), 1, 2, ... (sampling attempts)
  needle_event = 4,      // step = event; sub = 0: index 0 (event time, side); sub = 1: index = attempt at the impact
                         // point; sub = 2: index = attempt at the bath velocity; sub = 3: step = 0, index 0 (start)
  event_candidate = 5,   // event scheme (001 sec. 4): sub = 0, step = waiting-time draw, index = block 0..3
  brownian_sync = 6,     // event scheme: sub = 0, step = sample index, index = particle (Remark 2 update)
  white_noise_kick = 7,  // time-stepped white noise: sub = species, step = time step, index = particle
  relaxation = 8,        // BGK-like relaxation (003): sub = 0, step = time step, index = block 0, 1, ...
  swpm_candidate = 9,    // weighted particles: sub = 0, step = candidate draw, index = block 0..3
  swpm_sync = 10,        // weighted particles: sub = 0, step = update of every particle, index = particle
  initial_spin = 11,     // rough particles: sub = species, step = 0, index = particle
  white_noise_spin_kick =
      12,  // rough particles' share of white noise: sub = species, step = time step, index = particle
};

}  // namespace granmc
