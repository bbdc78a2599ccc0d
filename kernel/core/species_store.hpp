#pragma once
// SpeciesStore: the particles of one species in one replica. Mass and diameter live in the scene, once
// per species; the store holds per-particle state only.
//
// The velocity layout is hidden behind this interface (physics never indexes the raw buffer), because it
// is a measured choice: a random candidate pair among 10^7 particles touches 6 cache lines with one array
// per component but 2 with one packed 32-byte record per particle (x, y, z, aux), and ran 1.6x faster
// in a plain loop, 2.1-2.3x with prefetch (perf/bench_layout.cpp keeps the measurement;
// docs/performance.md the figures). The fourth slot `aux`
// is reserved for the lazy-update time t_j of the event scheme (001 sec. 4), so that scheme also stays
// within 32 bytes per particle.
#include <cstddef>
#include <cstdint>

#include "kernel/core/aligned_buffer.hpp"
#include "kernel/core/vec3.hpp"

namespace granmc {

class SpeciesStore {
  struct Record;

 public:
  /// One particle of the store, found once and then read and written without the store: a batch of
  /// candidates from several species (a mixture's pairs) looks each particle up when it is drawn, so the
  /// loads of its velocity do not wait on which store and which pair it belongs to.
  class Particle {
   public:
    [[nodiscard]] Vec3 velocity() const noexcept { return {r_->v[0], r_->v[1], r_->v[2]}; }
    void set_velocity(const Vec3& v) const noexcept {
      r_->v[0] = v.x;
      r_->v[1] = v.y;
      r_->v[2] = v.z;
    }
    /// Hint that the particle will be read and written soon (random pairs are memory-latency bound).
    void prefetch() const noexcept { __builtin_prefetch(r_, 1, 3); }

   private:
    friend class SpeciesStore;
    Record* r_ = nullptr;
  };

  SpeciesStore() = default;
  explicit SpeciesStore(std::size_t particles) : records_(particles) {}

  [[nodiscard]] std::size_t size() const noexcept { return records_.size(); }

  [[nodiscard]] Vec3 velocity(std::size_t k) const noexcept {
    const Record& r = records_[k];
    return {r.v[0], r.v[1], r.v[2]};
  }
  void set_velocity(std::size_t k, const Vec3& v) noexcept {
    Record& r = records_[k];
    r.v[0] = v.x;
    r.v[1] = v.y;
    r.v[2] = v.z;
  }
  /// The time of particle k's last lazy update (event scheme, 001 sec. 4: particles are (v_j, t_j)).
  [[nodiscard]] double last_update(std::size_t k) const noexcept { return records_[k].aux; }
  void set_last_update(std::size_t k, double t) noexcept { records_[k].aux = t; }

  [[nodiscard]] Particle particle(std::size_t k) noexcept {
    Particle p;
    p.r_ = &records_[k];
    return p;
  }

  /// Hint that particle k will be read soon (random pair selection is memory-latency bound).
  void prefetch(std::size_t k) const noexcept { __builtin_prefetch(&records_[k], 1, 3); }

  /// Applies f(Vec3&) to every velocity in storage order.
  template <class F>
  void for_each_velocity(F&& f) noexcept {
    for (std::size_t k = 0; k < records_.size(); ++k) {
      Vec3 v = velocity(k);
      f(v);
      set_velocity(k, v);
    }
  }
  /// Calls f(const Vec3&) for every velocity in storage order.
  template <class F>
  void for_each_velocity(F&& f) const noexcept {
    for (std::size_t k = 0; k < records_.size(); ++k) f(velocity(k));
  }

  /// Bytes of particle state per particle (the budget of DESIGN.md: at most 32).
  static constexpr std::size_t bytes_per_particle() noexcept { return sizeof(Record); }

 private:
  struct alignas(32) Record {
    double v[3];
    double aux;
  };
  static_assert(sizeof(Record) == 32);
  AlignedBuffer<Record> records_;
};

}  // namespace granmc
