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
//
// The scalar of the record is the scene's storage precision (run.storage, docs/scenes.md): double, or
// float for half the memory (16-byte records). The physics always computes in double: a velocity is
// converted when loaded and rounded when stored. A float last-update time is kept relative to the time of
// the last full synchronisation (restart_clock), so its resolution is that of the time since then, not
// that of the run's whole span.
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "kernel/core/aligned_buffer.hpp"
#include "kernel/core/rounded_float.hpp"
#include "kernel/core/vec3.hpp"

namespace granmc {

template <class Real>
class BasicSpeciesStore {
  static_assert(std::is_same_v<Real, double> || std::is_same_v<Real, float>);
  struct Record;

 public:
  /// One particle of the store, found once and then read and written without the store: a batch of
  /// candidates from several species (a mixture's pairs) looks each particle up when it is drawn, so the
  /// loads of its velocity do not wait on which store and which pair it belongs to.
  class Particle {
   public:
    [[nodiscard]] Vec3 velocity() const noexcept { return {r_->v[0], r_->v[1], r_->v[2]}; }
    void set_velocity(const Vec3& v) const noexcept { store(*r_, v); }
    /// Hint that the particle will be read and written soon (random pairs are memory-latency bound).
    void prefetch() const noexcept { __builtin_prefetch(r_, 1, 3); }
    /// Where the record is: equal for two handles of the same particle.
    [[nodiscard]] const void* address() const noexcept { return r_; }

   private:
    friend class BasicSpeciesStore;
    Record* r_ = nullptr;
  };

  BasicSpeciesStore() = default;
  explicit BasicSpeciesStore(std::size_t particles) : records_(particles) {}

  [[nodiscard]] std::size_t size() const noexcept { return records_.size(); }

  [[nodiscard]] Vec3 velocity(std::size_t k) const noexcept {
    const Record& r = records_[k];
    return {r.v[0], r.v[1], r.v[2]};
  }
  void set_velocity(std::size_t k, const Vec3& v) noexcept { store(records_[k], v); }
  /// The time of particle k's last lazy update (event scheme, 001 sec. 4: particles are (v_j, t_j)).
  [[nodiscard]] double last_update(std::size_t k) const noexcept { return clock_origin_ + records_[k].aux; }
  void set_last_update(std::size_t k, double t) noexcept { records_[k].aux = rounded(t - clock_origin_); }
  /// Declares that every particle's last update is t (all were just brought to t): float times restart
  /// from t, so they keep their resolution over long runs. Double times are already exact: nothing to do.
  void restart_clock(double t) noexcept {
    if constexpr (std::is_same_v<Real, float>) {
      clock_origin_ = t;
      for (std::size_t k = 0; k < records_.size(); ++k) records_[k].aux = 0.0f;
    }
  }

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
  struct alignas(4 * sizeof(Real)) Record {
    Real v[3];
    Real aux;
  };
  static_assert(sizeof(Record) == 4 * sizeof(Real));
  /// Rounds to the storage precision (to nearest; no rounding for double), past GCC 12.2's fault
  /// (core/rounded_float.hpp).
  static void store(Record& r, const Vec3& v) noexcept {
    r.v[0] = rounded(v.x);
    r.v[1] = rounded(v.y);
    r.v[2] = rounded(v.z);
  }
  static Real rounded(double x) noexcept {
    if constexpr (std::is_same_v<Real, float>) {
      return rounded_float(x);
    } else {
      return x;
    }
  }
  AlignedBuffer<Record> records_;
  double clock_origin_ = 0.0;  // last_update(k) = clock_origin_ + aux (0 for double)
};

/// The default store: double precision, 32 bytes per particle.
using SpeciesStore = BasicSpeciesStore<double>;
/// Half the memory: float records of 16 bytes (run.storage = "float").
using FloatSpeciesStore = BasicSpeciesStore<float>;

}  // namespace granmc
