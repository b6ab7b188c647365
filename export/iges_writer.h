// IGES 5.3 writer for kernel NURBS: curves as entity 126 (rational B-spline curve), surfaces as
// entity 128 (rational B-spline surface), chains of curves as entity 102 (composite curve, one wire
// on import), in millimetres, with full double precision and truthful closed / planar / periodic /
// polynomial flags. Names go to the DE label (8 characters) and, when longer, a 406 form 15 Name.
#pragma once

#include <filesystem>
#include <string>
#include <variant>
#include <vector>

#include "src/nurbs/nurbs_curve.h"
#include "src/nurbs/nurbs_surface.h"

namespace polarform {

struct IgesHeader {
  std::string description = "polarform NURBS export";  // Start section
  std::string file_name;     // Global 4; empty: the saved file's name ("polarform.igs" for str())
  std::string author;        // Global 21
  std::string organization;  // Global 22
  std::string time_stamp;    // Global 18 and 25, "YYYYMMDD.HHNNSS"; empty: now (UTC)
  // Global 19, mm: the smallest distance the model distinguishes; also the tolerance of the
  // closed and planar flags and of composite-curve joints.
  double resolution = 1e-6;
};

class IgesWriter {
 public:
  // Throw InputError (naming the entity) for degree 0 or an interior knot above C0, or a name that
  // is not printable ASCII.
  void add(const NurbsCurve2d& curve, const std::string& name = "");
  void add(const NurbsCurve3d& curve, const std::string& name = "");
  void add(const NurbsSurface& surface, const std::string& name = "");
  // Segments joined end to start (within the header resolution, checked on output) as one
  // composite curve; a single closed planar curve imports as a closed planar wire.
  void add_composite(const std::vector<NurbsCurve2d>& segments, const std::string& name = "");
  void add_composite(const std::vector<NurbsCurve3d>& segments, const std::string& name = "");

  std::string str(const IgesHeader& header = {}) const;
  // Written atomically; the file name goes to Global 4 unless the header names one.
  void save(const std::filesystem::path& path, const IgesHeader& header = {}) const;

 private:
  struct Item {
    std::variant<NurbsCurve3d, NurbsSurface, std::vector<NurbsCurve3d>> geometry;
    std::string name;
  };
  std::vector<Item> items_;
};

}  // namespace polarform
