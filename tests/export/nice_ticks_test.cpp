// Nice tick values: the 1-2-5 sequence, multiples inside a range, labels, decades on log axes.
#include "export/nice_ticks.h"

#include <gtest/gtest.h>

#include <cmath>

namespace polarform {
namespace {

std::vector<double> values(const TickSet& t) {
  std::vector<double> v;
  for (const Tick& tick : t.major) v.push_back(tick.value);
  return v;
}

std::vector<std::string> labels(const TickSet& t) {
  std::vector<std::string> v;
  for (const Tick& tick : t.major) v.push_back(tick.label);
  return v;
}

TEST(NiceTicks, StepSequenceIsOneTwoFive) {
  EXPECT_EQ(nice_step(0), 1);
  EXPECT_EQ(nice_step(1), 2);
  EXPECT_EQ(nice_step(2), 5);
  EXPECT_EQ(nice_step(3), 10);
  EXPECT_EQ(nice_step(-1), 0.5);
  EXPECT_EQ(nice_step(-3), 0.1);
  EXPECT_EQ(nice_step(-5), 0.02);
  EXPECT_EQ(nice_step(nice_step_index(0.3)), 0.5);
  EXPECT_EQ(nice_step(nice_step_index(2.0)), 2);
  EXPECT_EQ(nice_step(nice_step_index(2.0000001)), 5);
  EXPECT_EQ(nice_step(nice_step_index(7e-5)), 1e-4);
  EXPECT_EQ(nice_step(nice_step_index(31)), 50);
}

TEST(NiceTicks, LinearMultiplesInsideTheRangeWithUniformDecimals) {
  EXPECT_EQ(values(linear_ticks(-0.03, 7.3, 2)), (std::vector<double>{0, 2, 4, 6}));
  EXPECT_EQ(labels(linear_ticks(-0.03, 7.3, 2)), (std::vector<std::string>{"0", "2", "4", "6"}));
  // Ends that are multiples up to rounding are kept; values are the exact decimals.
  const TickSet t = linear_ticks(-0.3, 0.3, 0.1);
  EXPECT_EQ(values(t), (std::vector<double>{-0.3, -0.2, -0.1, 0, 0.1, 0.2, 0.3}));
  EXPECT_EQ(labels(t), (std::vector<std::string>{"\u22120.3", "\u22120.2", "\u22120.1", "0.0",
                                                 "0.1", "0.2", "0.3"}));
  EXPECT_EQ(labels(linear_ticks(0, 1, 0.25)),
            (std::vector<std::string>{"0.00", "0.25", "0.50", "0.75", "1.00"}));
  EXPECT_EQ(values(linear_ticks(0, 360, 60)),
            (std::vector<double>{0, 60, 120, 180, 240, 300, 360}));
  EXPECT_TRUE(linear_ticks(0, 360, 60).factor.empty());
}

TEST(NiceTicks, LargeAndSmallValuesShareAPowerOfTenFactor) {
  const TickSet big = linear_ticks(0, 2.5e8, 5e7);
  EXPECT_EQ(big.factor, "\u00D710\u2076");
  EXPECT_EQ(labels(big), (std::vector<std::string>{"0", "50", "100", "150", "200", "250"}));
  EXPECT_EQ(big.major[3].value, 1.5e8);
  const TickSet small = linear_ticks(-2e-5, 3e-5, 1e-5);
  EXPECT_EQ(small.factor, "\u00D710\u207B\u2076");
  EXPECT_EQ(labels(small),
            (std::vector<std::string>{"\u221220", "\u221210", "0", "10", "20", "30"}));
}

TEST(NiceTicks, LogTicksAreDecadesWithMinorTicks) {
  const TickSet t = log_decade_ticks(0.7e-3, 150, 1);
  EXPECT_EQ(values(t), (std::vector<double>{1e-3, 1e-2, 1e-1, 1, 10, 100}));
  EXPECT_EQ(labels(t), (std::vector<std::string>{"0.001", "0.01", "0.1", "1", "10", "100"}));
  // 8 minor ticks in each of the 5 full decades, 0.0007..0.0009 below, none in 100..150.
  EXPECT_EQ(t.minor.size(), 5u * 8u + 3u);
  EXPECT_DOUBLE_EQ(t.minor.front(), 7e-4);
  EXPECT_DOUBLE_EQ(t.minor.back(), 90);

  const TickSet wide = log_decade_ticks(1e-12, 1e3, 3);
  EXPECT_EQ(values(wide), (std::vector<double>{1e-12, 1e-9, 1e-6, 1e-3, 1, 1e3}));
  EXPECT_EQ(wide.major[0].label, "10\u207B\u00B9\u00B2");
  EXPECT_EQ(wide.major[4].label, "10\u2070");  // one style per axis
  EXPECT_EQ(wide.major[5].label, "10\u00B3");
  EXPECT_EQ(wide.minor.size(), 10u);  // the skipped decades

  const TickSet narrow = log_mantissa_ticks(1.5, 9, std::vector<int>{1, 2, 5});
  EXPECT_EQ(values(narrow), (std::vector<double>{2, 5}));
  EXPECT_EQ(narrow.minor, (std::vector<double>{3, 4, 6, 7, 8, 9}));
  EXPECT_EQ(log_mantissa_ticks(1e-7, 5e-7, std::vector<int>{1, 2, 5}).major[1].label,
            "2\u00D710\u207B\u2077");
}

TEST(NiceTicks, PowersOfTenAreTheDecimalLiterals) {
  EXPECT_EQ(power_of_ten(-1), 0.1);
  EXPECT_EQ(power_of_ten(-7), 1e-7);
  EXPECT_EQ(power_of_ten(22), 1e22);
  EXPECT_EQ(power_of_ten(-400), 0.0);
  EXPECT_EQ(superscript_power_of_ten(-3), "10\u207B\u00B3");
  EXPECT_EQ(superscript_power_of_ten(10), "10\u00B9\u2070");
}

}  // namespace
}  // namespace polarform
