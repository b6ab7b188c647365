// The vessel project file: the examples load without warnings, save → load is exact, every bad
// value names file:line:attribute, unknown fields are warnings.
#include "jobs/project/vessel_project.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <numbers>

#include "src/error.h"

namespace polarform {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;
constexpr double kPi = std::numbers::pi;

const fs::path kExamples = fs::path(POLARFORM_SOURCE_DIR) / "examples" / "vessels";

std::string error_of(const std::string& xml) {
  std::vector<std::string> warnings;
  try {
    parse_vessel_project(xml, "t.xml", warnings);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

std::string vessel(const std::string& attributes, const std::string& children) {
  return "<polarform version=\"1\">\n<vessel " + attributes + ">\n" + children +
         "</vessel>\n</polarform>";
}

const std::string kVessel = "radius=\"500\" length=\"1500\" thickness=\"10\" pressure=\"2\"";

TEST(VesselProject, ExamplesLoadWithoutWarnings) {
  for (const char* name : {"hemispherical.xml", "ellipsoidal_2_1.xml", "torispherical_100_6.xml",
                           "custom_curvature.xml"}) {
    std::vector<std::string> warnings;
    const VesselProject p = read_vessel_project(kExamples / name, warnings);
    EXPECT_TRUE(warnings.empty()) << name << ": " << (warnings.empty() ? "" : warnings[0]);
    EXPECT_GT(p.design.radius, 0.0) << name;
  }
  std::vector<std::string> warnings;
  const VesselProject t = read_vessel_project(kExamples / "torispherical_100_6.xml", warnings);
  ASSERT_TRUE(t.design.preset);
  EXPECT_EQ(*t.design.preset, torispherical_100_6(t.design.radius));
  const VesselProject c = read_vessel_project(kExamples / "custom_curvature.xml", warnings);
  EXPECT_FALSE(c.design.preset);
  EXPECT_GE(c.curvatures.size(), 5u);
}

VesselProject odd_project() {
  VesselProject p;
  p.design.radius = 612.345678901234;
  p.design.length = 1.0 / 3.0;
  p.design.thickness = 0.1;
  p.design.pressure = 1e-7;
  p.compaction = Compaction::none;
  p.curvatures = {{0.0, 1.0 / 612.345678901234, false, 1.0},
                  {33.3333333333333, 0.0017, false, 2.5},
                  {90.0, -2450.5, true, 1e-3},
                  {180.0, 1e-3, false, 7}};
  p.design.end_a = EndCondition{612.345678901234, std::nullopt, -0.3};
  p.design.end_b = EndCondition{std::nullopt, 0.0, std::nullopt};
  p.design.preset = HeadPreset{HeadKind::torispherical, 2.0, 1224.69, 61.2345};
  p.design.preset_targets = 73;
  p.design.synthesis = {6, 23, 3.14e-9, true, 77};
  p.tolerance = 2.5e-4;
  return p;
}

TEST(VesselProject, SaveLoadRoundTripIsExact) {
  const VesselProject p = odd_project();
  std::vector<std::string> warnings;
  EXPECT_EQ(parse_vessel_project(vessel_project_xml(p), "mem.xml", warnings), p);
  EXPECT_TRUE(warnings.empty());

  VesselProject e = odd_project();
  e.design.preset = HeadPreset{HeadKind::ellipsoidal, 1.75};
  e.design.end_b.reset();
  EXPECT_EQ(parse_vessel_project(vessel_project_xml(e), "mem.xml", warnings), e);

  const fs::path dir =
      fs::temp_directory_path() / ("polarform_vessel_project_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  write_vessel_project(p, dir / "p.xml");
  EXPECT_EQ(read_vessel_project(dir / "p.xml", warnings), p);
  EXPECT_TRUE(warnings.empty());
  fs::remove_all(dir);
}

// A curvature head of a prescribed depth: from its targets without a preset, or from a preset's;
// saved and loaded exactly; the depth is refused on an exact head.
TEST(VesselProject, CurvatureHeadOfAGivenDepth) {
  std::vector<std::string> warnings;
  const VesselProject p =
      parse_vessel_project(vessel(kVessel,
                                  "<curvature theta=\"45\" radius=\"450\"/>\n"
                                  "<head design=\"curvature\" depth=\"420\"/>\n"),
                           "t.xml", warnings);
  EXPECT_EQ(p.design.head_design, HeadDesign::curvature);
  EXPECT_EQ(p.design.depth, 420.0);
  EXPECT_FALSE(p.design.preset);
  EXPECT_EQ(parse_vessel_project(vessel_project_xml(p), "mem.xml", warnings), p);
  const VesselProject q = parse_vessel_project(
      vessel(kVessel, "<head preset=\"ellipsoidal\" design=\"curvature\" depth=\"200\"/>\n"),
      "t.xml", warnings);
  EXPECT_EQ(q.design.depth, 200.0);
  EXPECT_EQ(parse_vessel_project(vessel_project_xml(q), "mem.xml", warnings), q);
  EXPECT_TRUE(warnings.empty());
  EXPECT_EQ(error_of(vessel(kVessel, "<head preset=\"ellipsoidal\" depth=\"200\"/>\n")),
            "t.xml:3: <head> attribute 'depth': expected no depth unless "
            "design=\"minimum-stress\" or \"curvature\", got '200'");
}

// Targets by arc length or meridian angle, a volume, and the smoothing rules: read, carried into
// the design (φ in radians), saved and loaded exactly, and their errors named.
TEST(VesselProject, TargetPlacesVolumeAndSmoothingRules) {
  std::vector<std::string> warnings;
  const VesselProject p =
      parse_vessel_project(vessel(kVessel,
                                  "<curvature s=\"120\" kappa=\"0.003\"/>\n"
                                  "<curvature phi=\"30\" radius=\"600\" weight=\"2\"/>\n"
                                  "<curvature theta=\"90\" radius=\"700\"/>\n"
                                  "<head design=\"curvature\" volume=\"1.2e8\"/>\n"
                                  "<synthesis smoothing=\"auto\" kappa-tolerance=\"2e-5\"/>\n"),
                           "t.xml", warnings);
  ASSERT_EQ(p.curvatures.size(), 3u);
  EXPECT_EQ(p.curvatures[0].place, TargetPlace::arc_length);
  EXPECT_EQ(p.curvatures[0].position, 120.0);
  EXPECT_EQ(p.curvatures[1].place, TargetPlace::meridian_angle);
  EXPECT_EQ(p.design.volume, 1.2e8);
  EXPECT_FALSE(p.design.preset);
  EXPECT_EQ(p.design.synthesis.smoothing_rule, SmoothingRule::tolerance);
  EXPECT_EQ(p.design.synthesis.kappa_tolerance, 2e-5);
  const VesselDesign d = to_design(p);
  EXPECT_EQ(d.targets[0].place, TargetPlace::arc_length);
  EXPECT_DOUBLE_EQ(d.targets[1].position, kPi / 6);
  EXPECT_DOUBLE_EQ(d.targets[1].kappa, 1 / 600.0);
  EXPECT_EQ(d.targets[2].place, TargetPlace::polar_angle);
  EXPECT_EQ(parse_vessel_project(vessel_project_xml(p), "mem.xml", warnings), p);
  const VesselProject fixed = parse_vessel_project(
      vessel(kVessel, "<curvature s=\"0\" kappa=\"0.002\"/>\n<synthesis smoothing=\"1e-5\"/>\n"),
      "t.xml", warnings);
  EXPECT_EQ(fixed.design.synthesis.smoothing_rule, SmoothingRule::fixed);
  EXPECT_EQ(fixed.design.synthesis.smoothing, 1e-5);
  EXPECT_EQ(parse_vessel_project(vessel_project_xml(fixed), "mem.xml", warnings), fixed);
  EXPECT_TRUE(warnings.empty());
  EXPECT_EQ(error_of(vessel(kVessel, "<curvature theta=\"20\" s=\"40\" kappa=\"0.002\"/>\n")),
            "t.xml:3: <curvature> attribute 's': expected exactly one of theta (polar angle, "
            "degrees), s (arc length from junction A, mm) and phi (meridian angle, degrees), got "
            "'40'");
  EXPECT_EQ(error_of(vessel(kVessel, "<curvature phi=\"95\" kappa=\"0.002\"/>\n")),
            "t.xml:3: <curvature> attribute 'phi': expected a meridian angle in [-90, 90] degrees "
            "(90 at junction A, 0 at the apex), got '95'");
  EXPECT_EQ(error_of(vessel(kVessel,
                            "<curvature s=\"20\" kappa=\"0.002\"/>\n"
                            "<synthesis smoothing=\"1e-6\" kappa-tolerance=\"1e-5\"/>\n")),
            "t.xml:4: <synthesis> attribute 'kappa-tolerance': expected no kappa-tolerance with a "
            "fixed smoothing (use smoothing=\"auto\"), got '1e-5'");
  EXPECT_EQ(error_of(vessel(kVessel, "<head preset=\"ellipsoidal\" volume=\"1e8\"/>\n")),
            "t.xml:3: <head> attribute 'volume': expected no volume unless "
            "design=\"curvature\", got '1e8'");
}

// A flanged flat head: its knuckle read and saved; a missing or too large knuckle named.
TEST(VesselProject, FlatHead) {
  std::vector<std::string> warnings;
  const VesselProject p = parse_vessel_project(
      vessel(kVessel, "<head preset=\"flat\" knuckle=\"60\"/>\n"), "t.xml", warnings);
  ASSERT_TRUE(p.design.preset);
  EXPECT_EQ(p.design.preset->kind, HeadKind::flat);
  EXPECT_EQ(p.design.preset->knuckle, 60.0);
  EXPECT_EQ(p.design.head_design, HeadDesign::exact);
  EXPECT_EQ(parse_vessel_project(vessel_project_xml(p), "mem.xml", warnings), p);
  EXPECT_EQ(error_of(vessel(kVessel, "<head preset=\"flat\"/>\n")),
            "t.xml:3: <head> attribute 'knuckle': expected a number (attribute is missing)");
  EXPECT_EQ(
      error_of(vessel(kVessel, "<head preset=\"flat\" knuckle=\"500\"/>\n")),
      "t.xml:3: <head> attribute 'knuckle': expected a knuckle radius below the vessel radius "
      "500 mm, got '500'");
}

TEST(VesselProject, ToDesignConvertsUnits) {
  const VesselDesign d = to_design(odd_project());
  ASSERT_EQ(d.targets.size(), 4u);
  EXPECT_DOUBLE_EQ(d.targets[1].theta, 33.3333333333333 * kPi / 180);
  EXPECT_EQ(d.targets[1].kappa, 0.0017);
  EXPECT_EQ(d.targets[2].kappa, 1 / -2450.5);  // a radius of curvature
  EXPECT_EQ(d.targets[2].weight, 1e-3);
  EXPECT_DOUBLE_EQ(d.targets[3].theta, kPi);
  EXPECT_EQ(d.radius, 612.345678901234);
}

TEST(VesselProject, BareVesselRootAndDefaults) {
  std::vector<std::string> warnings;
  const VesselProject p = parse_vessel_project(
      "<vessel " + kVessel + "><head preset=\"hemispherical\"/></vessel>", "t.xml", warnings);
  EXPECT_TRUE(warnings.empty());
  EXPECT_EQ(p.design.preset, HeadPreset{});
  // A project's synthesis chooses its smoothing unless the file fixes it (smoothing_choice.h).
  SynthesisSettings defaults;
  defaults.smoothing_rule = SmoothingRule::shape_preserving;
  EXPECT_EQ(p.design.synthesis, defaults);
  EXPECT_FALSE(p.design.end_a);
  EXPECT_EQ(p.tolerance, 1e-3);
  EXPECT_EQ(p.compaction, Compaction::refit);
  EXPECT_EQ(p.design.preset_targets, 48);
}

TEST(VesselProject, BadValuesNameFileLineAndAttribute) {
  const std::string head = "<head preset=\"hemispherical\"/>\n";
  const std::pair<std::string, std::string> cases[] = {
      {vessel("radius=\"-1\" length=\"1500\" thickness=\"10\" pressure=\"2\"", head),
       "t.xml:2: <vessel> attribute 'radius': expected a number > 0, got '-1'"},
      {vessel("radius=\"500\" length=\"1500\" thickness=\"10\"", head),
       "t.xml:2: <vessel> attribute 'pressure': expected a number (attribute is missing)"},
      {vessel(kVessel, "<curvature theta=\"200\" kappa=\"0.002\"/>\n"),
       "t.xml:3: <curvature> attribute 'theta': expected an angle in [0, 180] degrees, got '200'"},
      {vessel(kVessel, "<curvature theta=\"20\" kappa=\"0.002\" radius=\"500\"/>\n"),
       "t.xml:3: <curvature> attribute 'radius': expected either kappa or radius, not both, got "
       "'500'"},
      {vessel(kVessel, "<curvature theta=\"20\"/>\n"),
       "t.xml:3: <curvature> attribute 'kappa': expected a number (attribute is missing)"},
      {vessel(kVessel, "<curvature theta=\"20\" radius=\"0\"/>\n"),
       "t.xml:3: <curvature> attribute 'radius': expected a non-zero radius of curvature in mm, "
       "got '0'"},
      {vessel(kVessel, "<curvature theta=\"20\" kappa=\"0.002\" weight=\"0\"/>\n"),
       "t.xml:3: <curvature> attribute 'weight': expected a number > 0, got '0'"},
      {vessel(kVessel, head + "<end at=\"C\"/>\n"),
       "t.xml:4: <end> attribute 'at': expected one of A|B, got 'C'"},
      {vessel(kVessel, head + "<end at=\"A\" r=\"500\"/>\n<end at=\"A\" dr=\"0\"/>\n"),
       "t.xml:5: <end> attribute 'at': expected each end at most once, got 'A'"},
      {vessel(kVessel, head + "<end at=\"B\" ddr=\"x\"/>\n"),
       "t.xml:4: <end> attribute 'ddr': expected a finite number, got 'x'"},
      {vessel(kVessel, "<head preset=\"torispherical\" crown=\"1000\" knuckle=\"600\"/>\n"),
       "t.xml:3: <head> attribute 'knuckle': expected a knuckle radius below the vessel radius 500 "
       "mm, got '600'"},
      {vessel(kVessel, "<head preset=\"torispherical\" crown=\"400\" knuckle=\"60\"/>\n"),
       "t.xml:3: <head> attribute 'crown': expected a crown radius at least the vessel radius 500 "
       "mm, got '400'"},
      {vessel(kVessel, "<head preset=\"dome\"/>\n"),
       "t.xml:3: <head> attribute 'preset': expected one of "
       "hemispherical|ellipsoidal|torispherical|conical|flat, got 'dome'"},
      {vessel(kVessel, "<head preset=\"conical\"/>\n"),
       "t.xml:3: <head> attribute 'half-angle': expected a number (attribute is missing)"},
      {vessel(kVessel, "<head preset=\"hemispherical\" targets=\"0\"/>\n"),
       "t.xml:3: <head> attribute 'targets': expected a number of curvature targets in [1, 20000], "
       "got '0'"},
      // Sizes the user controls are limited before anything is allocated.
      {vessel(kVessel, "<head preset=\"hemispherical\" targets=\"1000000000\"/>\n"),
       "t.xml:3: <head> attribute 'targets': expected a number of curvature targets in [1, 20000], "
       "got '1000000000'"},
      {vessel(kVessel, head + "<synthesis ordinates=\"1000000\"/>\n"),
       "t.xml:4: <synthesis> attribute 'ordinates': expected an integer in [degree + 1 = 6, 400], "
       "got '1000000'"},
      {vessel(kVessel, head + "<synthesis max-iterations=\"1000000000\"/>\n"),
       "t.xml:4: <synthesis> attribute 'max-iterations': expected an integer in [1, 10000], got "
       "'1000000000'"},
      {vessel(kVessel, head + "<synthesis degree=\"2\"/>\n"),
       "t.xml:4: <synthesis> attribute 'degree': expected an integer in [3, 40], got '2'"},
      {vessel(kVessel, head + "<synthesis ordinates=\"5\"/>\n"),
       "t.xml:4: <synthesis> attribute 'ordinates': expected an integer in [degree + 1 = 6, 400], "
       "got '5'"},
      {vessel(kVessel, head + "<synthesis symmetric=\"yes\"/>\n"),
       "t.xml:4: <synthesis> attribute 'symmetric': expected one of true|false, got 'yes'"},
      {vessel(kVessel, head + "<synthesis smoothing=\"-1\"/>\n"),
       "t.xml:4: <synthesis> attribute 'smoothing': expected a number >= 0, got '-1'"},
      {vessel(kVessel, head + "<synthesis/>\n<synthesis/>\n"),
       "t.xml:5: <synthesis>: expected one <synthesis> per vessel"},
      {vessel(kVessel, ""), "t.xml:2: <vessel>: expected <curvature> elements or a <head preset>"},
      {"<polarform version=\"1\"/>", "t.xml:1: <polarform>: expected a <vessel> element"},
      {"<cam/>", "t.xml:1: <cam>: expected a <polarform> or <vessel> root element"},
      {"<polarform version=\"2\"><vessel/></polarform>",
       "t.xml:1: <polarform> attribute 'version': expected 1 (the project version this polarform "
       "reads; --lenient reads a newer one as far as it knows it), got '2'"},
  };
  for (const auto& [xml, expected] : cases) EXPECT_EQ(error_of(xml), expected) << xml;
}

// A vessel in inches: lengths, radii of curvature and end conditions to mm, κ to 1/mm, a given
// tolerance to mm; the pressure stays in MPa.
TEST(VesselProject, InchProjectsAreReadInMillimetres) {
  std::vector<std::string> warnings;
  const VesselProject p = parse_vessel_project(
      "<polarform version=\"1\" units=\"inch\">\n<vessel radius=\"20\" length=\"40\" "
      "thickness=\"0.5\" pressure=\"2\">\n<curvature theta=\"20\" kappa=\"0.05\"/>\n"
      "<curvature theta=\"90\" radius=\"10\"/>\n<end at=\"A\" r=\"20\" dr=\"0\" ddr=\"1\"/>\n"
      "<head preset=\"torispherical\" crown=\"20\" knuckle=\"2\"/>\n</vessel>\n"
      "<conversion tolerance=\"0.0001\"/>\n</polarform>\n",
      "t.xml", warnings);
  EXPECT_DOUBLE_EQ(p.design.radius, 508.0);
  EXPECT_DOUBLE_EQ(p.design.length, 1016.0);
  EXPECT_DOUBLE_EQ(p.design.thickness, 12.7);
  EXPECT_DOUBLE_EQ(p.design.pressure, 2.0);
  EXPECT_DOUBLE_EQ(p.curvatures[0].value, 0.05 / 25.4);
  EXPECT_DOUBLE_EQ(p.curvatures[1].value, 254.0);
  EXPECT_DOUBLE_EQ(*p.design.end_a->r, 508.0);
  EXPECT_DOUBLE_EQ(*p.design.end_a->ddr, 25.4);
  EXPECT_DOUBLE_EQ(p.design.preset->crown, 508.0);
  EXPECT_DOUBLE_EQ(p.design.preset->knuckle, 50.8);
  EXPECT_DOUBLE_EQ(p.tolerance, 0.00254);
  EXPECT_TRUE(warnings.empty());
  // Drawings give the diameter: accepted, never together with the radius; a name that is not
  // accepted is refused with the accepted ones.
  const std::string head = "<head preset=\"hemispherical\"/>\n";
  EXPECT_DOUBLE_EQ(parse_vessel_project(vessel("diameter=\"1000\" length=\"1500\" thickness=\"10\" "
                                               "pressure=\"2\"",
                                               head),
                                        "t.xml", warnings)
                       .design.radius,
                   500.0);
  EXPECT_NE(error_of(vessel(kVessel + " diameter=\"1000\"", head))
                .find("attribute 'diameter': expected one of radius, diameter (inside) and "
                      "outside-diameter"),
            std::string::npos);
  EXPECT_NE(
      error_of(vessel(kVessel + " dia=\"1000\"", head))
          .find("unknown attribute 'dia' on <vessel> (known here: density, diameter, length, "),
      std::string::npos)
      << error_of(vessel(kVessel + " dia=\"1000\"", head));
}

TEST(VesselProject, UnknownNamesAreErrorsOrLenientWarnings) {
  const std::string xml =
      "<polarform version=\"1\">\n<vessel " + kVessel +
      " colour=\"red\">\n"
      "<curvature theta=\"20\" kappa=\"0.002\" unit=\"1/mm\"/>\n"
      "<head preset=\"hemispherical\" crown=\"900\"/>\n"
      "<nozzle/>\n</vessel>\n<conversion tolerance=\"0.01\" base=\"quasi-uniform\"/>\n</polarform>";
  std::vector<std::string> warnings;
  const std::string error = error_of(xml);
  for (const char* line :
       {"t.xml:3: unknown attribute 'unit' on <curvature> (known here: ",
        "t.xml:4: unknown attribute 'crown' on <head> (known here: ",
        "t.xml:2: unknown attribute 'colour' on <vessel> (known here: ",
        "t.xml:5: unknown element <nozzle> in <vessel> (known here: ",
        "t.xml:7: unknown attribute 'base' on <conversion> (known here: compaction, tolerance)"})
    EXPECT_NE(error.find(line), std::string::npos) << line << " in " << error;
  parse_vessel_project(xml, "t.xml", warnings, UnknownNames::warn);
  ASSERT_EQ(warnings.size(), 5u);
  EXPECT_EQ(warnings[0].rfind(
                "t.xml:3: unknown attribute 'unit' on <curvature> ignored (known here: ", 0),
            0u)
      << warnings[0];
  EXPECT_EQ(warnings[4],
            "t.xml:7: unknown attribute 'base' on <conversion> ignored (known here: compaction, "
            "tolerance)");
}

}  // namespace
}  // namespace polarform
