#include "export/colormap.h"

#include <algorithm>
#include <cmath>

namespace polarform {

Eigen::Vector3d diverging_color(double d, double limit) {
  const double t = std::clamp(d / limit, -1.0, 1.0);
  const Eigen::Vector3d white(1.0, 1.0, 1.0), blue(0.13, 0.4, 0.67), red(0.7, 0.09, 0.17);
  return t < 0 ? Eigen::Vector3d(white + (-t) * (blue - white))
               : Eigen::Vector3d(white + t * (red - white));
}

Eigen::Vector3d sequential_color(double v, double lo, double hi) {
  // viridis at 0, 1/8, ..., 1.
  static const double anchors[9][3] = {
      {0.267, 0.005, 0.329}, {0.279, 0.175, 0.483}, {0.230, 0.322, 0.546},
      {0.173, 0.449, 0.558}, {0.128, 0.567, 0.551}, {0.153, 0.683, 0.502},
      {0.369, 0.789, 0.383}, {0.678, 0.864, 0.190}, {0.993, 0.906, 0.144}};
  const double t = hi > lo ? std::clamp((v - lo) / (hi - lo), 0.0, 1.0) : 0.5;
  const double x = 8.0 * t;
  const int i = std::min(7, static_cast<int>(std::floor(x)));
  const double f = x - i;
  Eigen::Vector3d c;
  for (int k = 0; k < 3; ++k) c[k] = (1 - f) * anchors[i][k] + f * anchors[i + 1][k];
  return c;
}

std::array<unsigned char, 3> to_rgb8(const Eigen::Vector3d& c) {
  std::array<unsigned char, 3> out{};
  for (int k = 0; k < 3; ++k)
    out[static_cast<std::size_t>(k)] =
        static_cast<unsigned char>(std::lround(255.0 * std::clamp(c[k], 0.0, 1.0)));
  return out;
}

}  // namespace polarform
