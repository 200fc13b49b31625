"""Checks of a written closed triangle surface (OBJ), shared by make-test-shapes.py and
make-printhead.py: read back with VTK's reader, what a mesher or the printhead loader would
refuse is counted (open or non-manifold edges, inconsistent orientation, degenerate triangles,
more than one piece), and the volume, genus and bounding box are measured."""
import numpy as np

from vtkmodules.vtkFiltersCore import vtkFeatureEdges, vtkMassProperties, vtkPolyDataConnectivityFilter
from vtkmodules.vtkIOGeometry import vtkOBJReader
from vtkmodules.util.numpy_support import vtk_to_numpy


def signed_volume(V, F):
    """Divergence-theorem volume of a closed triangle mesh (positive when it is outward)."""
    a, b, c = V[F[:, 0]], V[F[:, 1]], V[F[:, 2]]
    return np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6.0


def _feature_edge_count(pd, boundary, nonmanifold):
    fe = vtkFeatureEdges()
    fe.SetInputData(pd)
    fe.SetBoundaryEdges(boundary)
    fe.SetNonManifoldEdges(nonmanifold)
    fe.FeatureEdgesOff()
    fe.ManifoldEdgesOff()
    fe.Update()
    return fe.GetOutput().GetNumberOfCells()


def check_obj(path):
    """The counts and measures of the OBJ at `path` (a dict), with its vertices V and triangles F
    (0-based) for checks of a script's own."""
    r = vtkOBJReader()
    r.SetFileName(path)
    r.Update()
    pd = r.GetOutput()
    V = vtk_to_numpy(pd.GetPoints().GetData()).astype(float)
    F = vtk_to_numpy(pd.GetPolys().GetConnectivityArray()).reshape(-1, 3).astype(np.int64)
    out = dict(V=V, F=F, vertices=len(V), triangles=len(F))
    out["boundary"] = _feature_edge_count(pd, True, False)
    out["nonmanifold"] = _feature_edge_count(pd, False, True)
    conn = vtkPolyDataConnectivityFilter()
    conn.SetInputData(pd)
    conn.SetExtractionModeToAllRegions()
    conn.Update()
    out["components"] = conn.GetNumberOfExtractedRegions()
    mp = vtkMassProperties()
    mp.SetInputData(pd)
    mp.Update()
    out["vtk_volume"] = mp.GetVolume()
    out["area"] = mp.GetSurfaceArea()
    out["signed_volume"] = signed_volume(V, F)
    d = np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]])
    _, dcount = np.unique(d, axis=0, return_counts=True)
    out["inconsistent"] = int(np.count_nonzero(dcount > 1))  # a directed edge used twice
    E = np.unique(np.sort(d, axis=1), axis=0)
    out["euler"] = len(np.unique(F)) - len(E) + len(F)
    out["genus"] = (2 - out["euler"]) / 2.0
    lo, hi = V.min(axis=0), V.max(axis=0)
    out["bbox"] = (lo, hi)
    diag = float(np.linalg.norm(hi - lo))
    area = 0.5 * np.linalg.norm(np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]]), axis=1)
    out["degenerate"] = int(np.count_nonzero(area <= 1e-12 * diag * diag))
    return out
