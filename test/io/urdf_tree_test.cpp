// URDF structure checked at load (src/io/urdf_tree.cpp): one parent joint per link, every link reached from
// the root, names that can head CSV columns, and chains of any depth loaded without recursion. Reference:
// the URDF specification (a tree of links) and docs/config.md "URDF mapping".

#include <gtest/gtest.h>

#include <pthread.h>
#include <urdf_model/model.h>

#include <chrono>
#include <cstdio>
#include <functional>

#include "flexmbd/io/urdf_tree.hpp"
#include "io_test_util.hpp"

namespace flexmbd {
namespace urdf_tree_test {
using test::LoadInline;
using test::WorldUrdf;

std::string Hinge(const std::string& name, const std::string& parent, const std::string& child) {
  return "<joint name=\"" + name + "\" type=\"continuous\"><parent link=\"" + parent + "\"/><child link=\"" + child +
         "\"/><axis xyz=\"0 1 0\"/></joint>";
}

// A chain of `n` hinged links l0 .. l<n-1> hanging 0.1 m apart below the world.
std::string ChainUrdf(int n) {
  std::vector<std::string> links;
  std::string joints;
  std::string parent = "world";
  for (int k = 0; k < n; ++k) {
    const std::string link = "l" + std::to_string(k);
    links.push_back(link);
    joints += "<joint name=\"j" + std::to_string(k) + "\" type=\"continuous\"><parent link=\"" + parent +
              "\"/><child link=\"" + link + "\"/><origin xyz=\"0 0 -0.1\"/><axis xyz=\"0 1 0\"/></joint>";
    parent = link;
  }
  return WorldUrdf(links, joints);
}

TEST(UrdfTree, LinkWithTwoParentJointsIsRejected) {
  const std::string urdf = WorldUrdf({"a", "b"}, Hinge("j1", "world", "a") + Hinge("j2", "world", "b") +
                                                     Hinge("j3", "a", "b"));
  EXPECT_CONFIG_ERROR(LoadInline(urdf, ""),
                      "test.urdf: link 'b' is the child of joints 'j2' and 'j3'; expected one parent joint per link");
}

TEST(UrdfTree, CycleApartFromTheRootIsRejected) {
  const std::string urdf = WorldUrdf({"a", "b", "c"}, Hinge("j1", "world", "a") + Hinge("j2", "b", "c") +
                                                          Hinge("j3", "c", "b"));
  EXPECT_CONFIG_ERROR(LoadInline(urdf, ""),
                      "test.urdf: joints 'j2', 'j3' form a cycle (links b -> c -> b), which the root link 'world' "
                      "does not reach; expected a tree");
}

TEST(UrdfTree, LinksHangingBelowACycleNameTheCycle) {
  const std::string urdf = WorldUrdf({"a", "b", "c", "d"}, Hinge("j1", "world", "a") + Hinge("j2", "b", "c") +
                                                               Hinge("j3", "c", "b") + Hinge("j4", "c", "d"));
  EXPECT_CONFIG_ERROR(LoadInline(urdf, ""), "test.urdf: joints 'j2', 'j3' form a cycle");
}

TEST(UrdfTree, JointFromALinkToItselfIsACycle) {
  const std::string urdf = WorldUrdf({"a", "b"}, Hinge("j1", "world", "a") + Hinge("loop", "b", "b"));
  EXPECT_CONFIG_ERROR(LoadInline(urdf, ""), "test.urdf: joints 'loop' form a cycle (links b -> b)");
}

TEST(UrdfTree, CommaInALinkNameIsRejected) {
  const std::string urdf = WorldUrdf({"arm,left"}, Hinge("j1", "world", "arm,left"));
  EXPECT_CONFIG_ERROR(LoadInline(urdf, ""),
                      "test.urdf: link 'arm,left': the name contains a comma; expected a name without commas, double "
                      "quotes or control characters");
}

TEST(UrdfTree, QuoteInAJointNameIsRejected) {
  const std::string urdf = WorldUrdf({"a"}, Hinge("j&quot;1", "world", "a"));
  EXPECT_CONFIG_ERROR(LoadInline(urdf, ""), "test.urdf: joint 'j\"1': the name contains a double quote");
}

TEST(UrdfTree, NewlineInANameIsRejectedOnOneLine) {
  const std::string urdf = WorldUrdf({"a"}, Hinge("j&#10;1", "world", "a"));
  const std::string message = test::ConfigErrorOf([&]() { LoadInline(urdf, ""); });
  EXPECT_NE(message.find("test.urdf: joint 'j\\n1': the name contains a control character"), std::string::npos)
      << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

// The tree is walked depth first with each link's joints in URDF order, as before the walk was iterative:
// the joint order fixes the CSV columns.
TEST(UrdfTree, JointsListedDepthFirstInUrdfOrder) {
  const std::string urdf = WorldUrdf({"a", "b", "c", "d"}, Hinge("ja", "world", "a") + Hinge("jb", "a", "b") +
                                                               Hinge("jc", "world", "c") + Hinge("jd", "a", "d"));
  std::vector<std::string> order;
  for (const JointSpec& joint : LoadInline(urdf, "").joints) order.push_back(joint.name);
  // urdfdom keeps a link's child joints in name order (a std::map): ja, jc under world; jb, jd under a
  EXPECT_EQ(order, std::vector<std::string>({"ja", "jb", "jd", "jc"}));
}

// Runs `work` on a thread with a stack of `bytes`, and waits for it.
void RunOnStack(size_t bytes, const std::function<void()>& work) {
  pthread_attr_t attributes;
  pthread_attr_init(&attributes);
  pthread_attr_setstacksize(&attributes, bytes);
  pthread_t thread;
  auto run = [](void* argument) -> void* {
    (*static_cast<const std::function<void()>*>(argument))();
    return nullptr;
  };
  ASSERT_EQ(pthread_create(&thread, &attributes, run, const_cast<std::function<void()>*>(&work)), 0);
  pthread_join(thread, nullptr);
  pthread_attr_destroy(&attributes);
}

// 50,000 links loaded on a 1 MiB stack: the recursive walks (tree, placement) took a stack frame per link
// and overflowed it. Loading must stay linear; the time bound leaves a wide margin over the about 2.5 s
// this takes on one core.
TEST(UrdfTree, DeepChainLoadsWithoutRecursion) {
  constexpr int kLinks = 50000;
  constexpr size_t kStackBytes = 1 << 20;
  constexpr double kMaxLoadSeconds = 60.0;
  const std::string urdf = ChainUrdf(kLinks);
  ModelSpec spec;
  double seconds = 0.0;
  RunOnStack(kStackBytes, [&]() {
    const auto start = std::chrono::steady_clock::now();
    spec = LoadInline(urdf, "");
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  });
  ASSERT_EQ(spec.joints.size(), static_cast<size_t>(kLinks));
  EXPECT_EQ(spec.joints.back().parent, "l" + std::to_string(kLinks - 2));
  // each joint origin is 0.1 m below its parent's: the last link sits kLinks x 0.1 m below the world
  EXPECT_NEAR(spec.bodies.back().p_WB.z(), -0.1 * kLinks, 1.0e-6 * kLinks);
  EXPECT_LT(seconds, kMaxLoadSeconds);
}

// urdfdom links own their children: destroying a 200,000-link chain recursed once per link and overflowed
// the stack (measured with urdfdom 3.0.1).
TEST(UrdfTree, OwnerDestroysADeepChainWithoutRecursion) {
  constexpr int kLinks = 200000;
  auto urdf = std::make_shared<urdf::ModelInterface>();
  urdf::LinkSharedPtr parent;
  for (int k = 0; k < kLinks; ++k) {
    auto link = std::make_shared<urdf::Link>();
    char name[16];
    std::snprintf(name, sizeof(name), "l%06d", k);  // the root first in the links' map
    link->name = name;
    if (parent) parent->child_links.push_back(link);
    urdf->links_[link->name] = link;
    parent = link;
  }
  parent.reset();
  { const io::UrdfTreeOwner owner(std::move(urdf)); }
  SUCCEED();  // reaching here is the test: the recursive destruction crashes the process
}

}  // namespace urdf_tree_test
}  // namespace flexmbd
