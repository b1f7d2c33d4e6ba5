#pragma once
/// @file
/// Name of the frame the link transforms are given in.

#include <string>

#include "flexmbd/model/model.hpp"

namespace flexmbd {
namespace ros {

/// The URDF's root link when it is the ground (no body of `model`), so tf joins the frames of a URDF whose
/// root is e.g. "base_link"; otherwise (a free-floating root body) "world".
/// @pre `urdf_xml` is the URDF `model` was loaded from.
std::string WorldFrameName(const std::string& urdf_xml, const Model& model);

}  // namespace ros
}  // namespace flexmbd
