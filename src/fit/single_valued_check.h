// Is the data single-valued in the orthogonal coordinates, i.e. does every ray from the centre
// cross it once (Bae 2002, §2.1: r = F(θ) must be a function)? The angle (or angle × height)
// domain is cut into cells of ~32 points; in each, the radii minus a local quadratic trend must
// form one cluster. Two clusters farther apart than the noise (8 robust σ, and at least 1e-4 of
// the typical radius) whose points interleave across the cell are two branches: a fold.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <vector>

#include "src/fit/parallel.h"

namespace polarform {

struct FoldRegion {
  double s0 = 0.0, s1 = 0.0;  // extent in the first coordinate (the angle for curves)
  double t0 = 0.0, t1 = 0.0;  // extent in the second coordinate (0 for curves)
  double separation = 0.0;    // largest radial distance between branches found (units of r)
  std::size_t points = 0;
};

struct SingleValuedness {
  bool single_valued = true;
  double noise = 0.0;      // robust σ of the detrended radii within their branch
  double typical_radius = 0.0;  // the median radius
  double threshold = 0.0;  // branch separation counted as a fold
  std::vector<FoldRegion> folds;
};

// r over the coordinates s (curves: s only, t empty; surfaces: s and t of equal length). The
// coordinates should be comparably scaled (angles, or height and r̄·θ).
SingleValuedness check_single_valued(const Eigen::VectorXd& s, const Eigen::VectorXd& t,
                                     const Eigen::VectorXd& r, int threads = 1);

// The largest scatter of the detrended radii, as a fraction of the typical radius, of data that
// lies on a curve or surface r = F: more is a filled region (a disc, a solid), not a profile.
constexpr double kMaxRelativeScatter = 0.05;

// Throws InputError "<fit>: the points fill a region …" when check.noise exceeds
// kMaxRelativeScatter · check.typical_radius.
void require_thin_data(const SingleValuedness& check, const std::string& fit);

// How many fold regions describe_folds lists before it counts the rest.
constexpr std::size_t kListedFolds = 3;

// "[a, b]" lists of the first kListedFolds fold regions (then "… and N more"), the first
// coordinate scaled by s_unit (e.g. 180/π for degrees) and labelled s_name; the second likewise
// when present.
std::string describe_folds(const SingleValuedness& check, const std::string& s_name, double s_unit,
                           const std::string& t_name = "", double t_unit = 1.0);

}  // namespace polarform
