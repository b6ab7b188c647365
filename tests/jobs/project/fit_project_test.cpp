// Fit project files: the example loads and names an existing scan; every field round-trips
// exactly; a minimal file takes the defaults; each kind of bad value gives its own error naming
// file, line and attribute; unknown fields warn.
#include "jobs/project/fit_project.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "src/error.h"

namespace polarform {
namespace {

namespace fs = std::filesystem;

FitProject parse(const std::string& xml, std::vector<std::string>* warnings = nullptr) {
  std::vector<std::string> local;
  return parse_fit_project(xml, "fit.xml", warnings ? *warnings : local);
}

std::string error_of(const std::string& fit_attributes) {
  try {
    parse("<polarform version=\"1\">\n  <fit " + fit_attributes + "/>\n</polarform>\n");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(FitProject, ExampleNamesAnExistingScan) {
  const fs::path file = fs::path(POLARFORM_SOURCE_DIR) / "examples/scans/sphere_like_fit.xml";
  std::vector<std::string> warnings;
  const FitProject p = read_fit_project(file, warnings);
  EXPECT_TRUE(warnings.empty());
  EXPECT_EQ(p.method, FitJobMethod::spherical);
  EXPECT_EQ(p.closure, Closure::closed);
  EXPECT_EQ(p.pole, PoleTreatment::g1);
  EXPECT_EQ(p.ctrl, std::make_pair(12, 24));
  EXPECT_TRUE(fs::exists(scan_path(p, file)));
}

TEST(FitProject, EveryFieldRoundTripsExactly) {
  FitProject p;
  p.scan = "scans/part & co <1>.ply";
  p.method = FitJobMethod::cylindrical;
  p.closure = Closure::open;
  p.pole = PoleTreatment::cap;
  p.degree = {2, 5};
  p.tolerance = 0.1 + 0.2;  // not a short decimal
  p.measure = ToleranceMeasure::p95;
  p.center = Eigen::Vector3d(1.0 / 3, -2e-17, 123456.789);
  p.axis = Eigen::Vector3d(0, 0.6, 0.8);
  p.skip_bad = true;
  p.reject_outliers = true;
  p.fairness = FairnessOptions::Mode::fixed;
  p.fairness_weight = 1.0 / 7;
  p.base = ArcKind::quartic;
  EXPECT_NE(fit_project_xml(p).find(" reject-outliers=\"true\""), std::string::npos);
  const FitProject back = parse(fit_project_xml(p));
  EXPECT_EQ(back, p);
  EXPECT_EQ(fit_project_xml(back), fit_project_xml(p));

  const fs::path file = fs::temp_directory_path() /
                        ("polarform_fit_project_test_" + std::to_string(::getpid()) + ".xml");
  write_fit_project(p, file);
  std::vector<std::string> warnings;
  EXPECT_EQ(read_fit_project(file, warnings), p);
  fs::remove(file);
}

// Found by fuzzing: a scan name holding line breaks (a CR, which XML readers turn into LF) must
// read back as written.
TEST(FitProject, ScanNamesWithLineBreaksRoundTrip) {
  FitProject p;
  p.scan = "odd\rname\n\twith & <breaks>.xyz";
  const FitProject back = parse(fit_project_xml(p));
  EXPECT_EQ(back.scan, p.scan);
  EXPECT_EQ(fit_project_xml(back), fit_project_xml(p));
}

TEST(FitProject, MinimalFileTakesTheDefaults) {
  const FitProject p = parse("<fit scan=\"a.xyz\"/>");
  EXPECT_EQ(p.scan, fs::path("a.xyz"));
  EXPECT_EQ(p.method, FitJobMethod::automatic);
  EXPECT_EQ(p.closure, Closure::automatic);
  EXPECT_FALSE(p.pole || p.degree || p.ctrl || p.tolerance || p.center || p.axis);
  EXPECT_EQ(p.measure, ToleranceMeasure::max);
  EXPECT_FALSE(p.skip_bad);
  EXPECT_FALSE(p.reject_outliers);
  EXPECT_EQ(p.fairness, FairnessOptions::Mode::relative);
  EXPECT_EQ(p.fairness_weight, 1e-7);
  EXPECT_EQ(p.base, ArcKind::rqb);
  EXPECT_EQ(scan_path(p, "/data/project/fit.xml"), fs::path("/data/project/a.xyz"));
  EXPECT_EQ(scan_path(parse("<fit scan=\"/abs/b.ply\"/>"), "/x/fit.xml"), fs::path("/abs/b.ply"));
}

TEST(FitProject, BadValuesNameLineAndAttribute) {
  const struct {
    const char* attributes;
    const char* expected;
  } cases[] = {
      {"method=\"spherical\"", "fit.xml:2: <fit> attribute 'scan'"},
      {"scan=\"a.xyz\" method=\"conical\"", "attribute 'method'"},
      {"scan=\"a.xyz\" closed=\"maybe\"", "attribute 'closed'"},
      {"scan=\"a.xyz\" pole=\"g2\"", "attribute 'pole'"},
      {"scan=\"a.xyz\" degree=\"3\"", "attribute 'degree'"},
      {"scan=\"a.xyz\" degree=\"3,x\"", "attribute 'degree'"},
      {"scan=\"a.xyz\" degree=\"3,10\"", "[1, 9]"},
      {"scan=\"a.xyz\" ctrl=\"1,12\"", "[2, 2000]"},
      {"scan=\"a.xyz\" ctrl=\"12,12.5\"", "attribute 'ctrl'"},
      // Found by fuzzing: a count beyond int was cast before its range was checked (UB).
      {"scan=\"a.xyz\" ctrl=\"1e10,12\"", "[2, 2000]"},
      {"scan=\"a.xyz\" degree=\"3,-1e300\"", "[1, 9]"},
      {"scan=\"a.xyz\" tolerance=\"-1\"", "attribute 'tolerance'"},
      {"scan=\"a.xyz\" ctrl=\"12,12\" tolerance=\"0.1\"", "either ctrl or tolerance"},
      {"scan=\"a.xyz\" tolerance-measure=\"median\"", "attribute 'tolerance-measure'"},
      {"scan=\"a.xyz\" center=\"1,2\"", "attribute 'center'"},
      {"scan=\"a.xyz\" axis=\"0,0,0\"", "non-zero direction"},
      {"scan=\"a.xyz\" axis=\"0,nan,1\"", "attribute 'axis'"},
      {"scan=\"a.xyz\" skip-bad=\"1\"", "attribute 'skip-bad'"},
      {"scan=\"a.xyz\" reject-outliers=\"yes\"",
       "fit.xml:2: <fit> attribute 'reject-outliers': expected one of true|false, got 'yes'"},
      {"scan=\"a.xyz\" fairness=\"smooth\"", "attribute 'fairness'"},
      {"scan=\"a.xyz\" lambda=\"0\"", "attribute 'lambda'"},
      {"scan=\"a.xyz\" lambda=\"inf\"", "attribute 'lambda'"},
      {"scan=\"a.xyz\" base=\"cubic\"", "attribute 'base'"},
  };
  for (const auto& c : cases)
    EXPECT_NE(error_of(c.attributes).find(c.expected), std::string::npos)
        << c.attributes << " -> " << error_of(c.attributes);
  try {
    parse("<polarform version=\"1\"><cam/></polarform>");
    FAIL() << "no error without <fit>";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("expected a <fit> element"), std::string::npos);
  }
  EXPECT_THROW(parse("<vessel/>"), InputError);
  EXPECT_THROW(parse("<polarform version=\"2\"><fit scan=\"a\"/></polarform>"), InputError);
  EXPECT_THROW(parse("<fit scan=\"a.xyz\""), InputError);
}

TEST(FitProject, UnknownNamesAreErrorsOrLenientWarnings) {
  const std::string xml =
      "<polarform version=\"1\">\n<fit scan=\"a.xyz\" "
      "colour=\"red\">\n<extra/>\n</fit>\n</polarform>\n";
  std::string error;
  try {
    parse(xml);
  } catch (const InputError& e) {
    error = e.what();
  }
  EXPECT_NE(error.find("fit.xml:2: unknown attribute 'colour' on <fit> (known here: "),
            std::string::npos)
      << error;
  EXPECT_NE(error.find("reject-outliers"), std::string::npos) << error;  // a known name
  EXPECT_NE(error.find("fit.xml:3: unknown element <extra> in <fit> (none known here)"),
            std::string::npos)
      << error;
  std::vector<std::string> warnings;
  const FitProject p = parse_fit_project(xml, "fit.xml", warnings, UnknownNames::warn);
  EXPECT_EQ(p.scan, "a.xyz");
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].find("fit.xml:2: unknown attribute 'colour' on <fit> ignored"),
            std::string::npos)
      << warnings[0];
  EXPECT_NE(warnings[1].find("<extra>"), std::string::npos) << warnings[1];
}

}  // namespace
}  // namespace polarform
