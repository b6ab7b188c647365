#include "designers/cam/groove_wall.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "src/error.h"
#include "src/number_text.h"

namespace polarform {

namespace {

constexpr int kMaxIterations = 60;
// Newton converges quadratically: once a step is below this (relative), the new iterate is at
// round-off.
constexpr double kConverged = 1e-10;

}  // namespace

GrooveWall::GrooveWall(const BarrelCam& cam, int side) : cam_(cam), side_(side) {
  if (side != 1 && side != -1) throw InputError("groove wall: side must be +1 or -1");
}

double GrooveWall::min_radius() const { return std::sqrt(2.0) * cam_.roller_radius(); }

// g(t) = t² + Rr² a²/(a² + t²) − ρ², g'(t) = 2t (1 − Rr² a²/(a² + t²)²) > 0 for t >= Rr; the root
// lies in [sqrt(ρ² − Rr²), ρ] (cos² α <= 1). Newton, kept inside the bracket by bisection.
double GrooveWall::distance(double a, double rho) const {
  const double rr = cam_.roller_radius(), a2 = a * a;
  double lo = std::sqrt(std::max(0.0, rho * rho - rr * rr)), hi = rho, t = hi;
  for (int i = 0; i < kMaxIterations; ++i) {
    const double q = a2 + t * t;
    const double g = t * t + rr * rr * a2 / q - rho * rho;
    if (g == 0) return t;
    if (g > 0)
      hi = t;
    else
      lo = t;
    const double dg = 2 * t * (1 - rr * rr * a2 / (q * q));
    double next = t - g / dg;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - t) <= kConverged * rho) return next;
    t = next;
  }
  return t;
}

// ψ = φ + atan(c/t), c = side σ Rr a/L, L = sqrt(a² + t²), with t(θ) from g(θ, t) = 0:
// t' = −g_θ/g_t, g_θ = 2 Rr² a a' t²/L⁴, g_t = 2t (1 − Rr² a²/L⁴), c' = side σ Rr (a' t² − a t
// t')/L³, ψ' = φ' + (t c' − c t')/ρ² (t² + c² = ρ²); φ' = −σ (cam_frame.h).
void GrooveWall::polar_angle(double theta, double rho, double* psi, double* rate) const {
  double s[3];
  cam_.program().derivatives(theta, 2, s);
  const double sigma = sense(cam_.rotation()), rr = cam_.roller_radius(), k = side_ * sigma;
  const double a = s[1], da = s[2], t = distance(a, rho);
  const double L2 = a * a + t * t, L = std::sqrt(L2), L4 = L2 * L2;
  const double c = k * rr * a / L;
  const double dt = -(2 * rr * rr * a * da * t * t / L4) / (2 * t * (1 - rr * rr * a * a / L4));
  const double dc = k * rr * (da * t * t - a * t * dt) / (L2 * L);
  *psi = std::numbers::pi / 2 - sigma * theta + std::atan2(c, t);
  *rate = -sigma + (t * dc - c * dt) / (t * t + c * c);
}

// θ with ψ(θ) = ψ: |ψ − φ(θ)| = |asin(c/ρ)| <= asin(Rr/ρ), so the root lies within that of
// θ0 = σ(π/2 − ψ); Newton safeguarded by bisection on the bracket.
WallPoint GrooveWall::at(double psi, double rho) const {
  if (!(rho >= min_radius() * (1 - 1e-12)))
    throw InputError("groove wall: radius " + number_text(rho) +
                     " mm is below √2·Rr = " + number_text(min_radius()) + " mm");
  const double sigma = sense(cam_.rotation());
  const double theta0 = sigma * (std::numbers::pi / 2 - psi);
  const double delta = std::asin(std::min(1.0, cam_.roller_radius() / rho)) * (1 + 1e-9) + 1e-12;
  double lo = theta0 - delta, hi = theta0 + delta, p, rate;
  polar_angle(lo, rho, &p, &rate);
  const double f_lo = p - psi;
  polar_angle(hi, rho, &p, &rate);
  if (f_lo * (p - psi) > 0)
    throw NumericalError("groove wall: no contact at polar angle " + degrees_text(psi) +
                         ", radius " + number_text(rho) + " mm");
  double theta = theta0;
  for (int i = 0; i < kMaxIterations; ++i) {
    polar_angle(theta, rho, &p, &rate);
    const double f = p - psi;
    if (f == 0) break;
    if ((f < 0) == (f_lo < 0))
      lo = theta;
    else
      hi = theta;
    if (rate * -sigma <= 0)
      throw NumericalError("groove wall: not single-valued in polar angle near " +
                           degrees_text(psi) + " at radius " + number_text(rho) +
                           " mm (the groove undercuts itself)");
    double next = theta - f / rate;
    if (!(next > std::min(lo, hi) && next < std::max(lo, hi))) next = 0.5 * (lo + hi);
    if (std::abs(next - theta) <= kConverged * (1 + std::abs(theta))) {
      theta = next;
      break;
    }
    theta = next;
  }
  double s[2];
  cam_.program().derivatives(theta, 1, s);
  const double t = distance(s[1], rho);
  return {theta, t, cam_.z0() + s[0] + side_ * cam_.roller_radius() * t / std::hypot(s[1], t)};
}

}  // namespace polarform
