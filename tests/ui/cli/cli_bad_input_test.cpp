// The polarform CLI on bad input: a table of broken projects (malformed XML, wrong types, negative
// radii, unknown laws, segments that leave a gap, overlap or stop short of 360°, bad tolerances,
// infeasible designs) and bad options. Each exits with status 2 (no crash), prints one line on
// stderr naming the file and the line / field, and writes nothing: the output directory is not
// created, and one that holds a previous good run is left exactly as it was.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "tests/support/jobs/cam_job_support.h"
#include "tests/ui/cli/cli_run.h"

namespace polarform {
namespace {

using namespace cam_job_test;

const std::string kGood =
    "<?xml version=\"1.0\"?>\n"
    "<polarform version=\"1\">\n"
    "  <cam type=\"plate\" follower=\"roller\" base-radius=\"40\" roller-radius=\"10\" "
    "rpm=\"300\">\n"
    "    <segment kind=\"dwell\" to=\"90\"/>\n"
    "    <segment kind=\"rise\" law=\"cycloidal\" lift=\"20\" to=\"180\"/>\n"
    "    <segment kind=\"dwell\" to=\"240\"/>\n"
    "    <segment kind=\"return\" law=\"4-5-6-7\" to=\"360\"/>\n"
    "  </cam>\n"
    "  <conversion tolerance=\"0.001\"/>\n"
    "</polarform>\n";

// kGood (or `xml`) with the first occurrence of `from` replaced by `to`.
std::string edited(const std::string& from, const std::string& to, std::string xml = kGood) {
  const auto at = xml.find(from);
  if (at == std::string::npos) throw std::runtime_error("kGood has no '" + from + "'");
  return xml.replace(at, from.size(), to);
}

struct BadProject {
  std::string name;
  std::string xml;
  std::string expected;  // a fragment of the message, with the line number where there is one
};

std::vector<BadProject> bad_projects() {
  return {
      {"truncated", kGood.substr(0, 150), ":4: malformed XML"},
      {"empty", "", "malformed XML: the document is empty"},
      {"not_xml", "base-radius = 40\n", "malformed XML"},
      {"wrong_root", "<project version=\"1\"><cam/></project>\n",
       ":1: <project>: expected the root element <polarform>"},
      {"wrong_version", edited("version=\"1\"", "version=\"2\""),
       ":2: <polarform> attribute 'version'"},
      {"no_cam", "<polarform version=\"1\"/>\n", "no <cam> element"},
      {"misspelt_units", edited("type=\"plate\"", "type=\"plate\" unit=\"inch\""),
       ":3: unknown attribute 'unit' on <cam> (known here: "},
      {"unknown_element", edited("</cam>", "<follower-arm length=\"100\"/></cam>"),
       "unknown element <follower-arm> in <cam> (known here: conjugate, segment)"},
      {"no_segments",
       "<polarform version=\"1\"><cam follower=\"knife-edge\" base-radius=\"40\"/>"
       "</polarform>\n",
       "no <segment> elements"},
      {"radius_not_a_number", edited("base-radius=\"40\"", "base-radius=\"forty\""),
       ":3: <cam> attribute 'base-radius': expected a finite number, got 'forty'"},
      {"unknown_cam_type", edited("type=\"plate\"", "type=\"disk\""),
       ":3: <cam> attribute 'type': expected one of plate|cylindrical, got 'disk'"},
      {"negative_base_radius", edited("base-radius=\"40\"", "base-radius=\"-40\""),
       ":3: <cam> attribute 'base-radius': expected a number > 0, got '-40'"},
      {"negative_roller_radius", edited("roller-radius=\"10\"", "roller-radius=\"-10\""),
       ":3: <cam> attribute 'roller-radius': expected a number > 0, got '-10'"},
      {"missing_roller_radius", edited("roller-radius=\"10\"", ""),
       ":3: <cam> attribute 'roller-radius': expected a number (attribute is missing)"},
      {"unknown_law", edited("cycloidal", "parabolic"), ":5: <segment> attribute 'law'"},
      {"unknown_kind", edited("kind=\"rise\"", "kind=\"hold\""),
       ":5: <segment> attribute 'kind': expected one of dwell|rise|return|rise-return, got 'hold'"},
      {"angle_not_a_number", edited("to=\"180\"", "to=\"180deg\""),
       ":5: <segment> attribute 'to': expected a finite number, got '180deg'"},
      {"backwards_segment", edited("to=\"180\"", "to=\"80\""),
       ":5: <segment> attribute 'to': expected an angle after the segment start 90°"},
      {"not_covering_360", edited("to=\"360\"", "to=\"350\""),
       ":3: <cam>: the segments end at 350°; they must cover 0° to 360°"},
      {"gap", edited("law=\"4-5-6-7\"", "law=\"4-5-6-7\" from=\"250\""),
       ":7: <segment>: segment starts at 250° but the previous one ends at 240° (a gap)"},
      {"overlap", edited("law=\"4-5-6-7\"", "law=\"4-5-6-7\" from=\"230\""),
       ":7: <segment>: segment starts at 230° but the previous one ends at 240° (an overlap)"},
      {"negative_lift", edited("lift=\"20\"", "lift=\"-20\""),
       ":5: <segment> attribute 'lift': expected a number > 0, got '-20'"},
      {"zero_tolerance", edited("tolerance=\"0.001\"", "tolerance=\"0\""),
       ":9: <conversion> attribute 'tolerance': expected a number > 0, got '0'"},
      {"text_tolerance", edited("tolerance=\"0.001\"", "tolerance=\"fine\""),
       ":9: <conversion> attribute 'tolerance': expected a finite number, got 'fine'"},
      {"unreachable_tolerance", edited("tolerance=\"0.001\"", "tolerance=\"1e-12\""),
       ":9: <conversion> attribute 'tolerance': expected a tolerance >= 1e-09 mm, got '1e-12'"},
      {"fractional_max_degree", edited("tolerance=\"0.001\"", "max-degree=\"2.5\""),
       ":9: <conversion> attribute 'max-degree': expected an integer, got '2.5'"},
      {"offset_beyond_prime_circle", edited("rpm=\"300\"", "rpm=\"300\" offset=\"60\""),
       "follower offset |e| = 60 mm must be below the prime radius 50 mm"},
      {"groove_on_a_knife_edge",
       edited("follower=\"roller\"", "follower=\"knife-edge\" groove-depth=\"8\""),
       ":3: <cam> attribute 'groove-depth': expected no groove for a knife-edge follower"},
      {"groove_on_a_flat_face",
       edited("follower=\"roller\"", "follower=\"flat-faced\" groove-depth=\"8\""),
       ":3: <cam> attribute 'groove-depth': expected no groove for a flat-faced follower"},
      {"overlapping_rollers", edited("</cam>", "<conjugate roller-distance=\"15\"/></cam>"),
       "conjugate roller-distance 15 mm: the rollers overlap"},
      // y0 + stroke + Rr = 50 + 20 + 10 = 80 mm: the second roller would reach the cam centre.
      {"second_roller_at_the_centre", edited("</cam>", "<conjugate roller-distance=\"75\"/></cam>"),
       "conjugate roller-distance 75 mm is too small: the second roller would reach the cam "
       "centre; the second cam's base radius D − (y0 + stroke) − Rr2 must be > 0, so D > 80 mm"},
      {"conjugate_and_groove",
       edited("rpm=\"300\"", "rpm=\"300\" groove-depth=\"5\"",
              edited("</cam>", "<conjugate roller-distance=\"120\"/></cam>")),
       "groove-depth: a grooved cam is already driven both ways"},
      // A 45° rise: the second cam's pitch curve turns with a radius below the roller's.
      {"second_cam_undercuts",
       edited("to=\"180\"", "to=\"135\"",
              edited("</cam>", "<conjugate roller-distance=\"82\"/></cam>")),
       "cam conjugate (second) contour is not single-valued in polar angle between θ = "},
  };
}

// Runs `polarform cam` on each bad project into `out` and checks status, message and `out`.
void expect_rejected_everywhere(const ScratchDir& scratch, const fs::path& out) {
  const std::map<std::string, std::string> before = snapshot(out);
  for (const BadProject& bad : bad_projects()) {
    SCOPED_TRACE(bad.name);
    const fs::path file = scratch / (bad.name + ".xml");
    spit(file, bad.xml);
    const CliRun run = run_cli({"cam", file.string(), "--out", out.string()}, scratch);
    EXPECT_EQ(run.status, 2) << run.err;
    EXPECT_EQ(run.out, "");
    EXPECT_EQ(run.err.rfind("polarform: error: " + file.string(), 0), 0u) << run.err;
    EXPECT_NE(run.err.find(bad.expected), std::string::npos) << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_EQ(fs::exists(out), !before.empty());
    EXPECT_TRUE(snapshot(out) == before) << "the output directory changed";
  }
}

TEST(CliBadInput, BrokenProjectsExitTwoAndWriteNothing) {
  const ScratchDir scratch("bad_projects");
  spit(scratch / "good.xml", kGood);  // the table's base is itself a good project
  ASSERT_EQ(
      run_cli({"cam", (scratch / "good.xml").string(), "--out", (scratch / "ok").string(), "-q"},
              scratch)
          .status,
      0);
  expect_rejected_everywhere(scratch, scratch / "out");
}

TEST(CliBadInput, BrokenProjectsLeaveAPreviousRunUntouched) {
  const ScratchDir scratch("bad_projects_over_good");
  spit(scratch / "good.xml", kGood);
  ASSERT_EQ(
      run_cli({"cam", (scratch / "good.xml").string(), "--out", (scratch / "out").string(), "-q"},
              scratch)
          .status,
      0);
  ASSERT_EQ(snapshot(scratch / "out").size(), 12u);
  expect_rejected_everywhere(scratch, scratch / "out");
}

// A motion table (law="table") that is not increasing in x: exit 2, one line naming the table's
// file, line and field, nothing written.
TEST(CliBadInput, ABrokenMotionTableExitsTwoNamingItsLineAndField) {
  const ScratchDir scratch("bad_table");
  spit(scratch / "motion.csv", "x,S\n0,0\n0.2,0.1\n0.4,0.3\n0.35,0.6\n0.8,0.9\n1,1\n");
  const fs::path file = scratch / "table.xml";
  spit(file, edited("law=\"cycloidal\"", "law=\"table\" file=\"motion.csv\""));
  const CliRun run = run_cli({"cam", file.string(), "--out", (scratch / "out").string()}, scratch);
  EXPECT_EQ(run.status, 2) << run.err;
  EXPECT_EQ(run.err, "polarform: error: " + (scratch / "motion.csv").string() +
                         ":5: x: expected x increasing strictly (after 0.4)\n");
  EXPECT_FALSE(fs::exists(scratch / "out"));
}

struct BadCommand {
  std::vector<std::string> args;  // "OUT" stands for the output directory
  std::string expected;
};

TEST(CliBadInput, BadOptionsExitTwoAndWriteNothing) {
  const ScratchDir scratch("bad_options");
  const std::string roller = (kExamples / "roller.xml").string();
  const std::string missing = (scratch / "missing.xml").string();
  const std::vector<BadCommand> commands = {
      {{"cam", missing, "--out", "OUT"}, missing},
      {{"cam", roller, "--out", "OUT", "--tol", "0"},
       "--tol: expected a tolerance >= 1e-09 mm, got '0'"},
      {{"cam", roller, "--out", "OUT", "--tol", "-1"}, "--tol: expected a tolerance >= 1e-09 mm"},
      {{"cam", roller, "--out", "OUT", "--tol", "abc"}, "--tol: expected a tolerance >= 1e-09 mm"},
      {{"cam", roller, "--out", "OUT", "--tol", "1e-12"}, "got '1e-12'"},
      {{"cam", roller, "--out", "OUT", "--base", "bezier"}, "--base"},
      {{"cam", roller, "--out", "OUT", "--solid", "-5"}, "--solid: expected a length > 0 in mm"},
      {{"cam", roller, "--out", "OUT", "--max-degree", "0"}, "--max-degree"},
      {{"cam", (kExamples / "cylindrical.xml").string(), "--out", "OUT", "--solid", "10"},
       "--solid applies to plate cams only"},
      {{"cam", roller}, "--out"},
      {{"study", missing, "--out", "OUT"}, missing},
      {{"study", roller, "--out", "OUT", "--tol", "1e-2"},
       "--tol '1e-2': expected LOOSEST:TIGHTEST"},
      {{"study", roller, "--out", "OUT", "--tol", "1e-2:1e-12"},
       "--tol '1e-2:1e-12': expected LOOSEST >= TIGHTEST >= 1e-09 mm"},
      {{"study", roller, "--out", "OUT", "--tol", "1e-4:1e-2"}, "expected LOOSEST >= TIGHTEST"},
      {{"study", roller, "--out", "OUT", "--steps-per-decade", "0"}, "--steps-per-decade"},
  };
  const std::string out = (scratch / "out").string();
  for (BadCommand c : commands) {
    std::replace(c.args.begin(), c.args.end(), std::string("OUT"), out);
    const CliRun run = run_cli(c.args, scratch);
    SCOPED_TRACE(c.args[0] + " " + c.args.back());
    EXPECT_EQ(run.status, 2) << run.err;
    EXPECT_NE(run.err.find(c.expected), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(out));
  }
}

// An undercut design is refused (exit 2, no profile), but its analyses are written so that the
// user sees where: into --out when that holds nothing yet, else beside it (out.infeasible), so
// that an earlier run's outputs stay as they were.
TEST(CliBadInput, UndercutDesignWritesItsAnalysesWhereTheyAlterNothing) {
  const ScratchDir scratch("undercut");
  const fs::path file = scratch / "undercut.xml";
  spit(file,
       edited("base-radius=\"40\" roller-radius=\"10\"", "base-radius=\"5\" roller-radius=\"40\""));
  const std::set<std::string> analyses = {"analysis.svg", "report.html", "report.json", "svaj.csv",
                                          "svaj.svg"};
  const auto files = [](const fs::path& dir) {
    std::set<std::string> names;
    for (const auto& [name, content] : snapshot(dir)) names.insert(name);
    return names;
  };
  const auto expect_analyses_in = [&](const fs::path& dir, const CliRun& run) {
    EXPECT_EQ(run.status, 2) << run.err;
    EXPECT_EQ(run.out, "");
    EXPECT_EQ(run.err.rfind("polarform: error: " + file.string() + ": ", 0), 0u) << run.err;
    EXPECT_NE(run.err.find("not single-valued"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find(fs::absolute(dir).string() + " (report.html"), std::string::npos)
        << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_EQ(files(dir), analyses);
    const json j = read_json(dir / "report.json");
    EXPECT_EQ(j["feasible"], false);
    EXPECT_NE(j["infeasible_reason"].get<std::string>().find("not single-valued"),
              std::string::npos);
    ASSERT_EQ(j["undercut"], true);
    ASSERT_FALSE(j["undercut_ranges_deg"].empty());
    const double from = j["undercut_ranges_deg"][0][0], to = j["undercut_ranges_deg"][0][1];
    EXPECT_LT(from, to);
    EXPECT_NE(slurp(dir / "report.html").find("INFEASIBLE"), std::string::npos);
    EXPECT_NE(slurp(dir / "analysis.svg").find("undercut"), std::string::npos);
  };
  // A fresh --out: the analyses go there.
  const fs::path fresh = scratch / "fresh";
  expect_analyses_in(fresh, run_cli({"cam", file.string(), "--out", fresh.string()}, scratch));
  // Over an earlier good run: that run's files stay byte for byte; the analyses go beside them.
  spit(scratch / "good.xml", kGood);
  const fs::path out = scratch / "out";
  ASSERT_EQ(run_cli({"cam", (scratch / "good.xml").string(), "--out", out.string(), "-q"}, scratch)
                .status,
            0);
  const std::map<std::string, std::string> before = snapshot(out);
  expect_analyses_in(scratch / "out.infeasible",
                     run_cli({"cam", file.string(), "--out", out.string()}, scratch));
  EXPECT_TRUE(snapshot(out) == before) << "the earlier run's outputs changed";
}

TEST(CliBadInput, StudyOfABrokenProjectNamesTheFile) {
  const ScratchDir scratch("bad_study");
  const fs::path file = scratch / "undercut.xml";
  spit(file,
       edited("base-radius=\"40\" roller-radius=\"10\"", "base-radius=\"5\" roller-radius=\"40\""));
  const CliRun run =
      run_cli({"study", file.string(), "--out", (scratch / "out").string(), "-q"}, scratch);
  EXPECT_EQ(run.status, 2) << run.err;
  EXPECT_EQ(run.err.rfind("polarform: error: " + file.string() + ": ", 0), 0u) << run.err;
  EXPECT_FALSE(fs::exists(scratch / "out"));
}

}  // namespace
}  // namespace polarform
