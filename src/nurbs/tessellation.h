// Sampling NURBS curves and surfaces for drawing: the parameters of [a, b] in equal steps plus
// every distinct interior knot (so corners and curvature jumps at knots are hit exactly), a curve's
// points there, and a surface's grid of points and unit normals. Every figure, view and mesh that
// draws a NURBS samples it here; measurements that need equal parameter steps sample on their own.
#pragma once

#include <vector>

#include "src/nurbs/knots.h"
#include "src/nurbs/nurbs_curve.h"
#include "src/nurbs/nurbs_surface.h"

namespace polarform {

// a + (b − a)·k / count for k = 0..count and every distinct knot strictly inside (a, b), sorted and
// without duplicates: a step closer than 1e-12·(b − a) to a knot gives way to the knot, so the knot
// itself is sampled. `knots` is a knot vector (sorted). Throws InputError unless count >= 1 and
// a < b, both finite.
std::vector<double> tessellation_parameters(const Knots& knots, double a, double b, int count);

template <int Dim>
struct CurveTessellation {
  std::vector<double> parameters;           // tessellation_parameters over the curve's domain
  typename NurbsCurve<Dim>::Points points;  // points[k] = C(parameters[k])
};

// The curve at tessellation_parameters(knots, front, back, count).
CurveTessellation<2> tessellate(const NurbsCurve2d& curve, int count);
CurveTessellation<3> tessellate(const NurbsCurve3d& curve, int count);

struct SurfaceTessellation {
  std::vector<double> u, v;  // tessellation_parameters in u and in v
  // At (u[i], v[j]), index i * v.size() + j: S(u, v) and the unit normal S_u × S_v.
  NurbsSurface::Points points, normals;
};

// The surface on the grid of tessellation_parameters in u (count_u steps) and v (count_v steps).
// A degenerate normal (S_u × S_v = 0, as at a pole) is taken from the neighbouring sample along u
// (the next one, or in the last row the previous one, after its own replacement); where that one
// degenerates too — a pole whose row runs along u, as a revolved profile's point on the axis — from
// the neighbour along v in the same way.
SurfaceTessellation tessellate(const NurbsSurface& surface, int count_u, int count_v);

}  // namespace polarform
