// A whole DSMC run written the way a researcher would first write it, the reference of the whole-run comparison
// (perf/naive_ratio.py, `make bench-naive`): one cell, an array of structs {vx, vy, vz}, std::mt19937_64 with
// the standard distributions, one candidate at a time, Bird's no-time-counter scheme for elastic hard spheres
// (Bird 1994, sec. 11.1):
//   set-up: N Maxwellian velocities at T = 1 (m = 1), the mean removed; g_max = 2 max_k |v_k| (a bound at t = 0);
//   each step of dt: (N - 1) n pi sigma^2 g_max dt / 2 candidates (the fraction carried to the next step);
//   a candidate: k != l uniform; g = |v_k - v_l|; if g > g_max, g_max := g and it collides, else it collides
//   with probability g / g_max; a collision keeps the centre of mass and turns g to a uniform direction.
// The same physics as `granmc run` on drivers/scenes/scaling/one_replica_*.toml (elastic hard spheres, n = sigma
// = 1, T(0) = 1), so the collision counts agree within their noise and the rates compare like for like.
// Prints one JSON object: particles, steps, candidates, collisions, wall_seconds (set-up included).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace {

struct Particle {
  double vx, vy, vz;
};

struct Args {
  std::size_t particles = 1000000;
  double t_end = 20.0, dt = 0.1;
  std::uint64_t seed = 7;
};

Args parse(int argc, char** argv) {
  Args a;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    const char* value = argv[i + 1];
    if (key == "--particles")
      a.particles = std::strtoull(value, nullptr, 10);
    else if (key == "--t-end")
      a.t_end = std::strtod(value, nullptr);
    else if (key == "--dt")
      a.dt = std::strtod(value, nullptr);
    else if (key == "--seed")
      a.seed = std::strtoull(value, nullptr, 10);
    else {
      std::fprintf(stderr, "naive_run: unknown option %s (--particles N --t-end T --dt DT --seed S)\n", key.c_str());
      std::exit(2);
    }
  }
  if (argc % 2 == 0 || a.particles < 2 || !(a.dt > 0.0) || !(a.t_end >= a.dt)) {
    std::fprintf(stderr, "naive_run: --particles N (>= 2) --t-end T --dt DT (0 < DT <= T) --seed S\n");
    std::exit(2);
  }
  return a;
}

}  // namespace

int main(int argc, char** argv) {
  const Args args = parse(argc, argv);
  const auto start = std::chrono::steady_clock::now();
  const double pi = std::numbers::pi, density = 1.0, diameter = 1.0;

  std::mt19937_64 gen(args.seed);
  std::normal_distribution<double> maxwell(0.0, 1.0);
  std::vector<Particle> particles(args.particles);
  double mx = 0.0, my = 0.0, mz = 0.0;
  for (Particle& p : particles) {
    p = {maxwell(gen), maxwell(gen), maxwell(gen)};
    mx += p.vx, my += p.vy, mz += p.vz;
  }
  const auto n = static_cast<double>(args.particles);
  double g_max = 0.0;
  for (Particle& p : particles) {
    p.vx -= mx / n, p.vy -= my / n, p.vz -= mz / n;
    g_max = std::max(g_max, 2.0 * std::sqrt(p.vx * p.vx + p.vy * p.vy + p.vz * p.vz));
  }

  std::uniform_int_distribution<std::size_t> pick(0, args.particles - 1);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const auto steps = static_cast<std::uint64_t>(std::llround(args.t_end / args.dt));
  std::uint64_t candidates = 0, collisions = 0;
  double carried = 0.0;
  for (std::uint64_t step = 0; step < steps; ++step) {
    const double wanted = 0.5 * (n - 1.0) * density * pi * diameter * diameter * g_max * args.dt + carried;
    const auto count = static_cast<std::uint64_t>(wanted);
    carried = wanted - static_cast<double>(count);
    for (std::uint64_t c = 0; c < count; ++c) {
      const std::size_t k = pick(gen);
      std::size_t l = pick(gen);
      while (l == k) l = pick(gen);
      Particle& pk = particles[k];
      Particle& pl = particles[l];
      const double gx = pk.vx - pl.vx, gy = pk.vy - pl.vy, gz = pk.vz - pl.vz;
      const double g = std::sqrt(gx * gx + gy * gy + gz * gz);
      if (g > g_max)
        g_max = g;
      else if (uniform(gen) * g_max >= g)
        continue;
      // Elastic hard spheres scatter isotropically: g' = |g| times a uniform unit vector.
      const double cos_theta = 2.0 * uniform(gen) - 1.0;
      const double sin_theta = std::sqrt(1.0 - cos_theta * cos_theta);
      const double phi = 2.0 * pi * uniform(gen);
      const double hx = 0.5 * g * sin_theta * std::cos(phi), hy = 0.5 * g * sin_theta * std::sin(phi),
                   hz = 0.5 * g * cos_theta;
      const double cx = 0.5 * (pk.vx + pl.vx), cy = 0.5 * (pk.vy + pl.vy), cz = 0.5 * (pk.vz + pl.vz);
      pk = {cx + hx, cy + hy, cz + hz};
      pl = {cx - hx, cy - hy, cz - hz};
      ++collisions;
    }
    candidates += count;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(
      "{\"particles\": %zu, \"steps\": %llu, \"candidates\": %llu, \"collisions\": %llu, \"wall_seconds\": %.6f}\n",
      args.particles, static_cast<unsigned long long>(steps), static_cast<unsigned long long>(candidates),
      static_cast<unsigned long long>(collisions), seconds);
  return 0;
}
