"""A real single-node Slurm cluster in a temporary directory, for sweep_slurm.py: munged with its own key and
socket, slurmctld and slurmd in the foreground as child processes, state, spool and logs in the directory,
no cgroups, free ports. Runs as root (CI does): SlurmUser=root."""

import os
import socket
import subprocess
import time

# Seconds for the daemons to start and the node to be idle, on a loaded 2-core machine.
START_TIMEOUT = 60.0


def _free_port():
    with socket.socket() as probe:
        probe.bind(('127.0.0.1', 0))
        return probe.getsockname()[1]


def _slurm_conf(directory, host, munge_socket):
    return '\n'.join([
        'ClusterName=flexmbdtest',
        f'SlurmctldHost={host}(127.0.0.1)',
        f'SlurmctldPort={_free_port()}',
        f'SlurmdPort={_free_port()}',
        'SlurmUser=root',
        'SlurmdUser=root',
        'AuthType=auth/munge',
        'CredType=cred/munge',
        f'AuthInfo=socket={munge_socket}',
        f'StateSaveLocation={directory}/state',
        f'SlurmdSpoolDir={directory}/spool',
        f'SlurmctldPidFile={directory}/slurmctld.pid',
        f'SlurmdPidFile={directory}/slurmd.pid',
        f'SlurmctldLogFile={directory}/log/slurmctld.log',
        f'SlurmdLogFile={directory}/log/slurmd.log',
        'ProctrackType=proctrack/linuxproc',
        'TaskPlugin=task/none',
        'JobAcctGatherType=jobacct_gather/none',
        'AccountingStorageType=accounting_storage/none',
        'MpiDefault=none',
        'SwitchType=switch/none',
        'SchedulerType=sched/builtin',
        'SelectType=select/cons_tres',
        'SelectTypeParameters=CR_CPU',
        'ReturnToService=2',
        'SlurmdParameters=config_overrides',  # CPUs as configured, whatever the machine has
        f'NodeName={host} NodeAddr=127.0.0.1 CPUs=2 State=UNKNOWN',
        'PartitionName=debug Default=YES Nodes=ALL MaxTime=INFINITE State=UP',
        ''])


class SlurmCluster:
    def __init__(self, directory):
        self.directory = directory
        self.processes = []
        self.host = socket.gethostname().split('.')[0]
        # munged refuses a socket whose directories are not searchable by all (mkdtemp makes them 0700).
        os.chmod(directory, 0o755)
        for sub in ('munge', 'socket', 'state', 'spool', 'log'):
            os.makedirs(os.path.join(directory, sub), mode=0o755)
        os.chmod(os.path.join(directory, 'munge'), 0o700)
        self.munge_socket = os.path.join(directory, 'socket', 'munge.socket')
        self.conf = os.path.join(directory, 'slurm.conf')
        with open(self.conf, 'w', encoding='utf-8') as stream:
            stream.write(_slurm_conf(directory, self.host, self.munge_socket))
        self.env = dict(os.environ, SLURM_CONF=self.conf)

    def _start(self, name, command):
        with open(os.path.join(self.directory, 'log', f'{name}.out'), 'w', encoding='utf-8') as log:
            self.processes.append(subprocess.Popen(command, stdout=log, stderr=subprocess.STDOUT, env=self.env))

    def log_tail(self):
        """The daemons' output, for a failure message."""
        text = []
        for name in sorted(os.listdir(os.path.join(self.directory, 'log'))):
            with open(os.path.join(self.directory, 'log', name), encoding='utf-8', errors='replace') as stream:
                text.append(f'--- {name}\n' + ''.join(stream.readlines()[-15:]))
        return '\n'.join(text)

    def start(self):
        key = os.path.join(self.directory, 'munge', 'munge.key')
        with open(os.open(key, os.O_WRONLY | os.O_CREAT, 0o600), 'wb') as stream:
            stream.write(os.urandom(1024))
        munge = os.path.join(self.directory, 'munge')
        self._start('munged', ['munged', '--foreground', f'--socket={self.munge_socket}', f'--key-file={key}',
                               f'--log-file={munge}/munged.log', f'--pid-file={munge}/munged.pid',
                               f'--seed-file={munge}/munged.seed'])
        self._wait_for(lambda: os.path.exists(self.munge_socket), 'munged to create its socket')
        self._start('slurmctld', ['slurmctld', '-D', '-i'])
        self._start('slurmd', ['slurmd', '-D', '-N', self.host])
        self._wait_for(self._node_idle, 'the node to be idle')

    def _node_idle(self):
        done = subprocess.run(['sinfo', '--noheader', '--format=%T'], stdout=subprocess.PIPE,
                              stderr=subprocess.DEVNULL, text=True, env=self.env, check=False)
        return done.returncode == 0 and done.stdout.strip() == 'idle'

    def _wait_for(self, condition, what):
        deadline = time.monotonic() + START_TIMEOUT
        while not condition():
            for process in self.processes:
                if process.poll() is not None:
                    raise RuntimeError(f'{process.args[0]} exited ({process.returncode}) while waiting for '
                                       f'{what}\n{self.log_tail()}')
            if time.monotonic() > deadline:
                raise RuntimeError(f'timed out waiting for {what}\n{self.log_tail()}')
            time.sleep(0.5)

    def stop(self):
        for process in reversed(self.processes):
            process.terminate()
        for process in self.processes:
            try:
                process.wait(timeout=15)
            except subprocess.TimeoutExpired:
                process.kill()
                process.wait()
