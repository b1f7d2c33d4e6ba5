#!/usr/bin/python3
"""Python and command-line clients of flexmbd_node, as a ROS user runs them (python_clients.test)."""

import subprocess
import unittest

import rospy
import rostest
from sensor_msgs.msg import JointState
from std_srvs.srv import Trigger

from flexmbd.msg import JointContactArray

# Seconds a client waits for the node: its start and the first sample, on a loaded 2-core machine.
TIMEOUT = 30.0


def run_tool(*command):
    """Runs a ROS command-line tool; returns its exit status and output."""
    done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                          timeout=TIMEOUT)
    return done.returncode, done.stdout


class PythonClients(unittest.TestCase):
    def test_joint_states_reach_a_rospy_subscriber(self):
        state = rospy.wait_for_message('/joint_states', JointState, timeout=TIMEOUT)
        self.assertEqual(list(state.name), ['hinge'])
        self.assertEqual(len(state.position), 1)

    def test_contacts_arrive_as_python_flexmbd_messages(self):
        sample = rospy.wait_for_message('/flexmbd/contacts', JointContactArray, timeout=TIMEOUT)
        self.assertGreater(len(sample.contacts), 0)
        self.assertEqual(sample.contacts[0].joint, 'hinge')

    def test_rostopic_echo_prints_a_joint_state(self):
        status, output = run_tool('rostopic', 'echo', '-n', '1', '/joint_states')
        self.assertEqual(status, 0, output)
        self.assertIn('hinge', output)

    def test_pause_and_resume_answer_rospy_and_rosservice(self):
        rospy.wait_for_service('/flexmbd/pause', timeout=TIMEOUT)
        self.assertTrue(rospy.ServiceProxy('/flexmbd/pause', Trigger)().success)
        status, output = run_tool('rosservice', 'call', '/flexmbd/pause')
        self.assertEqual(status, 0, output)
        self.assertIn('success: True', output)
        # Resumed, so that the other tests still see samples.
        status, output = run_tool('rosservice', 'call', '/flexmbd/resume')
        self.assertEqual(status, 0, output)
        self.assertIn('success: True', output)

    def test_rosrun_finds_the_runner(self):
        # Without arguments the runner prints its usage and exits 1 (README, exit statuses).
        status, output = run_tool('rosrun', 'flexmbd', 'flexmbd_run')
        self.assertEqual(status, 1, output)
        self.assertIn('usage: flexmbd_run', output)


if __name__ == '__main__':
    rospy.init_node('python_clients')
    rostest.rosrun('flexmbd', 'python_clients', PythonClients)
