#include "src/message_text.h"

#include <locale>
#include <numbers>
#include <sstream>

namespace polarform {

std::string number_text(double value) {
  std::ostringstream out;
  out.imbue(std::locale::classic());
  out.precision(6);
  out << value;
  return out.str();
}

std::string degrees_text(double radians) { return number_text(radians * 180.0 / std::numbers::pi) + "°"; }

}  // namespace polarform
