#pragma once
/// @file
/// Where elements keep what they may recompute at any time (DESIGN.md, "Model / State / Workspace"): caches of
/// quantities of one configuration, which an element checks against the configuration it is asked about. The
/// frozen Model holds none; an element's own state, which fixes the future, belongs to the State
/// (State::element_history, element_states). One workspace per element, made by the element, owned by whoever
/// builds the contexts it is evaluated in (StepContextBuilder), reached through StepContext::workspaces.

#include <memory>
#include <vector>

namespace flexmbd {

class Element;

/// Base of an element's workspace.
class ElementWorkspace {
 public:
  virtual ~ElementWorkspace() = default;
};

/// The workspaces of a model's elements, by Element::index() (null where an element keeps none).
class ElementWorkspaces {
 public:
  explicit ElementWorkspaces(const std::vector<std::unique_ptr<Element>>& elements);

  ElementWorkspace* of(int element_index) const { return workspaces_[element_index].get(); }

 private:
  std::vector<std::unique_ptr<ElementWorkspace>> workspaces_;
};

}  // namespace flexmbd
