#include "flexmbd/elements/element_workspace.hpp"

#include "flexmbd/elements/element.hpp"

namespace flexmbd {

ElementWorkspaces::ElementWorkspaces(const std::vector<std::unique_ptr<Element>>& elements) {
  workspaces_.resize(elements.size());
  for (const auto& element : elements) workspaces_[element->index()] = element->MakeWorkspace();
}

}  // namespace flexmbd
