#!/usr/bin/python3
"""/clock under the launch files' default use_sim_time, as a ROS client sees it (clock_rate*.test).

Private parameters: ~above_hz, a rate the ticks per simulated second must exceed (the case's output sample
rate, at which the node used to tick); ~rate_hz, if set, the ~clock_rate_hz the node was given, which the
ticks must keep; ~loop_hz, if set, a rospy.Rate loop that must keep its rate in simulated time.
"""

import unittest

import rospy
import rostest
from rosgraph_msgs.msg import Clock

# Seconds a client waits for the node to start and its clock to run, on a loaded 2-core machine.
TIMEOUT = 30.0
# Simulated seconds measured (the cases run at real_time_factor 1: as many wall seconds).
SPAN = 2.0
# Stamps are rounded to the nanosecond (ros::Time): a grid tick is within that of t0 + k / rate.
STAMP_RESOLUTION = 1.0e-9
# A rospy.Rate loop sleeps to the first tick at or after its due time: it keeps its schedule (it does not
# drift), so over SPAN it runs (loop_hz SPAN) +- 1 times, unless this process falls two periods behind (then
# it starts its schedule over): the loop's rate is kept low enough for a loaded machine to keep up.
LOOP_COUNT_SLACK = 1


class ClockRate(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.ticks = []
        subscriber = rospy.Subscriber('/clock', Clock, lambda m: cls.ticks.append(m.clock.to_sec()),
                                      queue_size=10000)
        rospy.wait_for_message('/clock', Clock, timeout=TIMEOUT)
        start = rospy.get_time()
        while rospy.get_time() < start + SPAN and not rospy.is_shutdown():
            rospy.sleep(0.01)
        subscriber.unregister()
        cls.window = [t for t in cls.ticks if start < t <= start + SPAN]

    def test_ticks_per_simulated_second_exceed_the_sample_rate(self):
        self.assertGreater(len(self.window) / SPAN, rospy.get_param('~above_hz'))

    def test_ticks_keep_the_clock_rate(self):
        rate = rospy.get_param('~rate_hz', 0.0)
        if rate == 0.0:
            return
        # rospy's own /clock subscription keeps the last message of each read (queue_size=1), and a client's
        # subscription shares its connection: a tick may be missing here. None may be off the grid t0 + k / rate
        # (t0 = 0), none may be extra, and consecutive ones arrive 1 / rate apart.
        grid = [round(t * rate) for t in self.window]
        for t, k in zip(self.window, grid):
            self.assertLess(abs(t - k / rate), STAMP_RESOLUTION, t)
        gaps = [b - a for a, b in zip(grid, grid[1:])]
        self.assertGreaterEqual(min(gaps), 1)
        self.assertIn(1, gaps)
        self.assertLessEqual(len(self.window), rate * SPAN + 1)

    def test_a_rospy_rate_loop_keeps_its_rate_in_simulated_time(self):
        loop_hz = rospy.get_param('~loop_hz', 0.0)
        if loop_hz == 0.0:
            return
        rate = rospy.Rate(loop_hz)
        start = rospy.get_time()
        count = 0
        while rospy.get_time() < start + SPAN and not rospy.is_shutdown():
            rate.sleep()
            count += 1
        self.assertLessEqual(abs(count - loop_hz * SPAN), LOOP_COUNT_SLACK)


if __name__ == '__main__':
    rospy.init_node('clock_rate')
    rostest.rosrun('flexmbd', 'clock_rate', ClockRate)
