"""Shared by test_client_server.py and test_mpi.py (pvpython / pvbatch): the GeoLattice pipeline on a
small model and a summary of every output that must not depend on where the pipeline ran (class, point
and cell counts, the names, tuple counts and components of the point, cell and field arrays, and the
Gamma range); compare() (from summary_compare.py) says how two summaries differ.

    pvbatch tests/gui/pipeline_summary.py OUT.json [--remote] [--partition-tets] [--waypoints CSV]

runs the pipeline in this session (e.g. under `mpiexec -n 2 pvbatch`) and writes the summary.
--partition-tets puts a Programmable Filter between the tet mesh and GL Geodesic Distance Fields
that splits the mesh over the MPI ranks (rank 0 broadcasts it, each rank keeps its share of the
cells, in order): a partitioned input, which the GeoLattice filters gather on rank 0. With one
process it keeps the whole mesh. --waypoints writes the toolpath with GL Waypoint CSV Writer (a
writer proxy: ParaView updates it on every process) and adds its row count to the summary."""
import json
import os
import sys

SOURCE_DIR = os.environ.get("GEOLATTICE_SOURCE_DIR") or os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(SOURCE_DIR, "pvpython"))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import geolattice_pipeline as pipeline  # noqa: E402
from summary_compare import compare  # noqa: E402,F401
from paraview import servermanager, simple  # noqa: E402

MODEL = os.path.join(SOURCE_DIR, "testdata", "y_shape.obj")
PARAMETERS = dict(edge_length=2.5, base_tolerance=0.5)
# (key of build_pipeline, output port, time): every output up to the toolpath; None = no time.
OUTPUTS = [("reader", 0, None), ("place", 0, None), ("tets", 0, None), ("fields", 0, None), ("layers", 0, None),
           ("layers", 1, None), ("lattice", 0, None), ("skeleton", 0, None), ("sequencer", 0, None),
           ("sequencer", 1, None), ("sequencer", 2, None), ("verifier", 0, None), ("overhang", 0, None),
           ("toolpath", 0, 1.0), ("toolpath_verifier", 0, 1.0)]


def summary(proxies):
    result = {}
    for key, port, time_value in OUTPUTS:
        if key not in proxies:
            continue
        proxy = proxies[key]
        if time_value is None:
            proxy.UpdatePipeline()
        else:
            proxy.UpdatePipeline(time_value)
        data = servermanager.Fetch(proxy, idx=port)
        arrays = {}
        for kind, attributes in (("point", data.GetPointData()), ("cell", data.GetCellData()),
                                 ("field", data.GetFieldData())):
            for i in range(attributes.GetNumberOfArrays()):
                a = attributes.GetAbstractArray(i)
                arrays["%s/%s" % (kind, a.GetName())] = [a.GetNumberOfTuples(), a.GetNumberOfComponents()]
        entry = {"class": data.GetClassName(), "points": data.GetNumberOfPoints(), "cells": data.GetNumberOfCells(),
                 "arrays": arrays}
        gamma = data.GetPointData().GetArray("Gamma")
        if gamma is not None:
            entry["gamma"] = list(gamma.GetRange())
        result["%s:%d" % (key, port)] = entry
    return result


# The Programmable Filter of --partition-tets (runs on every rank; vtkExtractCells keeps the cell
# order and numbers the points by first use). It returns the requested piece: piece `rank` of
# `size` in ParaView's parallel updates (the mesh, on rank 0 only, is broadcast first), the whole
# mesh when the whole data is asked for (piece 0 of 1, e.g. for a writer proxy).
PARTITION_SCRIPT = """
from vtkmodules.vtkCommonCore import vtkIdList
from vtkmodules.vtkCommonDataModel import vtkUnstructuredGrid
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as sddp
from vtkmodules.vtkFiltersCore import vtkExtractCells
from vtkmodules.vtkParallelCore import vtkMultiProcessController
controller = vtkMultiProcessController.GetGlobalController()
rank, size = controller.GetLocalProcessId(), controller.GetNumberOfProcesses()
info = self.GetOutputInformation(0)
piece, pieces = info.Get(sddp.UPDATE_PIECE_NUMBER()), info.Get(sddp.UPDATE_NUMBER_OF_PIECES())
whole = vtkUnstructuredGrid()
whole.ShallowCopy(self.GetInput())
if size > 1 and pieces == size:
    controller.Broadcast(whole, 0)
else:
    piece, pieces = 0, 1
n = whole.GetNumberOfCells()
ids = vtkIdList()
for c in range(n * piece // pieces, n * (piece + 1) // pieces):
    ids.InsertNextId(c)
extract = vtkExtractCells()
extract.SetInputData(whole)
extract.SetCellList(ids)
extract.Update()
part = extract.GetOutput()
for data in (part.GetPointData(), part.GetCellData()):
    for name in ("vtkOriginalPointIds", "vtkOriginalCellIds"):
        data.RemoveArray(name)
self.GetOutput().ShallowCopy(part)
print("partition-tets: rank %d of %d keeps %d of %d tets (piece %d of %d)" % (
    rank, size, part.GetNumberOfCells(), n, piece, pieces))
"""


def write_waypoints(proxies, path):
    """Writes the toolpath's waypoint CSV; its summary entry holds the number of rows."""
    writer = servermanager.writers.GLWaypointCSVWriter(Input=proxies["toolpath"], FileName=path)
    writer.UpdatePipeline()
    rows = 0
    if os.path.isfile(path):
        with open(path) as f:
            rows = len(f.readlines()) - 1
    return {"class": "csv", "points": rows, "cells": 0, "arrays": {}}


def run(plugin, remote=False, partition_tets=False, waypoints=None):
    """Loads the plugin into the current session and returns the summary of the pipeline."""
    simple.LoadPlugin(plugin, remote=remote)
    proxies = pipeline.build_pipeline(MODEL, **PARAMETERS)
    if partition_tets:
        proxies["fields"].Input = simple.ProgrammableFilter(
            Input=proxies["tets"], OutputDataSetType="vtkUnstructuredGrid", Script=PARTITION_SCRIPT)
    result = summary(proxies)
    if waypoints:
        result["waypoints.csv"] = write_waypoints(proxies, waypoints)
    return result


if __name__ == "__main__":
    plugin = os.environ.get("GEOLATTICE_PLUGIN") or os.path.join(
        SOURCE_DIR, "build", "lib", "paraview-5.11", "plugins", "GeoLattice", "GeoLattice.so")
    waypoints = sys.argv[sys.argv.index("--waypoints") + 1] if "--waypoints" in sys.argv else None
    result = run(plugin, remote="--remote" in sys.argv, partition_tets="--partition-tets" in sys.argv,
                 waypoints=waypoints)
    with open(sys.argv[1], "w") as f:
        json.dump(result, f, indent=1, sort_keys=True)
