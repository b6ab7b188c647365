#include "jobs/cam/cam_job.h"

#include <algorithm>
#include <chrono>
#include <numbers>

#include "designers/cam/contour_polar_function.h"
#include "src/error.h"
#include "src/number_text.h"
#include "src/nurbs/symbolic_product.h"

namespace polarform {

namespace {

// The track centre line (Rc·X, Rc·Y, z): the base circle's homogeneous rows times the factors
// (Rc, F − offset, 1), with F the converted track height (Bae 2002, eq. (B.3) in curve form).
NurbsCurve3d track_curve(const PolarConversion& c, double radius, double offset) {
  const BSpline& F = c.function.spline();
  Eigen::MatrixXd rows(3, F.size());
  rows.row(0).setConstant(radius);
  rows.row(1) = F.coefs().row(0).array() - offset;
  rows.row(2).setOnes();
  return NurbsCurve3d(product_rows(BSpline(F.degree(), F.knots(), std::move(rows)), {0, 0, 1, 2},
                                   c.base.curve().homogeneous(), {0, 1, 2, 2}));
}

// The track height z(φ) + offset as the converter's (positive) polar function, exact form kept.
PolarFunction offset_track_height(const BarrelCam& barrel, double offset) {
  PolarFunction f = barrel.track_height();
  const auto height = f.derivatives;
  f.derivatives = [height, offset](double t, int d, double* out) {
    height(t, d, out);
    out[0] += offset;
  };
  if (f.exact) {
    const BSpline& e = f.exact->spline();
    f.exact = BSplineFunction(
        BSpline(e.degree(), e.knots(), Eigen::MatrixXd(e.coefs().array() + offset)));
  }
  return f;
}

}  // namespace

double track_height_offset(const CamDesign& design) {
  // s >= 0 is measured from the lowest level, so z >= z0.
  return std::max(0.0, -design.z0) + design.cylinder_radius;
}

PolarFunction cam_profile_function(const CamDesign& design) {
  if (design.type == CamType::Plate) return cam_polar_function(make_plate_cam(design));
  return offset_track_height(make_barrel_cam(design), track_height_offset(design));
}

CamJobResult run_cam_job(const CamProject& project, const CamJobOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  if (!(project.conversion.tolerance >= kMinTolerance))
    throw InputError("conversion tolerance " + format_round_trip(project.conversion.tolerance) +
                     " mm: expected >= " + format_round_trip(kMinTolerance) + " mm");
  const CamDesign& design = project.cam;
  CamJobResult r(project, make_program(design));
  r.continuity = check_continuity(r.program, 2);
  r.angles = uniform_angles(options.analysis_angles);
  for (double theta : r.angles) r.kinematics.push_back(r.program.kinematics(theta, design.rpm));

  if (design.type == CamType::Plate) {
    r.plate = make_plate_cam(design);
    r.analysis = analyse(*r.plate, r.angles);
    r.profile_function = cam_polar_function(*r.plate);
    r.conversion = convert_polar_function(r.profile_function, project.conversion);
    r.profile = r.conversion.curve;
    // The degree-limited profile is an extra: when its degree cannot reach the tolerance the
    // exact profile still stands, so the job says so instead of failing.
    if (options.with_limited) try {
        r.limited = approximate_polar_curve(r.profile_function, options.limited_degree,
                                            project.conversion.tolerance);
      } catch (const NumericalError& e) {
        r.warnings.push_back("degree-" + std::to_string(options.limited_degree) +
                             " profile not written: " + e.what());
      }
    if (project.max_degree && r.profile.degree() > *project.max_degree)
      r.capped = approximate_polar_curve(r.profile_function, *project.max_degree,
                                         project.conversion.tolerance);
  } else {
    r.barrel = make_barrel_cam(design);
    for (double theta : r.angles)
      r.barrel_pressure_angle.push_back(r.barrel->pressure_angle(theta, design.cylinder_radius));
    r.track_offset = track_height_offset(design);
    r.profile_function = offset_track_height(*r.barrel, r.track_offset);
    r.conversion = convert_polar_function(r.profile_function, project.conversion);
    r.track = track_curve(r.conversion, design.cylinder_radius, r.track_offset);
    if (design.groove_depth > 0) {
      const GrooveOptions groove{design.cylinder_radius - design.groove_depth / 2,
                                 design.cylinder_radius + design.groove_depth / 2,
                                 project.conversion.tolerance, project.conversion.alpha};
      for (int side : {-1, 1}) r.groove.push_back(groove_surface(*r.barrel, side, groove));
    }
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace polarform
