// The automatic choice between spherical and cylindrical fitting (Bae 2002, §4.3 and §4.5: sphere-
// like parts are fitted spherically, cylinder-like ones cylindrically): from the type of the
// best-fit quadric, and, where the type does not decide or the preferred fit fails, from the error
// each fit actually achieves. The reason for the choice is returned with the numbers behind it.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <optional>
#include <string>
#include <variant>

#include "src/fit/cylindrical_fit.h"
#include "src/fit/frame_candidates.h"
#include "src/fit/spherical_fit.h"

namespace polarform {

enum class FitMethod { spherical, cylindrical };
std::string to_string(FitMethod method);

struct RotationalFitOptions {
  SphericalFitOptions spherical;
  CylindricalFitOptions cylindrical;
  std::optional<FitMethod> method;  // forces the method when given
};

struct RotationalFit {
  std::variant<SphericalFit, CylindricalFit> fit;
  std::string reason;
  // Every frame tried with the chosen method, with the error its fit achieved and whether F(u)
  // alone explained the data in it; the fit uses the best by the rule of fit_rotational (empty
  // when origin and axis were both given).
  std::vector<FrameCandidate> frame_candidates;
  int chosen_candidate = -1;  // the index of the frame used in frame_candidates (-1: none listed)

  FitMethod method() const;
  const NurbsSurface& surface() const;
  const FitReport& report() const;
  FitReport& report();
  const FrameEstimate& frame() const;
};

// Real ellipsoid → spherical; real elliptic cylinder or hyperboloid of one sheet → cylindrical;
// cone, elliptic paraboloid, hyperboloid of two sheets → both, the smaller RMS distance wins. A
// preferred fit that fails (not single-valued, tolerance not met) falls back to the other. Throws
// the preferred method's error when both fail. Unless origin and axis are both given, the chosen
// method is then refitted in more frames, a given origin or axis kept fixed in each: the
// least-squares axis line and the PCA axis refined by the rotational criterion
// (profile_refined_axis) for cylindrical fits; the least-squares centre and the axis refined by
// the rotational criterion through it for spherical ones. A frame in which the F-test made F(u)
// alone (a surface of revolution) replaces one that needs F(u, v) unless the latter's true
// distances are smaller beyond the noise (the extra-sum-of-squares F-test of the two fits, level
// kRevolutionAlpha): F(u, v) in a tilted frame absorbs the tilt, so its rms alone cannot tell the
// frames apart. Otherwise an rms smaller by more than 0.1 % wins. Clouds of more than 200,000
// points score the frames on a strided subsample of 100,000 with the first fit's net and fit only
// the winner to every point.
RotationalFit fit_rotational(const Eigen::Matrix3Xd& points, const RotationalFitOptions& options = {});
RotationalFit fit_rotational(const std::filesystem::path& file, const RotationalFitOptions& options = {},
                             const ReadOptions& read = {});

}  // namespace polarform
