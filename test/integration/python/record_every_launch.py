#!/usr/bin/python3
"""roslaunch flexmbd CASE.launch record:=BAG t_end:=T for every launch file (record_every_launch.test).

The recorder's topics were typed into each launch file and drifted from what the node publishes: wing_aileron
lacked ~beam_loads and rotor_engage ~aero_loads, and the node, waiting for a subscriber on every sample topic,
never sent a sample (explore23 ros/record_hang). The recorder now takes the node's own list, ~recorded_topics.

The launches run in PARALLEL_LAUNCHES groups side by side, each group on a master of its own (the launch files share
node names, /tf and /clock): one after another they took 74-151 s on the loaded 2-core machine (three runs, load
11-18), four at a time 55-84 s, for about 6 s more CPU (the masters); bench/README.md, "Build and test time".
"""

import concurrent.futures
import glob
import os
import shutil
import socket
import subprocess
import tempfile
import time
import unittest

import rosbag
import rosgraph
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
# seconds each, longer with four launches at once; the node's own bound on the wait for the recorder
# (~wait_for_subscribers_timeout) is 60 s.
RUN_TIMEOUT = 180.0
MASTER_START_TIMEOUT = 60.0
# Launches at once: most of a launch is roslaunch and the recorder starting and stopping, much of it waiting.
PARALLEL_LAUNCHES = 4
# Latched topics, published once before the first sample; every other one carries each sample.
LATCHED = ('/flexmbd/markers', '/tf_static')


def launch_files():
    directory = os.path.join(rospkg.RosPack().get_path('flexmbd'), 'launch')
    return sorted(os.path.basename(path) for path in glob.glob(os.path.join(directory, '*.launch')))


def free_port():
    with socket.socket() as probe:
        probe.bind(('localhost', 0))
        return probe.getsockname()[1]


class Recording:
    """What one launch left: roslaunch's exit code and output, the node's ~recorded_topics, the bag's path."""

    def __init__(self, returncode, output, listed, bag_path):
        self.returncode, self.output, self.listed, self.bag_path = returncode, output, listed, bag_path


def record_one_after_another(launches, directory):
    """Runs each of `launches` with record:= on a master of this group's own; returns {launch: Recording}."""
    port = free_port()
    uri = 'http://localhost:%d' % port
    env = dict(os.environ, ROS_MASTER_URI=uri)
    master_process = subprocess.Popen(('rosmaster', '--core', '-p', str(port)), env=env,
                                      stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        master = rosgraph.Master('/record_every_launch', master_uri=uri)
        deadline = time.monotonic() + MASTER_START_TIMEOUT
        while not master.is_online():
            if time.monotonic() > deadline or master_process.poll() is not None:
                return {launch: Recording(None, 'rosmaster on port %d did not start' % port, None, None)
                        for launch in launches}
            time.sleep(0.1)
        return {launch: record(launch, directory, env, master) for launch in launches}
    finally:
        master_process.terminate()
        master_process.wait()


def record(launch, directory, env, master):
    bag_path = os.path.join(directory, launch.replace('.launch', '.bag'))
    short_run = SHORT_RUN.get(launch, ('t_end:=' + T_END,))
    done = subprocess.run(('roslaunch', 'flexmbd', launch, 'real_time_factor:=0', 'record:=' + bag_path) + short_run,
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=RUN_TIMEOUT, env=env)
    parameter = '/flexmbd/recorded_topics'
    listed = None
    if master.hasParam(parameter):
        listed = master.getParam(parameter)
        master.deleteParam(parameter)  # the next launch on this master lists its own
    return Recording(done.returncode, done.stdout, listed, bag_path)


class RecordEveryLaunch(unittest.TestCase):
    def setUp(self):
        self.directory = tempfile.mkdtemp(prefix='record_every_launch_')
        self.addCleanup(shutil.rmtree, self.directory, ignore_errors=True)

    def test_every_launch_file_records_every_topic_its_node_publishes(self):
        files = launch_files()
        self.assertEqual(len(files), 8, files)
        groups = [files[k::PARALLEL_LAUNCHES] for k in range(PARALLEL_LAUNCHES)]
        recordings = {}
        with concurrent.futures.ThreadPoolExecutor(max_workers=PARALLEL_LAUNCHES) as pool:
            for group in pool.map(lambda launches: record_one_after_another(launches, self.directory), groups):
                recordings.update(group)
        for launch in files:
            with self.subTest(launch=launch):
                self.check_recording(launch, recordings[launch])

    def check_recording(self, launch, recording):
        output = recording.output
        self.assertEqual(recording.returncode, 0, output)
        self.assertNotIn('stopped at t = 0 s', output)
        listed = recording.listed
        self.assertIsNotNone(listed, output)
        with rosbag.Bag(recording.bag_path) as bag:
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
