// Motion table files: the normalised and the absolute (theta, s) forms read to the same table,
// comments and blank lines are skipped, and every broken file gives an error naming the file, the
// line and the field.
#include "jobs/project/motion_table_csv.h"

#include <gtest/gtest.h>

#include <numbers>

#include "src/error.h"

namespace polarform {
namespace {

constexpr double kPi = std::numbers::pi;
const TableSegment kRise{kPi / 2, kPi, 20, true};  // 90° to 180°, 20 mm

const std::string kNormalised =
    "# cycloid-ish\nx,S\n0,0\n0.2,0.05\n0.4,0.35\n\n0.6,0.65\n0.8,0.95\n1,1\n";

std::string error_of(const std::string& text, const TableSegment& segment = kRise) {
  try {
    parse_motion_table(text, "m.csv", segment, TableEnds::Rest);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(MotionTableCsv, NormalisedAndAbsoluteFormsReadTheSameTable) {
  const MotionTable t = parse_motion_table(kNormalised, "m.csv", kRise, TableEnds::Free);
  EXPECT_EQ(t.x, (std::vector<double>{0, 0.2, 0.4, 0.6, 0.8, 1}));
  EXPECT_EQ(t.s, (std::vector<double>{0, 0.05, 0.35, 0.65, 0.95, 1}));
  EXPECT_EQ(t.ends, TableEnds::Free);
  EXPECT_EQ(t.file, "m.csv");
  const std::string absolute = "Theta , s\n90,5\n108,6\n126,12\n144,18\n162,24 # comment\n180,25\n";
  const MotionTable a = parse_motion_table(absolute, "m.csv", kRise, TableEnds::Free);
  for (std::size_t i = 0; i < t.x.size(); ++i) {
    EXPECT_NEAR(a.x[i], t.x[i], 1e-15);
    EXPECT_NEAR(a.s[i], t.s[i], 1e-15);
  }
  // A return's s falls by the lift; the table is still the fraction travelled.
  const MotionTable r = parse_motion_table("theta,s\n90,25\n108,24\n126,18\n144,12\n162,6\n180,5\n",
                                           "m.csv", {kPi / 2, kPi, 20, false}, TableEnds::Rest);
  EXPECT_NEAR(r.s[1], 0.05, 1e-15);
  EXPECT_EQ(r.s.back(), 1.0);
}

TEST(MotionTableCsv, BrokenTablesNameFileLineAndField) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"", "m.csv: empty; expected the header 'x,S' or 'theta,s' and rows"},
      {"a,b\n0,0\n",
       "m.csv:1: expected the header 'x,S' (normalised) or 'theta,s' (degrees, length), got 'a,b'"},
      {"x,S\n0,0\n0.5\n", "m.csv:3: expected two comma-separated fields, got '0.5'"},
      {"x,S\n0,0\n0.5,nan\n", "m.csv:3: S: expected a finite number, got 'nan'"},
      {"x,S\n0,0\nhalf,0.5\n", "m.csv:3: x: expected a finite number, got 'half'"},
      {"x,S\n0,0\n0.5,0.5\n1,1\n", "m.csv: 3 rows, expected between 6 and 100000 rows"},
      {"x,S\n0,0\n0.2,0.1\n0.4,0.3\n0.3,0.6\n0.8,0.9\n1,1\n",
       "m.csv:5: x: expected x increasing strictly (after 0.4)"},
      {"x,S\n0,0\n0.2,0.1\n0.4,0.3\n0.6,0.6\n0.8,0.9\n1,0.98\n",
       "m.csv:7: S: expected S = 1 in the last row"},
      {"theta,s\n91,5\n108,6\n126,12\n144,18\n162,24\n180,25\n",
       "m.csv:2: theta = 91, expected the segment's start angle 90°"},
      {"theta,s\n90,5\n108,6\n126,12\n144,18\n162,24\n180,26\n",
       "m.csv:7: s = 26, expected the first row's 5 + the lift 20"},
      {"theta,s\n90,5\n108,6\n100,12\n144,18\n162,24\n180,25\n",
       "m.csv:4: theta: expected x increasing strictly (after 0.2) (normalised by the first and "
       "last rows)"},
      {"x,S\n0,0\n0.2,0.1,7\n", "m.csv:3: expected two comma-separated fields, got '0.2,0.1,7'"},
  };
  for (const auto& [text, expected] : cases) EXPECT_EQ(error_of(text), expected) << text;
}

TEST(MotionTableCsv, MissingFilesAreNamed) {
  try {
    read_motion_table("/nonexistent/cam.xml", "motion.csv", kRise, TableEnds::Rest);
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "/nonexistent/motion.csv: no such file (motion table named by /nonexistent/cam.xml)");
  }
}

// Any bytes: an InputError or a table, never anything else.
TEST(MotionTableCsv, ArbitraryBytesNeverEscapeAsAnythingButInputError) {
  std::string text = kNormalised;
  for (std::size_t i = 0; i < text.size(); ++i)
    for (const char c : {'\0', ',', '\n', '9', '-', 'e', '#', '\xff'}) {
      std::string broken = text;
      broken[i] = c;
      try {
        parse_motion_table(broken, "m.csv", kRise, TableEnds::Rest);
      } catch (const InputError&) {
      }
    }
}

}  // namespace
}  // namespace polarform
