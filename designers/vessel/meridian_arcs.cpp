#include "designers/vessel/meridian_arcs.h"

#include <cmath>

namespace polarform {

// Ray–circle intersection |R u(θ) − c|² = r², differentiated by the chain rule on h = √g.
void circle_polar(double cx, double cz, double r, double theta, int d, double* out) {
  const double c = std::cos(theta), s_ = std::sin(theta);
  const double s0 = cx * c + cz * s_, s1 = -cx * s_ + cz * c, s2 = -s0, s3 = -s1;
  const double q = cx * cx + cz * cz - r * r;
  const double g0 = s0 * s0 - q, g1 = 2 * s0 * s1, g2 = 2 * (s1 * s1 + s0 * s2),
               g3 = 2 * (3 * s1 * s2 + s0 * s3);
  const double h0 = std::sqrt(g0), h1 = g1 / (2 * h0), h2 = (g2 - 2 * h1 * h1) / (2 * h0),
               h3 = (g3 - 6 * h1 * h2) / (2 * h0);
  const double R[4] = {s0 + h0, s1 + h1, s2 + h2, s3 + h3};
  for (int k = 0; k <= d; ++k) out[k] = R[k];
}

// 1/R² = cos²θ/a² + sin²θ/b², written as R = ab g^{-1/2} with g = (a²+b²)/2 − (a²−b²)/2 cos 2θ.
void ellipse_polar(double a, double b, double theta, int d, double* out) {
  const double e = a * a - b * b, c2 = std::cos(2 * theta), s2 = std::sin(2 * theta);
  const double g = 0.5 * (a * a + b * b) - 0.5 * e * c2, g1 = e * s2, g2 = 2 * e * c2,
               g3 = -4 * e * s2;
  const double ab = a * b, r = 1 / std::sqrt(g);  // g^{-1/2}
  const double r3 = r * r * r, r5 = r3 * r * r, r7 = r5 * r * r;
  const double R[4] = {ab * r, -0.5 * ab * r3 * g1, ab * (0.75 * r5 * g1 * g1 - 0.5 * r3 * g2),
                       ab * (-1.875 * r7 * g1 * g1 * g1 + 2.25 * r5 * g1 * g2 - 0.5 * r3 * g3)};
  for (int k = 0; k <= d; ++k) out[k] = R[k];
}

// R = d·sec u with u = θ − β: sec' = sec·tan, tan' = sec², so R' = d·s·t, R'' = d(s·t² + s³),
// R''' = d(s·t³ + 5s³·t) with s = sec u, t = tan u.
void line_polar(double beta, double distance, double theta, int d, double* out) {
  const double s = 1 / std::cos(theta - beta), t = std::tan(theta - beta);
  const double R[4] = {distance * s, distance * s * t, distance * (s * t * t + s * s * s),
                       distance * (s * t * t * t + 5 * s * s * s * t)};
  for (int k = 0; k <= d; ++k) out[k] = R[k];
}

}  // namespace polarform
