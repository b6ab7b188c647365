#include "jobs/project/sweep_project.h"

#include <cmath>
#include <sstream>

#include "export/atomic_file.h"
#include "export/xml_escape.h"
#include "jobs/project/xml_reader.h"
#include "src/error.h"
#include "src/number_text.h"

namespace polarform {

namespace {

using tinyxml2::XMLElement;

constexpr const char* kKinds[] = {"auto", "revolution", "extrusion",
                                  "sections"};  // in SweepKind's order

Eigen::Vector3d direction(const XmlElementReader& r, const char* name) {
  const std::vector<double> v = r.numbers(name, 3);
  const Eigen::Vector3d d(v[0], v[1], v[2]);
  if (!(d.norm() > 0.0)) r.fail(name, "a non-zero direction x,y,z");
  return d;
}

void read_sweep(const XMLElement* e, const std::string& file, std::vector<UnknownName>& unknown,
                SweepProject& p) {
  const XmlElementReader r(e, file);
  const std::string scan = r.text("scan", "");
  if (scan.empty()) r.fail("scan", "the scan or mesh file (path relative to the project file)");
  p.scan = scan;
  const std::string kind =
      r.choice("kind", {"auto", "revolution", "extrusion", "sections"}, "auto");
  for (int k = 0; k < 4; ++k)
    if (kind == kKinds[k]) p.kind = static_cast<SweepKind>(k);
  if (r.has("axis")) p.axis = direction(r, "axis");
  if (r.has("center")) {
    const std::vector<double> v = r.numbers("center", 3);
    p.center = Eigen::Vector3d(v[0], v[1], v[2]);
    if (!p.axis) r.fail("center", "an axis with it (attribute axis)");
    if (p.kind == SweepKind::extrusion) r.fail("center", "no center for an extrusion");
  }
  if (r.has("tolerance")) p.tolerance = r.positive("tolerance");
  if (r.has("degree")) {
    const double d = r.number("degree");
    if (!(d >= 1 && d <= 9) || d != std::floor(d)) r.fail("degree", "an integer in [1, 9]");
    p.degree = static_cast<int>(d);
  }
  if (r.has("corner-angle")) {
    p.corner_angle_deg = r.number("corner-angle");
    if (!(p.corner_angle_deg > 0 && p.corner_angle_deg < 180))
      r.fail("corner-angle", "degrees in (0, 180)");
  }
  p.skip_bad = r.choice("skip-bad", {"true", "false"}, "false") == "true";
  r.collect_unknown_names(unknown);
}

SweepProject read_document(const XmlDocument& doc, std::vector<std::string>& warnings,
                           UnknownNames policy) {
  SweepProject p;
  std::vector<UnknownName> unknown;
  const XMLElement* root = doc.root();
  if (std::string(root->Name()) == "sweep") {
    read_sweep(root, doc.file(), unknown, p);
  } else {
    const XmlElementReader r(root, doc.file());
    if (std::string(root->Name()) != "polarform")
      throw InputError(r.where() + ": expected a <polarform> or <sweep> root element");
    check_project_version(r, policy, warnings);
    const XMLElement* sweep = r.child("sweep");
    if (!sweep) throw InputError(r.where() + ": expected a <sweep> element");
    read_sweep(sweep, doc.file(), unknown, p);
    r.collect_unknown_names(unknown);
  }
  settle_unknown_names(unknown, policy, warnings);
  return p;
}

void attribute(std::ostream& out, const char* name, const std::string& value) {
  out << ' ' << name << "=\"" << value << '"';
}

std::string triple(const Eigen::Vector3d& v) {
  return format_round_trip(v.x()) + "," + format_round_trip(v.y()) + "," + format_round_trip(v.z());
}

}  // namespace

const char* sweep_kind_word(SweepKind kind) { return kKinds[static_cast<int>(kind)]; }

std::filesystem::path scan_path(const SweepProject& project,
                                const std::filesystem::path& project_file) {
  return project.scan.is_absolute() ? project.scan : project_file.parent_path() / project.scan;
}

SweepJobOptions sweep_job_options(const SweepProject& p) {
  SweepJobOptions o;
  o.kind = p.kind;
  o.axis = p.axis;
  o.center = p.center;
  o.tolerance = p.tolerance.value_or(0.0);
  o.degree = p.degree;
  o.corner_angle_deg = p.corner_angle_deg;
  o.skip_bad = p.skip_bad;
  return o;
}

SweepProject read_sweep_project(const std::filesystem::path& file,
                                std::vector<std::string>& warnings, UnknownNames policy) {
  return read_document(XmlDocument(file), warnings, policy);
}

SweepProject parse_sweep_project(const std::string& text, const std::string& file,
                                 std::vector<std::string>& warnings, UnknownNames policy) {
  return read_document(XmlDocument(text, file), warnings, policy);
}

std::string sweep_project_xml(const SweepProject& p) {
  std::ostringstream out;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<polarform version=\"1\">\n  <sweep";
  attribute(out, "scan", xml_escape(p.scan.generic_string()));
  attribute(out, "kind", sweep_kind_word(p.kind));
  if (p.axis) attribute(out, "axis", triple(*p.axis));
  if (p.center) attribute(out, "center", triple(*p.center));
  if (p.tolerance) attribute(out, "tolerance", format_round_trip(*p.tolerance));
  attribute(out, "degree", std::to_string(p.degree));
  attribute(out, "corner-angle", format_round_trip(p.corner_angle_deg));
  attribute(out, "skip-bad", p.skip_bad ? "true" : "false");
  out << "/>\n</polarform>\n";
  return out.str();
}

void write_sweep_project(const SweepProject& project, const std::filesystem::path& file) {
  write_file_atomically(file, sweep_project_xml(project));
}

}  // namespace polarform
