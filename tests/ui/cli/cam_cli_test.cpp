// The polarform CLI on good input: --help, --version and each command's --help exit 0; `cam` on
// an example exits 0 and writes the job's files; --tol, --base and --max-degree override the
// project and the report shows it; unknown project fields warn (naming line and name) but run.
#include <gtest/gtest.h>

#include <map>
#include <regex>

#include "jobs/cam/cam_key_figures.h"
#include "tests/support/jobs/cam_job_support.h"
#include "tests/ui/cli/cli_run.h"

namespace polarform {
namespace {

using namespace cam_job_test;

// Every file of a folder with its bytes; a sub-folder as "<dir>".
std::map<std::string, std::string> listing(const fs::path& dir) {
  std::map<std::string, std::string> out;
  for (const auto& e : fs::directory_iterator(dir))
    out[e.path().filename().string()] = fs::is_directory(e) ? "<dir>" : slurp(e.path());
  return out;
}

// A run that fails while writing (a folder stands where one of its files goes) exits 2 naming
// the file and leaves the earlier run's outputs byte for byte, for a bundle of text files (cam)
// and one with the binary deviation.ply (fit).
TEST(Cli, AFailedWriteLeavesTheEarlierOutputsAsTheyWere) {
  const ScratchDir scratch("cli_transaction");
  const fs::path scans = fs::path(POLARFORM_SOURCE_DIR) / "examples" / "scans";
  const std::vector<std::vector<std::string>> runs = {
      {"cam", (kExamples / "roller.xml").string(), "--tol", "0.002"},
      {"fit", (scans / "vase.xyz").string(), "--ctrl", "8,8"}};
  const std::vector<std::string> in_the_way = {"svaj.svg", "surface.x3d"};
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const fs::path out = scratch / ("out" + std::to_string(k));
    std::vector<std::string> args = runs[k];
    args.insert(args.end(), {"--out", out.string(), "-q"});
    ASSERT_EQ(run_cli(args, scratch).status, 0);
    fs::remove(out / in_the_way[k]);
    fs::create_directory(out / in_the_way[k]);
    const auto before = listing(out);
    args[3] = runs[k][0] == "cam" ? "0.001" : "10,10";  // another result, other bytes
    const CliRun failed = run_cli(args, scratch);
    EXPECT_EQ(failed.status, 2) << failed.err;
    EXPECT_NE(failed.err.find(in_the_way[k]), std::string::npos) << failed.err;
    EXPECT_TRUE(listing(out) == before) << runs[k][0] << ": the earlier outputs changed";
  }
}

TEST(Cli, HelpAndVersionExitZero) {
  const ScratchDir scratch("cli_help");
  const CliRun help = run_cli({"--help"}, scratch);
  EXPECT_EQ(help.status, 0);
  EXPECT_NE(help.out.find("cam"), std::string::npos);
  EXPECT_NE(help.out.find("study"), std::string::npos);
  const CliRun cam = run_cli({"cam", "--help"}, scratch);
  EXPECT_EQ(cam.status, 0);
  for (const char* option : {"--out", "--tol", "--base", "--max-degree", "--solid", "--bore"})
    EXPECT_NE(cam.out.find(option), std::string::npos) << option;
  const CliRun study = run_cli({"study", "--help"}, scratch);
  EXPECT_EQ(study.status, 0);
  EXPECT_NE(study.out.find("--steps-per-decade"), std::string::npos);
  const CliRun version = run_cli({"--version"}, scratch);
  EXPECT_EQ(version.status, 0);
  EXPECT_TRUE(std::regex_match(version.out, std::regex(R"(polarform \d+\.\d+\.\d+\n)")))
      << version.out;
  EXPECT_EQ(run_cli({}, scratch).status, 2);  // a command is required
}

TEST(Cli, CamOnTheRollerExampleWritesTheJobsFiles) {
  const ScratchDir scratch("cli_cam");
  const CliRun run = run_cli(
      {"cam", (kExamples / "roller.xml").string(), "--out", (scratch / "out").string()}, scratch);
  ASSERT_EQ(run.status, 0) << run.err;
  // The cycloidal rise starts and ends with a jerk step (4π²h/β³ = 203.718 mm/rad³): the CLI
  // names every continuity issue the report lists, up to jerk.
  const std::string jerk_steps =
      "polarform: motion: jerk jumps by 203.718 mm/rad³ (0 -> 203.718) at 90° between "
      "'segment 1' and 'segment 2'\n"
      "polarform: motion: jerk jumps by -203.718 mm/rad³ (203.718 -> 0) at 180° between "
      "'segment 2' and 'segment 3'\n";
  EXPECT_EQ(run.err, jerk_steps);
  const json cli = read_json(scratch / "out" / "report.json");
  const json job = read_json(example("roller").dir / "report.json");
  const std::string summary = std::to_string(job["arcs"].get<int>()) + " arcs, degree " +
                              std::to_string(job["degree"].get<int>()) + ", " +
                              std::to_string(job["control_points"].get<int>()) + " control points";
  EXPECT_NE(run.out.find(summary), std::string::npos) << run.out;
  // The design and key results, in report.html's words.
  const CamJobResult& r = example("roller").result;
  for (const auto& figures :
       {cam_design_inputs(r.design), cam_key_results(r.design, r.analysis, &r.conversion)})
    for (const KeyFigure& f : figures)
      EXPECT_NE(run.out.find(f.name + ": " + f.value + "\n"), std::string::npos) << f.name;
  for (const char* field : {"arcs", "degree", "control_points", "knot_count", "tolerance_mm",
                            "max_radial_error_mm", "max_normal_error_mm", "max_pressure_angle_deg",
                            "min_radius_of_curvature_mm", "undercut", "arc_list", "files"})
    EXPECT_EQ(cli[field], job[field]) << field;
  EXPECT_EQ(snapshot(scratch / "out").size(), 12u);
  // --quiet prints nothing but the warnings and motion notes.
  const CliRun quiet = run_cli(
      {"cam", (kExamples / "roller.xml").string(), "--out", (scratch / "quiet").string(), "-q"},
      scratch);
  EXPECT_EQ(quiet.status, 0);
  EXPECT_EQ(quiet.out + quiet.err, jerk_steps);
}

TEST(Cli, OptionsOverrideTheProject) {
  const ScratchDir scratch("cli_options");
  const std::string design = (kExamples / "roller.xml").string();
  ASSERT_EQ(run_cli({"cam", design, "--out", (scratch / "loose").string(), "--tol", "0.01", "-q"},
                    scratch)
                .status,
            0);
  const json loose = read_json(scratch / "loose" / "report.json");
  EXPECT_EQ(loose["tolerance_mm"].get<double>(), 0.01);
  EXPECT_LE(loose["max_radial_error_mm"].get<double>(), 0.01);
  EXPECT_GT(loose["max_radial_error_mm"].get<double>(), 1e-3);  // it used the looser budget
  const json exact = read_json(example("roller").dir / "report.json");
  EXPECT_LT(loose["control_points"].get<int>(), exact["control_points"].get<int>());

  ASSERT_EQ(
      run_cli({"cam", design, "--out", (scratch / "rqb").string(), "--base", "rqb", "-q"}, scratch)
          .status,
      0);
  const json rqb = read_json(scratch / "rqb" / "report.json");
  EXPECT_EQ(rqb["base"], "rqb");
  // RQB arcs follow the angle less closely: more of them for the same tolerance.
  EXPECT_GT(rqb["arcs"].get<int>(), exact["arcs"].get<int>());
  EXPECT_LE(rqb["max_radial_error_mm"].get<double>(), 1e-3);

  ASSERT_EQ(
      run_cli({"cam", design, "--out", (scratch / "capped").string(), "--max-degree", "3", "-q"},
              scratch)
          .status,
      0);
  const json capped = read_json(scratch / "capped" / "report.json");
  EXPECT_EQ(capped["exported_profile"]["degree"], 3);
  EXPECT_LE(capped["exported_profile"]["max_radial_error_mm"].get<double>(), 1e-3);
}

TEST(Cli, UnknownProjectFieldsAreErrorsUnlessLenient) {
  const ScratchDir scratch("cli_warn");
  std::string xml = slurp(kExamples / "roller.xml");
  xml.replace(xml.find("rpm=\"300\""), 9, "rpm=\"300\" colour=\"red\"");
  xml.replace(xml.find("</cam>"), 6, "<note/>\n  </cam>");
  spit(scratch / "warn.xml", xml);
  const CliRun strict = run_cli(
      {"cam", (scratch / "warn.xml").string(), "--out", (scratch / "out").string(), "-q"}, scratch);
  EXPECT_EQ(strict.status, 2) << strict.err;
  EXPECT_NE(strict.err.find("warn.xml:5: unknown attribute 'colour' on <cam> (known here: "),
            std::string::npos)
      << strict.err;
  EXPECT_FALSE(fs::exists(scratch / "out"));
  const CliRun run = run_cli({"cam", (scratch / "warn.xml").string(), "--out",
                              (scratch / "out").string(), "-q", "--lenient"},
                             scratch);
  EXPECT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.err.find("warn.xml:5: unknown attribute 'colour' on <cam> ignored (known here: "),
            std::string::npos)
      << run.err;
  EXPECT_NE(
      run.err.find("unknown element <note> in <cam> ignored (known here: conjugate, segment)"),
      std::string::npos)
      << run.err;
  EXPECT_EQ(snapshot(scratch / "out").size(), 12u);
}

}  // namespace
}  // namespace polarform
