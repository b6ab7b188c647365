// Cam project files: the examples load cleanly, round-trip exactly and are the designs the
// designer tests build in code; every kind of broken file gives its own error naming file, line
// and field; random corruption never escapes as anything but InputError.
#include "jobs/project/cam_project.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>
#include <sstream>

#include "src/error.h"
#include "src/units.h"
#include "tests/support/designers/example_cams.h"

namespace polarform {
namespace {

namespace fs = std::filesystem;
const fs::path kExamples = fs::path(POLARFORM_SOURCE_DIR) / "examples" / "cams";
constexpr double kPi = std::numbers::pi;

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string error_of(const std::string& xml) {
  std::vector<std::string> warnings;
  try {
    parse_cam_project(xml, "cam.xml", warnings);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

std::string cam(const std::string& attributes, const std::string& segments) {
  return "<polarform version=\"1\">\n<cam " + attributes + ">\n" + segments + "</cam>\n</polarform>\n";
}

const std::string kPlate = "follower=\"roller\" base-radius=\"40\" roller-radius=\"10\"";
const std::string kSegments =
    "<segment kind=\"rise\" law=\"cycloidal\" lift=\"20\" to=\"180\"/>\n"
    "<segment kind=\"return\" law=\"4-5-6-7\" to=\"360\"/>\n";

TEST(CamProject, ExamplesLoadWithoutWarningsAndRoundTripExactly) {
  int count = 0;
  for (const auto& entry : fs::directory_iterator(kExamples)) {
    std::vector<std::string> warnings;
    const CamProject p = read_cam_project(entry.path(), warnings);
    EXPECT_TRUE(warnings.empty()) << entry.path() << ": " << (warnings.empty() ? "" : warnings[0]);
    std::vector<std::string> again_warnings;
    const CamProject again = parse_cam_project(cam_project_xml(p), "saved.xml", again_warnings);
    EXPECT_TRUE(again == p) << entry.path();
    EXPECT_TRUE(again_warnings.empty());
    EXPECT_EQ(cam_project_xml(again), cam_project_xml(p));
    ++count;
  }
  EXPECT_EQ(count, 10);
}

// law="scca" with its fractions b, c, d (b + c + d = 1), kept through a save; the program's
// displacement is the SCCA law's.
TEST(CamProject, SccaLawsAreReadWithTheirFractions) {
  std::vector<std::string> warnings;
  const CamProject p = parse_cam_project(
      cam(kPlate,
          "<segment kind=\"rise\" law=\"scca\" b=\"0.2\" c=\"0.6\" d=\"0.2\" lift=\"20\" "
          "to=\"180\"/>\n<segment kind=\"return\" law=\"scca\" to=\"360\"/>\n"),
      "cam.xml", warnings);
  const SegmentSpec& rise = p.cam.segments[0];
  EXPECT_EQ(rise.law, MotionLaw::Scca);
  EXPECT_EQ(rise.scca, (SccaParameters{0.2, 0.6, 0.2}));
  EXPECT_EQ(p.cam.segments[1].scca, SccaParameters{});  // the modified trapezoid's by default
  EXPECT_TRUE(parse_cam_project(cam_project_xml(p), "saved.xml", warnings) == p);
  const MotionSegment segment(rise, 0.0);
  double s[3], law[3];
  segment.derivatives(kPi / 4, 2, s);
  SccaLaw({0.2, 0.6, 0.2}).derivatives(0.25, 2, law);
  EXPECT_NEAR(s[0], 20 * law[0], 1e-12);
  EXPECT_NEAR(s[2], 20 * law[2] / (kPi * kPi), 1e-12);
  EXPECT_NE(error_of(cam(kPlate,
                         "<segment kind=\"rise\" law=\"scca\" b=\"0.5\" c=\"0.5\" d=\"0.5\" "
                         "lift=\"20\" to=\"180\"/>\n<segment kind=\"return\" to=\"360\"/>\n"))
                .find("attribute 'd': expected fractions with b + c + d = 1"),
            std::string::npos);
}

TEST(CamProject, PressureAngleLimitIsReadInDegreesAndSaved) {
  std::vector<std::string> warnings;
  const CamProject p = parse_cam_project(cam(kPlate + " pressure-angle-limit=\"35\"", kSegments),
                                         "cam.xml", warnings);
  ASSERT_TRUE(p.pressure_angle_limit);
  EXPECT_NEAR(*p.pressure_angle_limit * kDegreesPerRadian, 35.0, 1e-12);
  EXPECT_NE(cam_project_xml(p).find("pressure-angle-limit=\"35\""), std::string::npos);
  EXPECT_TRUE(parse_cam_project(cam_project_xml(p), "saved.xml", warnings) == p);
  EXPECT_FALSE(parse_cam_project(cam(kPlate, kSegments), "cam.xml", warnings).pressure_angle_limit);
  for (const char* bad : {"0", "90", "-5", "x"})
    EXPECT_NE(error_of(cam(kPlate + " pressure-angle-limit=\"" + bad + "\"", kSegments))
                  .find("attribute 'pressure-angle-limit'"),
              std::string::npos)
        << bad;
}

// A project in inches is converted to mm as it is read: every length, the endpoint derivatives
// (mm/rad^k) and a given tolerance; the default tolerance stays 1 µm; the angles and the speed
// are no lengths.
TEST(CamProject, InchProjectsAreReadInMillimetres) {
  std::vector<std::string> warnings;
  const std::string segments =
      "<segment kind=\"rise\" law=\"polynomial\" lift=\"1\" to=\"180\">"
      "<start v=\"0.5\"/><end v=\"0.25\" a=\"2\"/></segment>\n"
      "<segment kind=\"return\" law=\"cycloidal\" to=\"360\"/>\n";
  const CamProject inch = parse_cam_project(
      cam("units=\"inch\" follower=\"roller\" base-radius=\"2\" roller-radius=\"0.5\" "
          "offset=\"0.25\" rpm=\"120\"",
          segments),
      "cam.xml", warnings);
  EXPECT_DOUBLE_EQ(inch.cam.base_radius, 50.8);
  EXPECT_DOUBLE_EQ(inch.cam.follower.roller_radius, 12.7);
  EXPECT_DOUBLE_EQ(inch.cam.follower.offset, 6.35);
  EXPECT_DOUBLE_EQ(inch.cam.rpm, 120.0);
  EXPECT_DOUBLE_EQ(inch.cam.segments[0].lift, 25.4);
  EXPECT_DOUBLE_EQ(inch.cam.segments[1].lift, 25.4);  // the level reached, in mm
  EXPECT_DOUBLE_EQ(inch.cam.segments[0].at_start.velocity, 12.7);
  EXPECT_DOUBLE_EQ(inch.cam.segments[0].at_end.acceleration, 50.8);
  EXPECT_DOUBLE_EQ(inch.cam.segments[0].end * kDegreesPerRadian, 180.0);
  EXPECT_DOUBLE_EQ(inch.conversion.tolerance, 1e-3);
  // On the root, with a tolerance: the same conversion; saved in mm, the same project again.
  const std::string root_inch =
      "<polarform version=\"1\" units=\"inch\">\n<cam follower=\"roller\" base-radius=\"2\" "
      "roller-radius=\"0.5\" offset=\"0.25\" rpm=\"120\">\n" +
      segments + "</cam>\n<conversion tolerance=\"0.0001\"/>\n</polarform>\n";
  const CamProject root = parse_cam_project(root_inch, "cam.xml", warnings);
  EXPECT_TRUE(root.cam == inch.cam);
  EXPECT_DOUBLE_EQ(root.conversion.tolerance, 0.00254);
  EXPECT_TRUE(parse_cam_project(cam_project_xml(root), "saved.xml", warnings) == root);
  // The tolerance floor (1e-9 mm) applies in mm: 5e-10 inch is 1.27e-9 mm, above it.
  std::string fine = root_inch;
  fine.replace(fine.find("0.0001"), 6, "5e-10");
  EXPECT_DOUBLE_EQ(parse_cam_project(fine, "cam.xml", warnings).conversion.tolerance, 5e-10 * 25.4);
  EXPECT_TRUE(warnings.empty());
  EXPECT_NE(error_of(cam("units=\"furlong\" " + kPlate, kSegments)).find("attribute 'units'"),
            std::string::npos);
  std::string conflict = root_inch;
  conflict.replace(conflict.find("<cam "), 5, "<cam units=\"mm\" ");
  EXPECT_NE(error_of(conflict).find("attribute 'units': expected the units of the root element"),
            std::string::npos)
      << error_of(conflict);
}

// The tests of designers/ build the examples in code: every file reads to exactly that design
// (segment starts, given in a file as the previous end in degrees, to rounding).
TEST(CamProject, ExamplesAreTheDesignsTheDesignerTestsBuild) {
  for (const std::string& name : test::example_cam_names()) {
    SCOPED_TRACE(name);
    std::vector<std::string> warnings;
    CamDesign read = read_cam_project(kExamples / (name + ".xml"), warnings).cam;
    const CamDesign built = test::example_cam_design(name);
    ASSERT_EQ(read.segments.size(), built.segments.size());
    for (std::size_t k = 0; k < read.segments.size(); ++k) {
      EXPECT_NEAR(read.segments[k].start, built.segments[k].start, 1e-14) << "segment " << k;
      read.segments[k].start = built.segments[k].start;
    }
    EXPECT_TRUE(read == built);
  }
}

TEST(CamProject, ReadsTheRollerExample) {
  std::vector<std::string> warnings;
  const CamProject p = read_cam_project(kExamples / "roller.xml", warnings);
  EXPECT_EQ(p.cam.type, CamType::Plate);
  EXPECT_EQ(p.cam.follower.kind, FollowerKind::Roller);
  EXPECT_EQ(p.cam.follower.roller_radius, 10.0);
  EXPECT_EQ(p.cam.base_radius, 40.0);
  EXPECT_EQ(p.cam.rpm, 300.0);
  ASSERT_EQ(p.cam.segments.size(), 4u);
  EXPECT_EQ(p.cam.segments[1].law, MotionLaw::Cycloidal);
  EXPECT_DOUBLE_EQ(p.cam.segments[1].start, std::numbers::pi / 2);
  EXPECT_EQ(p.cam.segments[3].lift, 20.0);  // a return's lift defaults to the level reached
  EXPECT_EQ(p.cam.segments[3].law, MotionLaw::Polynomial4567);
  EXPECT_EQ(p.conversion.tolerance, 0.001);
  EXPECT_EQ(p.conversion.base, ArcKind::quartic);
  EXPECT_EQ(p.conversion.compaction, Compaction::refit);
  EXPECT_FALSE(p.max_degree);
}

// <conversion compaction="…">: each of the three values read and saved; another value is an error
// naming the attribute and the allowed values.
TEST(CamProject, CompactionIsReadAndSaved) {
  const std::string roller = slurp(kExamples / "roller.xml");
  const std::size_t at = roller.find("<conversion") + std::string("<conversion").size();
  for (const auto& [name, compaction] :
       {std::pair{"refit", Compaction::refit}, std::pair{"knot-removal", Compaction::full},
        std::pair{"none", Compaction::none}}) {
    std::string xml = roller;
    xml.insert(at, std::string(" compaction=\"") + name + "\"");
    std::vector<std::string> warnings;
    const CamProject p = parse_cam_project(xml, "c.xml", warnings);
    EXPECT_EQ(p.conversion.compaction, compaction) << name;
    EXPECT_NE(cam_project_xml(p).find(std::string("compaction=\"") + name + "\""),
              std::string::npos);
    EXPECT_TRUE(parse_cam_project(cam_project_xml(p), "saved.xml", warnings) == p) << name;
  }
  std::string bad = roller;
  bad.insert(at, " compaction=\"fast\"");
  std::vector<std::string> warnings;
  try {
    parse_cam_project(bad, "c.xml", warnings);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("compaction"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("knot-removal"), std::string::npos) << e.what();
  }
}

TEST(CamProject, PolynomialConstraintsSetTheirOrder) {
  std::vector<std::string> warnings;
  const CamProject p = read_cam_project(kExamples / "polynomial.xml", warnings);
  EXPECT_EQ(p.cam.segments[1].law, MotionLaw::Polynomial);
  EXPECT_EQ(p.cam.segments[1].constrained_order, 3);
  EXPECT_EQ(p.cam.segments[3].constrained_order, 2);
}

// An oscillating follower's arm is read in the file's length unit; its lifts (and endpoint
// derivatives) are the arm's swing in degrees, never scaled; its dynamics are an inertia and a
// torsion spring. A swing the arm cannot make is refused naming the file and line.
TEST(CamProject, OscillatingFollowersReadTheArmInLengthsAndTheSwingInDegrees) {
  const std::string arm =
      "follower=\"oscillating-roller\" units=\"inch\" base-radius=\"2\" roller-radius=\"0.5\" "
      "pivot-distance=\"5\" arm-length=\"4\" pivot-side=\"left\"";
  const std::string swing =
      "<segment kind=\"rise\" law=\"cycloidal\" lift=\"15\" to=\"180\"/>\n"
      "<segment kind=\"return\" law=\"4-5-6-7\" to=\"360\"/>\n";
  std::vector<std::string> warnings;
  const CamProject p = parse_cam_project(cam(arm, swing), "cam.xml", warnings);
  EXPECT_TRUE(warnings.empty());
  EXPECT_EQ(p.cam.follower.kind, FollowerKind::OscillatingRoller);
  EXPECT_DOUBLE_EQ(p.cam.follower.pivot_distance, 127.0);
  EXPECT_DOUBLE_EQ(p.cam.follower.arm_length, 101.6);
  EXPECT_DOUBLE_EQ(p.cam.follower.roller_radius, 12.7);
  EXPECT_EQ(p.cam.follower.pivot_side, -1);
  EXPECT_DOUBLE_EQ(p.cam.segments[0].lift, 15.0);
  EXPECT_EQ(parse_cam_project(cam_project_xml(p), "saved.xml", warnings), p);

  const std::string too_far =
      "<segment kind=\"rise\" law=\"cycloidal\" lift=\"179\" to=\"180\"/>\n"
      "<segment kind=\"return\" law=\"4-5-6-7\" to=\"360\"/>\n";
  EXPECT_THAT(error_of(cam(arm, too_far)),
              testing::AllOf(
                  testing::StartsWith("cam.xml:2: <cam>: plate cam: the arm cannot swing the lift"),
                  testing::HasSubstr("swings it 179°")));
  // The arm's dynamics: inertia and torsion spring, no lengths to scale; a mass is not the arm's.
  const std::string with_dynamics =
      "<polarform version=\"1\">\n<cam " + arm + ">\n" + swing +
      "</cam>\n<dynamics inertia=\"0.02\" torsion-rate=\"40\" preload-torque=\"8\" "
      "torsion-damping=\"0.1\" contact-width=\"0.5\"/>\n</polarform>\n";
  const CamProject loaded = parse_cam_project(with_dynamics, "cam.xml", warnings);
  ASSERT_TRUE(loaded.load);
  EXPECT_TRUE(loaded.load->arm);
  EXPECT_DOUBLE_EQ(loaded.load->inertia, 0.02);
  EXPECT_DOUBLE_EQ(loaded.load->torsion_rate, 40);
  EXPECT_DOUBLE_EQ(loaded.load->preload_torque, 8);
  EXPECT_DOUBLE_EQ(loaded.load->torsion_damping, 0.1);
  EXPECT_DOUBLE_EQ(loaded.load->contact_width, 12.7);
  EXPECT_EQ(parse_cam_project(cam_project_xml(loaded), "saved.xml", warnings), loaded);
  EXPECT_THAT(error_of("<polarform version=\"1\">\n<cam " + arm + ">\n" + swing +
                       "</cam>\n<dynamics mass=\"1\"/>\n</polarform>\n"),
              testing::StartsWith("cam.xml:6: <dynamics> attribute 'inertia': expected a number"));
}

TEST(CamProject, BrokenFilesGiveSpecificErrors) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"<polarform version=\"1\"><cam",
       "cam.xml:1: malformed XML: cannot parse an element (a tag is not closed with '>', or a "
       "'<' stands in text: write &lt;)"},
      {cam(kPlate, "<segment kind=\"rise\" law=\"cycloidal\" lift=\"twenty\" to=\"180\"/>\n"),
       "cam.xml:3: <segment> attribute 'lift': expected a finite number, got 'twenty'"},
      {cam("follower=\"roller\" base-radius=\"-40\" roller-radius=\"10\"", kSegments),
       "cam.xml:2: <cam> attribute 'base-radius': expected a number > 0, got '-40'"},
      {cam(kPlate, "<segment kind=\"rise\" law=\"parabolic\" lift=\"20\" to=\"180\"/>\n"),
       "cam.xml:3: <segment> attribute 'law': expected a motion law (unknown motion law "
       "'parabolic'; expected one of: harmonic, cycloidal, modified-trapezoid, modified-sine, "
       "3-4-5, 4-5-6-7, polynomial, bspline, scca, constant-acceleration, cubic, double-harmonic, "
       "constant-velocity, table), got 'parabolic'"},
      {cam(kPlate,
           "<segment kind=\"rise\" law=\"cycloidal\" lift=\"20\" to=\"180\"/>\n"
           "<segment kind=\"return\" law=\"cycloidal\" to=\"300\"/>\n"),
       "cam.xml:2: <cam>: the segments end at 300°; they must cover 0° to 360°"},
      {cam(kPlate,
           "<segment kind=\"rise\" law=\"cycloidal\" lift=\"20\" to=\"180\"/>\n"
           "<segment kind=\"return\" law=\"cycloidal\" from=\"170\" to=\"360\"/>\n"),
       "cam.xml:4: <segment>: segment starts at 170° but the previous one ends at 180° (an "
       "overlap)"},
      {cam(kPlate,
           "<segment kind=\"rise\" law=\"cycloidal\" lift=\"20\" to=\"180\"/>\n"
           "<segment kind=\"return\" law=\"cycloidal\" from=\"190\" to=\"360\"/>\n"),
       "cam.xml:4: <segment>: segment starts at 190° but the previous one ends at 180° (a gap)"},
      {cam(kPlate,
           "<segment kind=\"rise\" law=\"cycloidal\" lift=\"20\" to=\"180\"/>\n"
           "<segment kind=\"dwell\" to=\"120\"/>\n"),
       "cam.xml:4: <segment> attribute 'to': expected an angle after the segment start 180°, got "
       "'120'"},
      {cam(kPlate, "<segment kind=\"lift\" to=\"360\"/>\n"),
       "cam.xml:3: <segment> attribute 'kind': expected one of dwell|rise|return|rise-return, got "
       "'lift'"},
      {cam(kPlate, ""), "cam.xml:2: <cam>: no <segment> elements"},
      {cam("follower=\"roller\" base-radius=\"40\"", kSegments),
       "cam.xml:2: <cam> attribute 'roller-radius': expected a number (attribute is missing)"},
      {cam("type=\"cylindrical\" follower=\"flat-faced\" cylinder-radius=\"60\"", kSegments),
       "cam.xml:2: <cam> attribute 'follower': expected a (translating) roller follower for a "
       "cylindrical cam, got 'flat-faced'"},
      // Oscillating followers: the arm must reach the base circle and swing the lift.
      {cam("follower=\"oscillating-roller\" base-radius=\"40\" roller-radius=\"10\" "
           "arm-length=\"80\"",
           kSegments),
       "cam.xml:2: <cam> attribute 'pivot-distance': expected a number (attribute is missing)"},
      {cam("follower=\"oscillating-roller\" base-radius=\"40\" roller-radius=\"10\" "
           "pivot-distance=\"140\" arm-length=\"80\"",
           kSegments),
       "cam.xml:2: <cam>: plate cam: the arm cannot put the roller on the prime circle: the roller "
       "centre at rest must be base-radius + roller-radius = 50 mm from the cam centre, but "
       "pivot-distance 140 mm and arm-length 80 mm reach only between 60 and 220 mm"},
      {cam("follower=\"oscillating-flat-faced\" base-radius=\"40\" pivot-distance=\"45\" "
           "face-offset=\"10\"",
           kSegments),
       "cam.xml:2: <cam>: plate cam: the face cannot touch the base circle: pivot-distance 45 mm "
       "must exceed |base-radius + face-offset| = 50 mm"},
      {cam("follower=\"oscillating-roller\" base-radius=\"40\" roller-radius=\"10\" "
           "pivot-distance=\"110\" arm-length=\"80\" pivot-side=\"up\"",
           kSegments),
       "cam.xml:2: <cam> attribute 'pivot-side': expected one of right|left, got 'up'"},
      {"<cam/>", "cam.xml:1: <cam>: expected the root element <polarform>"},
      {"<polarform version=\"2\"/>",
       "cam.xml:1: <polarform> attribute 'version': expected 1 (the project version this "
       "polarform reads; --lenient reads a newer one as far as it knows it), got '2'"},
      {cam(kPlate, "<segment kind=\"return\" law=\"cycloidal\" to=\"360\"/>\n"),
       "cam.xml:3: <segment> attribute 'lift': expected a lift > 0 mm (the follower is already at "
       "the base circle)"},
      // Sizes and speeds are limited before anything is allocated or overflows.
      {cam(kPlate,
           "<segment kind=\"rise\" law=\"bspline\" lift=\"20\" to=\"180\" "
           "control-values=\"1000000000\"/>\n"),
       "cam.xml:3: <segment> attribute 'control-values': expected an integer in [1, 500], got "
       "'1000000000'"},
      {cam("follower=\"roller\" base-radius=\"40\" roller-radius=\"10\" rpm=\"1e300\"", kSegments),
       "cam.xml:2: <cam> attribute 'rpm': expected a speed in (0, 100000] rev/min, got '1e300'"},
  };
  for (const auto& [xml, expected] : cases) EXPECT_EQ(error_of(xml), expected) << xml;
}

TEST(CamProject, UnknownNamesAreErrorsNamingLineAndKnownNames) {
  // A misspelt unit and an oscillating follower that does not exist would build another cam
  // than the one written.
  const std::string inch = error_of(cam(kPlate + " unit=\"inch\"", kSegments));
  EXPECT_NE(inch.find("cam.xml:2: unknown attribute 'unit' on <cam> (known here: "),
            std::string::npos)
      << inch;
  EXPECT_NE(inch.find("base-radius"), std::string::npos) << inch;
  EXPECT_NE(inch.find("--lenient"), std::string::npos) << inch;
  const std::string arm =
      error_of(cam(kPlate + " motion=\"oscillating\" arm-length=\"100\"", kSegments));
  EXPECT_NE(arm.find("unknown attribute 'motion' on <cam>"), std::string::npos) << arm;
  EXPECT_NE(arm.find("unknown attribute 'arm-length' on <cam>"), std::string::npos) << arm;
  const std::string note = error_of(cam(kPlate, kSegments + "<note/>\n"));
  EXPECT_NE(
      note.find("cam.xml:5: unknown element <note> in <cam> (known here: conjugate, segment)"),
      std::string::npos)
      << note;
}

TEST(CamProject, LenientReadingWarnsWithTheirLine) {
  std::vector<std::string> warnings;
  const CamProject p = parse_cam_project(cam(kPlate + " colour=\"red\"", kSegments + "<note/>\n"),
                                         "cam.xml", warnings, UnknownNames::warn);
  EXPECT_EQ(p.cam.segments.size(), 2u);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_EQ(warnings[0].substr(0, 56), "cam.xml:2: unknown attribute 'colour' on <cam> ignored (");
  EXPECT_EQ(warnings[1],
            "cam.xml:5: unknown element <note> in <cam> ignored (known here: conjugate, segment)");
}

// Random corruption of valid projects: every outcome is a project or an InputError.
TEST(CamProject, FuzzedFilesNeverEscapeAsAnythingButInputError) {
  std::vector<std::string> corpus;
  for (const auto& entry : fs::directory_iterator(kExamples)) corpus.push_back(slurp(entry.path()));
  std::mt19937 rng(7);
  const std::string alphabet = "<>/=\" 0123456789.-eabcdefxyz\n";
  int accepted = 0, rejected = 0;
  for (int k = 0; k < 3000; ++k) {
    std::string text = corpus[k % corpus.size()];
    const int edits = 1 + static_cast<int>(rng() % 4);
    for (int e = 0; e < edits && !text.empty(); ++e) {
      const std::size_t at = rng() % text.size();
      switch (rng() % 3) {
        case 0: text[at] = alphabet[rng() % alphabet.size()]; break;
        case 1: text.erase(at, 1 + rng() % 8); break;
        default: text.resize(at); break;
      }
    }
    std::vector<std::string> warnings;
    try {
      parse_cam_project(text, "fuzz.xml", warnings);
      ++accepted;
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("fuzz.xml", 0), 0u) << e.what();
      ++rejected;
    }
  }
  EXPECT_GT(accepted, 100);
  EXPECT_GT(rejected, 1000);
}

TEST(CamProject, SavingIsAtomic) {
  const fs::path dir =
      fs::temp_directory_path() / ("polarform_cam_project_test_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::vector<std::string> warnings;
  const CamProject p = read_cam_project(kExamples / "roller.xml", warnings);
  write_cam_project(p, dir / "a.xml");
  EXPECT_TRUE(read_cam_project(dir / "a.xml", warnings) == p);
  EXPECT_THROW(write_cam_project(p, dir / "missing" / "b.xml"), InputError);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}), 1);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace polarform
