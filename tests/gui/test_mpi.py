"""MPI test: the GeoLattice pipeline under `mpiexec -n 2 pvbatch` gives the same data as serial pvbatch.

Runs tests/gui/pipeline_summary.py once with `pvbatch` and once with `mpiexec -n 2 pvbatch` and
compares the summaries (class, counts, array names/tuples/components, Gamma range) of every output.

What happens under MPI (ParaView 5.11): GL Mesh Reader cannot split a file, so only rank 0 gets the
model; rank 1 gets empty inputs and every GeoLattice filter there reports an "empty input" error (the
test prints how many), while rank 0 computes everything on the whole model, so the gathered results
equal the serial ones. The filters are not parallel-aware: on a partitioned mesh (e.g. after
Redistribute DataSet) each rank would compute on its part only, without a warning; this test does not
cover that case.

Exit code 0 = same results, 1 = different or failed, 77 = skipped (no mpiexec or pvbatch).
Environment: GEOLATTICE_PLUGIN, GEOLATTICE_SOURCE_DIR, PVBATCH, MPIEXEC (defaults: on the PATH)."""
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

SKIP = 77
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from summary_compare import compare  # noqa: E402


def run(command, env, timeout):
    start = time.time()
    proc = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env,
                            start_new_session=True)
    try:
        out, _ = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        out, _ = proc.communicate()
        return None, out, time.time() - start
    finally:
        try:
            os.killpg(proc.pid, signal.SIGKILL)  # leftover ranks, if any
        except ProcessLookupError:
            pass
    return proc.returncode, out, time.time() - start


def main():
    pvbatch = os.environ.get("PVBATCH") or shutil.which("pvbatch")
    mpiexec = os.environ.get("MPIEXEC") or shutil.which("mpiexec")
    if not pvbatch or not mpiexec:
        print("SKIPPED: %s not found" % ("pvbatch" if not pvbatch else "mpiexec"))
        return SKIP
    env = dict(os.environ)
    # Open MPI refuses to run as root without these and may count fewer slots than 2 on a small machine.
    env.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OMPI_MCA_rmaps_base_oversubscribe="1")
    work = tempfile.mkdtemp(prefix="geolattice-mpi-")
    script = os.path.join(HERE, "pipeline_summary.py")
    try:
        results, seconds = {}, {}
        for name, prefix in (("serial", []), ("mpi", [mpiexec, "-n", "2"])):
            path = os.path.join(work, name + ".json")
            rc, out, seconds[name] = run(prefix + [pvbatch, script, path], env, 300)
            errors = [l for l in out.splitlines() if "ERR|" in l]
            by_rank = {}
            for line in errors:
                rank = re.search(r"\[pvbatch(?:\.(\d+))?", line)
                by_rank.setdefault("rank " + ((rank.group(1) or "0") if rank else "?"), []).append(line)
            print("%s: %.1f s, exit code %s, error lines per rank %s" % (
                name, seconds[name], rc, {k: len(v) for k, v in sorted(by_rank.items())}))
            for line in errors[:20]:
                print("   " + re.sub(r"\x1b\[[0-9;]*m", "", line).strip()[:200])
            if rc != 0 or not os.path.isfile(path):
                print("FAIL: %s run failed (exit code %s):\n%s" % (name, rc, out[-3000:]))
                return 1
            with open(path) as f:
                results[name] = json.load(f)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    problems = compare(results["serial"], results["mpi"])
    if problems:
        print("FAIL: mpiexec -n 2 pvbatch differs from serial pvbatch:\n  " + "\n  ".join(problems))
        return 1
    print("PASS: %d outputs identical under mpiexec -n 2 pvbatch and serial pvbatch" % len(results["serial"]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
