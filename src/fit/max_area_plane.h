// The plane a surface blanket projects onto with the largest area (Piegl & Tiller 2001, §3.2; spec
// P5), and the fold check that decides whether a projection to a plane can parametrise it.
#pragma once

#include <Eigen/Core>

#include "src/nurbs/surface_decomposition.h"

namespace polarform {

struct MaxAreaPlane {
  Eigen::Vector3d normal;             // N* = A/|A|, A = Σ A_k the vector area (maximises Σ A_k·N)
  Eigen::Vector3d eigen_normal;       // the seed's choice: dominant eigenvector of Σ A_k A_kᵀ
  double angle_between_deg = 0.0;     // between the two (sign-free)
  Eigen::Vector3d lsq_normal;         // total-least-squares plane of the vertices, for the report
  Eigen::Vector3d centroid;           // of the blanket vertices
  double projected_area = 0.0;        // Σ A_k·normal
  double area = 0.0;                  // Σ |A_k|
  int folded_triangles = 0;           // triangles with A_k·normal <= 0: not projectable
};

// Two triangles per quad, (a,b)(a+1,b)(a+1,b+1) and (a,b)(a+1,b+1)(a,b+1), oriented by u × v.
MaxAreaPlane max_area_plane(const SurfaceBlanket& blanket);

}  // namespace polarform
