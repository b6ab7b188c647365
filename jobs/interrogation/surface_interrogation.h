// Surface interrogation of fitted and recovered surfaces (MIT 13.472J §8.2.4; spec M5): Gaussian,
// mean and absolute curvature on a tessellation of every surface, their extremes, the area
// fractions of elliptic (K > 0), hyperbolic (K < 0) and parabolic regions, and reflection lines
// from a light set chosen from the surfaces themselves. `--interrogate` of fit, sweep and patch
// writes curvature.x3d (the coloured tessellation, the exact surface in a Switch), curvature.ply
// and reflection.x3d from it.
#pragma once

#include <array>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "src/nurbs/nurbs_surface.h"
#include "src/nurbs/surface_curvature.h"

namespace polarform {

enum class CurvatureQuantity { gaussian, mean, absolute };
std::string curvature_quantity_name(CurvatureQuantity q);

struct InterrogatedSurface {
  NurbsSurface surface;
  std::vector<double> u, v;             // tessellation parameters (tessellation.h)
  std::vector<Eigen::Vector3d> points;  // at (u[i], v[j]), index i·v.size() + j
  std::vector<Eigen::Vector3d> normals;  // unit, a pole's from its neighbours (tessellation.h)
  std::vector<double> gaussian, mean, absolute, reflection;  // NaN where degenerate / unlit
};

struct SurfaceInterrogation {
  CurvatureQuantity shown = CurvatureQuantity::gaussian;
  std::vector<InterrogatedSurface> surfaces;
  double min_gaussian = 0, max_gaussian = 0, min_mean = 0, max_mean = 0, min_absolute = 0,
         max_absolute = 0;
  // Of the total area (tessellation cells classified by K at corners and centre, mixed ones
  // quartered 6 levels deep; |K| <= 1e-9·max|K| is parabolic).
  double elliptic_area_fraction = 0, hyperbolic_area_fraction = 0, parabolic_area_fraction = 0;
  double area = 0;  // mm²
  ReflectionLights lights;
};

// Each surface tessellated with `steps` equal steps per direction plus its knots.
SurfaceInterrogation interrogate_surfaces(const std::vector<NurbsSurface>& surfaces,
                                          CurvatureQuantity shown, int steps = 64);

// curvature.x3d, reflection.x3d (text) of the interrogation; `title` names the part.
std::map<std::string, std::string> interrogation_x3d(const SurfaceInterrogation& q,
                                                     const std::string& title);

// The vertices of every tessellation, their colours (by the shown quantity) and values, for
// curvature.ply.
struct InterrogationCloud {
  Eigen::Matrix3Xd points;
  std::vector<std::array<unsigned char, 3>> colors;
  std::vector<double> values;
};
InterrogationCloud interrogation_cloud(const SurfaceInterrogation& q);

// Writes curvature.ply, or that and curvature.x3d, reflection.x3d, into the transaction (dir is its
// folder).
class OutputTransaction;
void add_interrogation_ply(OutputTransaction& outputs, const std::filesystem::path& dir,
                           const SurfaceInterrogation& q);
void add_interrogation_files(OutputTransaction& outputs, const std::filesystem::path& dir,
                             const SurfaceInterrogation& q, const std::string& title);
// Their names, sorted.
std::vector<std::string> interrogation_file_names();

// report.json's "interrogation" of a surface: shown, {min,max}_{gaussian,mean,absolute},
// elliptic/hyperbolic/parabolic_area_fraction, area_mm2.
nlohmann::ordered_json surface_interrogation_json(const SurfaceInterrogation& q);

}  // namespace polarform
