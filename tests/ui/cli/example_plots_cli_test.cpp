// Every plot of every bundled example, as the CLI writes it: no legend box hides data, an
// annotation, a highlighted point or a reference-line label (checked on the SVG's own pixel
// coordinates, independently of the layout code), and every angle axis says which angle it is.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <regex>
#include <string>
#include <vector>

#include "tests/support/export/svg_elements.h"
#include "tests/ui/cli/cli_run.h"

namespace polarform::cam_job_test {
namespace {

using tinyxml2::XMLElement;

struct Box {
  double left, top, right, bottom;
  bool overlaps(const Box& o) const {
    return left < o.right && o.left < right && top < o.bottom && o.top < bottom;
  }
  bool contains(double x, double y) const { return x > left && x < right && y > top && y < bottom; }
};

// Text extent from its font size: a lower bound on the glyphs' width (0.45 em per character) so
// that the check never blames the legend for text it does not cover.
double text_length(const XMLElement* text) {
  const std::string s = text->GetText() ? text->GetText() : "";
  std::size_t characters = 0;
  for (unsigned char c : s) characters += (c & 0xC0) != 0x80;
  return 0.45 * text->DoubleAttribute("font-size") * static_cast<double>(characters);
}

Box text_box(const XMLElement* text) {
  const double x = text->DoubleAttribute("x"), y = text->DoubleAttribute("y");
  const double font = text->DoubleAttribute("font-size"), w = text_length(text);
  const std::string anchor = text->Attribute("text-anchor") ? text->Attribute("text-anchor") : "";
  if (text->Attribute("transform"))  // rotated −90° about (x, y), ending there: runs downwards
    return {x - 0.7 * font, y, x, y + w};
  const double left = anchor == "end" ? x - w : anchor == "middle" ? x - w / 2 : x;
  return {left, y - 0.7 * font, left + w, y};
}

// What the legend of `panel` hides: one description per hidden item.
std::vector<std::string> hidden_by_legend(const XMLElement* panel) {
  std::vector<std::string> hidden;
  for (const XMLElement* legend : test::by_class(panel, "legend")) {
    const XMLElement* r = legend->FirstChildElement("rect");
    const double x = r->DoubleAttribute("x"), y = r->DoubleAttribute("y");
    const Box box{x, y, x + r->DoubleAttribute("width"), y + r->DoubleAttribute("height")};
    for (const XMLElement* series : test::by_class(panel, "series"))
      for (const Polyline& piece : test::subpaths(series->Attribute("d")))
        for (std::size_t i = 0; i < piece.size(); ++i) {
          const auto [x0, y0] = piece[i];
          const auto [x1, y1] = piece[i + 1 < piece.size() ? i + 1 : i];
          const double steps = std::ceil(std::hypot(x1 - x0, y1 - y0)) + 1;
          for (double k = 0; k <= steps; ++k)
            if (box.contains(x0 + (x1 - x0) * k / steps, y0 + (y1 - y0) * k / steps)) {
              hidden.push_back("a data line at (" + std::to_string(x0) + ", " + std::to_string(y0) +
                               ")");
              k = steps;
            }
        }
    for (const XMLElement* markers : test::by_class(panel, "markers"))
      for (const Polyline& marker : test::subpaths(markers->Attribute("d")))
        if (box.contains(marker.front().x, marker.front().y)) hidden.push_back("a marker");
    for (const XMLElement* ring : test::by_class(panel, "highlight")) {
      const double cx = ring->DoubleAttribute("cx"), cy = ring->DoubleAttribute("cy");
      if (box.overlaps({cx - 3, cy - 3, cx + 3, cy + 3})) hidden.push_back("a highlight");
    }
    for (const char* cls : {"annotation", "reference-label"})
      for (const XMLElement* text : test::by_class(panel, cls))
        if (box.overlaps(text_box(text)))
          hidden.push_back(std::string(cls) + " '" + text->GetText() + "'");
  }
  return hidden;
}

struct ExampleRun {
  std::string name;
  std::vector<std::string> args;  // the CLI arguments before --out
};

std::vector<ExampleRun> every_example() {
  const fs::path examples = fs::path(POLARFORM_SOURCE_DIR) / "examples";
  std::vector<ExampleRun> runs;
  for (const std::string& cam : kExampleNames)
    runs.push_back({"cam " + cam, {"cam", (examples / "cams" / (cam + ".xml")).string()}});
  for (const char* vessel :
       {"hemispherical", "ellipsoidal_2_1", "torispherical_100_6", "custom_curvature",
        "torispherical_100_6_exact", "minimum_stress_2_1_depth", "toriconical_30"})
    runs.push_back({std::string("vessel ") + vessel,
                    {"vessel", (examples / "vessels" / (std::string(vessel) + ".xml")).string()}});
  for (const char* scan : {"sphere_like_fit.xml", "lobed_profile_fit.xml", "sphere_like.xyz",
                           "vase.xyz", "lobed_profile.xyz"})
    runs.push_back({std::string("fit ") + scan, {"fit", (examples / "scans" / scan).string()}});
  runs.push_back({"scan-cam",
                  {"scan-cam", (examples / "scans" / "cam_plate.xyz").string(), "--nominal",
                   (examples / "cams" / "roller.xml").string()}});
  runs.push_back({"viz", {"viz", (examples / "scans" / "sphere_grid.csv").string()}});
  runs.push_back({"study", {"study", (examples / "cams" / "roller.xml").string()}});
  return runs;
}

TEST(ExamplePlots, LegendsHideNothingAndAngleAxesNameTheirAngle) {
  const ScratchDir scratch("example_plots");
  int plots = 0, legends = 0;
  for (const ExampleRun& example : every_example()) {
    SCOPED_TRACE(example.name);
    const fs::path out = scratch / ("out" + std::to_string(plots));
    std::vector<std::string> args = example.args;
    args.insert(args.end(), {"--out", out.string(), "--quiet"});
    const CliRun run = run_cli(args, scratch);
    ASSERT_EQ(run.status, 0) << run.err;
    for (const auto& entry : fs::directory_iterator(out)) {
      if (entry.path().extension() != ".svg") continue;
      SCOPED_TRACE(entry.path().filename().string());
      ++plots;
      tinyxml2::XMLDocument doc;
      ASSERT_EQ(doc.LoadFile(entry.path().c_str()), tinyxml2::XML_SUCCESS);
      for (const XMLElement* panel : test::by_class(doc.RootElement(), "panel")) {
        legends += static_cast<int>(test::by_class(panel, "legend").size());
        EXPECT_THAT(hidden_by_legend(panel), testing::IsEmpty());
      }
      // θ (cam angle, azimuth), ψ (polar angle of a contour), φ (polar angle from an axis).
      for (const XMLElement* label : test::by_class(doc.RootElement(), "x-label")) {
        const std::string text = label->GetText();
        if (text.find("angle") == std::string::npos && text.find("azimuth") == std::string::npos)
          continue;
        EXPECT_TRUE(text.find("θ") != std::string::npos || text.find("ψ") != std::string::npos ||
                    text.find("φ") != std::string::npos)
            << text;
      }
    }
  }
  EXPECT_GE(plots, 40);    // 4 per cam, 3 per vessel, 1 per fit, 4 scan-cam, 1 viz, 2 study
  EXPECT_GE(legends, 30);  // the check saw legends to check
}

}  // namespace
}  // namespace polarform::cam_job_test
