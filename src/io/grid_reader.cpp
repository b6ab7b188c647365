#include "src/io/grid_reader.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <vector>

#include "src/error.h"
#include "src/io/csv_text.h"
#include "src/io/text_scan.h"
#include "src/number_text.h"
#include "src/units.h"

namespace polarform {

namespace {

using io_detail::trim;

// Fields separated by commas (blanks around them allowed) or, without commas, by blanks.
std::vector<std::string_view> fields(std::string_view line) {
  std::vector<std::string_view> out;
  const bool commas = line.find(',') != std::string_view::npos;
  while (true) {
    if (commas) {
      const std::size_t c = line.find(',');
      out.push_back(trim(line.substr(0, c)));
      if (c == std::string_view::npos) break;
      line.remove_prefix(c + 1);
    } else {
      line = trim(line);
      if (line.empty()) break;
      const std::size_t e = line.find_first_of(" \t");
      out.push_back(line.substr(0, e));
      if (e == std::string_view::npos) break;
      line.remove_prefix(e);
    }
  }
  return out;
}

const char* kHeaderHelp =
    "expected three column names: phi_deg and theta_deg (spherical set-up) or theta_deg and z_mm "
    "(cylindrical set-up), and the value under any other name";

}  // namespace

ScalarGrid parse_scalar_grid(std::string_view text, const std::string& name) {
  ScalarGrid g;
  int column[3] = {-1, -1, -1};  // value, first coordinate (phi or theta), second (theta or z)
  std::vector<double> rows[3];
  bool header = false;
  for_each_data_line(text, name, [&](std::string_view line, const std::string& where) {
    const std::vector<std::string_view> f = fields(line);
    if (!header) {
      header = true;
      int phi = -1, theta = -1, z = -1, value = -1;
      for (int i = 0; i < static_cast<int>(f.size()); ++i) {
        int& slot = f[i] == "phi_deg"     ? phi
                    : f[i] == "theta_deg" ? theta
                    : f[i] == "z_mm"      ? z
                                          : value;
        if (slot != -1 || f[i].empty() || f.size() != 3)
          throw InputError(where + "header '" + std::string(line) + "': " + kHeaderHelp);
        slot = i;
      }
      if (theta < 0 || (phi < 0) == (z < 0) || value < 0)
        throw InputError(where + "header '" + std::string(line) + "': " + kHeaderHelp);
      g.setup = phi >= 0 ? GridSetup::spherical : GridSetup::cylindrical;
      g.value_name = std::string(f[static_cast<std::size_t>(value)]);
      column[0] = value;
      column[1] = g.setup == GridSetup::spherical ? phi : theta;
      column[2] = g.setup == GridSetup::spherical ? theta : z;
      return;
    }
    if (f.size() != 3)
      throw InputError(where + "expected 3 numbers (" + std::string(line) + "), found " +
                       std::to_string(f.size()) + " fields");
    const std::string names[3] = {g.value_name,
                                  g.setup == GridSetup::spherical ? "phi_deg" : "theta_deg",
                                  g.setup == GridSetup::spherical ? "theta_deg" : "z_mm"};
    for (int c = 0; c < 3; ++c) {
      const std::string_view s = f[static_cast<std::size_t>(column[c])];
      double v = 0.0;
      const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
      if (s.empty() || ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v))
        throw InputError(where + names[c] + " '" + std::string(s) + "': expected a finite number");
      if (names[c] == "phi_deg" && (v < 0.0 || v > 180.0))
        throw InputError(where + "phi_deg " + std::string(s) +
                         ": expected a polar angle in [0, 180]");
      rows[c].push_back(v);
    }
  });
  if (!header) throw InputError(name + ": no header line; " + kHeaderHelp);
  if (rows[0].size() < 16)
    throw InputError(name + ": " + std::to_string(rows[0].size()) +
                     " data rows, expected at least 16");
  // A surface over the grid needs a range in both coordinates: one meridian or one ring is not one.
  const bool sph = g.setup == GridSetup::spherical;
  const char* coordinate[3] = {"", sph ? "phi_deg" : "theta_deg", sph ? "theta_deg" : "z_mm"};
  for (int c = 1; c < 3; ++c) {
    const auto [lo, hi] = std::minmax_element(rows[c].begin(), rows[c].end());
    if (*lo == *hi)
      throw InputError(name + ": every row has " + coordinate[c] + " = " + number_text(*lo) +
                       "; a surface needs at least two distinct " + coordinate[c] + " values");
  }
  const auto vec = [](const std::vector<double>& v, double scale) {
    return Eigen::VectorXd(
        Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size())) * scale);
  };
  g.value = vec(rows[0], 1.0);
  if (g.setup == GridSetup::spherical) {
    g.phi = vec(rows[1], kRadiansPerDegree);
    g.theta = vec(rows[2], kRadiansPerDegree);
  } else {
    g.theta = vec(rows[1], kRadiansPerDegree);
    g.z = vec(rows[2], 1.0);
  }
  return g;
}

ScalarGrid read_scalar_grid(const std::filesystem::path& file) {
  return parse_scalar_grid(read_text_file(file), file.string());
}

}  // namespace polarform
