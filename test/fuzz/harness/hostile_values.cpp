#include "hostile_values.hpp"

#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <sstream>
#include <vector>

namespace flexmbd {
namespace fuzz {
namespace {

// Spellings as YAML and URDF readers meet them: YAML's .nan/.inf, C's nan/inf, overflows of int and double.
const std::vector<std::string> kSpecialNumbers = {
    "0",     "-0",     "-1",    "1",      "nan",     ".nan",   "NaN",          "inf",         "-inf",
    ".inf",  "-.inf",  "1e308", "-1e308", "1e309",   "1e-308", "4.9e-324",     "2147483648",  "-2147483649",
    "1e9",   "1e18",   "-1e18", "0.5",    "1e-300",  "",       "x",            "1 2",         "0x10",
    "true",  "1e999",  "-1e-9", "3",      "100000",  "1.",     "9223372036854775808"};

std::string Format(double value) {
  std::ostringstream text;
  text << std::setprecision(17) << value;
  return text.str();
}

}  // namespace

size_t Pick(Rng* rng, size_t n) { return std::uniform_int_distribution<size_t>(0, n - 1)(*rng); }

bool Chance(Rng* rng, double p) { return std::uniform_real_distribution<double>(0.0, 1.0)(*rng) < p; }

std::string HostileNumber(const std::string& original, Rng* rng) {
  char* end = nullptr;
  const double value = std::strtod(original.c_str(), &end);
  const bool numeric = !original.empty() && end != original.c_str();
  if (!numeric || Chance(rng, 0.6)) return kSpecialNumbers[Pick(rng, kSpecialNumbers.size())];
  switch (Pick(rng, 3)) {
    case 0:
      return Format(-value);
    case 1:
      return Format(value * std::pow(10.0, static_cast<double>(Pick(rng, 41)) - 20.0));
    default:
      return Format(value + (Chance(rng, 0.5) ? 1.0 : -1.0));
  }
}

}  // namespace fuzz
}  // namespace flexmbd
