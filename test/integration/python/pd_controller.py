#!/usr/bin/python3
"""A separate controller node that closes a loop through the node's topics (pd_hold.test, docs/ros.md
"Commands"): on each /joint_states sample it sends the double pendulum's elbow a PD effort towards ~target_deg
plus the elbow's gravity and spring load at the measured angles (so that the loop settles on the target
itself), and the driven shoulder a set-point ~shoulder_deg.

The load comes from the case the node runs: the elbow link's mass and centre of mass from robot_description,
the spring from the node's joints.elbow.spring.k, gravity from its solver.gravity. The double pendulum's links
lie along their x axes and turn about y, so with q positive downwards from the horizontal gravity pulls the
elbow with m g x_cm cos(q_shoulder + q_elbow) and the spring with -k q_elbow.
"""

import math
import xml.etree.ElementTree as ElementTree

import rospy
from sensor_msgs.msg import JointState


def elbow_link_load():
    """Mass [kg] and centre-of-mass distance [m] of the elbow's child link, from robot_description."""
    robot = ElementTree.fromstring(rospy.get_param('/robot_description'))
    child = next(j for j in robot.iter('joint') if j.get('name') == 'elbow').find('child').get('link')
    inertial = next(link for link in robot.iter('link') if link.get('name') == child).find('inertial')
    return float(inertial.find('mass').get('value')), float(inertial.find('origin').get('xyz').split()[0])


class PdController:
    def __init__(self):
        self.kp = rospy.get_param('~kp')  # [N m/rad]
        self.kd = rospy.get_param('~kd')  # [N m s/rad]
        self.target = math.radians(rospy.get_param('~target_deg'))
        self.shoulder = math.radians(rospy.get_param('~shoulder_deg'))
        mass, arm = elbow_link_load()
        self.weight_moment = mass * -rospy.get_param('/flexmbd/solver/gravity')[2] * arm  # [N m]
        self.spring = rospy.get_param('/flexmbd/joints/elbow/spring/k')  # [N m/rad]
        self.efforts = rospy.Publisher('/flexmbd/effort_command', JointState, queue_size=1, tcp_nodelay=True)
        self.setpoints = rospy.Publisher('/flexmbd/position_command', JointState, queue_size=1, tcp_nodelay=True)
        rospy.Subscriber('/joint_states', JointState, self.on_sample, queue_size=1, tcp_nodelay=True)

    def on_sample(self, sample):
        q = dict(zip(sample.name, sample.position))
        rate = dict(zip(sample.name, sample.velocity))
        load = self.weight_moment * math.cos(q['shoulder'] + q['elbow']) - self.spring * q['elbow']
        effort = self.kp * (self.target - q['elbow']) - self.kd * rate['elbow'] - load
        self.efforts.publish(JointState(header=sample.header, name=['elbow'], effort=[effort]))
        self.setpoints.publish(JointState(header=sample.header, name=['shoulder'], position=[self.shoulder]))


if __name__ == '__main__':
    rospy.init_node('pd_controller')
    PdController()
    rospy.spin()
