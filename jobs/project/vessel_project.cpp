#include "jobs/project/vessel_project.h"

#include <charconv>
#include <numbers>
#include <sstream>

#include "designers/convert/polar_conversion.h"
#include "export/atomic_file.h"
#include "jobs/project/compaction_attribute.h"
#include "jobs/project/xml_reader.h"
#include "src/error.h"
#include "src/nurbs/knots.h"
#include "src/units.h"

namespace polarform {

namespace {

using tinyxml2::XMLElement;

std::string number(double x) {
  char buf[32];
  const auto result = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, result.ptr);
}

// Reads every element through an XmlElementReader and collects what nobody read.
class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  template <class F>
  void visit(const XMLElement* e, F&& read) {
    const XmlElementReader r(e, file_);
    read(r);
    r.collect_unknown_names(unknown_);
  }
  const std::vector<UnknownName>& unknown() const { return unknown_; }

 private:
  std::string file_;
  std::vector<UnknownName> unknown_;
};

CurvatureEntry read_curvature(const XmlElementReader& r) {
  CurvatureEntry c;
  const int places = r.has("theta") + r.has("s") + r.has("phi");
  if (places != 1)
    r.fail(places == 0    ? "theta"
           : r.has("phi") ? "phi"
                          : "s",
           "exactly one of theta (polar angle, degrees), s (arc length from junction A, mm) and "
           "phi (meridian angle, degrees)");
  if (r.has("s")) {
    c.place = TargetPlace::arc_length;
    c.position = r.positive("s", 0.0, true);
  } else if (r.has("phi")) {
    c.place = TargetPlace::meridian_angle;
    c.position = r.number("phi");
    if (!(c.position >= -90.0 && c.position <= 90.0))
      r.fail("phi", "a meridian angle in [-90, 90] degrees (90 at junction A, 0 at the apex)");
  } else {
    c.theta_deg = r.number("theta");
    if (!(c.theta_deg >= 0.0 && c.theta_deg <= 180.0))
      r.fail("theta", "an angle in [0, 180] degrees");
  }
  if (r.has("kappa") && r.has("radius")) r.fail("radius", "either kappa or radius, not both");
  c.is_radius = r.has("radius");
  c.value = r.number(c.is_radius ? "radius" : "kappa");
  if (c.is_radius && c.value == 0.0) r.fail("radius", "a non-zero radius of curvature in mm");
  c.weight = r.positive("weight", 1.0);
  return c;
}

// kappa="κ" states the end's curvature instead of R'' (with R' = 0): R'' = R − κR², from
// κ = (R² + 2R'² − R R'')/(R² + R'²)^{3/2}; κ = 0 is curvature continuity with the cylinder.
EndCondition read_end(const XmlElementReader& r, double radius) {
  EndCondition c;
  if (r.has("r")) c.r = r.positive("r");
  c.dr = r.optional_number("dr");
  c.ddr = r.optional_number("ddr");
  if (r.has("kappa")) {
    if (c.ddr) r.fail("kappa", "either kappa or ddr, not both");
    if (c.dr && *c.dr != 0.0) r.fail("kappa", "kappa with dr=\"0\" or no dr (R' = 0 at the end)");
    const double kappa = r.number("kappa");
    const double R = c.r.value_or(radius);
    c.dr = 0.0;
    c.ddr = R - kappa * R * R;
  }
  return c;
}

// `curvature_inputs`: the vessel has <curvature>, <end> or <synthesis> elements, which ask for a
// curvature design unless design="exact" or "minimum-stress" says otherwise; `has_curvatures`: it
// has <curvature> elements, which an exact or minimum-stress head refuses. Sets d.head_design,
// d.preset (absent for a minimum-stress head or a curvature head of a given depth), d.depth,
// d.junction_kappa, d.preset_targets.
void read_head(const XmlElementReader& r, VesselDesign& d, bool curvature_inputs,
               bool has_curvatures) {
  const bool synthesised = curvature_inputs || r.has("targets");
  const std::string design = r.choice("design", {"exact", "curvature", "minimum-stress"},
                                      synthesised ? "curvature" : "exact");
  d.head_design = design == "exact"            ? HeadDesign::exact
                  : design == "minimum-stress" ? HeadDesign::minimum_stress
                                               : HeadDesign::curvature;
  if (d.head_design != HeadDesign::curvature && has_curvatures)
    r.fail("design",
           "design=\"curvature\" with <curvature> targets (an " + design + " head takes none)");
  if (d.head_design == HeadDesign::minimum_stress) {
    if (r.has("volume")) r.fail("volume", "no volume unless design=\"curvature\"");
    if (r.has("depth")) d.depth = r.positive("depth");
    if (d.depth && !(*d.depth <= 4 * d.radius))
      r.fail("depth", "a head depth up to 4 × the vessel radius " + number(4 * d.radius) + " mm");
    d.junction_kappa = r.optional_number("junction-kappa");
    if (!r.has("preset")) {
      if (!d.depth) r.fail("depth", "the head's depth (or a preset to take it from)");
      return;
    }
  } else if (d.head_design == HeadDesign::curvature) {
    // A curvature design of a prescribed depth, R(π/2) = depth; its targets may come without a
    // preset.
    if (r.has("junction-kappa"))
      r.fail("junction-kappa", "no junction-kappa unless design=\"minimum-stress\"");
    if (r.has("depth")) d.depth = r.positive("depth");
    if (d.depth && !(*d.depth <= 4 * d.radius))
      r.fail("depth", "a head depth up to 4 × the vessel radius " + number(4 * d.radius) + " mm");
    if (r.has("volume")) d.volume = r.positive("volume");
    if (!r.has("preset") && (d.depth || d.volume)) return;
  } else {
    if (r.has("volume")) r.fail("volume", "no volume unless design=\"curvature\"");
    for (const char* name : {"depth", "junction-kappa"})
      if (r.has(name))
        r.fail(name,
               std::string("no ") + name + " unless design=\"minimum-stress\" or \"curvature\"");
  }
  HeadPreset h;
  const std::string preset =
      r.choice("preset", {"hemispherical", "ellipsoidal", "torispherical", "conical", "flat"});
  if (preset == "ellipsoidal") {
    h.kind = HeadKind::ellipsoidal;
    h.ratio = r.positive("ratio", 2.0);
  } else if (preset == "torispherical") {
    h.kind = HeadKind::torispherical;
    h.crown = r.positive("crown");
    h.knuckle = r.positive("knuckle");
    if (!(h.knuckle < d.radius))
      r.fail("knuckle", "a knuckle radius below the vessel radius " + number(d.radius) + " mm");
    if (!(h.crown >= d.radius))
      r.fail("crown", "a crown radius at least the vessel radius " + number(d.radius) + " mm");
  } else if (preset == "flat") {
    h.kind = HeadKind::flat;
    h.knuckle = r.positive("knuckle");
    if (!(h.knuckle < d.radius))
      r.fail("knuckle", "a knuckle radius below the vessel radius " + number(d.radius) + " mm");
  } else if (preset == "conical") {
    h.kind = HeadKind::conical;
    const double angle = r.positive("half-angle");
    if (!(angle < 90.0)) r.fail("half-angle", "a half apex angle in (0, 90) degrees");
    h.half_angle = to_radians(angle);
    h.knuckle = r.positive("knuckle", 0.0, true);
    if (!(h.knuckle < d.radius))
      r.fail("knuckle", "a knuckle radius below the vessel radius " + number(d.radius) + " mm");
  }
  d.straight_flange = r.positive("straight-flange", 0.0, true);
  if (!(2 * d.straight_flange < d.length))
    r.fail("straight-flange",
           "a straight flange below half the length " + number(d.length) + " mm");
  d.preset_targets = r.integer("targets", d.preset_targets);
  if (d.preset_targets < 1 || d.preset_targets > kMaxCurvatureTargets)
    r.fail("targets",
           "a number of curvature targets in [1, " + std::to_string(kMaxCurvatureTargets) + "]");
  d.preset = h;
}

// <code allowable-stress="MPa" joint-efficiency="1" corrosion-allowance="mm"/>: ASME VIII-1.
CodeInputs read_code(const XmlElementReader& r) {
  CodeInputs c;
  c.allowable_stress = r.positive("allowable-stress");
  c.joint_efficiency = r.positive("joint-efficiency", 1.0);
  if (c.joint_efficiency > 1.0) r.fail("joint-efficiency", "a joint efficiency in (0, 1]");
  c.corrosion_allowance = r.positive("corrosion-allowance", 0.0, true);
  return c;
}

// smoothing="λ" fixes the weight; "auto" (the default) or kappa-tolerance="1/mm" let the design
// choose it (smoothing_choice.h).
SynthesisSettings read_synthesis(const XmlElementReader& r, SynthesisSettings s) {
  s.degree = r.integer("degree", s.degree);
  if (s.degree < 3 || s.degree > kMaxDegree)
    r.fail("degree", "an integer in [3, " + std::to_string(kMaxDegree) + "]");
  s.ordinates = r.integer("ordinates", s.ordinates);
  if (s.ordinates < s.degree + 1 || s.ordinates > kMaxOrdinates)
    r.fail("ordinates", "an integer in [degree + 1 = " + std::to_string(s.degree + 1) + ", " +
                            std::to_string(kMaxOrdinates) + "]");
  if (r.has("smoothing") && r.text("smoothing", "") != "auto") {
    s.smoothing = r.positive("smoothing", s.smoothing, true);
    s.smoothing_rule = SmoothingRule::fixed;
    if (r.has("kappa-tolerance"))
      r.fail("kappa-tolerance",
             "no kappa-tolerance with a fixed smoothing (use smoothing=\"auto\")");
  }
  if (r.has("kappa-tolerance")) {
    s.kappa_tolerance = r.positive("kappa-tolerance");
    s.smoothing_rule = SmoothingRule::tolerance;
  }
  s.symmetric = r.choice("symmetric", {"true", "false"}, s.symmetric ? "true" : "false") == "true";
  s.max_iterations = r.integer("max-iterations", s.max_iterations);
  if (s.max_iterations < 1 || s.max_iterations > kMaxSynthesisIterations)
    r.fail("max-iterations", "an integer in [1, " + std::to_string(kMaxSynthesisIterations) + "]");
  return s;
}

// Every length of a design read in another unit, in mm (κ in 1/mm): the jobs work in mm only.
void to_millimetres(VesselProject& p, double unit) {
  VesselDesign& d = p.design;
  for (double* length : {&d.radius, &d.length, &d.thickness}) *length *= unit;
  if (d.code) d.code->corrosion_allowance *= unit;
  for (CurvatureEntry& c : p.curvatures) {
    c.value = c.is_radius ? c.value * unit : c.value / unit;
    if (c.place == TargetPlace::arc_length) c.position *= unit;
  }
  d.synthesis.kappa_tolerance /= unit;
  if (d.volume) *d.volume *= unit * unit * unit;
  for (std::optional<EndCondition>* end : {&d.end_a, &d.end_b})
    if (*end)
      for (std::optional<double>* v : {&(*end)->r, &(*end)->dr, &(*end)->ddr})
        if (*v) **v *= unit;
  if (d.preset) {
    d.preset->crown *= unit;
    d.preset->knuckle *= unit;
  }
  if (d.depth) *d.depth *= unit;
  d.straight_flange *= unit;
  if (d.junction_kappa) *d.junction_kappa /= unit;
}

// The <vessel> element; `root` is the <polarform> root (null when <vessel> is the root), whose
// units apply too. Returns the length unit in mm.
double read_vessel(const XMLElement* e, const XmlElementReader* root, Reader& reader,
                   VesselProject& p) {
  double unit = 1.0;
  reader.visit(e, [&](const XmlElementReader& r) {
    unit = read_length_unit(root ? *root : r, r);
    VesselDesign& d = p.design;
    d.thickness = r.positive("thickness");
    const int sizes = r.has("radius") + r.has("diameter") + r.has("outside-diameter");
    if (sizes > 1)
      r.fail(r.has("outside-diameter") ? "outside-diameter" : "diameter",
             "one of radius, diameter (inside) and outside-diameter");
    if (r.has("diameter")) {  // what drawings give; saved as the radius
      d.radius = r.positive("diameter") / 2;
    } else if (r.has("outside-diameter")) {  // the inside radius follows from the wall
      d.radius = r.positive("outside-diameter") / 2 - d.thickness;
      if (!(d.radius > 0.0))
        r.fail("outside-diameter",
               "an outside diameter above twice the thickness " + number(2 * d.thickness) + " mm");
    } else {
      d.radius = r.positive("radius");
    }
    d.length = r.positive("length");
    d.pressure = r.positive("pressure");
    d.density = r.positive("density", d.density);
    d.poisson = r.positive("poisson", d.poisson, true);
    if (!(d.poisson < 0.5)) r.fail("poisson", "a Poisson's ratio in [0, 0.5)");
    d.synthesis.smoothing_rule = SmoothingRule::shape_preserving;
    const std::vector<const XMLElement*> curvatures = r.children("curvature");
    if (curvatures.size() > kMaxCurvatureTargets)
      throw InputError(r.where() + ": " + std::to_string(curvatures.size()) +
                       " <curvature> elements, above the limit " +
                       std::to_string(kMaxCurvatureTargets));
    for (const XMLElement* c : curvatures)
      reader.visit(c, [&](const XmlElementReader& cr) { p.curvatures.push_back(read_curvature(cr)); });
    for (const XMLElement* c : r.children("end"))
      reader.visit(c, [&](const XmlElementReader& er) {
        std::optional<EndCondition>& end = er.choice("at", {"A", "B"}) == "A" ? d.end_a : d.end_b;
        if (end) er.fail("at", "each end at most once");
        end = read_end(er, d.radius);
      });
    const bool curvature_inputs =
        !curvatures.empty() || !r.children("end").empty() || !r.children("synthesis").empty();
    const std::vector<const XMLElement*> heads = r.children("head");
    for (const XMLElement* h : heads)
      reader.visit(h, [&](const XmlElementReader& hr) {
        if (h != heads.front()) throw InputError(hr.where() + ": expected one <head> per vessel");
        read_head(hr, d, curvature_inputs, !curvatures.empty());
      });
    const std::vector<const XMLElement*> codes = r.children("code");
    for (const XMLElement* c : codes)
      reader.visit(c, [&](const XmlElementReader& cr) {
        if (c != codes.front()) throw InputError(cr.where() + ": expected one <code> per vessel");
        d.code = read_code(cr);
      });
    const std::vector<const XMLElement*> settings = r.children("synthesis");
    for (const XMLElement* s : settings)
      reader.visit(s, [&](const XmlElementReader& sr) {
        if (s != settings.front())
          throw InputError(sr.where() + ": expected one <synthesis> per vessel");
        d.synthesis = read_synthesis(sr, d.synthesis);
      });
    if (p.curvatures.empty() && !d.preset && d.head_design != HeadDesign::minimum_stress)
      throw InputError(r.where() + ": expected <curvature> elements or a <head preset>");
  });
  to_millimetres(p, unit);
  return unit;
}

VesselProject read_document(const XmlDocument& doc, std::vector<std::string>& warnings,
                            UnknownNames policy) {
  VesselProject p;
  Reader reader(doc.file());
  const XMLElement* root = doc.root();
  if (std::string(root->Name()) == "vessel") {
    read_vessel(root, nullptr, reader, p);
    settle_unknown_names(reader.unknown(), policy, warnings);
    return p;
  }
  reader.visit(root, [&](const XmlElementReader& r) {
    if (std::string(root->Name()) != "polarform")
      throw InputError(r.where() + ": expected a <polarform> or <vessel> root element");
    check_project_version(r, policy, warnings);
    const XMLElement* vessel = r.child("vessel");
    if (!vessel) throw InputError(r.where() + ": expected a <vessel> element");
    const double unit = read_vessel(vessel, &r, reader, p);
    if (const XMLElement* conversion = r.child("conversion"))
      reader.visit(conversion, [&](const XmlElementReader& cr) {
        if (cr.has("tolerance")) p.tolerance = cr.positive("tolerance") * unit;
        if (p.tolerance < kMinTolerance)
          cr.fail("tolerance", "a tolerance >= " + number(kMinTolerance) + " mm");
        p.compaction = read_compaction(cr);
      });
  });
  settle_unknown_names(reader.unknown(), policy, warnings);
  return p;
}

void attribute(std::ostream& out, const char* name, const std::string& value) {
  out << ' ' << name << "=\"" << value << '"';
}

void attribute(std::ostream& out, const char* name, double value) {
  attribute(out, name, number(value));
}

}  // namespace

VesselDesign to_design(const VesselProject& project) {
  VesselDesign d = project.design;
  d.targets.clear();
  for (const CurvatureEntry& c : project.curvatures)
    d.targets.push_back(
        {c.theta_deg * kRadiansPerDegree, c.is_radius ? 1.0 / c.value : c.value, c.weight, c.place,
         c.place == TargetPlace::meridian_angle ? c.position * kRadiansPerDegree : c.position});
  return d;
}

VesselProject read_vessel_project(const std::filesystem::path& file,
                                  std::vector<std::string>& warnings, UnknownNames policy) {
  return read_document(XmlDocument(file), warnings, policy);
}

VesselProject parse_vessel_project(const std::string& text, const std::string& file,
                                   std::vector<std::string>& warnings, UnknownNames policy) {
  return read_document(XmlDocument(text, file), warnings, policy);
}

std::string vessel_project_xml(const VesselProject& p) {
  const VesselDesign& d = p.design;
  std::ostringstream out;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<polarform version=\"1\">\n  <vessel";
  attribute(out, "radius", d.radius);
  attribute(out, "length", d.length);
  attribute(out, "thickness", d.thickness);
  attribute(out, "pressure", d.pressure);
  attribute(out, "density", d.density);
  attribute(out, "poisson", d.poisson);
  out << ">\n";
  if (d.code) {
    out << "    <code";
    attribute(out, "allowable-stress", d.code->allowable_stress);
    attribute(out, "joint-efficiency", d.code->joint_efficiency);
    attribute(out, "corrosion-allowance", d.code->corrosion_allowance);
    out << "/>\n";
  }
  for (const CurvatureEntry& c : p.curvatures) {
    out << "    <curvature";
    if (c.place == TargetPlace::polar_angle) attribute(out, "theta", c.theta_deg);
    if (c.place == TargetPlace::arc_length) attribute(out, "s", c.position);
    if (c.place == TargetPlace::meridian_angle) attribute(out, "phi", c.position);
    attribute(out, c.is_radius ? "radius" : "kappa", c.value);
    attribute(out, "weight", c.weight);
    out << "/>\n";
  }
  for (const auto& [name, end] : {std::pair{"A", &d.end_a}, std::pair{"B", &d.end_b}}) {
    if (!*end) continue;
    out << "    <end";
    attribute(out, "at", std::string(name));
    if ((*end)->r) attribute(out, "r", *(*end)->r);
    if ((*end)->dr) attribute(out, "dr", *(*end)->dr);
    if ((*end)->ddr) attribute(out, "ddr", *(*end)->ddr);
    out << "/>\n";
  }
  if (d.preset || d.depth || d.volume || d.head_design == HeadDesign::minimum_stress) {
    out << "    <head";
    if (d.preset) attribute(out, "preset", std::string(head_kind_name(d.preset->kind)));
    attribute(out, "design", std::string(head_design_name(d.head_design)));
    if (d.preset && d.preset->kind == HeadKind::ellipsoidal)
      attribute(out, "ratio", d.preset->ratio);
    if (d.preset && d.preset->kind == HeadKind::torispherical) {
      attribute(out, "crown", d.preset->crown);
      attribute(out, "knuckle", d.preset->knuckle);
    }
    if (d.preset && d.preset->kind == HeadKind::flat) attribute(out, "knuckle", d.preset->knuckle);
    if (d.preset && d.preset->kind == HeadKind::conical) {
      attribute(out, "half-angle", to_degrees(d.preset->half_angle));
      attribute(out, "knuckle", d.preset->knuckle);
    }
    if (d.preset) attribute(out, "targets", std::to_string(d.preset_targets));
    if (d.straight_flange > 0.0) attribute(out, "straight-flange", d.straight_flange);
    if (d.depth) attribute(out, "depth", *d.depth);
    if (d.volume) attribute(out, "volume", *d.volume);
    if (d.junction_kappa) attribute(out, "junction-kappa", *d.junction_kappa);
    out << "/>\n";
  }
  const SynthesisSettings& s = d.synthesis;
  out << "    <synthesis";
  attribute(out, "degree", std::to_string(s.degree));
  attribute(out, "ordinates", std::to_string(s.ordinates));
  if (s.smoothing_rule == SmoothingRule::fixed)
    attribute(out, "smoothing", s.smoothing);
  else
    attribute(out, "smoothing", std::string("auto"));
  if (s.smoothing_rule == SmoothingRule::tolerance)
    attribute(out, "kappa-tolerance", s.kappa_tolerance);
  attribute(out, "symmetric", std::string(s.symmetric ? "true" : "false"));
  attribute(out, "max-iterations", std::to_string(s.max_iterations));
  out << "/>\n  </vessel>\n  <conversion";
  attribute(out, "tolerance", p.tolerance);
  attribute(out, "compaction", compaction_name(p.compaction));
  out << "/>\n</polarform>\n";
  return out.str();
}

void write_vessel_project(const VesselProject& project, const std::filesystem::path& file) {
  write_file_atomically(file, vessel_project_xml(project));
}

}  // namespace polarform
