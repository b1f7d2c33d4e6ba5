#include "flexmbd/io/yaml_document.hpp"

#include <yaml-cpp/eventhandler.h>

#include <limits>
#include <sstream>
#include <vector>

#include "flexmbd/common/error.hpp"
#include "flexmbd/io/message_text.hpp"

namespace flexmbd {
namespace io {
namespace {

std::string LineColumn(const YAML::Mark& mark) {
  return "line " + std::to_string(mark.line + 1) + ", column " + std::to_string(mark.column + 1);
}

// Walks the parser's events of one document (aliases are events, never expanded, so an alias bomb costs
// nothing), keeping the field path of each node as the loader names it ("joints.B1.spring.k", "loads[0]"),
// and rejects explicit tags. yaml-cpp reports an untagged node as "?" (plain) or "!" (quoted).
class TagCheck : public YAML::EventHandler {
 public:
  explicit TagCheck(std::string file) : file_(std::move(file)) {}

  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override { NodePath(nullptr); }
  void OnAlias(const YAML::Mark&, YAML::anchor_t) override { NodePath(nullptr); }
  void OnScalar(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t, const std::string& value) override {
    Check(mark, tag, NodePath(&value));
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t,
                       YAML::EmitterStyle::value) override {
    Open(mark, tag, false);
  }
  void OnSequenceEnd() override { levels_.pop_back(); }
  void OnMapStart(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t, YAML::EmitterStyle::value) override {
    Open(mark, tag, true);
  }
  void OnMapEnd() override { levels_.pop_back(); }

 private:
  // An open map or list: its path, and where the next node in it goes.
  struct Level {
    bool map = false;
    std::string path;
    size_t next_index = 0;    // list: index of the next entry
    bool next_is_key = true;  // map: the next node is a key (else the value of `key`)
    std::string key;
  };

  void Open(const YAML::Mark& mark, const std::string& tag, bool map) {
    const std::string path = NodePath(nullptr);
    Check(mark, tag, path);
    Level level;
    level.map = map;
    level.path = path;
    levels_.push_back(level);
  }

  // The path of the node that starts now; `scalar` is its text if it is a scalar (a map key names the value
  // that follows it).
  std::string NodePath(const std::string* scalar) {
    if (levels_.empty()) return "";
    Level& level = levels_.back();
    if (!level.map) return level.path + "[" + std::to_string(level.next_index++) + "]";
    const std::string prefix = level.path.empty() ? "" : level.path + ".";
    if (level.next_is_key) {
      level.next_is_key = false;
      level.key = scalar ? QuoteForMessage(*scalar) : "(a key that is not text)";
      return prefix + level.key;
    }
    level.next_is_key = true;
    return prefix + level.key;
  }

  void Check(const YAML::Mark& mark, const std::string& tag, const std::string& path) const {
    if (tag.empty() || tag == "?" || tag == "!") return;
    throw ConfigError(file_ + ": " + (path.empty() ? "" : path + ": ") + LineColumn(mark) + ": YAML tag '" +
                      QuoteForMessage(AsWritten(tag)) + "' is not accepted; expected a value without a tag " +
                      "(the schema gives each field its type, docs/config.md)");
  }

  // yaml-cpp expands the standard tags ("!!str" reads "tag:yaml.org,2002:str"): show them as written
  static std::string AsWritten(const std::string& tag) {
    const std::string kStandardPrefix = "tag:yaml.org,2002:";
    return tag.rfind(kStandardPrefix, 0) == 0 ? "!!" + tag.substr(kStandardPrefix.size()) : tag;
  }

  std::string file_;
  std::vector<Level> levels_;
};

// Notes where a document starts, to name the line of a second one.
class DocumentStart : public YAML::EventHandler {
 public:
  void OnDocumentStart(const YAML::Mark& mark) override { mark_ = mark; }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
  void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
  void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t, const std::string&) override {}
  void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {}
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {}
  void OnMapEnd() override {}
  const YAML::Mark& mark() const { return mark_; }

 private:
  YAML::Mark mark_;
};

std::string LineAt(const std::string& text, int line) {
  std::istringstream lines(text);
  for (int i = 0; i < line; ++i) lines.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
  std::string current;
  std::getline(lines, current);
  return current;
}

// A document marker ('---') or a directive ('%YAML') at the start of a line.
bool StartsWithMarker(const std::string& line) { return line.rfind("---", 0) == 0 || line.rfind('%', 0) == 0; }

void CheckOneUntaggedDocument(const std::string& text, const std::string& name) {
  std::istringstream stream(text);
  YAML::Parser parser(stream);
  TagCheck tags(name);
  parser.HandleNextDocument(tags);
  DocumentStart second;
  if (!parser.HandleNextDocument(second)) return;
  const std::string where = name + ": line " + std::to_string(second.mark().line + 1);
  // yaml-cpp also starts a document, without a marker, at a key less indented than the first key of the file.
  if (!StartsWithMarker(LineAt(text, second.mark().line))) {
    throw ConfigError(where + ": a key less indented than the first key of the file, which ends the document "
                              "there; expected every top-level key to start in the same column (is the first "
                              "key indented?)");
  }
  throw ConfigError(where + ": a second YAML document; expected one document (remove the '---' separator and what "
                            "follows, or merge the documents)");
}

}  // namespace

YAML::Node ParseYamlDocument(const std::string& text, const std::string& name) {
  try {
    CheckOneUntaggedDocument(text, name);
    return YAML::Load(text);
  } catch (const YAML::ParserException& error) {
    throw ConfigError(name + ": " + LineColumn(error.mark) + ": not valid YAML (" + error.msg + ")");
  }
}

}  // namespace io
}  // namespace flexmbd
