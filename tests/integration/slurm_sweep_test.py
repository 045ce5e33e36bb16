#!/usr/bin/python3
"""`rig sweep --slurm` against a real single-node Slurm (issue 18, item 5).

Usage: slurm_sweep_test.py RIG_BINARY SOURCE_DIR

Starts Debian's munged, slurmctld and slurmd directly (PID 1 need not be systemd) with a munge
key and a slurm.conf generated in a temporary folder (free TCP ports, this host as the one
node, no accounting), runs `rig sweep SPEC --slurm --workers 2` of a 20-run spec (the step steer
over 5 masses x 4 road frictions) as a job array, and checks: the sbatch script is a 20-task
array limited to 2 at once; each task ran under Slurm (its task-<i>.out, written by slurmd) and
left its run's status and summary; campaign.csv has the 20 runs, none missing; and the same spec
swept locally gives the same campaign.csv (but for wall times): the cluster runs are the
deterministic offline runs. The daemons are stopped at the end whatever happens.

Exit 77 (ctest: skipped), with the reason, only where the daemons cannot run: not root (munged
and slurmd need it here), or the Slurm/munge programs missing (scripts/setup installs them).
"""

import csv
import os
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from rig_checks import check  # noqa: E402

RIG, SRC = sys.argv[1:3]
PROGRAMS = ["munged", "slurmctld", "slurmd", "sbatch", "squeue", "sinfo", "scancel"]


def skip(why):
    print(f"SKIP: {why}")
    sys.exit(77)


def find(program):
    for d in ("/usr/sbin", "/usr/bin", "/sbin", "/bin"):
        if os.access(os.path.join(d, program), os.X_OK):
            return os.path.join(d, program)
    return None


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def wait_for(cond, what, timeout_s=60):
    end = time.monotonic() + timeout_s
    while time.monotonic() < end:
        if cond():
            return
        time.sleep(0.2)
    raise RuntimeError(f"timed out waiting for {what}")


def slurm_conf(tmp, host, cpus):
    return f"""ClusterName=rigtest
SlurmctldHost={host}(127.0.0.1)
SlurmctldPort={free_port()}
SlurmdPort={free_port()}
AuthType=auth/munge
AuthInfo=socket={tmp}/munge.socket
CredType=cred/munge
SlurmUser=root
SlurmdUser=root
StateSaveLocation={tmp}/state
SlurmdSpoolDir={tmp}/spool
SlurmctldPidFile={tmp}/slurmctld.pid
SlurmdPidFile={tmp}/slurmd.pid
SlurmctldLogFile={tmp}/slurmctld.log
SlurmdLogFile={tmp}/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/builtin
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
ReturnToService=2
NodeName={host} NodeAddr=127.0.0.1 CPUs={cpus} State=UNKNOWN
PartitionName=rig Nodes={host} Default=YES MaxTime=INFINITE State=UP
"""


class Cluster:
    """munged, slurmctld and slurmd of one node, in `tmp`."""

    def __init__(self, tmp):
        self.tmp, self.procs = tmp, []
        os.makedirs(tmp)
        os.chmod(tmp, 0o711)  # munged: the socket's folder must be searchable by all
        for d in ("state", "spool"):
            os.makedirs(os.path.join(tmp, d), mode=0o755)
        key = os.path.join(tmp, "munge.key")
        with open(key, "wb") as f:
            f.write(os.urandom(1024))
        os.chmod(key, 0o600)
        self.host = socket.gethostname().split(".")[0]
        self.conf = os.path.join(tmp, "slurm.conf")
        open(self.conf, "w").write(slurm_conf(tmp, self.host, os.cpu_count() or 2))
        self.env = dict(os.environ, SLURM_CONF=self.conf)

    def start(self):
        t = self.tmp
        self.run([find("munged"), "-F", f"--key-file={t}/munge.key", f"--socket={t}/munge.socket",
                  f"--pid-file={t}/munged.pid", f"--log-file={t}/munged.log", f"--seed-file={t}/munged.seed"],
                 "munged")
        wait_for(lambda: os.path.exists(f"{t}/munge.socket"), "munged's socket")
        self.run([find("slurmctld"), "-D", "-f", self.conf], "slurmctld")
        self.run([find("slurmd"), "-D", "-f", self.conf, "-N", self.host], "slurmd")

        def idle():
            r = subprocess.run(["sinfo", "-h", "-o", "%T"], env=self.env, capture_output=True, text=True)
            return r.returncode == 0 and r.stdout.strip() == "idle"
        wait_for(idle, "the node to be idle (sinfo)")

    def run(self, argv, name):
        log = open(os.path.join(self.tmp, f"{name}.stdout"), "w")
        self.procs.append(subprocess.Popen(argv, stdout=log, stderr=subprocess.STDOUT, env=self.env))
        time.sleep(0.3)
        check(self.procs[-1].poll() is None, f"{name} runs ({open(log.name).read()[-500:]})")

    def stop(self):
        for p in reversed(self.procs):  # slurmd, slurmctld, munged
            if p.poll() is None:
                p.send_signal(signal.SIGTERM)
                try:
                    p.wait(timeout=20)
                except subprocess.TimeoutExpired:
                    p.kill()
                    p.wait()

    def logs(self):
        out = ""
        for name in ("slurmctld.log", "slurmd.log"):
            path = os.path.join(self.tmp, name)
            if os.path.exists(path):
                out += f"--- {name}\n" + "".join(open(path).readlines()[-15:])
        return out


def rows_of(out):
    return list(csv.DictReader(open(os.path.join(out, "campaign.csv"), newline="")))


def main():
    # ctest's timeout sends SIGTERM: end through `finally`, which stops the daemons
    signal.signal(signal.SIGTERM, lambda *_: sys.exit("terminated"))
    if os.geteuid() != 0:
        skip("not root: munged and slurmd run as root here (CI runs as root)")
    missing = [p for p in PROGRAMS if find(p) is None]
    if missing:
        skip(f"{' '.join(missing)} not installed (scripts/setup installs slurmctld slurmd slurm-client munge)")
    tmp = tempfile.mkdtemp(prefix="rig_slurm_")
    os.chmod(tmp, 0o711)
    maneuver = os.path.abspath(os.path.join(SRC, "config", "maneuvers", "step-steer-iso7401.toml"))
    spec = os.path.join(tmp, "spec.toml")
    open(spec, "w").write(f"""name = "slurm20"
base = "{maneuver}"
[[vary]]
key = "vehicle.chassis.mass_kg"
values = [1300, 1400, 1500, 1600, 1700]
[[vary]]
key = "model.road_friction"
values = [0.7, 0.8, 0.9, 1.0]
""")
    cluster = Cluster(os.path.join(tmp, "cluster"))
    out = os.path.join(tmp, "out")
    try:
        cluster.start()
        t0 = time.monotonic()
        r = subprocess.run([RIG, "sweep", spec, "--slurm", "--workers", "2", "--out", out, "--no-plots"],
                           env=cluster.env, capture_output=True, text=True, timeout=900)
        print(f"rig sweep --slurm: exit {r.returncode} in {time.monotonic() - t0:.1f} s")
        print(r.stderr[-1500:])
        check(r.returncode == 0, f"exit {r.returncode}\n{cluster.logs()}")
    finally:
        cluster.stop()
    script = open(os.path.join(out, "sweep.sbatch")).read()
    check("#SBATCH --array=0-19%2\n" in script and "--task \"$SLURM_ARRAY_TASK_ID\"" in script,
          "a 20-task array, 2 at once, each running its task")
    outs = sorted(os.listdir(os.path.join(out, "slurm")))
    check(all(f"task-{i}.out" in outs for i in range(20)), f"slurmd ran the 20 tasks ({outs})")
    rows = rows_of(out)
    check(len(rows) == 20 and all(r["status"] in ("ok", "kpi_failed") for r in rows),
          f"20 runs ended as asked ({[r['status'] for r in rows]})")
    local = os.path.join(tmp, "local")
    r = subprocess.run([RIG, "sweep", spec, "--out", local, "--no-plots"], capture_output=True, text=True,
                       timeout=600)
    check(r.returncode == 0, f"the local sweep: exit {r.returncode}")
    strip = lambda rs: [{k: v for k, v in x.items() if k != "wall_time_s"} for x in rs]  # noqa: E731
    check(strip(rows) == strip(rows_of(local)), "the Slurm runs = the local runs (deterministic)")
    shutil.rmtree(tmp, ignore_errors=True)
    print("PASS slurm")


main()
