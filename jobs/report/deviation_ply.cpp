#include "jobs/report/deviation_ply.h"

#include <algorithm>
#include <array>
#include <vector>

#include "export/atomic_file.h"
#include "export/colormap.h"
#include "export/ply_writer.h"
#include "src/fit/error_stats.h"

namespace polarform {

void add_deviation_ply(OutputTransaction& outputs, const std::filesystem::path& dir,
                       const Eigen::Matrix3Xd& points, const Eigen::VectorXd& d, double limit) {
  if (!(limit > 0)) limit = std::max(abs_quantile(d, 0.99), 1e-9);
  std::vector<std::array<unsigned char, 3>> colors(static_cast<std::size_t>(d.size()));
  std::vector<double> deviation(colors.size());
  for (Eigen::Index k = 0; k < d.size(); ++k) {
    colors[static_cast<std::size_t>(k)] = to_rgb8(diverging_color(d[k], limit));
    deviation[static_cast<std::size_t>(k)] = d[k];
  }
  outputs.add("deviation.ply",
              ply_writer(dir / "deviation.ply", points, &colors, &deviation, "deviation"));
}

}  // namespace polarform
