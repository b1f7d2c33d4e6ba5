#!/usr/bin/python3
"""rosbag record of the topics a flexmbd node publishes for its model (the launch files' record:=, docs/ros.md).

usage: record_node_topics.py BAG [NODE]   (NODE: the node's name in this one's namespace; default flexmbd)

The node writes the resolved names of its topics to ~recorded_topics once it has advertised them; this waits for
that list (at most WAIT_SECONDS) and then becomes `rosbag record -O BAG` of exactly those topics. A list typed into
each launch file drifted from what the node publishes (~beam_loads, ~aero_loads were missing), and the node,
waiting for a subscriber on every sample topic, never started.
"""

import os
import signal
import sys
import time

# roslaunch ends the recorder with SIGINT when the node ends, perhaps before the node listed its topics (a node that
# refused its input): quietly, even in the middle of the imports below. rosbag record, exec'd, has its own handler.
signal.signal(signal.SIGINT, lambda *_: os._exit(0))

import rosgraph  # noqa: E402 (after the handler)
import rosgraph.names  # noqa: E402
import roslib.packages  # noqa: E402
import rospy  # noqa: E402

# The node sets the list after loading and building its model (a second or two; large beams take longer on a
# loaded machine); a node that fails to load ends the launch first (required="true").
WAIT_SECONDS = 120.0
POLL_SECONDS = 0.1


def recorded_topics(master, parameter):
    deadline = time.monotonic() + WAIT_SECONDS
    while time.monotonic() < deadline:
        if master.hasParam(parameter):
            return master.getParam(parameter)
        time.sleep(POLL_SECONDS)
    return None


def node_parameter(master, namespace, node, name):
    parameter = rosgraph.names.ns_join(rosgraph.names.ns_join(namespace, node), name)
    return master.getParam(parameter) if master.hasParam(parameter) else None


def same_file(node_bag, recorded_bag):
    """rosbag record -O adds .bag to a name without it; the node writes the name as given."""
    recorded = recorded_bag if recorded_bag.endswith('.bag') else recorded_bag + '.bag'
    return os.path.realpath(node_bag) == os.path.realpath(recorded)


def main():
    arguments = rospy.myargv(sys.argv)[1:]
    if len(arguments) not in (1, 2):
        sys.exit(__doc__)
    bag = arguments[0]
    node = arguments[1] if len(arguments) == 2 else 'flexmbd'
    namespace = rosgraph.names.get_ros_namespace(argv=sys.argv)
    parameter = rosgraph.names.ns_join(rosgraph.names.ns_join(namespace, node), 'recorded_topics')
    master = rosgraph.Master(rosgraph.names.ns_join(namespace, 'record_node_topics'))
    node_bag = node_parameter(master, namespace, node, 'bag')
    if node_bag and same_file(node_bag, bag):
        print(f'record_node_topics.py: record:={bag} is the bag the node writes (bag:=); expected another file '
              '(the recorder would replace the node\'s bag)', file=sys.stderr)
        return 2
    topics = recorded_topics(master, parameter)
    if not topics:
        print(f'record_node_topics.py: {parameter} not set after {WAIT_SECONDS:g} s; expected the flexmbd node '
              f'{node} of this namespace to have started and listed its topics', file=sys.stderr)
        return 1
    record = roslib.packages.find_node('rosbag', 'record')[0]
    remappings = [argument for argument in sys.argv[1:] if ':=' in argument]  # __name:=, __log:= of roslaunch
    os.execv(record, [record, '-O', bag] + topics + remappings)


if __name__ == '__main__':
    sys.exit(main())
