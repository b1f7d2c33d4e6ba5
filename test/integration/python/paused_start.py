#!/usr/bin/python3
"""A case launched with paused:=true (paused_start.test): no sample until ~step, exactly one per ~step, and
samples flow after ~resume."""

import unittest

import rospy
import rostest
from sensor_msgs.msg import JointState
from std_srvs.srv import Trigger

# Seconds a client waits for the node's services, on a loaded 2-core machine.
TIMEOUT = 30.0
# Wall seconds the test listens for samples a paused node must not send: the case runs at real time, 100
# samples per second, so a node that ignored paused:=true would send about 200 in that time.
QUIET = 2.0


class PausedStart(unittest.TestCase):
    def test_paused_start_sends_samples_only_when_asked(self):
        states = []
        rospy.Subscriber('/joint_states', JointState, states.append, queue_size=1000)
        rospy.wait_for_service('/flexmbd/step', timeout=TIMEOUT)
        rospy.rostime.wallsleep(QUIET)
        self.assertEqual(states, [])
        reply = rospy.ServiceProxy('/flexmbd/step', Trigger)()
        self.assertTrue(reply.success, reply.message)
        self.assertIn('t = 0 s', reply.message)
        rospy.rostime.wallsleep(QUIET)
        self.assertEqual(len(states), 1)
        self.assertTrue(rospy.ServiceProxy('/flexmbd/resume', Trigger)().success)
        rospy.rostime.wallsleep(QUIET)
        self.assertGreater(len(states), 1)


if __name__ == '__main__':
    rospy.init_node('paused_start')
    rostest.rosrun('flexmbd', 'paused_start', PausedStart)
