#include "jobs/project/pipe_project.h"

#include <cmath>
#include <sstream>

#include "export/atomic_file.h"
#include "jobs/project/xml_reader.h"
#include "src/error.h"
#include "src/number_text.h"
#include "src/nurbs/knots.h"

namespace polarform {

namespace {

using tinyxml2::XMLElement;

constexpr const char* kFrames[] = {"rmf", "frenet", "fixed"};  // in FrameRule's order
constexpr const char* kClosures[] = {"auto", "yes", "no"};     // in SpineClosure's order
constexpr FrameRule kFrameRules[] = {FrameRule::rmf, FrameRule::frenet, FrameRule::fixed};

const char* frame_word(FrameRule f) {
  for (int k = 0; k < 3; ++k)
    if (kFrameRules[k] == f) return kFrames[k];
  return kFrames[0];
}

// Clamped, non-decreasing, points + degree + 1 of them, interior multiplicity <= degree.
void check_knots(const XmlElementReader& r, const std::vector<double>& u, int degree, int n) {
  const auto fail = [&](const std::string& why) {
    r.fail("knots",
           std::to_string(n + degree + 1) + " clamped, non-decreasing knots (" + why + ")");
  };
  if (static_cast<int>(u.size()) != n + degree + 1)
    fail(std::to_string(u.size()) + " given for " + std::to_string(n) + " points of degree " +
         std::to_string(degree));
  for (std::size_t i = 1; i < u.size(); ++i)
    if (u[i] < u[i - 1]) fail("knot " + std::to_string(i) + " decreases");
  for (int i = 1; i <= degree; ++i)
    if (u[i] != u[0] || u[u.size() - 1 - i] != u.back()) fail("the ends are not clamped");
  if (!(u[0] < u.back())) fail("the domain is empty");
  for (const Breakpoint& b : breakpoints(u))
    if (b.value != u[0] && b.value != u.back() && b.multiplicity > degree)
      fail("knot " + number_text(b.value) + " repeats " + std::to_string(b.multiplicity) +
           " times, at most the degree inside");
}

void read_pipe(const XMLElement* e, const std::string& file, std::vector<UnknownName>& unknown,
               PipeProject& p) {
  const XmlElementReader r(e, file);
  if (r.has("radius")) p.radius = r.positive("radius");
  if (r.has("tol")) p.tolerance = r.positive("tol");
  const std::string frame = r.choice("frame", {"rmf", "frenet", "fixed"}, "rmf");
  for (int k = 0; k < 3; ++k)
    if (frame == kFrames[k]) p.frame = kFrameRules[k];
  const std::string closed = r.choice("closed", {"auto", "yes", "no"}, "auto");
  for (int k = 0; k < 3; ++k)
    if (closed == kClosures[k]) p.closure = static_cast<SpineClosure>(k);
  if (r.has("degree")) {
    const double d = r.number("degree");
    if (!(d >= 1 && d <= 9) || d != std::floor(d)) r.fail("degree", "an integer in [1, 9]");
    p.degree = static_cast<int>(d);
  }
  for (const XMLElement* pe : r.children("point")) {
    const XmlElementReader pr(pe, file);
    const std::vector<double> v = pr.numbers("at", 3);
    p.points.emplace_back(v[0], v[1], v[2]);
    p.weights.push_back(pr.positive("weight", 1.0));
    pr.collect_unknown_names(unknown);
  }
  const int n = static_cast<int>(p.points.size());
  if (n < p.degree + 1)
    throw InputError(r.where() +
                     ": expected at least degree + 1 = " + std::to_string(p.degree + 1) +
                     " <point at=\"x,y,z\"/> elements, got " + std::to_string(n));
  if (r.has("knots")) {
    p.knots = r.number_list("knots");
    check_knots(r, p.knots, p.degree, n);
  }
  r.collect_unknown_names(unknown);
}

PipeProject read_document(const XmlDocument& doc, std::vector<std::string>& warnings,
                          UnknownNames policy) {
  PipeProject p;
  std::vector<UnknownName> unknown;
  const XMLElement* root = doc.root();
  if (std::string(root->Name()) == "pipe") {
    read_pipe(root, doc.file(), unknown, p);
  } else {
    const XmlElementReader r(root, doc.file());
    if (std::string(root->Name()) != "polarform")
      throw InputError(r.where() + ": expected a <polarform> or <pipe> root element");
    check_project_version(r, policy, warnings);
    const XMLElement* pipe = r.child("pipe");
    if (!pipe) throw InputError(r.where() + ": expected a <pipe> element");
    read_pipe(pipe, doc.file(), unknown, p);
    r.collect_unknown_names(unknown);
  }
  settle_unknown_names(unknown, policy, warnings);
  return p;
}

void attribute(std::ostream& out, const char* name, const std::string& value) {
  out << ' ' << name << "=\"" << value << '"';
}

}  // namespace

NurbsCurve3d pipe_spine(const PipeProject& p) {
  const int n = static_cast<int>(p.points.size());
  Knots knots = p.knots.empty() ? uniform_clamped_knots(p.degree, n - p.degree, 0.0, 1.0) : p.knots;
  return NurbsCurve3d(p.degree, std::move(knots),
                      NurbsCurve3d::Points(p.points.begin(), p.points.end()), p.weights);
}

PipeJobOptions pipe_job_options(const PipeProject& p) {
  PipeJobOptions o;
  o.radius = p.radius.value_or(0.0);
  o.frame = p.frame;
  o.tolerance = p.tolerance.value_or(0.0);
  o.closure = p.closure;
  return o;
}

PipeProject read_pipe_project(const std::filesystem::path& file, std::vector<std::string>& warnings,
                              UnknownNames policy) {
  return read_document(XmlDocument(file), warnings, policy);
}

PipeProject parse_pipe_project(const std::string& text, const std::string& file,
                               std::vector<std::string>& warnings, UnknownNames policy) {
  return read_document(XmlDocument(text, file), warnings, policy);
}

std::string pipe_project_xml(const PipeProject& p) {
  std::ostringstream out;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<polarform version=\"1\">\n  <pipe";
  if (p.radius) attribute(out, "radius", format_round_trip(*p.radius));
  attribute(out, "frame", frame_word(p.frame));
  if (p.tolerance) attribute(out, "tol", format_round_trip(*p.tolerance));
  attribute(out, "degree", std::to_string(p.degree));
  attribute(out, "closed", kClosures[static_cast<int>(p.closure)]);
  if (!p.knots.empty()) {
    std::string u;
    for (std::size_t i = 0; i < p.knots.size(); ++i)
      u += (i ? "," : "") + format_round_trip(p.knots[i]);
    attribute(out, "knots", u);
  }
  out << ">\n";
  for (std::size_t i = 0; i < p.points.size(); ++i) {
    const Eigen::Vector3d& x = p.points[i];
    out << "    <point";
    attribute(
        out, "at",
        format_round_trip(x.x()) + "," + format_round_trip(x.y()) + "," + format_round_trip(x.z()));
    if (p.weights[i] != 1.0) attribute(out, "weight", format_round_trip(p.weights[i]));
    out << "/>\n";
  }
  out << "  </pipe>\n</polarform>\n";
  return out.str();
}

void write_pipe_project(const PipeProject& project, const std::filesystem::path& file) {
  write_file_atomically(file, pipe_project_xml(project));
}

}  // namespace polarform
