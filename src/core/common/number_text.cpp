#include "flexmbd/common/number_text.hpp"

#include <cstdio>
#include <cstdlib>

namespace flexmbd {

std::string FormatNumber(double value) {
  char buffer[32];
  for (int precision = 1; precision <= 17; ++precision) {
    std::snprintf(buffer, sizeof(buffer), "%.*g", precision, value);
    if (std::strtod(buffer, nullptr) == value) break;
  }
  return buffer;
}

}  // namespace flexmbd
