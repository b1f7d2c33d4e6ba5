#include "flexmbd/io/message_text.hpp"

#include <algorithm>
#include <cstdio>

namespace flexmbd {
namespace io {

std::string QuoteForMessage(const std::string& text) {
  std::string quoted;
  for (const char c : text) {
    const unsigned char code = static_cast<unsigned char>(c);
    if (c == '\n') {
      quoted += "\\n";
    } else if (c == '\r') {
      quoted += "\\r";
    } else if (c == '\t') {
      quoted += "\\t";
    } else if (code < 0x20 || code == 0x7f) {
      char escape[5];
      std::snprintf(escape, sizeof(escape), "\\x%02x", code);
      quoted += escape;
    } else {
      quoted += c;
    }
  }
  return quoted;
}

std::string FormatVector(const Vec3& value) {
  return "[" + FormatNumber(value.x()) + ", " + FormatNumber(value.y()) + ", " + FormatNumber(value.z()) + "]";
}

std::string JoinNames(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

int EditDistance(const std::string& a, const std::string& b) {
  const size_t n = a.size();
  const size_t m = b.size();
  // d[i][j]: distance between the first i characters of a and the first j of b
  std::vector<std::vector<int>> d(n + 1, std::vector<int>(m + 1, 0));
  for (size_t i = 0; i <= n; ++i) d[i][0] = static_cast<int>(i);
  for (size_t j = 0; j <= m; ++j) d[0][j] = static_cast<int>(j);
  for (size_t i = 1; i <= n; ++i) {
    for (size_t j = 1; j <= m; ++j) {
      const int cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
      }
    }
  }
  return d[n][m];
}

std::string ClosestName(const std::string& word, const std::vector<std::string>& candidates) {
  const int max_distance = std::max<int>(1, (static_cast<int>(word.size()) + 2) / 3);
  std::string best;
  int best_distance = max_distance + 1;
  for (const std::string& candidate : candidates) {
    const int distance = EditDistance(word, candidate);
    if (distance < best_distance) {
      best = candidate;
      best_distance = distance;
    }
  }
  return best;
}

std::string SuggestName(const std::string& word, const std::vector<std::string>& candidates, const std::string& what) {
  const std::string closest = ClosestName(word, candidates);
  if (!closest.empty()) return "did you mean '" + closest + "'?";
  return what + " are: " + (candidates.empty() ? std::string("(none)") : JoinNames(candidates));
}

std::string NotFoundMessage(const std::string& kind, const std::string& kinds, const std::string& name,
                            const std::string& where, const std::vector<std::string>& candidates) {
  const std::string closest = ClosestName(name, candidates);
  return "no " + kind + " '" + QuoteForMessage(name) + "' in " + where + "; " + kinds +
         " are: " + (candidates.empty() ? std::string("(none)") : JoinNames(candidates)) +
         (closest.empty() ? "" : "; did you mean '" + closest + "'?");
}

}  // namespace io
}  // namespace flexmbd
