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
        # The names the node resolved in its namespace (~recorded_topics), as its own bag:= names them.
        for topic in (NAMESPACE + '/joint_states', NAMESPACE + '/flexmbd/energy', NAMESPACE + '/flexmbd/contacts'):
            self.assertIn(topic, topics)
            self.assertGreater(topics[topic].message_count, 0, topic)

    def test_record_onto_the_nodes_bag_is_refused(self):
        # Once the recorder's bag silently replaced the node's (explore23 ros/kill).
        bag_path = os.path.join(tempfile.mkdtemp(), 'same.bag')
        done = subprocess.run(('roslaunch', 'flexmbd', 'double_pendulum.launch', 'real_time_factor:=0',
                               'bag:=' + bag_path, 'record:=' + bag_path),
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=RUN_TIMEOUT)
        self.assertIn('record_node_topics.py: record:=' + bag_path + ' is the bag the node writes (bag:=); '
                      'expected another file', done.stdout)
        self.assertIn('REQUIRED process [record-', done.stdout)


if __name__ == '__main__':
    rospy.init_node('record_launch')
    rostest.rosrun('flexmbd', 'record_launch', RecordLaunch)
