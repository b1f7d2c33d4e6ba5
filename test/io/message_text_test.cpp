// Text helpers of the loader's messages (src/io/message_text.cpp).

#include "flexmbd/io/message_text.hpp"

#include <gtest/gtest.h>

namespace flexmbd {
namespace io {
namespace message_text_test {

TEST(MessageText, EditDistanceCountsEditsAndTranspositions) {
  EXPECT_EQ(EditDistance("dt", "dt"), 0);
  EXPECT_EQ(EditDistance("dtt", "dt"), 1);     // one deletion
  EXPECT_EQ(EditDistance("tpye", "type"), 1);  // one transposition
  EXPECT_EQ(EditDistance("kitten", "sitting"), 3);
}

TEST(MessageText, ClosestNameSuggestsOnlyLikelyTypos) {
  const std::vector<std::string> keys = {"dt", "dt_min", "dt_max", "t_end"};
  EXPECT_EQ(ClosestName("dtt", keys), "dt");
  EXPECT_EQ(ClosestName("dt_mx", keys), "dt_max");
  EXPECT_EQ(ClosestName("sinus", {"sine", "table"}), "sine");
  EXPECT_EQ(ClosestName("gravity", keys), "");
}

TEST(MessageText, FormatNumberIsShortestExactText) {
  EXPECT_EQ(FormatNumber(-3.0), "-3");
  EXPECT_EQ(FormatNumber(0.1), "0.1");
  EXPECT_EQ(FormatNumber(1.0e-7), "1e-07");
  EXPECT_EQ(FormatNumber(1.0 / 3.0), "0.3333333333333333");
}

TEST(MessageText, NotFoundMessageListsCandidates) {
  EXPECT_EQ(NotFoundMessage("joint", "joints", "elbw", "arm.urdf", {"shoulder", "elbow"}),
            "no joint 'elbw' in arm.urdf; joints are: shoulder, elbow; did you mean 'elbow'?");
  EXPECT_EQ(NotFoundMessage("body", "bodies", "x", "arm.urdf", {"upper_arm"}),
            "no body 'x' in arm.urdf; bodies are: upper_arm");
}

}  // namespace message_text_test
}  // namespace io
}  // namespace flexmbd
