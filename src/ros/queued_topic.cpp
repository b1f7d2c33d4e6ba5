#include "flexmbd/ros/queued_topic.hpp"

#include <ros/poll_manager.h>
#include <ros/topic_manager.h>

#include <utility>

#include "flexmbd/common/error.hpp"

namespace flexmbd {
namespace ros {

QueuedTopic::QueuedTopic(::ros::Publisher publisher)
    : publisher_(std::move(publisher)),
      publication_(::ros::TopicManager::instance()->lookupPublication(publisher_.getTopic())) {
  FLEXMBD_DEMAND(publication_ && !publication_->isLatched());
}

void WakeTopicSender() { ::ros::PollManager::instance()->getPollSet().signal(); }

}  // namespace ros
}  // namespace flexmbd
