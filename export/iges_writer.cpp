#include "export/iges_writer.h"

#include <cctype>
#include <cmath>
#include <optional>

#include "export/atomic_file.h"
#include "export/exchange_geometry.h"
#include "export/exchange_text.h"
#include "export/iges_file.h"
#include "polarform_version.h"
#include "src/error.h"

namespace polarform {

namespace {

std::string real(double x) { return exchange_real(x, 'D'); }  // IGES 5.3 double-precision real
std::string flag(bool b) { return b ? "1" : "0"; }

// IGES 5.3 §4.23, entity 126 form 0: rational B-spline curve.
IgesEntity curve_entity(const NurbsCurve3d& c, double resolution) {
  const int n = c.size(), p = c.degree();
  const std::optional<Eigen::Vector3d> normal = plane_normal(control_points_of(c), resolution);
  IgesEntity e;
  e.type = 126;
  e.params = {std::to_string(n - 1), std::to_string(p), flag(normal.has_value()),
              flag(is_closed(c, resolution)), flag(!c.is_rational()),
              flag(has_periodic_structure(c.homogeneous()))};
  for (double k : c.knots()) e.params.push_back(real(k));
  for (int i = 0; i < n; ++i) e.params.push_back(real(c.weight(i)));
  for (int i = 0; i < n; ++i)
    for (double x : c.control_point(i)) e.params.push_back(real(x));
  e.params.push_back(real(c.front()));
  e.params.push_back(real(c.back()));
  const Eigen::Vector3d nrm = normal.value_or(Eigen::Vector3d::Zero());
  for (double x : nrm) e.params.push_back(real(x));
  return e;
}

// IGES 5.3 §4.24, entity 128 form 0: rational B-spline surface. Weights and points run with the
// first (u) index fastest.
IgesEntity surface_entity(const NurbsSurface& s, double resolution) {
  const int nu = s.size_u(), nv = s.size_v();
  IgesEntity e;
  e.type = 128;
  e.params = {std::to_string(nu - 1),
              std::to_string(nv - 1),
              std::to_string(s.degree_u()),
              std::to_string(s.degree_v()),
              flag(is_closed_u(s, resolution)),
              flag(is_closed_v(s, resolution)),
              flag(!s.is_rational()),
              flag(has_periodic_structure(s.homogeneous().along_u())),
              flag(has_periodic_structure(s.homogeneous().along_v()))};
  for (double k : s.knots_u()) e.params.push_back(real(k));
  for (double k : s.knots_v()) e.params.push_back(real(k));
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) e.params.push_back(real(s.weight(i, j)));
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i)
      for (double x : s.control_point(i, j)) e.params.push_back(real(x));
  for (double x : {s.front_u(), s.back_u(), s.front_v(), s.back_v()}) e.params.push_back(real(x));
  return e;
}

// Appends `e` named `name`: the first 8 characters as DE label, the whole name as a following
// IGES 5.3 entity 406 form 15 (Name property) when it is longer.
void append_named(std::vector<IgesEntity>& out, IgesEntity e, const std::string& name) {
  e.label = name.substr(0, 8);
  if (name.size() > 8) {
    e.name_property_de = iges_de_pointer(static_cast<int>(out.size()) + 1);
    out.push_back(std::move(e));
    IgesEntity prop;
    prop.type = 406;
    prop.form = 15;
    prop.params = {"1", iges_string(name, "name")};
    prop.status = "00010200";  // physically dependent definition
    out.push_back(std::move(prop));
  } else {
    out.push_back(std::move(e));
  }
}

void check_time_stamp(const std::string& t) {
  bool ok = t.size() == 15 && t[8] == '.';
  for (std::size_t i = 0; ok && i < t.size(); ++i)
    ok = i == 8 || std::isdigit(static_cast<unsigned char>(t[i]));
  if (!ok)
    throw InputError("IGES header time_stamp '" + t + "': expected YYYYMMDD.HHNNSS");
}

}  // namespace

void IgesWriter::add(const NurbsCurve2d& curve, const std::string& name) {
  add(lift_to_3d(curve), name);
}

void IgesWriter::add(const NurbsCurve3d& curve, const std::string& name) {
  require_exchangeable(curve.degree(), curve.knots(), "IGES curve '" + name + "'");
  iges_string(name, "curve name");
  items_.push_back({curve, name});
}

void IgesWriter::add(const NurbsSurface& surface, const std::string& name) {
  require_exchangeable(surface.degree_u(), surface.knots_u(), "IGES surface '" + name + "' (u)");
  require_exchangeable(surface.degree_v(), surface.knots_v(), "IGES surface '" + name + "' (v)");
  iges_string(name, "surface name");
  items_.push_back({surface, name});
}

void IgesWriter::add_composite(const std::vector<NurbsCurve2d>& segments, const std::string& name) {
  std::vector<NurbsCurve3d> lifted;
  for (const NurbsCurve2d& s : segments) lifted.push_back(lift_to_3d(s));
  add_composite(lifted, name);
}

void IgesWriter::add_composite(const std::vector<NurbsCurve3d>& segments, const std::string& name) {
  if (segments.empty())
    throw InputError("IGES composite curve '" + name + "': no segments, expected at least one");
  for (std::size_t i = 0; i < segments.size(); ++i)
    require_exchangeable(segments[i].degree(), segments[i].knots(),
                         "IGES composite curve '" + name + "' segment " + std::to_string(i));
  iges_string(name, "composite curve name");
  items_.push_back({segments, name});
}

std::string IgesWriter::str(const IgesHeader& header) const {
  if (!(header.resolution > 0.0) || !std::isfinite(header.resolution))
    throw InputError("IGES header resolution " + std::to_string(header.resolution) +
                     ": expected a finite length > 0 mm");
  const std::string stamp =
      header.time_stamp.empty() ? utc_time_stamp("%Y%m%d.%H%M%S") : header.time_stamp;
  check_time_stamp(stamp);
  const double tol = header.resolution;

  std::vector<IgesEntity> entities;
  std::vector<Eigen::Vector3d> all_points;
  for (const Item& item : items_) {
    if (const auto* c = std::get_if<NurbsCurve3d>(&item.geometry)) {
      append_named(entities, curve_entity(*c, tol), item.name);
      for (const auto& p : control_points_of(*c)) all_points.push_back(p);
    } else if (const auto* s = std::get_if<NurbsSurface>(&item.geometry)) {
      append_named(entities, surface_entity(*s, tol), item.name);
      for (const auto& p : control_points_of(*s)) all_points.push_back(p);
    } else {
      const auto& segments = std::get<std::vector<NurbsCurve3d>>(item.geometry);
      // IGES 5.3 entity 102 form 0 (composite curve) over physically dependent segments.
      IgesEntity composite;
      composite.type = 102;
      composite.params.push_back(std::to_string(segments.size()));
      for (std::size_t i = 0; i < segments.size(); ++i) {
        const NurbsCurve3d& seg = segments[i];
        if (i > 0 && (segments[i - 1].point(segments[i - 1].back()) - seg.point(seg.front()))
                             .norm() > tol)
          throw InputError("IGES composite curve '" + item.name + "': segment " +
                           std::to_string(i) + " does not start where segment " +
                           std::to_string(i - 1) + " ends (resolution " + real(tol) + " mm)");
        composite.params.push_back(std::to_string(iges_de_pointer(static_cast<int>(entities.size()))));
        IgesEntity e = curve_entity(seg, tol);
        e.status = "00010000";  // physically dependent geometry
        entities.push_back(std::move(e));
        for (const auto& p : control_points_of(seg)) all_points.push_back(p);
      }
      append_named(entities, std::move(composite), item.name);
    }
  }

  // IGES carries ASCII only: names of the user's files and the texts about them are folded.
  const std::string file_name =
      ascii_text(header.file_name.empty() ? "polarform.igs" : header.file_name);
  const std::string product = "polarform";
  const std::string version = std::string("polarform ") + POLARFORM_VERSION;
  // IGES 5.3 Global section, parameters 3-25.
  const std::vector<std::string> globals = {
      iges_string(product, "product id"),
      iges_string(file_name, "file name"),
      iges_string(version, "system id"),
      iges_string(version, "preprocessor version"),
      "32",   // bits of an integer
      "38",   // single precision: max power of ten
      "6",    // single precision: significant digits
      "308",  // double precision: max power of ten
      "15",   // double precision: significant digits
      iges_string(product, "receiver product id"),
      real(1.0),  // model space scale
      "2",        // unit flag: millimetres
      iges_string("MM", "unit name"),
      "1",        // line weight gradations
      real(1.0),  // width of the maximum line weight, mm
      iges_string(stamp, "time stamp"),
      real(tol),  // minimum user-intended resolution
      real(max_abs_coordinate(all_points)),
      iges_string(ascii_text(header.author), "author"),
      iges_string(ascii_text(header.organization), "organization"),
      "11",  // IGES 5.3
      "0",   // no drafting standard
      iges_string(stamp, "model time stamp")};
  return iges_file(ascii_text(header.description), globals, entities);
}

void IgesWriter::save(const std::filesystem::path& path, const IgesHeader& header) const {
  IgesHeader h = header;
  if (h.file_name.empty()) h.file_name = path.filename().string();
  write_file_atomically(path, str(h));
}

}  // namespace polarform
