#include "jobs/project/fit_project.h"

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

constexpr const char* kMethods[] = {"auto", "polar", "spherical", "cylindrical"};
constexpr const char* kClosures[] = {"auto", "no", "yes"};  // in Closure's order
constexpr const char* kMeasures[] = {"max", "p99", "p95", "rms"};
constexpr const char* kFairness[] = {"fixed", "relative", "gcv"};  // in FairnessOptions::Mode's

template <class Enum, std::size_t N>
Enum from_word(const std::string& word, const char* const (&words)[N]) {
  for (std::size_t k = 0; k < N; ++k)
    if (word == words[k]) return static_cast<Enum>(k);
  throw InputError("unknown word '" + word + "'");  // unreachable after XmlElementReader::choice
}

// "p,q" as two integers in [lo, hi].
std::pair<int, int> int_pair(const XmlElementReader& r, const char* name, int lo, int hi) {
  const std::vector<double> v = r.numbers(name, 2);
  for (double x : v)
    if (!(x >= lo && x <= hi) || x != std::floor(x))  // range first: no cast of 1e10 to int
      r.fail(name, "two comma-separated integers in [" + std::to_string(lo) + ", " +
                       std::to_string(hi) + "]");
  return {static_cast<int>(v[0]), static_cast<int>(v[1])};
}

Eigen::Vector3d vector3(const XmlElementReader& r, const char* name) {
  const std::vector<double> v = r.numbers(name, 3);
  return {v[0], v[1], v[2]};
}

void read_fit(const XMLElement* e, const std::string& file, std::vector<UnknownName>& unknown,
              FitProject& p) {
  const XmlElementReader r(e, file);
  const std::string scan = r.text("scan", "");
  if (scan.empty()) r.fail("scan", "the point-cloud file (path relative to the project file)");
  p.scan = scan;
  p.method = from_word<FitJobMethod>(r.choice("method", {"auto", "polar", "spherical", "cylindrical"},
                                           "auto"), kMethods);
  p.closure = from_word<Closure>(r.choice("closed", {"auto", "no", "yes"}, "auto"), kClosures);
  if (r.has("pole")) {
    const std::string pole = r.choice("pole", {"none", "g0", "g1", "cap"});
    p.pole = pole == "none" ? PoleTreatment::none
             : pole == "g0" ? PoleTreatment::g0
             : pole == "g1" ? PoleTreatment::g1
                            : PoleTreatment::cap;
  }
  if (r.has("degree")) p.degree = int_pair(r, "degree", 1, 9);
  if (r.has("ctrl")) p.ctrl = int_pair(r, "ctrl", 2, 2000);
  if (r.has("tolerance")) p.tolerance = r.positive("tolerance");
  if (p.ctrl && p.tolerance) r.fail("tolerance", "either ctrl or tolerance, not both");
  p.measure = from_word<ToleranceMeasure>(
      r.choice("tolerance-measure", {"max", "p99", "p95", "rms"}, "max"), kMeasures);
  if (r.has("center")) p.center = vector3(r, "center");
  if (r.has("axis")) {
    p.axis = vector3(r, "axis");
    if (p.axis->norm() == 0.0) r.fail("axis", "a non-zero direction x,y,z");
  }
  p.skip_bad = r.choice("skip-bad", {"true", "false"}, "false") == "true";
  p.reject_outliers = r.choice("reject-outliers", {"true", "false"}, "false") == "true";
  p.fairness = from_word<FairnessOptions::Mode>(
      r.choice("fairness", {"fixed", "relative", "gcv"}, "relative"), kFairness);
  if (r.has("lambda")) p.fairness_weight = r.positive("lambda");
  p.base = r.choice("base", {"rqb", "quartic"}, "rqb") == "quartic" ? ArcKind::quartic
                                                                     : ArcKind::rqb;
  const std::string revolution = r.choice("revolution", {"auto", "yes", "no"}, "auto");
  p.revolution = revolution == "yes"  ? RevolutionMode::yes
                 : revolution == "no" ? RevolutionMode::no
                                      : RevolutionMode::automatic;
  r.collect_unknown_names(unknown);
}

FitProject read_document(const XmlDocument& doc, std::vector<std::string>& warnings,
                         UnknownNames policy) {
  FitProject p;
  std::vector<UnknownName> unknown;
  const XMLElement* root = doc.root();
  if (std::string(root->Name()) == "fit") {
    read_fit(root, doc.file(), unknown, p);
  } else {
    const XmlElementReader r(root, doc.file());
    if (std::string(root->Name()) != "polarform")
      throw InputError(r.where() + ": expected a <polarform> or <fit> root element");
    check_project_version(r, policy, warnings);
    const XMLElement* fit = r.child("fit");
    if (!fit) throw InputError(r.where() + ": expected a <fit> element");
    read_fit(fit, doc.file(), unknown, p);
    r.collect_unknown_names(unknown);
  }
  settle_unknown_names(unknown, policy, warnings);
  return p;
}

void attribute(std::ostream& out, const char* name, const std::string& value) {
  out << ' ' << name << "=\"" << value << '"';
}

std::string list(std::initializer_list<double> values) {
  std::string out;
  for (double v : values) out += (out.empty() ? "" : ",") + format_round_trip(v);
  return out;
}

}  // namespace

const char* fairness_word(FairnessOptions::Mode mode) { return kFairness[static_cast<int>(mode)]; }

const char* pole_word(PoleTreatment pole) {
  constexpr const char* kPoles[] = {"auto", "none", "g0", "g1", "cap"};  // in PoleTreatment's order
  return kPoles[static_cast<int>(pole)];
}

std::filesystem::path scan_path(const FitProject& project,
                                const std::filesystem::path& project_file) {
  return project.scan.is_absolute() ? project.scan : project_file.parent_path() / project.scan;
}

FitProject read_fit_project(const std::filesystem::path& file, std::vector<std::string>& warnings,
                            UnknownNames policy) {
  return read_document(XmlDocument(file), warnings, policy);
}

FitProject parse_fit_project(const std::string& text, const std::string& file,
                             std::vector<std::string>& warnings, UnknownNames policy) {
  return read_document(XmlDocument(text, file), warnings, policy);
}

std::string fit_project_xml(const FitProject& p) {
  std::ostringstream out;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<polarform version=\"1\">\n  <fit";
  attribute(out, "scan", xml_escape(p.scan.generic_string()));
  attribute(out, "method", kMethods[static_cast<int>(p.method)]);
  attribute(out, "closed", kClosures[static_cast<int>(p.closure)]);
  if (p.pole) attribute(out, "pole", pole_word(*p.pole));
  if (p.degree) attribute(out, "degree", list({double(p.degree->first), double(p.degree->second)}));
  if (p.ctrl) attribute(out, "ctrl", list({double(p.ctrl->first), double(p.ctrl->second)}));
  if (p.tolerance) attribute(out, "tolerance", format_round_trip(*p.tolerance));
  attribute(out, "tolerance-measure", kMeasures[static_cast<int>(p.measure)]);
  if (p.center) attribute(out, "center", list({p.center->x(), p.center->y(), p.center->z()}));
  if (p.axis) attribute(out, "axis", list({p.axis->x(), p.axis->y(), p.axis->z()}));
  attribute(out, "skip-bad", p.skip_bad ? "true" : "false");
  attribute(out, "reject-outliers", p.reject_outliers ? "true" : "false");
  attribute(out, "fairness", fairness_word(p.fairness));
  attribute(out, "lambda", format_round_trip(p.fairness_weight));
  attribute(out, "base", p.base == ArcKind::quartic ? "quartic" : "rqb");
  attribute(out, "revolution", revolution_word(p.revolution));
  out << "/>\n</polarform>\n";
  return out.str();
}

void write_fit_project(const FitProject& project, const std::filesystem::path& file) {
  write_file_atomically(file, fit_project_xml(project));
}

}  // namespace polarform
