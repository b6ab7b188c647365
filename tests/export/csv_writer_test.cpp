// CSV output: exact round trip of every double, RFC 4180 header quoting, locale independence.
#include "export/csv_writer.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <locale>
#include <random>
#include <sstream>

#include "src/error.h"

namespace polarform {
namespace {

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  for (std::string part; std::getline(in, part, separator);) parts.push_back(part);
  return parts;
}

std::vector<double> awkward_doubles() {
  std::vector<double> v = {0.1,
                           1.0 / 3.0,
                           -0.0,
                           1e300,
                           -1e300,
                           DBL_MAX,
                           DBL_MIN,
                           5e-324,
                           2.2250738585072009e-308,
                           123456789.123456789,
                           -2.5e-17};
  std::mt19937_64 rng(2024);
  while (v.size() < 3000) {
    const double d = std::bit_cast<double>(rng());  // uniform over bit patterns: all exponents
    if (std::isfinite(d)) v.push_back(d);
  }
  for (int i = 0; i < 200; ++i) v.push_back(std::bit_cast<double>(rng() >> 12));  // subnormals
  return v;
}

std::string table(const std::vector<double>& values) {
  CsvWriter csv({"theta [deg]", "R [mm]", "error [mm]"});
  for (std::size_t i = 0; i + 3 <= values.size(); i += 3)
    csv.row({values[i], values[i + 1], values[i + 2]});
  return csv.str();
}

TEST(CsvWriter, EveryDoubleReadsBackExactly) {
  const std::vector<double> values = awkward_doubles();
  const std::vector<std::string> lines = split(table(values), '\n');
  ASSERT_EQ(lines.size(), 1 + values.size() / 3);
  EXPECT_EQ(lines[0], "theta [deg],R [mm],error [mm]");
  std::size_t k = 0;
  for (std::size_t i = 1; i < lines.size(); ++i)
    for (const std::string& field : split(lines[i], ',')) {
      const double back = std::strtod(field.c_str(), nullptr);
      ASSERT_EQ(std::bit_cast<std::uint64_t>(back), std::bit_cast<std::uint64_t>(values[k]))
          << field << " for value #" << k;
      ASSERT_LE(field.size(), 24u);  // shortest form, never 17 padded digits plus noise
      ++k;
    }
  EXPECT_EQ(k, values.size() / 3 * 3);
  EXPECT_EQ(lines[1], "0.1,0.3333333333333333,-0");
  EXPECT_EQ(lines[2], "1e+300,-1e+300,1.7976931348623157e+308");
}

// A locale that writes 1.234,5 as German does.
struct CommaDecimal : std::numpunct<char> {
  char do_decimal_point() const override { return ','; }
  char do_thousands_sep() const override { return '.'; }
  std::string do_grouping() const override { return "\3"; }
};

TEST(CsvWriter, OutputIsIndependentOfTheGlobalLocale) {
  const std::vector<double> values = awkward_doubles();
  const std::string classic = table(values);
  const std::locale previous =
      std::locale::global(std::locale(std::locale::classic(), new CommaDecimal));
  std::ostringstream probe;
  probe << 1234.5;
  const std::string probed = probe.str();
  const std::string localized = table(values);
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() /
      ("polarform_csv_locale_" + std::to_string(::getpid()) + ".csv");
  CsvWriter csv({"x [mm]"});
  csv.row({1234.5});
  csv.save(file);
  std::locale::global(previous);
  EXPECT_EQ(probed, "1.234,5");  // the facet is active, so the test can fail
  EXPECT_EQ(localized, classic);
  std::ifstream in(file);
  std::stringstream saved;
  saved << in.rdbuf();
  EXPECT_EQ(saved.str(), "x [mm]\n1234.5\n");
  std::filesystem::remove(file);
}

TEST(CsvWriter, HeadersAreQuotedPerRfc4180AndNonFiniteValuesNamed) {
  CsvWriter csv({"theta [deg]", "R, radius [mm]", "say \"hi\"", " padded"});
  csv.row({NAN, INFINITY, -INFINITY, 0.5});
  EXPECT_EQ(csv.str(),
            "theta [deg],\"R, radius [mm]\",\"say \"\"hi\"\"\",\" padded\"\nnan,inf,-inf,0.5\n");
  EXPECT_EQ(csv.rows(), 1u);
  EXPECT_EQ(csv.columns(), 4u);
}

TEST(CsvWriter, BadShapesAreRejected) {
  EXPECT_THROW(CsvWriter({}), InputError);
  EXPECT_THROW(CsvWriter({"x [mm]", ""}), InputError);
  CsvWriter csv({"x [mm]", "y [mm]"});
  csv.row({1, 2});
  try {
    csv.row({1, 2, 3});
    FAIL() << "a row of 3 values in 2 columns was accepted";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "CsvWriter: row 2 has 3 values; expected 2, one per header");
  }
}

}  // namespace
}  // namespace polarform
