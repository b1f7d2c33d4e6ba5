#!/usr/bin/python3
"""The node's tf tree looked up through tf2_ros, as a ROS user does (tf_tree.test, tf_static.test).

Private parameters: ~joints, a list of [parent link, child link, joint] revolute joints about y whose tf2
rotation parent -> child must equal the joint's position on joint_states; ~parents, [parent, child] pairs
that /tf must send as such; ~static, [parent, child] pairs that must arrive on the latched /tf_static and be
looked up through tf2.
"""

import math
import unittest

import rospy
import rostest
import tf2_ros
from sensor_msgs.msg import JointState
from tf2_msgs.msg import TFMessage

# Seconds a client waits for the node: its start and the first samples, on a loaded 2-core machine.
TIMEOUT = 30.0
# Joint states compared with the transforms at their stamps: a few seconds of the run, the joints moving.
SAMPLES = 50
# The double pendulum's joints hold to the Newton tolerance (tol = 1e-8, relative, on angles of order 1 rad):
# the link frames turn by the joint angle to well under a microradian. Both come from one state: with
# rate_hz:=0 each sample is a step's end, where the node sends that step's exact transforms.
ANGLE_TOLERANCE = 1.0e-6


def angle_about_y(rotation):
    """Angle [rad] of a rotation about y, and the size of its components about x and z."""
    return 2.0 * math.atan2(rotation.y, rotation.w), max(abs(rotation.x), abs(rotation.z))


def wrapped(angle):
    return math.atan2(math.sin(angle), math.cos(angle))


class TfTree(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.buffer = tf2_ros.Buffer(cache_time=rospy.Duration(60.0))
        cls.listener = tf2_ros.TransformListener(cls.buffer)

    def test_rotation_parent_to_child_is_the_joint_angle(self):
        joints = rospy.get_param('~joints', [])
        if not joints:
            return
        # The listener's /tf connection can come up after the joint_states one: a sample older than the first
        # transform received would never be found (and the lookup would wait until the run ends). Samples are
        # taken only once every joint's transform has arrived.
        for parent, child, _ in joints:
            self.assertTrue(self.buffer.can_transform(parent, child, rospy.Time(0), rospy.Duration(TIMEOUT)),
                            '%s -> %s never arrived on /tf' % (parent, child))
        states = []
        subscriber = rospy.Subscriber('/joint_states', JointState, states.append, queue_size=1000)
        deadline = rospy.get_time() + TIMEOUT
        while len(states) < SAMPLES and rospy.get_time() < deadline and not rospy.is_shutdown():
            rospy.sleep(0.05)
        subscriber.unregister()
        self.assertGreaterEqual(len(states), SAMPLES)
        for state in states:
            for parent, child, joint in joints:
                transform = self.buffer.lookup_transform(parent, child, state.header.stamp,
                                                         rospy.Duration(TIMEOUT))
                self.assertEqual(transform.header.frame_id, parent)
                angle, off_axis = angle_about_y(transform.transform.rotation)
                position = state.position[state.name.index(joint)]
                self.assertLess(abs(wrapped(angle - position)), ANGLE_TOLERANCE,
                                '%s at t = %s' % (joint, state.header.stamp.to_sec()))
                self.assertLess(off_axis, ANGLE_TOLERANCE, joint)

    def test_links_hang_from_their_urdf_parents(self):
        for parent, child in rospy.get_param('~parents', []):
            message = rospy.wait_for_message('/tf', TFMessage, timeout=TIMEOUT)
            parents = {t.child_frame_id: t.header.frame_id for t in message.transforms}
            self.assertEqual(parents.get(child), parent, child)

    def test_fixed_links_are_latched_on_tf_static(self):
        pairs = rospy.get_param('~static', [])
        if not pairs:
            return
        message = rospy.wait_for_message('/tf_static', TFMessage, timeout=TIMEOUT)
        sent = {(t.header.frame_id, t.child_frame_id) for t in message.transforms}
        for parent, child in pairs:
            self.assertIn((parent, child), sent)
            # static transforms hold at every time: the latest (time 0) is found at once
            transform = self.buffer.lookup_transform(parent, child, rospy.Time(0), rospy.Duration(TIMEOUT))
            self.assertEqual(transform.child_frame_id, child)


if __name__ == '__main__':
    rospy.init_node('tf_tree')
    rostest.rosrun('flexmbd', 'tf_tree', TfTree)
