#!/usr/bin/python3
"""launch/rotor_engage.launch, still air, first 0.05 s (rotor_engage_launch.test): joint_states carries the three
flap hinges, ~contacts their droop and flap stops, and the blades press their droop stops with the force their
weight calls for.

Reference: each blade (with its yoke and grip) hangs on its flap hinge with the first moment of mass S = 309.10 kg m
about it (config/rotor_engage: yoke 5 kg at 0.075 m, grip 10 kg at 0.25 m, blade 11 kg/m from 0.35 to 7.47 m; the
pitch horn lies on the hinge's axis and carries no flap moment), so a droop stop 0.3 m from the hinge holds it with
F_s = g S cos(0.54 deg) / 0.3 = 10107 N. The run starts from the static state held on the stop with the gap just
closed (no approach); released, a blade settles slowly into its Hertz stop (F = k a^1.5, with Hunt-Crossley
damping) towards the approach that carries its weight, 4.7e-4 m (the flap angle 0.003 deg below -0.54 deg at
0.05 s), while its bending modes, set ringing by the release, pass a varying share of the weight to the stop
(measured -2.6% to +1.9% of F_s)."""

import math
import unittest

import rospy
import rostest
from flexmbd.msg import JointContactArray
from sensor_msgs.msg import JointState
from std_srvs.srv import Trigger

# Seconds a client waits for the node's services and for the run, on a loaded 2-core machine (the 0.05 s take
# a few seconds of CPU).
TIMEOUT = 90.0
T_END = 0.05
BLADES = 3
RADIUS = 0.3
DROOP = math.radians(-0.54)
STATIC_FORCE = 9.81 * 309.10 * math.cos(DROOP) / RADIUS
# Share of F_s the ringing blade may add to or take from the stop (measured 2.6% at most).
RINGING = 0.05
STIFFNESS = 1.0e9  # N/m^1.5
# The flap angle on the stop: below -0.54 deg by at most the approach that carries the largest force,
# ((1 + RINGING) F_s / k)^(2/3) (4.8e-4 m), over the radius.
DEEPEST = DROOP - ((1 + RINGING) * STATIC_FORCE / STIFFNESS) ** (2.0 / 3.0) / RADIUS


class RotorEngageLaunch(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.states, cls.contacts = [], []
        rospy.Subscriber('/joint_states', JointState, cls.states.append, queue_size=10000)
        rospy.Subscriber('/flexmbd/contacts', JointContactArray, cls.contacts.append, queue_size=10000)
        rospy.wait_for_service('/flexmbd/resume', timeout=TIMEOUT)
        rospy.rostime.wallsleep(1.0)  # the subscriptions connect
        reply = rospy.ServiceProxy('/flexmbd/resume', Trigger)()
        assert reply.success, reply.message
        waited = 0.0
        while not (cls.contacts and cls.contacts[-1].header.stamp.to_sec() >= T_END - 1e-9) and waited < TIMEOUT:
            rospy.rostime.wallsleep(0.5)
            waited += 0.5
        rospy.rostime.wallsleep(1.0)  # the last joint_states

    def test_joint_states_carry_the_flap_hinges_on_their_droop_stops(self):
        self.assertTrue(self.states)
        self.assertGreaterEqual(self.states[-1].header.stamp.to_sec(), T_END - 1e-9)
        for message in self.states:
            for blade in range(BLADES):
                name = 'flap_%d' % blade
                self.assertIn(name, message.name)
                flap = message.position[message.name.index(name)]
                self.assertLessEqual(flap, DROOP + 1e-9, 'blade %d at t = %s' % (blade, message.header.stamp))
                self.assertGreaterEqual(flap, DEEPEST, 'blade %d at t = %s' % (blade, message.header.stamp))

    def test_droop_stops_carry_the_blades_weight_and_flap_stops_stay_open(self):
        self.assertTrue(self.contacts)
        self.assertGreaterEqual(self.contacts[-1].header.stamp.to_sec(), T_END - 1e-9)
        for message in self.contacts:
            stops = {(c.joint, c.stop): c for c in message.contacts}
            for blade in range(BLADES):
                droop, flap = stops[('flap_%d' % blade, 'lower')], stops[('flap_%d' % blade, 'upper')]
                self.assertFalse(flap.in_contact)
                self.assertEqual(flap.force, 0.0)
                self.assertAlmostEqual(droop.torque, RADIUS * droop.force, delta=1e-9 * (1 + droop.force))
                if message.header.stamp.to_sec() > 0:  # the contact begins with the first step
                    self.assertTrue(droop.in_contact, 'blade %d at t = %s' % (blade, message.header.stamp))
                    self.assertAlmostEqual(droop.force, STATIC_FORCE, delta=RINGING * STATIC_FORCE,
                                           msg='blade %d' % blade)


if __name__ == '__main__':
    rospy.init_node('rotor_engage_launch')
    rostest.rosrun('flexmbd', 'rotor_engage_launch', RotorEngageLaunch)
