// The scanned-cam pipeline: a 2D or 3D scan of a plate cam → its planar profile about the centre
// of rotation (cam_scan_profile.h) → a closed polar NURBS profile (Bae 2002, ch. 2) with the
// fairness weight chosen by GCV → with a nominal design, the phase (and mirror) that aligns the
// scan to it (phase_alignment.h), and the profile refitted in the nominal's cam frame → the
// follower displacement recovered by inverting the follower geometry (follower_inversion.h) and
// smoothed by GCV (displacement_fit.h), whose derivatives are the SVAJ.
#pragma once

#include <Eigen/Core>
#include <optional>

#include "designers/cam/plate_cam.h"
#include "designers/scan/cam_scan_profile.h"
#include "designers/scan/displacement_fit.h"
#include "designers/scan/phase_alignment.h"
#include "src/fit/polar_curve_fit.h"

namespace polarform {

struct ScannedCamOptions {
  CamProfileOptions profile;
  Follower follower;  // the follower that reads the displacement
  Rotation rotation = Rotation::CounterClockwise;
  std::optional<PlateCam> nominal;  // align to it when given (its follower is not implied)
  int contour_ctrl = 144;           // F's control values over the revolution (2.5° each)
  DisplacementFitOptions displacement;
  int threads = 2;
};

struct ScannedCam {
  CamProfile profile;
  bool mirrored = false;                    // the scan was seen from the other face (nominal only)
  std::optional<PhaseAlignment> alignment;  // nominal only
  // The cam frame in the scan's coordinates: origin = centre of rotation, k = axis, and i the
  // cam frame's x (θ = 0 puts the follower on its +y side); with a nominal, its own cam frame.
  LocalFrame cam_frame;
  Eigen::Matrix2Xd contour;    // the contour points in the cam frame
  PolarCurveFit fit;           // the profile in the cam frame
  double contour_noise = 0.0;  // σ̂ of the profile residuals (normal distances), mm
  FollowerSamples samples;
  DisplacementFit displacement;
  double measured_rest_height = 0.0;  // min over θ of the fitted y0 + s
  double rest_height = 0.0;           // y0 that s is measured from (nominal's, else measured)
  double base_radius = 0.0;           // Rb recovered from measured_rest_height and the follower
  Follower follower;
  Rotation rotation = Rotation::CounterClockwise;

  // s, s', …, s^(d) at cam angle θ (d <= 3), mm/rad^k.
  void displacement_derivatives(double theta, int d, double* out) const;
  // The fitted profile's radius at polar angle ψ of the cam frame (Bae 2002, eq. (2.1)).
  double radius(double psi) const;
};

// Throws InputError (see extract_cam_profile, fit_polar_curve, invert_follower) or
// NumericalError.
ScannedCam analyse_scanned_cam(const Eigen::Matrix3Xd& points, const ScannedCamOptions& options);

// The rest height y0 of a follower on a cam of base radius Rb (plate_cam.h): sqrt(Rp² − e²), or
// Rb for a flat face; and its inverse.
double rest_height(const Follower& follower, double base_radius);
double base_radius_from_rest(const Follower& follower, double rest_height);

}  // namespace polarform
