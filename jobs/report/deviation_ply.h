// deviation.ply of a job's bundle: every point coloured by its signed distance on the diverging
// map (±limit saturates), with the distance itself as the property `deviation`.
#pragma once

#include <Eigen/Core>
#include <filesystem>

namespace polarform {

class OutputTransaction;

// limit <= 0: the 99th percentile of |distance| (at least 1e-9).
void add_deviation_ply(OutputTransaction& outputs, const std::filesystem::path& dir,
                       const Eigen::Matrix3Xd& points, const Eigen::VectorXd& distances,
                       double limit = 0.0);

}  // namespace polarform
