#pragma once
// SpeciesStore: the particles of one species in one replica. Mass and diameter live in the scene, once
// per species; the store holds per-particle state only.
//
// The velocity layout is hidden behind this interface (physics never indexes the raw buffer), because it
// is a measured choice: a random candidate pair among 10^7 particles touches 6 cache lines with one array
// per component but 2 with one packed 32-byte record per particle (x, y, z, aux), and the packed records
// win (perf/bench_layout.cpp is the measurement; docs/developer-guide/performance.md, "Velocity layout", its
// figures on the project machine). The fourth slot `aux`
// is reserved for the lazy-update time t_j of the event scheme (001 sec. 4), so that scheme also stays
// within 32 bytes per particle; the time-stepped scheme leaves it unused.
//
// The scalar of the record is the scene's storage precision (run.storage, docs/formats/scenes.md): double, or
// float for half the memory (16-byte records). The physics always computes in double: a velocity is
// converted when loaded and rounded when stored. A float last-update time is kept relative to the time of
// the last full synchronisation (restart_clock), so its resolution is that of the time since then, not
// that of the run's whole span.
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "kernel/core/aligned_buffer.hpp"
#include "kernel/core/rounded_float.hpp"
#include "kernel/core/simd.hpp"
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
  /// `threads`: the threads that write its zeros first (core/aligned_buffer.hpp).
  explicit BasicSpeciesStore(std::size_t particles, int threads = 1) : records_(particles, threads) {}

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

  /// Rough particles (collide/rough_rule.hpp) also spin. The spin of particle k is kept as
  /// s_k = (sigma_i / 2) omega_k, the velocity of the rotation at the particle's surface, in the stored velocity
  /// unit (so the velocity scale applies to it as to c), in a second buffer beside the records that exists only
  /// after enable_spins: smooth particles carry none and their records stay 32 bytes. Disks spin about z only.
  void enable_spins() { spins_ = AlignedBuffer<SpinRecord>(records_.size()); }
  [[nodiscard]] bool has_spins() const noexcept { return spins_.size() != 0; }
  [[nodiscard]] Vec3 spin(std::size_t k) const noexcept {
    const SpinRecord& r = spins_[k];
    return {r.s[0], r.s[1], r.s[2]};
  }
  void set_spin(std::size_t k, const Vec3& s) noexcept {
    SpinRecord& r = spins_[k];
    r.s[0] = rounded(s.x), r.s[1] = rounded(s.y), r.s[2] = rounded(s.z);
  }
  /// Hint that particle k's spin will be read and written soon.
  void prefetch_spin(std::size_t k) const noexcept { __builtin_prefetch(&spins_[k], 1, 3); }
  /// The index of a particle of this store.
  [[nodiscard]] std::size_t index(const Particle& p) const noexcept {
    return static_cast<std::size_t>(p.r_ - records_.data());
  }

  [[nodiscard]] Particle particle(std::size_t k) noexcept {
    Particle p;
    p.r_ = &records_[k];
    return p;
  }

  /// Hint that particle k will be read soon (random pair selection is memory-latency bound).
  void prefetch(std::size_t k) const noexcept { __builtin_prefetch(&records_[k], 1, 3); }

  /// v as set_velocity would store it and velocity read it back.
  [[nodiscard]] static Vec3 as_stored(const Vec3& v) noexcept { return {rounded(v.x), rounded(v.y), rounded(v.z)}; }

// GCC 12 warns inside its own AVX-512 conversions (the _mm512_undefined_* idiom), as in core/simd.hpp.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
  /// A register of particles (the event scheme's candidates, one particle per lane): lane l of
  /// x, y, z is particle index[l]'s velocity and lane l of t its last update. With AVX-512 the records are
  /// loaded whole and transposed; otherwise lane by lane.
  template <class Arch>
  void load_lanes(const std::size_t* index, xsimd::batch<double, Arch>& x, xsimd::batch<double, Arch>& y,
                  xsimd::batch<double, Arch>& z, xsimd::batch<double, Arch>& t) const noexcept {
    using Batch = xsimd::batch<double, Arch>;
    constexpr std::size_t w = Batch::size;
#if XSIMD_WITH_AVX512F
    if constexpr (w == 8 && std::is_base_of_v<xsimd::avx512f, Arch>) {
      if constexpr (std::is_same_v<Real, float>) {  // 8 records of 4 floats: two per 256-bit register
        auto pair = [&](std::size_t a) {
          return _mm256_set_m128(_mm_load_ps(records_[index[a + 4]].v), _mm_load_ps(records_[index[a]].v));
        };
        const __m256 a0 = pair(0), a1 = pair(1), a2 = pair(2), a3 = pair(3);
        const __m256 t0 = _mm256_unpacklo_ps(a0, a1),
                     t1 = _mm256_unpackhi_ps(a0, a1);  // x0 x1 y0 y1 | ..., z0 z1 a0 a1 | ...
        const __m256 t2 = _mm256_unpacklo_ps(a2, a3),
                     t3 = _mm256_unpackhi_ps(a2, a3);  // x2 x3 y2 y3 | ..., z2 z3 a2 a3 | ...
        x = _mm512_cvtps_pd(_mm256_shuffle_ps(t0, t2, 0x44));
        y = _mm512_cvtps_pd(_mm256_shuffle_ps(t0, t2, 0xEE));
        z = _mm512_cvtps_pd(_mm256_shuffle_ps(t1, t3, 0x44));
        t = Batch(clock_origin_) + Batch(_mm512_cvtps_pd(_mm256_shuffle_ps(t1, t3, 0xEE)));
      } else {  // 8 records of 4 doubles: two per 512-bit register
        auto pair = [&](std::size_t a) {
          return _mm512_insertf64x4(_mm512_castpd256_pd512(_mm256_load_pd(records_[index[a]].v)),
                                    _mm256_load_pd(records_[index[a + 4]].v), 1);
        };
        const __m512d a0 = pair(0), a1 = pair(1), a2 = pair(2), a3 = pair(3);
        const __m512d t0 = _mm512_unpacklo_pd(a0, a1),
                      t1 = _mm512_unpackhi_pd(a0, a1);  // x0 x1 z0 z1 x4 ..., y0 y1 a0 a1 y4 ...
        const __m512d t2 = _mm512_unpacklo_pd(a2, a3),
                      t3 = _mm512_unpackhi_pd(a2, a3);  // x2 x3 z2 z3 x6 ..., y2 y3 a2 a3 y6 ...
        const __m512i low = _mm512_setr_epi64(0, 1, 8, 9, 4, 5, 12, 13),
                      high = _mm512_setr_epi64(2, 3, 10, 11, 6, 7, 14, 15);
        x = _mm512_permutex2var_pd(t0, low, t2);
        z = _mm512_permutex2var_pd(t0, high, t2);
        y = _mm512_permutex2var_pd(t1, low, t3);
        t = Batch(clock_origin_) + Batch(_mm512_permutex2var_pd(t1, high, t3));  // as last_update adds it
      }
    } else
#endif
    {
      alignas(64) double lx[w], ly[w], lz[w], lt[w];
      for (std::size_t l = 0; l < w; ++l) {
        const Vec3 v = velocity(index[l]);
        lx[l] = v.x, ly[l] = v.y, lz[l] = v.z, lt[l] = last_update(index[l]);
      }
      x = Batch::load_aligned(lx), y = Batch::load_aligned(ly), z = Batch::load_aligned(lz);
      t = Batch::load_aligned(lt);
    }
  }
  /// Stores lanes l < count: particle index[l] gets velocity (x, y, z) and last update t, each rounded
  /// to the storage precision as set_velocity and set_last_update round.
  template <class Arch>
  void store_lanes(const std::size_t* index, std::size_t count, const xsimd::batch<double, Arch>& x,
                   const xsimd::batch<double, Arch>& y, const xsimd::batch<double, Arch>& z,
                   const xsimd::batch<double, Arch>& t) noexcept {
    using Batch = xsimd::batch<double, Arch>;
    constexpr std::size_t w = Batch::size;
#if XSIMD_WITH_AVX512F
    if constexpr (w == 8 && std::is_base_of_v<xsimd::avx512f, Arch>) {
      if constexpr (std::is_same_v<Real, float>) {
        const __m256 fx = _mm512_cvtpd_ps(x), fy = _mm512_cvtpd_ps(y), fz = _mm512_cvtpd_ps(z);
        const __m256 fa = _mm512_cvtpd_ps(t - Batch(clock_origin_));
        const __m256 t0 = _mm256_unpacklo_ps(fx, fy), t1 = _mm256_unpackhi_ps(fx, fy);  // x0 y0 x1 y1 | x4 y4 x5 y5
        const __m256 t2 = _mm256_unpacklo_ps(fz, fa), t3 = _mm256_unpackhi_ps(fz, fa);
        const __m256 r[4] = {_mm256_shuffle_ps(t0, t2, 0x44), _mm256_shuffle_ps(t0, t2, 0xEE),
                             _mm256_shuffle_ps(t1, t3, 0x44), _mm256_shuffle_ps(t1, t3, 0xEE)};  // records l, l + 4
        for (std::size_t l = 0; l < count; ++l)
          _mm_store_ps(records_[index[l]].v, l < 4 ? _mm256_castps256_ps128(r[l]) : _mm256_extractf128_ps(r[l - 4], 1));
      } else {
        const __m512d a = t - Batch(clock_origin_);
        const __m512d xy0 = _mm512_unpacklo_pd(x, y),
                      xy1 = _mm512_unpackhi_pd(x, y);  // x0 y0 x2 y2 ... | x1 y1 x3 y3 ...
        const __m512d za0 = _mm512_unpacklo_pd(z, a),
                      za1 = _mm512_unpackhi_pd(z, a);  // z0 a0 z2 a2 ... | z1 a1 z3 a3 ...
        const __m512i first = _mm512_setr_epi64(0, 1, 8, 9, 2, 3, 10, 11),
                      second = _mm512_setr_epi64(4, 5, 12, 13, 6, 7, 14, 15);
        const __m512d r[4] = {_mm512_permutex2var_pd(xy0, first, za0), _mm512_permutex2var_pd(xy1, first, za1),
                              _mm512_permutex2var_pd(xy0, second, za0), _mm512_permutex2var_pd(xy1, second, za1)};
        for (std::size_t l = 0; l < count; ++l) {  // records 0, 2 | 1, 3 | 4, 6 | 5, 7
          const __m512d& pair = r[(l & 1u) + 2 * (l / 4)];
          _mm256_store_pd(records_[index[l]].v,
                          (l / 2) % 2 == 0 ? _mm512_castpd512_pd256(pair) : _mm512_extractf64x4_pd(pair, 1));
        }
      }
    } else
#endif
    {
      alignas(64) double lx[w], ly[w], lz[w], lt[w];
      x.store_aligned(lx), y.store_aligned(ly), z.store_aligned(lz), t.store_aligned(lt);
      for (std::size_t l = 0; l < count; ++l) {
        set_velocity(index[l], {lx[l], ly[l], lz[l]});
        set_last_update(index[l], lt[l]);
      }
    }
  }

#pragma GCC diagnostic pop

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
  /// Applies f(Vec3&) to every spin in storage order (none without enable_spins).
  template <class F>
  void for_each_spin(F&& f) noexcept {
    for (std::size_t k = 0; k < spins_.size(); ++k) {
      Vec3 s = spin(k);
      f(s);
      set_spin(k, s);
    }
  }

  /// Bytes of particle state per particle (at most 32, so that a random pair touches two cache lines), and the spins'
  /// record for rough particles (`spins`), which they pay on top.
  static constexpr std::size_t bytes_per_particle(bool spins = false) noexcept {
    return sizeof(Record) + (spins ? sizeof(SpinRecord) : 0);
  }

 private:
  struct alignas(4 * sizeof(Real)) Record {
    Real v[3];
    Real aux;  // the event scheme's last update
  };
  static_assert(sizeof(Record) == 4 * sizeof(Real));

 public:
  /// Particle k's record as it is, velocity and last-update time to the bit (the event scheme's concurrent
  /// rounds keep what a candidate overwrites, schemes/event_rounds.hpp), and how to put it back. Packed: the
  /// record's alignment would make it 64 bytes, and a round keeps thousands.
  struct KeptRecord {
    std::size_t k;
    Real values[4];
  };
  [[nodiscard]] KeptRecord kept(std::size_t k) const noexcept {
    const Record& r = records_[k];
    return {k, {r.v[0], r.v[1], r.v[2], r.aux}};
  }
  void put_back(const KeptRecord& kept) noexcept {
    Record& r = records_[kept.k];
    r.v[0] = kept.values[0], r.v[1] = kept.values[1], r.v[2] = kept.values[2], r.aux = kept.values[3];
  }

 private:
  struct alignas(4 * sizeof(Real)) SpinRecord {
    Real s[3];
    Real unused;
  };
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
  AlignedBuffer<SpinRecord> spins_;  // rough particles only (enable_spins)
  double clock_origin_ = 0.0;        // last_update(k) = clock_origin_ + aux (0 for double)
};

/// The default store: double precision, 32 bytes per particle.
using SpeciesStore = BasicSpeciesStore<double>;
/// Half the memory: float records of 16 bytes (run.storage = "float").
using FloatSpeciesStore = BasicSpeciesStore<float>;

}  // namespace granmc
