#include "flexmbd/ros/node_settings.hpp"

#include <cmath>
#include <sstream>

#include "flexmbd/common/error.hpp"
#include "flexmbd/ros/clock_ticks.hpp"

namespace flexmbd {
namespace ros {
namespace {

using Value = XmlRpc::XmlRpcValue;

// Reads typed settings from the private namespace; a setting of the wrong type or range is a ConfigError
// naming the parameter, its value and the expected form.
class SettingReader {
 public:
  explicit SettingReader(const ::ros::NodeHandle& handle) : handle_(handle) {}

  std::optional<std::string> Text(const std::string& name, const std::string& expected) const {
    const std::optional<Value> value = Get(name);
    if (!value) return std::nullopt;
    if (value->getType() != Value::TypeString) Fail(name, *value, "is not text", expected);
    return static_cast<const std::string&>(*value);
  }

  std::optional<bool> Flag(const std::string& name, const std::string& expected) const {
    const std::optional<Value> value = Get(name);
    if (!value) return std::nullopt;
    if (value->getType() != Value::TypeBoolean) Fail(name, *value, "is not true or false", expected);
    return static_cast<const bool&>(*value);
  }

  /// A number >= 0 (an integer is accepted).
  std::optional<double> NonNegative(const std::string& name, const std::string& expected) const {
    const std::optional<Value> value = Get(name);
    if (!value) return std::nullopt;
    double number = 0.0;
    if (value->getType() == Value::TypeInt) {
      number = static_cast<const int&>(*value);
    } else if (value->getType() == Value::TypeDouble) {
      number = static_cast<const double&>(*value);
    } else {
      Fail(name, *value, "is not a number", expected);
    }
    if (!(number >= 0.0) || !std::isfinite(number)) Fail(name, *value, "is not a finite number >= 0", expected);
    return number;
  }

  std::optional<int> Count(const std::string& name, const std::string& expected) const {
    const std::optional<Value> value = Get(name);
    if (!value) return std::nullopt;
    if (value->getType() != Value::TypeInt) Fail(name, *value, "is not an integer", expected);
    const int count = static_cast<const int&>(*value);
    if (count < 0) Fail(name, *value, "is negative", expected);
    return count;
  }

  [[noreturn]] void Fail(const std::string& name, const Value& value, const std::string& problem,
                         const std::string& expected) const {
    std::ostringstream text;
    value.write(text);
    throw ConfigError(handle_.resolveName(name) + ": '" + text.str() + "' " + problem + "; expected " + expected);
  }

 private:
  std::optional<Value> Get(const std::string& name) const {
    Value value;
    if (!handle_.getParam(name, value)) return std::nullopt;
    return value;
  }

  const ::ros::NodeHandle& handle_;
};

}  // namespace

const std::vector<std::string>& NodeSettingNames() {
  static const std::vector<std::string> names{
      "urdf_file",  "real_time_factor",     "bag",          "bag_compression", "publish", "rate_hz",
      "keep_alive", "wait_for_subscribers", "wait_for_subscribers_timeout", "clock_rate_hz", "paused",
      "setpoint_time_constant"};
  return names;
}

NodeSettings ReadNodeSettings(const ::ros::NodeHandle& private_node) {
  const SettingReader read(private_node);
  NodeSettings settings;
  settings.urdf_file = read.Text("urdf_file", "a URDF file path").value_or("");
  settings.real_time_factor =
      read.NonNegative("real_time_factor", "a factor >= 0 (0 = as fast as possible, 1 = wall-clock pace)")
          .value_or(settings.real_time_factor);
  settings.bag = read.Text("bag", "a bag file path, or \"\" for none");
  const std::string compression_expected = "none or lz4";
  if (const std::optional<std::string> compression = read.Text("bag_compression", compression_expected)) {
    const std::optional<BagCompression> parsed = ParseBagCompression(*compression);
    if (!parsed) read.Fail("bag_compression", Value(*compression), "is not a compression", compression_expected);
    settings.bag_compression = *parsed;
  }
  settings.publish = read.Flag("publish", "true or false").value_or(settings.publish);
  settings.rate_hz = read.NonNegative("rate_hz", "a sample rate >= 0 [Hz] (0 = every accepted step)");
  settings.keep_alive = read.Flag("keep_alive", "true or false").value_or(settings.keep_alive);
  settings.paused = read.Flag("paused", "true or false").value_or(settings.paused);
  settings.wait_for_subscribers =
      read.Count("wait_for_subscribers", "a number of subscribers >= 0").value_or(settings.wait_for_subscribers);
  const std::string timeout_expected = "a time > 0 [s] (wall clock) to wait for ~wait_for_subscribers";
  if (const std::optional<double> timeout = read.NonNegative("wait_for_subscribers_timeout", timeout_expected)) {
    if (*timeout == 0.0) read.Fail("wait_for_subscribers_timeout", Value(*timeout), "is not > 0", timeout_expected);
    settings.wait_for_subscribers_timeout = *timeout;
  }
  const std::string clock_expected = "a rate in [0, " + std::to_string(static_cast<int>(kMaxClockRateHz)) +
                                     "] [Hz] of simulated time (0 = at every step and sample)";
  if (const std::optional<double> clock_rate = read.NonNegative("clock_rate_hz", clock_expected)) {
    if (*clock_rate > kMaxClockRateHz) read.Fail("clock_rate_hz", Value(*clock_rate), "is too high", clock_expected);
    settings.clock_rate_hz = *clock_rate;
  }
  const std::string lag_expected = "a time constant > 0 [s] (the lag of a drive behind ~position_command)";
  if (const std::optional<double> lag = read.NonNegative("setpoint_time_constant", lag_expected)) {
    if (*lag == 0.0) read.Fail("setpoint_time_constant", Value(*lag), "is not > 0", lag_expected);
    settings.setpoint_time_constant = *lag;
  }
  return settings;
}

}  // namespace ros
}  // namespace flexmbd
