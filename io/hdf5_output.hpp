#pragma once
// The HDF5 result file of a run: the scene text, seed, version and units as root attributes, the replica
// series and their replica means with confidence half-widths, per-replica counters and the theory lines
// when they apply. Layout (S sample times, R replicas; every dataset carries a `description` attribute):
//
//   /                         attributes scene, scene_path, seed, replicas, method, version, units,
//                             wall_seconds, threads, ranks, particles
//   /times                    [S]
//   /temperature/{mean,ci}    [S], /temperature/replicas [R x S]
//   /log_temperature/{mean,ci} [S], /log_temperature/replicas [R x S]
//   /species/<name>/          attributes name, index (scene order), particles, mass,
//                             a2_last_half_mean, a2_last_half_ci
//     temperature/{mean,ci,replicas}, a2/{mean,ci,replicas}, a3/{mean,ci,replicas}
//                             (attributes a3_last_half_mean, a3_last_half_ci)
//     speed_distribution/{mean,ci} [K], speed_distribution/counts [R x K] (K = output.histogram shells)
//   /speed_shell_edges        [K + 1], scaled speed v* = |V|/v0
//   /momentum/replicas        [R x S x 3]
//   /momentum_relative/{mean,ci} [S], /momentum_relative/replicas [R x S]
//   /collisions/replicas      [R x S], cumulative accepted collisions (stored as double, exact below 2^53)
//   /counters/{candidates,majorant_updates,majorant_violations,rescales,histogram_samples} [R] uint64,
//   /counters/pair_collisions [R x P] uint64 (P ordered species pairs), /counters/momentum_removed_relative [R],
//   /counters/energy_residual [R] (time-stepped gas)
//   /temperature_ratio        scalar group with attributes mean, ci (two species only)
//   /viscosity/               shear runs: attributes {eta_star, eta_kinetic_star, eta, eta_kinetic, eta_over_eta0,
//                             eta_kinetic_over_eta0, drift}_{mean,ci}, steady, window_start;
//                             {reduced_shear_rate, pressure_xy, pressure_kinetic_xy, eta_star,
//                             eta_kinetic_star}_{mean,ci} [S]; pressure_kinetic, pressure_collisional [R x S x 6]
//                             (P / n T: xx, yy, zz, xy, xz, yz)
//   /theory/                  attributes a2_sonine, a2_model_error, a2_second_sonine, a3_second_sonine,
//                             cooling_rate0, cooling_rate0_first_sonine, cooling_rate0_maxwell,
//                             cooling_rate_model_error, chi, alpha, collision_frequency0;
//                             /theory/haff_temperature [S] (monodisperse cooling state only)
#include <string>

#include "io/run_report.hpp"
#include "kernel/core/scene.hpp"
#include "kernel/observe/gas_series.hpp"

namespace granmc {

/// Writes the result file to `path + ".tmp-<pid>"` and renames it to `path` when complete. On any failure
/// the temporary file is removed, `path` is left untouched, and std::runtime_error says what failed.
void write_hdf5(const std::string& path, const Scene& scene, const RunResult& result, const RunReport& report);

}  // namespace granmc
