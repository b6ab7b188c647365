// ISO 10303-21 (STEP physical file) container: numbered entity instances "#n=...;" in a DATA
// section, the HEADER (FILE_DESCRIPTION, FILE_NAME with an ISO 8601 time stamp, FILE_SCHEMA
// AUTOMOTIVE_DESIGN = AP214), and the token formatting every STEP writer shares (strings with
// \X2\ encoding, reals with a decimal point, references, logicals, lists).
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace polarform {

struct StepHeader {
  std::string description = "polarform NURBS export";  // FILE_DESCRIPTION
  std::string file_name;     // FILE_NAME name; empty: the saved file's name ("polarform.stp")
  std::string author;        // FILE_NAME author
  std::string organization;  // FILE_NAME organization
  std::string time_stamp;    // FILE_NAME time_stamp, ISO 8601; empty: now (UTC)
  // Millimetres: the UNCERTAINTY_MEASURE_WITH_UNIT of the context (importers use it as their
  // confusion tolerance) and the tolerance of the closed flags.
  double resolution = 1e-6;
};

class StepFile {
 public:
  // Appends instance "#id=record;" and returns id (1, 2, ...).
  int add(std::string record);
  int size() const { return static_cast<int>(records_.size()); }
  // The whole exchange file. Throws InputError for a malformed header field.
  std::string str(const StepHeader& header) const;
  // While set, step_point and step_direction (step_geometry.h) write placement·p and
  // placement.linear()·d: geometry built in a local frame lands rigidly moved in the file.
  std::optional<Eigen::Isometry3d> placement;

 private:
  std::vector<std::string> records_;
};

// ISO 10303-21 string: quoted, apostrophes and backslashes doubled, characters outside
// printable ASCII encoded from UTF-8 as \X2\hhhh\X0\ (or \X4\ beyond the BMP). Throws InputError
// naming `field` for invalid UTF-8.
std::string step_string(std::string_view utf8, std::string_view field);
std::string step_real(double x);
inline std::string step_ref(int id) { return "#" + std::to_string(id); }
inline std::string step_logical(bool b) { return b ? ".T." : ".F."; }
// "(a,b,c)"
std::string step_list(const std::vector<std::string>& items);

}  // namespace polarform
