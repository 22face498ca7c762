"""What the test and tool scripts share: the source tree, the failure exit, scratch directories and the MPI
environment. Standard library only; scripts put tools/ on sys.path and import from here."""
import atexit
import os
import shutil
import subprocess
import sys
import tempfile

SOURCE_DIR = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))


def fail(message):
    """Ends a check: one 'FAIL: ...' line on stdout (ctest shows it), exit status 1."""
    print("FAIL: " + message, flush=True)
    sys.exit(1)


def fresh_dir(path):
    """An empty directory at path (removed first if it exists)."""
    shutil.rmtree(path, ignore_errors=True)
    os.makedirs(path)


# Open MPI on one node without probing network transports (the UCX layer) and, for a run started without mpiexec,
# without forking a runtime daemon: lmp_runin starts in 0.14 s instead of 0.59 s (doc/measurements.md, "Test tiers"),
# which was most of a bad-input test.
# The same values as tools/run-tests exports; results do not depend on them.
MPI_START_ENV = {"OMPI_MCA_pml": "ob1", "OMPI_MCA_btl": "self,vader", "OMPI_MCA_ess_singleton_isolated": "1"}


_SESSION_DIRS = []


def _remove_session_dirs():
    for path in _SESSION_DIRS:
        shutil.rmtree(path, ignore_errors=True)


def mpi_env():
    """The environment for mpiexec runs: root allowed (containers), oversubscription allowed (2-core machines),
    one OpenMP thread per rank, and Open MPI's single-node start-up (MPI_START_ENV). Each call gets its own session
    directory tree (orte_tmpdir_base, removed at exit): concurrent runs that share Open MPI's /tmp tree can remove each
    other's directories as they finish ("orte_session_dir failed" at start-up, seen twice under ctest -j2 with other
    MPI jobs running)."""
    env = dict(os.environ)
    if "OMPI_MCA_orte_tmpdir_base" not in env:
        if not _SESSION_DIRS:
            atexit.register(_remove_session_dirs)
        _SESSION_DIRS.append(tempfile.mkdtemp(prefix="runin-ompi-"))
        env["OMPI_MCA_orte_tmpdir_base"] = _SESSION_DIRS[-1]
    for name, value in MPI_START_ENV.items():
        env.setdefault(name, value)
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    env.setdefault("OMPI_MCA_rmaps_base_oversubscribe", "1")
    env.setdefault("OMP_NUM_THREADS", "1")
    return env


def run_or_fail(command, **kwargs):
    """Runs command (capturing its output as text); a non-zero exit ends the check naming the command, the exit
    status and the end of its stderr. Returns the CompletedProcess."""
    result = subprocess.run(command, capture_output=True, text=True, **kwargs)
    if result.returncode != 0:
        fail(f"{' '.join(str(c) for c in command)}: exit {result.returncode}: {result.stderr.strip()[-800:]}")
    return result


def law_material_file(law):
    """The coefficient file a state law records (material.file: absolute, or relative to the source tree)."""
    path = law["material"]["file"]
    return path if os.path.isabs(path) else os.path.join(SOURCE_DIR, path)


def material_hardness(material_file, name):
    """H of 'material NAME E nu rho H [S_y]' in a RunIn coefficient file."""
    for line in open(material_file):
        words = line.split()
        if words[:2] == ["material", name]:
            return float(words[5])
    fail(f"{material_file}: no material {name}")


def interface_factor(material_file, a, b, state):
    """m of the pair's 'interface A B STATE m' line (either order of A and B)."""
    for line in open(material_file):
        words = line.split()
        if words[:1] == ["interface"] and sorted(words[1:3]) == sorted([a, b]) and words[3:4] == [state]:
            return float(words[4])
    fail(f"{material_file}: no '{state}' interface line for {a} / {b}")
