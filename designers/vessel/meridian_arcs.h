// The exact polar form R(θ) (about the head's polar origin, θ from the radial direction towards the
// axis) of the curves classical vessel heads are made of: a circular arc, an ellipse about the
// origin and a straight line (a cone), with derivatives up to third order in closed form. The
// preset heads are built from them; tests check them against their implicit equations.
#pragma once

namespace polarform {

// The circle of centre (cx, cz) and radius r in the meridian plane (x radial, z axial): R(θ) is
// the far intersection of the ray at θ, R = s + √(s² − q) with s = cx cos θ + cz sin θ and
// q = cx² + cz² − r². Writes R, R', …, R^(d) (d <= 3) into out; needs s² >= q (the ray meets it).
void circle_polar(double cx, double cz, double r, double theta, int d, double* out);

// The ellipse about the origin with semi-axis a along x and b along z:
// R = ab (b² cos²θ + a² sin²θ)^{-1/2}. Writes R, …, R^(d) (d <= 3) into out.
void ellipse_polar(double a, double b, double theta, int d, double* out);

// The straight line n·p = d with unit normal n = (cos β, sin β) (d > 0: the origin on its inner
// side): R = d / cos(θ − β). Writes R, …, R^(d) (d <= 3) into out; needs cos(θ − β) > 0.
void line_polar(double beta, double distance, double theta, int d, double* out);

}  // namespace polarform
