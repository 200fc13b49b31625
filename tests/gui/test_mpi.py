"""MPI test: the GeoLattice pipeline under `mpiexec -n 2 pvbatch` gives the same data as serial pvbatch,
and no rank reports an error.

Runs tests/gui/pipeline_summary.py with `pvbatch`, then twice with `mpiexec -n 2 pvbatch`, and compares
the summaries (class, counts, array names/tuples/components, Gamma range) of every output with the
serial ones:

1. As a user would: GL Mesh Reader cannot split a file, so ParaView runs it on rank 0 only and rank 1
   gets empty inputs. Every GeoLattice filter is a global algorithm (filters/vtkGLParallel.h): the rank
   that holds the data computes, the others output empty data without a message. (Before, every
   filter on rank 1 reported an "empty input" error.)
2. With --partition-tets: the tet mesh split over the two ranks (half of the tets each) before GL
   Geodesic Distance Fields, which gathers the parts on rank 0; the results must still equal the
   serial ones. (ParaView's Redistribute DataSet cannot make the partition here: on Debian 12 rank 1
   rejects the data it receives, "vtkXMLDataParser: not well-formed (invalid token)", the patched
   expat problem of the shared build notes, and keeps nothing.)

Every run also writes the waypoint CSV with GL Waypoint CSV Writer (a writer proxy, which ParaView
updates on every process with the whole data: only rank 0 writes) and compares its row count. Each MPI
run fails on any "ERR|" line of any rank, and run 2 on a partition that left a rank without tets. Exit code 0 = same results and no errors, 1 = different or failed, 77 = skipped (no mpiexec or
pvbatch). Environment: GEOLATTICE_PLUGIN, GEOLATTICE_SOURCE_DIR, PVBATCH, MPIEXEC (defaults: on the
PATH)."""
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
    mpi = [mpiexec, "-n", "2"]
    runs = (("serial", [], []), ("mpi", mpi, []), ("mpi partitioned tets", mpi, ["--partition-tets"]))
    failed = False
    try:
        results, seconds = {}, {}
        for name, prefix, options in runs:
            path = os.path.join(work, name.replace(" ", "_") + ".json")
            csv = os.path.join(work, name.replace(" ", "_") + ".csv")
            rc, out, seconds[name] = run(prefix + [pvbatch, script, path, "--waypoints", csv] + options, env, 300)
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
            if errors:
                print("FAIL: %s: %d error lines (every rank must stay quiet)" % (name, len(errors)))
                failed = True
            if options:
                shares = [int(m) for m in re.findall(r"partition-tets: rank \d+ of 2 keeps (\d+) of \d+ tets "
                                                     r"\(piece \d of 2\)", out)]
                print("   tets per rank after the partition: %s" % shares)
                if len(shares) != 2 or min(shares) == 0:
                    print("FAIL: %s: the tet mesh was not split over both ranks" % name)
                    failed = True
            with open(path) as f:
                results[name] = json.load(f)
            if not results[name].get("waypoints.csv", {}).get("points"):
                print("FAIL: %s: no waypoint CSV written" % name)
                failed = True
    finally:
        shutil.rmtree(work, ignore_errors=True)
    for name, _, _ in runs[1:]:
        problems = compare(results["serial"], results[name])
        if problems:
            print("FAIL: %s differs from serial pvbatch:\n  %s" % (name, "\n  ".join(problems)))
            failed = True
    if failed:
        return 1
    print("PASS: %d outputs identical under serial pvbatch, mpiexec -n 2 pvbatch and mpiexec -n 2 pvbatch with "
          "the tet mesh partitioned; no error on any rank" % len(results["serial"]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
