// The values of the fit-family commands (fit, viz, scan-cam) as the user types them: number lists
// "p,q" and "X,Y,Z" and named choices, parsed strictly (the whole text, finite numbers, the
// expected count) with an InputError that names the option and says what was expected.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace polarform {

// 1 to max_count comma-separated finite numbers; `option` names the flag in messages.
std::vector<double> parse_numbers(const std::string& option, const std::string& text, int min_count,
                                  int max_count);

// One or two integers in [lo, hi] ("3" or "3,5"); one value is used for both directions.
std::pair<int, int> parse_int_pair(const std::string& option, const std::string& text, int lo,
                                   int hi);

// The index of `text` in `choices`; InputError listing the choices otherwise.
int parse_choice(const std::string& option, const std::string& text,
                 const std::vector<std::string>& choices);

}  // namespace polarform
