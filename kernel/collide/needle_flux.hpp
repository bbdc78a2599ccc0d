#pragma once
// The needle intruder in a 2D Gaussian bath (002 sec. 3.2, derivation in docs/methods/derivations/needle.md):
// collision rates, the free-flight event time, exact sampling of the collision and its outcome.
//
// Bath: point particles of mass m = 1, number density rho per area, f(v) = (a / pi) exp(-a |v|^2), so
// T_B = 1 / (2a) per degree of freedom. Only the normal component c = v.n enters a collision with a thin,
// smooth needle, and its marginal is 002 eq. (18), sqrt(a / pi) exp(-a c^2): the per-length fluxes are the
// 1D ones of collide/bath_gaussian.hpp. Needle: length L, mass M, moment of inertia I, centre velocity
// v1, angle theta of its axis t = (cos theta, sin theta), normal n = (-sin theta, cos theta), angular
// velocity omega. The point at distance x from the centre (-L/2 <= x <= L/2) moves with normal velocity
// u = v_n + omega x, v_n = v1.n (002 eq. 24).
//
// Rates, in y = sqrt(a) v_n, s = sqrt(a) |omega| L / 2:
//   per length, + side (bath on the +n side, c <= u): phi_+(u) (002 eq. 19); both sides phi(u) =
//   (rho / sqrt a) phihat(sqrt(a) u), phihat(y) = exp(-y^2) / sqrt(pi) + y erf(y) (002 eq. 20);
//   whole needle: Phi = int phi(v_n + omega x) dx = (rho L / sqrt a) Phihat(y, s) (002 eqs. 25-26), with
//   Phihat(y, s) = [Ghat(y + s) - Ghat(y - s)] / (2 s), Ghat(z) = (z^2/2 + 1/4) erf(z) + z exp(-z^2) / (2 sqrt pi),
//   Ghat' = phihat; per side Phi_+- = (Phi +- rho L v_n) / 2.
// Time dependence: between collisions v1 and omega are constant and theta = theta_0 + omega t, so
// v_n(t) = |v1| sin(beta - theta(t)) (beta the direction of v1) oscillates and Phi(t) with it, between
// Phi(0, omega) and Phi(|v1|, omega) (Phi is even and convex in v_n). The event time solves
// int_0^t Phi = -ln xi (002 eq. 27) by Newton (002 eq. 28) safeguarded by a bisection fallback.
// Sampling, all exact for every state:
//   impact point x (002 eq. 29): density phi(v_n + omega x) / Phi; uniform proposal on [-L/2, L/2],
//     accepted with phi(u) / phi(|v_n| + |omega| L / 2) (phi is even, convex: its maximum is at an end);
//     acceptance >= 1 - 1/sqrt(2) by the bounds max(|y|, 1/sqrt(pi)) <= phihat(y) <= |y| + 1/sqrt(pi), and
//     numerically >= sqrt(2) - 1 (its limit for long windows);
//   side (002 eq. 30): + with probability phi_+(u) / phi(u);
//   normal velocity of the bath particle: g_+(c; u) (002 eq. 14), g_-(c; u) = g_+(-c; -u) (002 eq. 17),
//     by GaussianBath::try_sample_right.
// Outcome: 002 eqs. (31)-(33) with m = 1.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

#include "kernel/collide/bath_gaussian.hpp"
#include "kernel/collide/bath_power_law.hpp"
#include "kernel/core/philox_stream.hpp"
#include "kernel/core/sampling.hpp"

namespace granmc {

/// The needle's mass and moment of inertia (the bath particle's mass is 1).
struct NeedleBody {
  double mass = 1.0;     // M
  double inertia = 1.0;  // I
};

/// The needle's velocities and orientation.
struct NeedleState {
  double vx = 0.0, vy = 0.0;  // centre of mass velocity v1
  double theta = 0.0;         // angle of the axis t = (cos theta, sin theta)
  double omega = 0.0;         // angular velocity

  /// v_n = v1.n, n = (-sin theta, cos theta) (002 eq. 24).
  [[nodiscard]] double normal_velocity() const noexcept { return vy * std::cos(theta) - vx * std::sin(theta); }
};

/// The needle in a bath whose normal-velocity marginal is the 1D law of Bath (GaussianBath, 002 eq. 18, or
/// PowerLawBath, 002 eq. 23): Bath::unit_flux and Bath::unit_total_flux give phi and Phi in scaled units.
template <class Bath>
struct NeedleBath {
  Bath bath;            // a and rho of the bath
  double length = 1.0;  // L

  /// phi_+(u): collisions per unit time and length on the + side (002 eq. 19).
  [[nodiscard]] double flux_right(double u) const noexcept { return bath.flux_right(u); }

  /// phi(u) = phi_+(u) + phi_-(u), both sides (002 eq. 20).
  [[nodiscard]] double flux(double u) const noexcept {
    const double sa = std::sqrt(bath.a);
    return bath.rho / sa * Bath::unit_flux(sa * u);
  }

  /// Phi(v_n, omega) = int_{-L/2}^{L/2} phi(v_n + omega x) dx, both sides (002 eqs. 25-26).
  [[nodiscard]] double total_flux(double vn, double omega) const noexcept {
    const double sa = std::sqrt(bath.a);
    return bath.rho * length / sa * Bath::unit_total_flux(sa * vn, 0.5 * sa * std::fabs(omega) * length);
  }

  /// Phi_+(v_n, omega) = int phi_+(v_n + omega x) dx = (Phi + rho L v_n) / 2 (phi_+ - phi_- = rho u, 002 eq. 19).
  [[nodiscard]] double total_flux_right(double vn, double omega) const noexcept {
    return 0.5 * (total_flux(vn, omega) + bath.rho * length * vn);
  }

  /// One attempt at the impact point x (002 eq. 29) with u[0], u[1]; on acceptance sets x.
  bool try_sample_position(double vn, double omega, const RandomBlock& u, double& x) const noexcept {
    const double candidate = (uniform_open(u[0]) - 0.5) * length;
    const double bound = flux(std::fabs(vn) + 0.5 * std::fabs(omega) * length);  // max of phi on the needle
    if (uniform_open(u[1]) * bound >= flux(vn + omega * candidate)) return false;
    x = candidate;
    return true;
  }

  /// The side hit at a point of normal velocity u: + when xi < phi_+(u) / phi(u) (002 eq. 30).
  [[nodiscard]] bool side_is_right(double u, double xi) const noexcept {
    const double right = bath.flux_right(u), left = bath.flux_right(-u);
    return xi * (right + left) < right;
  }

  /// One attempt at the colliding bath particle's normal velocity c from g_+(c; u) or g_-(c; u)
  /// (002 eqs. 14, 17); on acceptance sets c.
  bool try_sample_normal_velocity(double u, bool right, const RandomBlock& r, double& c) const noexcept {
    if (right) return bath.try_sample_right(u, r, c);
    if (!bath.try_sample_right(-u, r, c)) return false;
    c = -c;  // g_-(c; u) = g_+(-c; -u)
    return true;
  }
};

/// A collision at distance x from the centre with a bath particle of normal velocity c:
/// 002 eqs. (31)-(33) with m = 1, g.n = v1.n + omega x - c.
inline void needle_collision(NeedleState& s, const NeedleBody& body, double alpha, double x, double c) noexcept {
  const double nx = -std::sin(s.theta), ny = std::cos(s.theta);
  const double gn = s.normal_velocity() + s.omega * x - c;
  const double dp = -(1.0 + alpha) * gn / (1.0 + 1.0 / body.mass + x * x / body.inertia);  // 002 eq. (33)
  s.vx += nx * dp / body.mass;                                                             // 002 eq. (31)
  s.vy += ny * dp / body.mass;
  s.omega += x * dp / body.inertia;  // 002 eq. (32)
}

/// Work of the event-time root finder, summed over events.
struct EventTimeCounters {
  std::uint64_t newton_iterations = 0;    // Newton steps taken (002 eq. 28)
  std::uint64_t bisection_fallbacks = 0;  // bisection steps taken instead of a Newton step
};

/// The free flight from the last collision (t = 0): v1, omega constant, theta(t) = theta_0 + omega t.
template <class Bath>
class NeedleFlight {
 public:
  NeedleFlight(const NeedleBath<Bath>& needle, const NeedleState& start) noexcept
      : needle_(needle),
        speed_(std::hypot(start.vx, start.vy)),
        phase_(std::atan2(start.vy, start.vx) - start.theta),
        omega_(start.omega) {
    // Panel width of the quadrature of Phi(t): in y = sqrt(a) v_n, Phihat(y, s) is analytic with an O(1)
    // imaginary reach (exp(-y^2) grows as exp(Im(y)^2)) and has features of width 1 at y = 0 (s small) or
    // at |y| = s (the ends of the averaging window); y = Y sin(psi), Y = sqrt(a) |v1|, psi the phase. A
    // panel of phase width min(1, 1 / Y) keeps the 8-point Gauss-Legendre rule below 1e-14 relative
    // (checked against a fine reference in tests/test_needle.cpp).
    const double y = std::sqrt(needle.bath.a) * speed_;
    panel_phase_ = y > 1.0 ? 1.0 / y : 1.0;
  }

  /// v_n(t) = v1.n(t) = |v1| sin(beta - theta_0 - omega t) (002 eq. 24).
  [[nodiscard]] double normal_velocity(double t) const noexcept { return speed_ * std::sin(phase_ - omega_ * t); }

  /// Phi(t) (002 eq. 25).
  [[nodiscard]] double flux(double t) const noexcept { return needle_.total_flux(normal_velocity(t), omega_); }

  /// Bounds of Phi(t) over the flight: Phi(0, omega) <= Phi(t) <= Phi(|v1|, omega).
  [[nodiscard]] double min_flux() const noexcept { return needle_.total_flux(0.0, omega_); }
  [[nodiscard]] double max_flux() const noexcept { return needle_.total_flux(speed_, omega_); }

  /// int_{t0}^{t1} Phi(t) dt (002 eq. 27) by 8-point Gauss-Legendre on panels of phase width <= panel_phase_.
  [[nodiscard]] double integrated_flux(double t0, double t1) const noexcept {
    static constexpr double node[4] = {0.1834346424956498049, 0.5255324099163289858, 0.7966664774136267396,
                                       0.9602898564975362317};
    static constexpr double weight[4] = {0.3626837833783619830, 0.3137066458778872873, 0.2223810344533744705,
                                         0.1012285362903762592};
    const double phase = std::fabs(omega_ * (t1 - t0));
    const double panels = std::max(1.0, std::ceil(phase / panel_phase_));
    const double h = (t1 - t0) / panels;
    double sum = 0.0;
    for (double p = 0.0; p < panels; p += 1.0) {
      const double mid = t0 + (p + 0.5) * h;
      double panel = 0.0;
      for (int k = 0; k < 4; ++k) panel += weight[k] * (flux(mid - 0.5 * h * node[k]) + flux(mid + 0.5 * h * node[k]));
      sum += 0.5 * h * panel;
    }
    return sum;
  }

  /// The time t of the next collision: int_0^t Phi = e, e = -ln xi_3 > 0 (002 eq. 27). Newton (002 eq. 28)
  /// from t = e / Phi(0) (the paper's guess) inside the bracket [e / Phi_max, e / Phi_min], which holds the
  /// root since Phi_min <= Phi(t) <= Phi_max; a Newton step that leaves the bracket (Newton's oscillation,
  /// 002 after eq. 28) or that fails to halve the residual is replaced by a bisection step. Converged when
  /// the residual is below event_time_tolerance e or the bracket is a few ulps wide.
  static constexpr double event_time_tolerance = 1e-12;
  double event_time(double e, EventTimeCounters& counters) const noexcept {
    double lo = e / max_flux(), hi = e / min_flux();
    double t = e / flux(0.0);
    double lambda = integrated_flux(0.0, t);
    double previous = std::numeric_limits<double>::infinity();  // |residual| before the last step
    bool last_newton = false;
    for (int k = 0; k < max_iterations; ++k) {
      const double f = lambda - e;  // 002 eq. (27)
      if (std::fabs(f) <= event_time_tolerance * e) break;
      (f < 0.0 ? lo : hi) = t;
      if (hi - lo <= 4.0 * std::numeric_limits<double>::epsilon() * hi) break;
      const bool stalled = last_newton && std::fabs(f) > 0.5 * previous;
      double next = t - f / flux(t);  // 002 eq. (28)
      last_newton = !stalled && next > lo && next < hi;
      if (last_newton) {
        ++counters.newton_iterations;
      } else {
        next = 0.5 * (lo + hi);
        ++counters.bisection_fallbacks;
      }
      previous = std::fabs(f);
      lambda += integrated_flux(t, next);
      t = next;
    }
    return t;
  }

 private:
  static constexpr int max_iterations = 200;  // bisection alone needs < 60 from any bracket
  NeedleBath<Bath> needle_;
  double speed_;  // |v1|
  double phase_;  // beta - theta_0
  double omega_;
  double panel_phase_;  // largest phase omega dt of a quadrature panel
};

}  // namespace granmc
