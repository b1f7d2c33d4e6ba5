#!/usr/bin/python3
"""roslaunch of one reference case after another on the rostest's master (launch_sequence.test).

Each launch file's node clears its private parameters first (clear_params): without that, the parameters the
first case loaded stayed on the server, and the antenna after the double pendulum failed with "no joint
'elbow'", or its dampers variant after the friction one ran with the friction block of the first.
"""

import os
import subprocess
import unittest

import rospy
import rostest

# A reference case's whole run at real_time_factor 0: well under a second here; the bound leaves room for a
# loaded machine and roslaunch's own start.
RUN_TIMEOUT = 90.0
# Launched in a namespace of their own, so that they do not replace each other's nodes with the same name.
NAMESPACE = '/sequence'


def launch(*arguments):
    """Runs roslaunch flexmbd ARGUMENTS to its end; returns its exit status and output."""
    env = dict(os.environ, ROS_NAMESPACE=NAMESPACE)
    done = subprocess.run(('roslaunch', 'flexmbd') + arguments + ('real_time_factor:=0',),
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=RUN_TIMEOUT,
                          env=env)
    return done.returncode, done.stdout


class LaunchSequence(unittest.TestCase):
    def assertRanToItsEnd(self, arguments):
        # roslaunch itself exits 0 when its required node dies, so the node's end is read from its report.
        status, output = launch(*arguments)
        self.assertEqual(status, 0, output)
        self.assertTrue('process has finished cleanly' in output, output)
        self.assertFalse('exit code' in output, output)

    def test_each_case_runs_with_its_own_parameters(self):
        self.assertRanToItsEnd(['double_pendulum.launch'])
        self.assertRanToItsEnd(['antenna.launch', 'variant:=friction'])
        self.assertTrue(rospy.has_param(NAMESPACE + '/flexmbd/joints/B1/friction'))
        self.assertRanToItsEnd(['antenna.launch', 'variant:=dampers'])
        # Nothing of the friction variant is left behind; the dampers are there.
        self.assertFalse(rospy.has_param(NAMESPACE + '/flexmbd/joints/B1/friction'))
        self.assertTrue(rospy.has_param(NAMESPACE + '/flexmbd/joints/B1/damper'))
        # The aeroelastic section (4 s below its flutter speed) after the antenna: its aero block, no hinge of it.
        self.assertRanToItsEnd(['conner_section.launch', 'variant:=flutter_below'])
        self.assertTrue(rospy.has_param(NAMESPACE + '/flexmbd/aero/sections/conner'))
        self.assertFalse(rospy.has_param(NAMESPACE + '/flexmbd/joints/B1'))


if __name__ == '__main__':
    rospy.init_node('launch_sequence')
    rostest.rosrun('flexmbd', 'launch_sequence', LaunchSequence)
