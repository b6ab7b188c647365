// Grid files of `polarform viz`: data measured on a spherical set-up {(p, φ, θ)} or a cylindrical
// one {(p, θ, z)} (Bae 2002, §5.3) as delimited text. The first line that is not empty or a '#'
// comment names three columns, separated by commas or blanks: phi_deg and theta_deg (spherical)
// or theta_deg and z_mm (cylindrical), in any order, and the value, under any other name. Every
// further line holds three finite numbers; angles in degrees (φ in [0, 180]), z in mm.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <string_view>

namespace polarform {

enum class GridSetup { spherical, cylindrical };

struct ScalarGrid {
  GridSetup setup = GridSetup::spherical;
  std::string value_name;      // the value column's header, e.g. "pressure_Pa"
  Eigen::VectorXd value;       // p_k
  Eigen::VectorXd phi, theta;  // radians (phi: spherical only)
  Eigen::VectorXd z;           // mm (cylindrical only)
};

// Throws InputError "name:line: …" for a bad header, a wrong field count, a bad or non-finite
// number, φ outside [0, 180], or fewer than 16 rows.
ScalarGrid parse_scalar_grid(std::string_view text, const std::string& name);
ScalarGrid read_scalar_grid(const std::filesystem::path& file);

}  // namespace polarform
