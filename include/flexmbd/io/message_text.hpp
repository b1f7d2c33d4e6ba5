#pragma once
/// @file
/// Small text helpers for the loader's error messages: number formatting (FormatNumber from number_text.hpp),
/// name lists and "did you mean" suggestions by edit distance.

#include <string>
#include <vector>

#include "flexmbd/common/number_text.hpp"
#include "flexmbd/model/model_spec.hpp"

namespace flexmbd {
namespace io {

/// `text` with control characters written as escapes (\n, \t, \x01), so that a message stays one line.
std::string QuoteForMessage(const std::string& text);

/// "[x, y, z]" with FormatNumber entries.
std::string FormatVector(const Vec3& value);

/// "a, b, c" (names in the given order).
std::string JoinNames(const std::vector<std::string>& names);

/// Optimal-string-alignment distance: insertions, deletions, substitutions and adjacent transpositions.
int EditDistance(const std::string& a, const std::string& b);

/// The candidate nearest to `word`, if it is close enough to be a likely typo (distance at most
/// max(1, ceil(|word| / 3))); empty otherwise. Ties go to the earlier candidate.
std::string ClosestName(const std::string& word, const std::vector<std::string>& candidates);

/// "did you mean 'dt'?" when a candidate is close to `word`, otherwise "<what> are: a, b, c".
std::string SuggestName(const std::string& word, const std::vector<std::string>& candidates, const std::string& what);

/// "no joint 'B7' in arm.urdf; joints are: B1, B2" plus "; did you mean 'B1'?" when one is close
/// (kind "joint", kinds "joints").
std::string NotFoundMessage(const std::string& kind, const std::string& kinds, const std::string& name,
                            const std::string& where, const std::vector<std::string>& candidates);

}  // namespace io
}  // namespace flexmbd
