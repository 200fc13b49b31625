"""Shared by test_client_server.py and test_mpi.py (pvpython / pvbatch): the GeoLattice pipeline on a
small model and a summary of every output that must not depend on where the pipeline ran (class, point
and cell counts, the names, tuple counts and components of the point, cell and field arrays, and the
Gamma range); compare() (from summary_compare.py) says how two summaries differ.

    pvbatch tests/gui/pipeline_summary.py OUT.json [--remote]

runs the pipeline in this session (e.g. under `mpiexec -n 2 pvbatch`) and writes the summary."""
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


def run(plugin, remote=False):
    """Loads the plugin into the current session and returns the summary of the pipeline."""
    simple.LoadPlugin(plugin, remote=remote)
    return summary(pipeline.build_pipeline(MODEL, **PARAMETERS))


if __name__ == "__main__":
    plugin = os.environ.get("GEOLATTICE_PLUGIN") or os.path.join(
        SOURCE_DIR, "build", "lib", "paraview-5.11", "plugins", "GeoLattice", "GeoLattice.so")
    result = run(plugin, remote="--remote" in sys.argv)
    with open(sys.argv[1], "w") as f:
        json.dump(result, f, indent=1, sort_keys=True)
