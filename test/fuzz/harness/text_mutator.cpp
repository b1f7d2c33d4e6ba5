#include "text_mutator.hpp"

#include <vector>

namespace flexmbd {
namespace fuzz {
namespace {

// Offsets at which a line starts.
std::vector<size_t> LineStarts(const std::string& text) {
  std::vector<size_t> starts = {0};
  for (size_t k = 0; k + 1 < text.size(); ++k) {
    if (text[k] == '\n') starts.push_back(k + 1);
  }
  return starts;
}

}  // namespace

void MutateText(std::string* text, bool yaml, Rng* rng) {
  const std::vector<size_t> starts = LineStarts(*text);
  const size_t line = starts[Pick(rng, starts.size())];
  switch (Pick(rng, yaml ? 4 : 2)) {
    case 0:
      text->resize(Pick(rng, text->size() + 1));
      return;
    case 1: {
      const size_t end = text->find('\n', line);
      text->erase(line, end == std::string::npos ? std::string::npos : end - line + 1);
      return;
    }
    case 2:
      *text += "---\nsolver: {t_end: 1.0}\n";
      return;
    default: {
      // after the first ": " of the line, so the tag lands on a value
      const size_t colon = text->find(": ", line);
      if (colon != std::string::npos) text->insert(colon + 2, Chance(rng, 0.5) ? "!!str " : "!custom ");
      return;
    }
  }
}

}  // namespace fuzz
}  // namespace flexmbd
