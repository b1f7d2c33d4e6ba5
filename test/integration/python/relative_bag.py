#!/usr/bin/python3
"""roslaunch CASE bag:=NAME record:=NAME from a directory, as a user types it (relative_bag.test): both bags
land in that directory, not in ~/.ros where roslaunch starts its nodes."""

import os
import subprocess
import tempfile
import unittest

import rosbag
import rospy
import rostest

# The pendulum's 3 s at real_time_factor 0 take well under a second; the bound leaves room for roslaunch, the
# recorder's start and a loaded machine.
RUN_TIMEOUT = 90.0


class RelativeBag(unittest.TestCase):
    def test_relative_bag_paths_are_the_callers(self):
        directory = tempfile.mkdtemp()
        # a shell sets PWD to the directory it runs roslaunch in
        env = dict(os.environ, PWD=directory)
        done = subprocess.run(('roslaunch', 'flexmbd', 'pendulum_stop.launch', 'real_time_factor:=0',
                               'bag:=node.bag', 'record:=recorded.bag'),
                              cwd=directory, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                              timeout=RUN_TIMEOUT)
        self.assertEqual(done.returncode, 0, done.stdout)
        for name in ('node.bag', 'recorded.bag'):
            with rosbag.Bag(os.path.join(directory, name)) as bag:
                self.assertGreater(bag.get_message_count(), 0, name)


if __name__ == '__main__':
    rospy.init_node('relative_bag')
    rostest.rosrun('flexmbd', 'relative_bag', RelativeBag)
