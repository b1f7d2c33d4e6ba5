#pragma once
/// @file
/// The values a hostile or careless user writes where a number belongs, shared by the URDF and YAML mutators.

#include <random>
#include <string>

namespace flexmbd {
namespace fuzz {

using Rng = std::mt19937_64;

/// A uniformly chosen integer in [0, n). @pre n > 0.
size_t Pick(Rng* rng, size_t n);

/// True with probability `p`.
bool Chance(Rng* rng, double p);

/// A replacement for the number text `original`: zero, a negative, NaN, an infinity, a huge or tiny
/// magnitude, an integer overflow, a scaled or negated copy of the original, or text that is no number.
std::string HostileNumber(const std::string& original, Rng* rng);

}  // namespace fuzz
}  // namespace flexmbd
