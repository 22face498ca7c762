#!/usr/bin/python3
"""SIGTERM or SIGINT to `runin` while its plot script runs (stdlib only; ctest label cli).

usage: check_plot_interrupt.py RUNIN SOURCE_DIR WORKDIR

The element run (pin-on-disk, the thesis case) plots through RUNIN_PYTHON = a python wrapper that marks its start
in a file, sleeps 3 s and then runs the real plot script on the staged files. The signal arrives during that
sleep. runin must stop the script (its process group) before it removes its staging directory: runin ends by
the signal, nothing of the script is left running, stderr holds no Python traceback, and neither the output
directory nor a staging directory is left. Before the fix the script went on after runin had gone and failed
on the removed staging directory (FileNotFoundError ... .out.staging-...).
"""
import os
import shutil
import signal
import subprocess
import sys
import time
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from runin_common import fail  # noqa: E402

WRAPPER = """#!/usr/bin/python3
import os, sys, time
with open({marker!r}, "w") as f:
    f.write(str(os.getpid()))
time.sleep(3)
os.execv("/usr/bin/python3", ["/usr/bin/python3"] + sys.argv[1:])
"""


def alive(pid):
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().split(")")[-1].split()[0] != "Z"
    except OSError:
        return False


def main():
    runin, source, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    case = os.path.join(source, "inputs", "pin_on_disk.toml")
    for signal_number in (signal.SIGTERM, signal.SIGINT):
        name = signal.Signals(signal_number).name
        marker = os.path.join(work, f"plot_started_{name}")
        wrapper = os.path.join(work, f"slow_python_{name}")
        with open(wrapper, "w") as f:
            f.write(WRAPPER.format(marker=marker))
        os.chmod(wrapper, 0o755)
        out = os.path.join(work, f"out_{name}")
        env = dict(os.environ, RUNIN_PYTHON=wrapper)
        proc = subprocess.Popen([runin, "pin-on-disk", case, "--output-dir", out], stdout=subprocess.PIPE,
                                stderr=subprocess.PIPE, text=True, env=env)
        deadline = time.monotonic() + 60
        while not os.path.exists(marker) or not open(marker).read():
            if proc.poll() is not None or time.monotonic() > deadline:
                proc.kill()
                fail(f"{name}: the plot never started (runin exit {proc.returncode})")
            time.sleep(0.05)
        script_pid = int(open(marker).read())
        proc.send_signal(signal_number)
        try:
            # EOF on the pipes needs every holder gone: a script left running keeps stderr open
            _, err = proc.communicate(timeout=20)
        except subprocess.TimeoutExpired:
            proc.kill()
            fail(f"{name}: runin or its plot script still running 20 s after the signal")
        if proc.returncode != -signal_number:
            fail(f"{name}: runin exit {proc.returncode}, expected death by the signal ({-signal_number})")
        if "Traceback" in err or "Error" in err:
            fail(f"{name}: the plot script went on after runin: {err.strip()}")
        time.sleep(0.5)
        if alive(script_pid):
            os.kill(script_pid, signal.SIGKILL)
            fail(f"{name}: the plot script (pid {script_pid}) is still running after runin ended")
        left = [n for n in os.listdir(work) if ".staging-" in n] + ([out] if os.path.exists(out) else [])
        if left:
            fail(f"{name}: left behind: {left}")
        print(f"{name}: runin ended by the signal, the plot script (pid {script_pid}) stopped with it, "
              "no traceback, nothing left")


if __name__ == "__main__":
    main()
