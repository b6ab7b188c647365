// Text primitives shared by the exchange writers (IGES, STEP, DXF, X3D): reals written as the
// shortest decimal that reads back to the identical double, always with a decimal point (IGES 5.3
// and ISO 10303-21 both need one to tell a real from an integer), and UTC time
// stamps for file headers (reproducible with SOURCE_DATE_EPOCH).
#pragma once

#include <ctime>
#include <string>
#include <string_view>

namespace polarform {

// 1 -> "1.0", 0.25 -> "0.25", -1e-7 -> "-1.0E-07", 6.02e23 -> "6.02E+23". exponent_letter 'D'
// marks an IGES double-precision real. Negative zero is written as "0.0". Throws InputError for
// a non-finite value.
std::string exchange_real(double x, char exponent_letter = 'E');

// Text for a format that carries only printable ASCII (IGES): UTF-8 letters of Latin-1 and Latin
// Extended-A with their diacritics removed ("rôle" → "role", "Łódź" → "Lodz", "ß" → "ss"), every
// other character that is not printable ASCII, and every byte that is not UTF-8, as '_'.
std::string ascii_text(std::string_view utf8);

// The moment exchange files are stamped with: now, or SOURCE_DATE_EPOCH when set (seconds since
// 1970 UTC; the reproducible-builds.org convention), so that the same input gives the same bytes.
// Throws InputError for a malformed SOURCE_DATE_EPOCH.
std::time_t stamp_time();
// stamp_time() in UTC formatted with std::strftime, e.g. "%Y%m%d.%H%M%S".
std::string utc_time_stamp(const char* strftime_format);

}  // namespace polarform
