#include "flexmbd/io/urdf_tree.hpp"

#include <map>
#include <set>
#include <vector>

#include "flexmbd/common/error.hpp"
#include "flexmbd/io/message_text.hpp"

namespace flexmbd {
namespace io {
std::string CsvNameProblem(const std::string& name) {
  for (const char c : name) {
    if (c == ',') return "a comma";
    if (c == '"') return "a double quote";
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) return "a control character (newline, tab, ...)";
  }
  return "";
}

namespace {

void CheckName(const std::string& kind, const std::string& name, const std::string& urdf_name) {
  const std::string problem = CsvNameProblem(name);
  if (problem.empty()) return;
  throw ConfigError(urdf_name + ": " + kind + " '" + QuoteForMessage(name) + "': the name contains " + problem +
                    "; expected a name without commas, double quotes or control characters (names head the CSV "
                    "columns)");
}

// The joints of a cycle reached by following parent joints up from `start`, which is not below the root:
// each link has one parent joint, so the walk up must close on itself.
std::vector<const urdf::Joint*> CycleAbove(const std::string& start,
                                          const std::map<std::string, const urdf::Joint*>& parent_joint) {
  std::set<std::string> seen;
  std::string link = start;
  while (seen.insert(link).second) link = parent_joint.at(link)->parent_link_name;
  // `link` is on the cycle: go round it once
  std::vector<const urdf::Joint*> cycle;
  const std::string first = link;
  do {
    cycle.insert(cycle.begin(), parent_joint.at(link));
    link = cycle.front()->parent_link_name;
  } while (link != first);
  return cycle;
}

[[noreturn]] void FailOnCycle(const std::vector<const urdf::Joint*>& cycle, const std::string& root,
                              const std::string& urdf_name) {
  std::string joints;
  std::string chain = cycle.front()->parent_link_name;
  for (const urdf::Joint* joint : cycle) {
    joints += (joints.empty() ? "'" : ", '") + joint->name + "'";
    chain += " -> " + joint->child_link_name;
  }
  throw ConfigError(urdf_name + ": joints " + joints + " form a cycle (links " + chain +
                    "), which the root link '" + root +
                    "' does not reach; expected a tree: one chain of joints from the root to every link");
}

}  // namespace

void CheckUrdfTree(const urdf::ModelInterface& urdf, const std::string& urdf_name) {
  for (const auto& entry : urdf.links_) CheckName("link", entry.first, urdf_name);
  for (const auto& entry : urdf.joints_) CheckName("joint", entry.first, urdf_name);

  // one parent joint per link (urdfdom keeps the last one it reads)
  std::map<std::string, const urdf::Joint*> parent_joint;
  for (const auto& [name, joint] : urdf.joints_) {
    const auto [known, added] = parent_joint.emplace(joint->child_link_name, joint.get());
    if (!added) {
      throw ConfigError(urdf_name + ": link '" + joint->child_link_name + "' is the child of joints '" +
                        known->second->name + "' and '" + name +
                        "'; expected one parent joint per link (a URDF is a tree)");
    }
  }

  // every link below the root
  const std::string& root = urdf.getRoot()->name;
  std::set<std::string> reached{root};
  std::vector<const urdf::Link*> to_visit{urdf.getRoot().get()};
  while (!to_visit.empty()) {
    const urdf::Link* link = to_visit.back();
    to_visit.pop_back();
    for (const urdf::JointSharedPtr& joint : link->child_joints) {
      if (reached.insert(joint->child_link_name).second) {
        to_visit.push_back(urdf.links_.at(joint->child_link_name).get());
      }
    }
  }
  for (const auto& entry : urdf.links_) {
    if (!reached.count(entry.first)) FailOnCycle(CycleAbove(entry.first, parent_joint), root, urdf_name);
  }
}

UrdfTreeOwner::~UrdfTreeOwner() {
  if (!urdf_) return;
  for (auto& entry : urdf_->links_) {
    entry.second->child_links.clear();
    entry.second->child_joints.clear();
  }
}

}  // namespace io
}  // namespace flexmbd
