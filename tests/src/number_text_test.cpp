// Number text for the writers (src/number_text.h): fixed decimals, trimmed pixel numbers,
// shortest round trip.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "src/number_text.h"

namespace polarform {
namespace {

TEST(NumberFormat, FixedRoundsAndNeverPrintsMinusZero) {
  EXPECT_EQ(format_fixed(1.005, 2), "1.00");  // 1.005 is 1.00499999999999989...
  EXPECT_EQ(format_fixed(2.675, 1), "2.7");
  EXPECT_EQ(format_fixed(-0.004, 2), "0.00");
  EXPECT_EQ(format_fixed(-0.0, 0), "0");
  EXPECT_EQ(format_fixed(-1.5, 3), "-1.500");
  EXPECT_EQ(format_fixed(1e20, 0), "100000000000000000000");
  EXPECT_EQ(format_fixed(std::numeric_limits<double>::quiet_NaN(), 2), "nan");
  EXPECT_EQ(format_fixed(-std::numeric_limits<double>::infinity(), 2), "-inf");
}

TEST(NumberFormat, TrimmedDropsTrailingZerosAndPoint) {
  EXPECT_EQ(format_trimmed(12.5, 2), "12.5");
  EXPECT_EQ(format_trimmed(3.0, 2), "3");
  EXPECT_EQ(format_trimmed(100.0, 2), "100");  // zeros before the point stay
  EXPECT_EQ(format_trimmed(0.126, 2), "0.13");
  EXPECT_EQ(format_trimmed(-0.001, 2), "0");
  EXPECT_EQ(format_trimmed(-7.25, 2), "-7.25");
}

TEST(NumberFormat, RoundTripIsShortestAndExact) {
  EXPECT_EQ(format_round_trip(0.1), "0.1");
  EXPECT_EQ(format_round_trip(1e300), "1e+300");
  EXPECT_EQ(format_round_trip(-0.0), "-0");
  EXPECT_EQ(format_round_trip(5e-324), "5e-324");
  EXPECT_EQ(format_round_trip(std::numeric_limits<double>::infinity()), "inf");
  const double third = 1.0 / 3.0;
  EXPECT_EQ(std::strtod(format_round_trip(third).c_str(), nullptr), third);
  EXPECT_EQ(format_round_trip(third).size(), 18u);  // "0." and 16 digits
}

}  // namespace
}  // namespace polarform
