#pragma once
/// @file
/// A topic whose messages wake roscpp's sending thread once per batch instead of once per message.
/// ros::Publisher::publish puts the serialised message on the publication's queue and then wakes roscpp's
/// poll thread through a pipe: a write on the publishing thread and a one-byte read on the poll thread, two
/// system calls per message that cost more than serialising and sending a small message (about 1 us each
/// on a VM; bench/node/README.md). QueuedTopic::Queue does the first half, and WakeTopicSender() the second,
/// once for all that was queued since. What goes on the wire is what publish() sends: roscpp numbers
/// header.seq per message, with or without subscribers, in both paths.

#include <ros/publication.h>
#include <ros/ros.h>
#include <ros/serialization.h>

#include <string>

namespace flexmbd {
namespace ros {

class QueuedTopic {
 public:
  /// Not advertised: Queue does nothing.
  QueuedTopic() = default;

  /// Advertises `topic` (not latched) on `handle`; `on_connect` as in NodeHandle::advertise.
  template <typename Message>
  static QueuedTopic Advertise(::ros::NodeHandle& handle, const std::string& topic, uint32_t queue_size,
                               const ::ros::SubscriberStatusCallback& on_connect = {}) {
    return QueuedTopic(handle.advertise<Message>(topic, queue_size, on_connect));
  }

  /// Queues `message` for every subscriber, to be sent once the sender is woken (WakeTopicSender); returns
  /// whether there was a subscriber to queue it for.
  template <typename Message>
  bool Queue(const Message& message) const {
    if (!publication_ || publication_->isDropped()) return false;
    if (!publication_->hasSubscribers()) {
      publication_->incrementSequence();  // as publish() does: the next subscriber sees the sample's number
      return false;
    }
    ::ros::SerializedMessage serialized = ::ros::serialization::serializeMessage(message);
    publication_->publish(serialized);
    return true;
  }

  explicit operator bool() const { return static_cast<bool>(publication_); }
  uint32_t NumSubscribers() const { return publisher_.getNumSubscribers(); }
  /// The resolved topic name.
  std::string Name() const { return publisher_.getTopic(); }

 private:
  explicit QueuedTopic(::ros::Publisher publisher);

  ::ros::Publisher publisher_;         ///< keeps the topic advertised
  ::ros::PublicationPtr publication_;  ///< roscpp's side of it, whose queue the sender drains
};

/// Wakes roscpp's sending thread, which then sends every message queued on any topic (one system call).
void WakeTopicSender();

}  // namespace ros
}  // namespace flexmbd
