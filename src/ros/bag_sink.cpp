#include "flexmbd/ros/bag_sink.hpp"

#include <rosbag/exceptions.h>

#include <boost/make_shared.hpp>

#include <cerrno>
#include <cstring>
#include <mutex>
#include <vector>

#include "flexmbd/common/error.hpp"

namespace flexmbd {
namespace ros {
namespace {

// rosbag::Bag's destructor closes the bag, which writes its index: after a failed write that fails as well,
// and an exception leaving a destructor terminates the process. A bag that failed is kept instead, never
// destroyed; the process ends soon after (the run has failed), and its end closes the file.
void KeepUndestroyed(std::unique_ptr<rosbag::Bag> bag) {
  static std::mutex mutex;
  static auto* const kept = new std::vector<std::unique_ptr<rosbag::Bag>>();
  std::lock_guard<std::mutex> lock(mutex);
  kept->push_back(std::move(bag));
}

}  // namespace

std::optional<BagCompression> ParseBagCompression(const std::string& text) {
  if (text == "none") return BagCompression::kNone;
  if (text == "lz4") return BagCompression::kLz4;
  return std::nullopt;
}

::ros::Time BagTime(const ::ros::Time& stamp) { return std::max(stamp, ::ros::TIME_MIN); }

template <typename Operation>
void BagSink::Checked(const char* action, Operation operation) {
  errno = 0;  // rosbag's messages do not say why a write failed; errno does
  try {
    operation();
  } catch (const rosbag::BagException& error) {
    Abandon(action, error, errno);
  }
}

BagSink::BagSink(const std::string& path, BagCompression compression, const TopicNames& topics,
                 const visualization_msgs::MarkerArray& markers, const tf2_msgs::TFMessage& static_transforms)
    : path_(path), bag_(std::make_unique<rosbag::Bag>()), topics_(topics) {
  errno = 0;
  try {
    bag_->open(path, rosbag::bagmode::Write);
  } catch (const rosbag::BagException& error) {
    // open also writes the bag's first bytes: a file opened that cannot take them (/dev/full) is an output
    // failure, not a bad path
    if (bag_->isOpen()) Abandon("writing", error, errno);
    throw ConfigError("cannot open bag '" + path + "' for writing (" + error.what() +
                      "); expected a writable file path");
  }
  bag_->setCompression(compression == BagCompression::kLz4 ? rosbag::compression::LZ4
                                                           : rosbag::compression::Uncompressed);
  Checked("writing", [&] { bag_->write(topics_.markers, ::ros::TIME_MIN, markers); });
  if (!static_transforms.transforms.empty()) {
    // a connection header given to rosbag replaces the one it makes: it names the type itself
    const auto latched = boost::make_shared<::ros::M_string>(::ros::M_string{
        {"type", ::ros::message_traits::DataType<tf2_msgs::TFMessage>::value()},
        {"md5sum", ::ros::message_traits::MD5Sum<tf2_msgs::TFMessage>::value()},
        {"message_definition", ::ros::message_traits::Definition<tf2_msgs::TFMessage>::value()},
        {"latching", "1"}});
    Checked("writing", [&] { bag_->write(topics_.tf_static, ::ros::TIME_MIN, static_transforms, latched); });
  }
}

BagSink::~BagSink() {
  try {
    Close();
  } catch (const OutputError&) {
    // the bag is still open here only while another exception unwinds, and that one is reported
  }
}

void BagSink::Write(const SampleMessages& messages) {
  FLEXMBD_DEMAND(bag_ != nullptr);  // SampleFanOut drops a recording once it failed or was closed
  Checked("writing", [&] { WriteSample(messages); });
  ++samples_;
}

void BagSink::Close() {
  if (!bag_) return;
  Checked("closing", [&] { bag_->close(); });
  bag_.reset();
}

void BagSink::WriteSample(const SampleMessages& messages) {
  const ::ros::Time time = BagTime(messages.joint_state.header.stamp);
  bag_->write(topics_.joint_states, time, messages.joint_state);
  bag_->write(topics_.energy, time, messages.energy);
  bag_->write(topics_.reactions, time, messages.reactions);
  bag_->write(topics_.solver, time, messages.solver);
  if (!messages.contacts.contacts.empty()) bag_->write(topics_.contacts, time, messages.contacts);
  if (!messages.friction.joints.empty()) bag_->write(topics_.friction, time, messages.friction);
  if (!messages.beam_loads.stations.empty()) bag_->write(topics_.beam_loads, time, messages.beam_loads);
  const AeroLoadsArray& aero = messages.aero_loads;
  if (!aero.sections.empty() || !aero.strip_stations.empty() || !aero.rotors.empty()) {
    bag_->write(topics_.aero_loads, time, aero);
  }
  if (messages.has_transforms && !messages.transforms.transforms.empty()) {
    bag_->write(topics_.tf, BagTime(messages.transforms.transforms.front().header.stamp), messages.transforms);
  }
}

void BagSink::Abandon(const std::string& action, const std::exception& error, int system_error) {
  KeepUndestroyed(std::move(bag_));
  std::string why = error.what();
  if (system_error != 0) why += ": " + std::string(std::strerror(system_error));
  const std::string holds = samples_ == 0 ? "the bag holds no sample"
                                          : "the bag is not indexed: 'rosbag reindex " + path_ +
                                                "' recovers the samples in its complete chunks";
  throw OutputError("bag '" + path_ + "': " + action + " failed after " + std::to_string(samples_) + " samples (" +
                    why + "); " + holds);
}

}  // namespace ros
}  // namespace flexmbd
