#!/usr/bin/python3
"""roslaunch CASE record:=BAG in a namespace, on the rostest's master (record_launch.test).

The node waits for the recorder to subscribe to every sample topic before its first sample. The recorder's
topic list used to lack ~contacts and to name the topics absolutely, so the pendulum on its stops, or any case
launched under a namespace, waited for ever and said nothing.
"""

import os
import subprocess
import tempfile
import unittest

import rosbag
import rospy
import rostest

# The pendulum's 3 s at real_time_factor 0 take well under a second; the bound leaves room for roslaunch, the
# recorder's start and a loaded machine. Before the fix this run never ended.
RUN_TIMEOUT = 90.0
NAMESPACE = '/included'


class RecordLaunch(unittest.TestCase):
    def test_record_in_a_namespace_finishes_with_the_case_topics(self):
        bag_path = os.path.join(tempfile.mkdtemp(), 'pendulum_stop.bag')
        env = dict(os.environ, ROS_NAMESPACE=NAMESPACE)
        done = subprocess.run(('roslaunch', 'flexmbd', 'pendulum_stop.launch', 'real_time_factor:=0',
                               'record:=' + bag_path),
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=RUN_TIMEOUT,
                              env=env)
        output = done.stdout
        self.assertEqual(done.returncode, 0, output)
        self.assertTrue('process has finished cleanly' in output, output)
        with rosbag.Bag(bag_path) as bag:
            topics = bag.get_type_and_topic_info().topics
        # rosbag record keeps the names as given, relative to the recorder's namespace (the launch's).
        for topic in ('joint_states', 'flexmbd/energy', 'flexmbd/contacts'):
            self.assertIn(topic, topics)
            self.assertGreater(topics[topic].message_count, 0, topic)


if __name__ == '__main__':
    rospy.init_node('record_launch')
    rostest.rosrun('flexmbd', 'record_launch', RecordLaunch)
