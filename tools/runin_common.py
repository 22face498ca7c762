"""What the test and tool scripts share: the source tree, the failure exit, scratch directories and the MPI
environment. Standard library only; scripts put tools/ on sys.path and import from here."""
import os
import shutil
import sys

SOURCE_DIR = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))


def fail(message):
    """Ends a check: one 'FAIL: ...' line on stdout (ctest shows it), exit status 1."""
    print("FAIL: " + message, flush=True)
    sys.exit(1)


def fresh_dir(path):
    """An empty directory at path (removed first if it exists)."""
    shutil.rmtree(path, ignore_errors=True)
    os.makedirs(path)


def mpi_env():
    """The environment for mpiexec runs: root allowed (containers), oversubscription allowed (2-core machines),
    one OpenMP thread per rank."""
    env = dict(os.environ)
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    env.setdefault("OMPI_MCA_rmaps_base_oversubscribe", "1")
    env.setdefault("OMP_NUM_THREADS", "1")
    return env
