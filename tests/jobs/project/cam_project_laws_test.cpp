// The motion laws of issue 15 in project files: every one is read with its attributes (blend,
// table file and ends, the rise-return kind), written back and read again to the same segments;
// a table is read relative to the project file; bad values name their attribute or the table's
// file, line and field.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <numbers>

#include "jobs/project/cam_project.h"
#include "src/error.h"

namespace polarform {
namespace {

namespace fs = std::filesystem;
constexpr double kPi = std::numbers::pi;

std::string cam(const std::string& segments) {
  return "<polarform version=\"1\">\n<cam follower=\"roller\" base-radius=\"40\" "
         "roller-radius=\"10\">\n" +
         segments + "</cam>\n</polarform>\n";
}

// A folder for a project and its table, removed afterwards.
struct Folder {
  fs::path dir = fs::temp_directory_path() / ("polarform_laws_" + std::to_string(::getpid()));
  Folder() { fs::create_directories(dir); }
  ~Folder() { fs::remove_all(dir); }
  fs::path write(const std::string& name, const std::string& text) const {
    std::ofstream(dir / name, std::ios::binary) << text;
    return dir / name;
  }
};

const std::string kTable =
    "x,S\n0,0\n0.1,0.00856\n0.3,0.16308\n0.5,0.5\n0.7,0.83692\n0.9,0.99144\n1,1\n";

const std::string kAllLaws =
    "<segment kind=\"rise\" law=\"constant-acceleration\" lift=\"10\" to=\"40\"/>\n"
    "<segment kind=\"rise\" law=\"cubic\" lift=\"5\" to=\"80\"/>\n"
    "<segment kind=\"rise\" law=\"constant-velocity\" blend=\"0.15\" lift=\"5\" to=\"120\"/>\n"
    "<segment kind=\"rise-return\" law=\"polynomial\" lift=\"4\" to=\"160\"/>\n"
    "<segment kind=\"rise-return\" law=\"double-harmonic\" lift=\"3\" to=\"200\"/>\n"
    "<segment kind=\"return\" law=\"double-harmonic\" lift=\"8\" to=\"240\"/>\n"
    "<segment kind=\"return\" law=\"table\" file=\"motion.csv\" ends=\"free\" lift=\"6\" "
    "to=\"300\"/>\n"
    "<segment kind=\"return\" law=\"constant-velocity\" to=\"360\"/>\n";

TEST(CamProjectLaws, EveryNewLawRoundTrips) {
  const Folder folder;
  folder.write("motion.csv", kTable);
  const fs::path file = folder.write("cam.xml", cam(kAllLaws));
  std::vector<std::string> warnings;
  const CamProject p = read_cam_project(file, warnings);
  EXPECT_TRUE(warnings.empty());
  const std::vector<SegmentSpec>& s = p.cam.segments;
  ASSERT_EQ(s.size(), 8u);
  EXPECT_EQ(s[0].law, MotionLaw::ConstantAcceleration);
  EXPECT_EQ(s[1].law, MotionLaw::Cubic);
  EXPECT_EQ(s[2].law, MotionLaw::ConstantVelocity);
  EXPECT_EQ(s[2].blend, 0.15);
  EXPECT_EQ(s[3].kind, SegmentKind::RiseReturn);
  EXPECT_EQ(s[3].law, MotionLaw::Polynomial);
  EXPECT_EQ(s[4].kind, SegmentKind::RiseReturn);
  EXPECT_EQ(s[5].law, MotionLaw::DoubleHarmonic);
  EXPECT_EQ(s[6].law, MotionLaw::Table);
  EXPECT_EQ(s[6].table.file, "motion.csv");
  EXPECT_EQ(s[6].table.ends, TableEnds::Free);
  EXPECT_EQ(s[6].table.s[2], 0.16308);
  EXPECT_EQ(s[7].blend, 0.2);  // the default
  EXPECT_EQ(s[7].lift, 6.0);   // a return's lift defaults to the level it starts from
  // Written into the same folder (the table path is kept as written) and read again.
  const std::string xml = cam_project_xml(p);
  EXPECT_NE(xml.find("law=\"table\" lift=\"6\""), std::string::npos) << xml;
  EXPECT_NE(xml.find("to=\"300\" file=\"motion.csv\" ends=\"free\"/>"), std::string::npos) << xml;
  EXPECT_NE(xml.find("blend=\"0.15\""), std::string::npos);
  EXPECT_NE(xml.find("kind=\"rise-return\" law=\"polynomial\""), std::string::npos);
  const CamProject again = read_cam_project(folder.write("saved.xml", xml), warnings);
  EXPECT_TRUE(again == p);
  EXPECT_EQ(cam_project_xml(again), xml);
}

TEST(CamProjectLaws, BadValuesNameTheirAttributeOrTableLine) {
  const Folder folder;
  folder.write("bad.csv", "x,S\n0,0\n0.2,0.1\n0.4,0.3\n0.3,0.6\n0.8,0.9\n1,1\n");
  const std::string rest = "<segment kind=\"return\" to=\"360\"/>\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"<segment kind=\"rise\" law=\"constant-velocity\" blend=\"0.7\" lift=\"10\" to=\"180\"/>\n" +
           rest,
       "cam.xml:3: <segment> attribute 'blend': expected a fraction of the segment at each end in "
       "[0, 0.5], got '0.7'"},
      {"<segment kind=\"rise\" law=\"table\" file=\"bad.csv\" lift=\"10\" to=\"180\"/>\n" + rest,
       (folder.dir / "bad.csv").string() + ":5: x: expected x increasing strictly (after 0.4)"},
      {"<segment kind=\"rise\" law=\"table\" file=\"none.csv\" lift=\"10\" to=\"180\"/>\n" + rest,
       (folder.dir / "none.csv").string() + ": no such file (motion table named by " +
           (folder.dir / "cam.xml").string() + ")"},
      {"<segment kind=\"rise\" law=\"table\" lift=\"10\" to=\"180\"/>\n" + rest,
       "cam.xml:3: <segment> attribute 'file': expected the motion table's file name (CSV, "
       "relative to the "
       "project)"},
      {"<segment kind=\"rise-return\" law=\"table\" file=\"bad.csv\" lift=\"10\" to=\"360\"/>\n",
       "cam.xml:3: <segment> attribute 'law': expected a rise or return for a motion table, got "
       "'table'"},
      {"<segment kind=\"dwell\" to=\"90\"/>\n<segment kind=\"rise\" law=\"constant-velocity\" "
       "blend=\"0\" "
       "lift=\"10\" to=\"180\"/>\n" +
           rest,
       "cam.xml:2: <cam>: cam program: segment 'segment 2' has constant velocity 6.3662 mm/rad "
       "without blends "
       "(blend=\"0\") but segment 'segment 1' moves at 0 mm/rad at 90°: infinite acceleration; "
       "give blend > 0 or "
       "a neighbour that ends at that velocity"},
  };
  for (const auto& [segments, expected] : cases) {
    std::vector<std::string> warnings;
    try {
      parse_cam_project(cam(segments), (folder.dir / "cam.xml").string(), warnings);
      ADD_FAILURE() << segments;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(expected), std::string::npos) << what;
    }
  }
}

// A polynomial law of a stated degree with interior constraints (constrained_polynomial.h): read,
// written back and read again to the same segments; the report's peak factors of a degree-5 law
// from rest-to-rest ends are the 3-4-5 law's closed forms.
TEST(CamProjectLaws, PolynomialDegreeAndInteriorConstraintsRoundTrip) {
  const std::string segments =
      "<segment kind=\"rise\" law=\"polynomial\" degree=\"7\" lift=\"10\" to=\"120\">\n"
      "  <start v=\"0\" a=\"0\"/>\n  <end v=\"0\" a=\"0\"/>\n"
      "  <constraint x=\"0.4\" value=\"0.3\"/>\n"
      "  <constraint x=\"0.6\" derivative=\"1\" value=\"1.9\"/>\n"
      "</segment>\n"
      "<segment kind=\"dwell\" to=\"180\"/>\n"
      "<segment kind=\"return\" law=\"polynomial\" degree=\"5\" to=\"300\"/>\n"
      "<segment kind=\"dwell\" to=\"360\"/>\n";
  std::vector<std::string> warnings;
  const CamProject p = parse_cam_project(cam(segments), "cam.xml", warnings);
  EXPECT_TRUE(warnings.empty());
  const SegmentSpec& rise = p.cam.segments[0];
  EXPECT_EQ(rise.polynomial_degree, 7);
  ASSERT_EQ(rise.interior.size(), 2u);
  EXPECT_EQ(rise.interior[0], (PolynomialConstraint{0.4, 0, 0.3}));
  EXPECT_EQ(rise.interior[1], (PolynomialConstraint{0.6, 1, 1.9}));
  EXPECT_EQ(p.cam.segments[2].polynomial_degree, 5);
  const std::string xml = cam_project_xml(p);
  EXPECT_NE(xml.find("law=\"polynomial\" lift=\"10\" from=\"0\" to=\""), std::string::npos) << xml;
  EXPECT_NE(xml.find("\" degree=\"7\">"), std::string::npos) << xml;
  EXPECT_NE(xml.find("<constraint x=\"0.6\" derivative=\"1\" value=\"1.9\"/>"), std::string::npos)
      << xml;
  const CamProject again = parse_cam_project(xml, "cam.xml", warnings);
  EXPECT_EQ(again.cam, p.cam);
  EXPECT_EQ(cam_project_xml(again), xml);
}

TEST(CamProjectLaws, PolynomialCountsAndFieldsAreNamed) {
  const std::string rest = "<segment kind=\"return\" to=\"360\"/>\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"<segment kind=\"rise\" law=\"polynomial\" degree=\"4\" lift=\"10\" to=\"180\"/>\n" + rest,
       "segment 'segment 1': over-determined: 6 constraints for the 5 coefficients of a degree-4 "
       "polynomial"},
      {"<segment kind=\"rise\" law=\"polynomial\" degree=\"0\" lift=\"10\" to=\"180\"/>\n" + rest,
       "cam.xml:3: <segment> attribute 'degree': expected an integer in [1, 20]"},
      {"<segment kind=\"rise\" law=\"polynomial\" lift=\"10\" to=\"180\">"
       "<constraint x=\"1\" value=\"1\"/></segment>\n" +
           rest,
       "<constraint> attribute 'x': expected a normalised position strictly inside (0, 1)"},
      {"<segment kind=\"rise\" law=\"polynomial\" lift=\"10\" to=\"180\">"
       "<constraint x=\"0.5\" derivative=\"7\" value=\"1\"/></segment>\n" +
           rest,
       "<constraint> attribute 'derivative': expected an integer in [0, 4]"},
  };
  for (const auto& [segments, expected] : cases) {
    std::vector<std::string> warnings;
    try {
      parse_cam_project(cam(segments), "cam.xml", warnings);
      ADD_FAILURE() << segments;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(expected), std::string::npos) << what;
    }
  }
}

}  // namespace
}  // namespace polarform
