#pragma once
// The Goland wing's URDF (config/goland_wing) and a two-element beam on its wing link, for inline YAML documents
// of the aero readers' tests.

#include <fstream>
#include <iterator>
#include <string>

namespace flexmbd {
namespace test {

inline std::string GolandUrdf() {
  std::ifstream in(std::string(FLEXMBD_SOURCE_DIR) + "/config/goland_wing/goland_wing.urdf");
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

const std::string kGolandBeam =
    "beams: {wing: {length: 6.0, elements: 2, section: {EA: 1.0e9, GA2: 1.0e9, GA3: 1.0e9, GJ: 1.0e6, EI2: 1.0e7, "
    "EI3: 1.0e8, m: 35.0, m_ii: [8.0, 0.1, 8.0]}}}\n";

}  // namespace test
}  // namespace flexmbd
