#!/usr/bin/python3
"""roslaunch flexmbd CASE.launch record:=BAG t_end:=T for every launch file, on the rostest's master
(record_every_launch.test).

The recorder's topics were typed into each launch file and drifted from what the node publishes: wing_aileron
lacked ~beam_loads and rotor_engage ~aero_loads, and the node, waiting for a subscriber on every sample topic,
never sent a sample (explore23 ros/record_hang). The recorder now takes the node's own list, ~recorded_topics.
"""

import glob
import os
import shutil
import subprocess
import tempfile
import unittest

import rosbag
import rospkg
import rospy
import rostest

# A few samples of each case: 2 (the antenna's 20 Hz) to 51 (the blade drop's 1000 Hz) by 0.05 s, fewer than the
# recorder's queue of 100, so none is dropped at real_time_factor 0. The wing with aileron and the blade drop
# start from a static equilibrium, which takes longer than the steps.
T_END = '0.05'
# The arguments that cut each launch file short. output.cycle_from must lie before t_end: the Conner section's
# default variant reports its cycle from 30 s (flutter_below has none), the wing with aileron from 2 s, which at
# its 500 samples/s would overflow the recorder's queue (10 samples/s give 21).
SHORT_RUN = {'conner_section.launch': ('variant:=flutter_below', 't_end:=' + T_END),
             'wing_aileron.launch': ('t_end:=2.05', 'rate_hz:=10')}
# roslaunch's start, the node's load and build and the recorder's start on a loaded 2-core machine: a few
# seconds each; the node's own bound on the wait for the recorder (~wait_for_subscribers_timeout) is 60 s.
RUN_TIMEOUT = 180.0
# Latched topics, published once before the first sample; every other one carries each sample.
LATCHED = ('/flexmbd/markers', '/tf_static')


def launch_files():
    directory = os.path.join(rospkg.RosPack().get_path('flexmbd'), 'launch')
    return sorted(os.path.basename(path) for path in glob.glob(os.path.join(directory, '*.launch')))


class RecordEveryLaunch(unittest.TestCase):
    def setUp(self):
        self.directory = tempfile.mkdtemp(prefix='record_every_launch_')
        self.addCleanup(shutil.rmtree, self.directory, ignore_errors=True)

    def test_every_launch_file_records_every_topic_its_node_publishes(self):
        files = launch_files()
        self.assertEqual(len(files), 8, files)
        for launch in files:
            with self.subTest(launch=launch):
                self.check_recording(launch)

    def check_recording(self, launch):
        bag_path = os.path.join(self.directory, launch.replace('.launch', '.bag'))
        short_run = SHORT_RUN.get(launch, ('t_end:=' + T_END,))
        done = subprocess.run(('roslaunch', 'flexmbd', launch, 'real_time_factor:=0', 'record:=' + bag_path)
                              + short_run,
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=RUN_TIMEOUT)
        output = done.stdout
        self.assertEqual(done.returncode, 0, output)
        self.assertNotIn('stopped at t = 0 s', output)
        listed = rospy.get_param('/flexmbd/recorded_topics', None)
        self.assertIsNotNone(listed, output)
        with rosbag.Bag(bag_path) as bag:
            topics = bag.get_type_and_topic_info().topics
        self.assertEqual(sorted(topics), sorted(listed), output)
        for topic in listed:
            self.assertGreater(topics[topic].message_count, 0, topic)
        samples = [topics[t].message_count for t in listed if t not in LATCHED and t != '/tf']
        self.assertEqual(len(set(samples)), 1, topics)  # each sample on every sample topic
        self.assertGreater(samples[0], 1, launch)


if __name__ == '__main__':
    rospy.init_node('record_every_launch')
    rostest.rosrun('flexmbd', 'record_every_launch', RecordEveryLaunch)
