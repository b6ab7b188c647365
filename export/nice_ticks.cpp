#include "export/nice_ticks.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>
#include <utility>

#include "src/number_text.h"

namespace polarform {

namespace {

constexpr double kSlack = 1e-9;  // relative tolerance for ticks that sit on a range end

constexpr int kMaxDecimals = 17;

// Smallest number of decimals that shows every multiple of step exactly (step = 0.25 -> 2);
// kMaxDecimals if there is none.
int decimals_for(double step) {
  for (int d = 0; d < kMaxDecimals; ++d) {
    const double scaled = step * power_of_ten(d);
    if (std::abs(scaled - std::round(scaled)) <= kSlack * scaled) return d;
  }
  return kMaxDecimals;
}

// A proper minus sign (U+2212) instead of the hyphen.
std::string with_minus_sign(std::string text) {
  if (!text.empty() && text.front() == '-') text.replace(0, 1, "\u2212");
  return text;
}

// Label of m × 10^k (m in 1..9): plain decimals or a superscript power of ten.
std::string log_label(int m, int k, bool plain) {
  if (plain) return format_fixed(m * power_of_ten(k), std::max(0, -k));
  const std::string power = superscript_power_of_ten(k);
  return m == 1 ? power : std::to_string(m) + "\u00D7" + power;
}

// One style per axis: plain decimals if every labelled exponent is in -3..4, powers otherwise.
void label_log_ticks(TickSet& ticks, const std::vector<std::pair<int, int>>& mantissa_exponent) {
  const bool plain = std::all_of(mantissa_exponent.begin(), mantissa_exponent.end(),
                                 [](auto me) { return me.second >= -3 && me.second <= 4; });
  for (std::size_t i = 0; i < ticks.major.size(); ++i)
    ticks.major[i].label =
        log_label(mantissa_exponent[i].first, mantissa_exponent[i].second, plain);
}

std::pair<int, int> decade_span(double lo, double hi) {
  return {static_cast<int>(std::floor(std::log10(lo))),
          static_cast<int>(std::ceil(std::log10(hi)))};
}

bool inside(double v, double lo, double hi) {
  return v >= lo * (1 - kSlack) && v <= hi * (1 + kSlack);
}

}  // namespace

double nice_step(int index) {
  static constexpr double mantissas[] = {1, 2, 5};
  const int decade = static_cast<int>(std::floor(index / 3.0));
  return mantissas[index - 3 * decade] * power_of_ten(decade);
}

int nice_step_index(double raw) {
  int index = 3 * static_cast<int>(std::floor(std::log10(raw))) - 3;
  while (nice_step(index) < raw * (1 - kSlack)) ++index;
  return index;
}

TickSet linear_ticks(double lo, double hi, double step) {
  const double slack = 1e-6 * step;  // admits an end that is a multiple up to rounding
  const auto first = static_cast<long long>(std::ceil((lo - slack) / step));
  const auto last = static_cast<long long>(std::floor((hi + slack) / step));
  int decimals = decimals_for(step);
  // Multiples of a decimal step computed as integer / 10^d, so 3 × 0.1 is exactly 0.3.
  const double denominator = power_of_ten(decimals);
  const double numerator = std::round(step * denominator);
  TickSet ticks;
  double largest = 0;
  for (long long i = first; i <= last; ++i) {
    const double value = decimals > 0 && decimals < kMaxDecimals
                             ? static_cast<double>(i) * numerator / denominator
                             : static_cast<double>(i) * step;
    ticks.major.push_back({value, {}});
    largest = std::max(largest, std::abs(value));
  }
  double scale = 1;
  if (largest >= 1e5 || (largest > 0 && largest < 1e-3)) {
    const int exponent = 3 * static_cast<int>(std::floor(std::floor(std::log10(largest)) / 3));
    scale = power_of_ten(exponent);
    ticks.factor = "\u00D7" + superscript_power_of_ten(exponent);
    decimals = decimals_for(step / scale);
  }
  for (Tick& tick : ticks.major)
    tick.label = with_minus_sign(format_fixed(tick.value / scale, decimals));
  return ticks;
}

TickSet log_decade_ticks(double lo, double hi, int stride) {
  const auto [kmin, kmax] = decade_span(lo, hi);
  TickSet ticks;
  std::vector<std::pair<int, int>> labelled;
  for (int k = kmin; k <= kmax; ++k) {
    const double decade = power_of_ten(k);
    if (inside(decade, lo, hi)) {
      if (k % stride == 0) {
        ticks.major.push_back({decade, {}});
        labelled.push_back({1, k});
      } else {
        ticks.minor.push_back(decade);
      }
    }
    if (stride == 1)
      for (int m = 2; m <= 9; ++m)
        if (inside(m * decade, lo, hi)) ticks.minor.push_back(m * decade);
  }
  label_log_ticks(ticks, labelled);
  return ticks;
}

TickSet log_mantissa_ticks(double lo, double hi, std::span<const int> mantissas) {
  const auto [kmin, kmax] = decade_span(lo, hi);
  TickSet ticks;
  std::vector<std::pair<int, int>> labelled;
  for (int k = kmin; k <= kmax; ++k)
    for (int m = 1; m <= 9; ++m) {
      const double value = m * power_of_ten(k);
      if (!inside(value, lo, hi)) continue;
      if (std::find(mantissas.begin(), mantissas.end(), m) != mantissas.end()) {
        ticks.major.push_back({value, {}});
        labelled.push_back({m, k});
      } else {
        ticks.minor.push_back(value);
      }
    }
  label_log_ticks(ticks, labelled);
  return ticks;
}

double power_of_ten(int k) {
  const std::string literal = "1e" + std::to_string(k);
  double value = 0;
  const auto result = std::from_chars(literal.data(), literal.data() + literal.size(), value);
  if (result.ec == std::errc::result_out_of_range) return k > 0 ? HUGE_VAL : 0.0;
  return value;
}

std::string superscript_power_of_ten(int k) {
  static constexpr const char* digits[] = {"\u2070", "\u00B9", "\u00B2", "\u00B3", "\u2074",
                                           "\u2075", "\u2076", "\u2077", "\u2078", "\u2079"};
  std::string text = "10";
  if (k < 0) text += "\u207B";
  for (const char c : std::to_string(std::abs(k))) text += digits[c - '0'];
  return text;
}

}  // namespace polarform
