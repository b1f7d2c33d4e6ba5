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
# drift), so over LOOP_SPAN from the loop's own start it runs (loop_hz LOOP_SPAN) +- 1 times, as long as this
# process wakes up less than a period late.
LOOP_SPAN = 1.0
LOOP_COUNT_SLACK = 1
# Other tests run beside this one: when this process is held up and wakes a period late or more (then rospy
# catches up or starts its schedule over), the load on the machine was measured, not the clock, and the loop is
# measured again, this many times at most (the case's t_end, 10 s, leaves room for them after SPAN).
LOOP_MEASUREMENTS = 4


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
        for _ in range(LOOP_MEASUREMENTS):
            count, wakes = rate_loop_count(loop_hz)
            # Late or not, the loop never sees time go back.
            self.assertEqual(wakes, sorted(wakes))
            if count is not None:
                break
        self.assertIsNotNone(count, 'the loop woke a period late or more in each of %d measurements'
                             % LOOP_MEASUREMENTS)
        self.assertLessEqual(abs(count - loop_hz * LOOP_SPAN), LOOP_COUNT_SLACK)


def rate_loop_count(loop_hz):
    """Sleeps of a rospy.Rate loop over LOOP_SPAN from the loop's own start (the time it read when made: a time
    read after it may be later already, by as much as this process was held up in between), or None when a
    wake-up came a period late or more; and the times it woke up."""
    rate = rospy.Rate(loop_hz)
    start = rate.last_time
    end = start + rospy.Duration.from_sec(LOOP_SPAN)
    wakes = []
    while rospy.get_rostime() < end and not rospy.is_shutdown():
        rate.sleep()
        wakes.append(rospy.get_rostime())
        due = start + rate.sleep_dur * len(wakes)
        if rate.last_time != due or wakes[-1] - due >= rate.sleep_dur:
            return None, wakes
    return len(wakes), wakes


if __name__ == '__main__':
    rospy.init_node('clock_rate')
    rostest.rosrun('flexmbd', 'clock_rate', ClockRate)
