// What is not a config file is refused (src/io/yaml_document.cpp, src/io/text_file.cpp): a second YAML
// document, an explicit tag, a directory or a device. Reference: docs/config.md "Errors"; each message names
// the file, the field or line, and the expected form.

#include <gtest/gtest.h>

#include <fstream>

#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/io/yaml_document.hpp"
#include "io_test_util.hpp"

namespace flexmbd {
namespace yaml_document_test {
using test::DataPath;

// Writes a YAML file for one test and returns its path.
std::string WriteYaml(const std::string& name, const std::string& text) {
  const std::string path = testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

TEST(YamlDocument, SecondDocumentIsRejected) {
  EXPECT_CONFIG_ERROR(io::ParseYamlDocument("solver: {t_end: 2.0}\n---\noutput: {rate_hz: 5}\n", "case.yaml"),
                      "case.yaml: line 2: a second YAML document; expected one document");
}

TEST(YamlDocument, EmptySecondDocumentIsRejected) {
  EXPECT_CONFIG_ERROR(io::ParseYamlDocument("solver: {t_end: 2.0}\n---\n", "case.yaml"),
                      "case.yaml: line 2: a second YAML document");
}

// yaml-cpp reads a key less indented than the first as the start of another document, without a marker.
TEST(YamlDocument, IndentedFirstKeyIsSaidToBeOne) {
  EXPECT_CONFIG_ERROR(io::ParseYamlDocument("  joints: {B1: {spring: {k: 1}}}\nsolver: {t_end: 2.0}\n", "case.yaml"),
                      "case.yaml: line 2: a key less indented than the first key of the file, which ends the "
                      "document there; expected every top-level key to start in the same column");
}

TEST(YamlDocument, DocumentEndMarkerAloneIsOneDocument) {
  const YAML::Node node = io::ParseYamlDocument("---\nsolver: {t_end: 2.0}\n...\n", "case.yaml");
  EXPECT_EQ(node["solver"]["t_end"].as<double>(), 2.0);
}

TEST(YamlDocument, UnknownTagNamesFieldAndLine) {
  EXPECT_CONFIG_ERROR(io::ParseYamlDocument("solver:\n  t_end: !seconds 2.0\n", "case.yaml"),
                      "case.yaml: solver.t_end: line 2, column 10: YAML tag '!seconds' is not accepted; expected a "
                      "value without a tag");
}

TEST(YamlDocument, StandardTagIsShownAsWritten) {
  EXPECT_CONFIG_ERROR(io::ParseYamlDocument("loads:\n  - {body: rod, force: !!seq [1, 2, 3]}\n", "case.yaml"),
                      "case.yaml: loads[0].force: line 2, column 24: YAML tag '!!seq' is not accepted");
}

TEST(YamlDocument, TagOnAMapNamesItsKey) {
  EXPECT_CONFIG_ERROR(io::ParseYamlDocument("joints:\n  B1: !!map {spring: {k: 1}}\n", "case.yaml"),
                      "case.yaml: joints.B1: line 2, column 7: YAML tag '!!map'");
}

TEST(YamlDocument, QuotedAndPlainValuesAreAccepted) {
  const YAML::Node node =
      io::ParseYamlDocument("output: {csv: \"run.csv\", bag: 'run.bag', rate_hz: 10}\n", "case.yaml");
  EXPECT_EQ(node["output"]["csv"].as<std::string>(), "run.csv");
}

TEST(YamlDocument, AliasesAreAcceptedWithoutTags) {
  const YAML::Node node = io::ParseYamlDocument("a: &k {c: 1.0}\nb: *k\n", "case.yaml");
  EXPECT_EQ(node["b"]["c"].as<double>(), 1.0);
}

TEST(YamlDocument, SyntaxErrorInASecondDocumentIsReported) {
  EXPECT_CONFIG_ERROR(io::ParseYamlDocument("solver: {t_end: 2.0}\n---\noutput: {rate_hz: 5\n", "case.yaml"),
                      "case.yaml: line 4, column 1: not valid YAML");
}

TEST(YamlDocument, MultiDocumentFileIsRejectedByTheLoader) {
  const std::string yaml = WriteYaml("two_documents.yaml", "solver: {t_end: 2.0}\n---\nsolver: {t_end: 3.0}\n");
  EXPECT_CONFIG_ERROR(LoadModelSpec(DataPath("urdf/pendulum.urdf"), yaml),
                      "two_documents.yaml: line 2: a second YAML document");
}

TEST(YamlDocument, DirectoryAsConfigIsRejected) {
  const std::string directory = DataPath("yaml");
  EXPECT_CONFIG_ERROR(LoadModelSpec(DataPath("urdf/pendulum.urdf"), directory),
                      "cannot read YAML file '" + directory + "': it is a directory; expected a text file");
}

TEST(YamlDocument, DeviceAsUrdfIsRejected) {
  EXPECT_CONFIG_ERROR(LoadModelSpec("/dev/zero", ""),
                      "cannot read URDF file '/dev/zero': it is a device; expected a text file");
}

}  // namespace yaml_document_test
}  // namespace flexmbd
