#pragma once
/// @file MeshReader.h
/// @brief Readers and writers for plain-text mesh formats: OFF and Wavefront OBJ surfaces
/// (OBJ so that core-only code, tests and benchmarks read surfaces without VTK), the
/// research codes' `.tet` tet meshes and TetGen `.node`/`.ele` pairs.
///
/// Data flow: file -> TriangleSurface / TetMesh (core containers, coordinates as stored in the
/// file, no unit conversion) -> filters/vtkGLMeshReader -> rest of the pipeline.
/// Every function throws geolattice::GeoLatticeError naming the file, and for a malformed
/// line the 1-based line number (`file:line: message`). Nothing is printed.
#include "mesh/TetMesh.h"

#include <string>

namespace geolattice {

/// Read an OFF surface (header `OFF`, `COFF`, `NOFF`, `CNOFF` or `NCOFF`; the counts
/// `#V #F #E` may follow on the header line or on the next line).
/// Vertex lines: `x y z` (extra values such as normals or colours are ignored).
/// Face lines: `n i_0 ... i_{n-1}` with 0-based indices (trailing colour values ignored);
/// polygons with n > 3 are fan-triangulated (i_0, i_k, i_{k+1}), keeping their orientation.
/// '#' starts a comment; blank lines are skipped.
/// @return #V points and #triangles (>= #F) vertex triples.
/// @throws GeoLatticeError on a missing/unreadable file, a malformed line, an index out of
///   range, fewer or more data lines than the header counts, or no vertices/faces.
TriangleSurface readOff(const std::string& path);

/// Read the triangles of a Wavefront OBJ surface. Only two kinds of lines are used:
/// `v x y z [w | r g b]` (the first three values are the position) and
/// `f i j k ...` where each vertex reference has the form `v`, `v/vt`, `v/vt/vn` or `v//vn`
/// (only v is used). Indices are 1-based; a negative index is relative to the vertices read so
/// far (-1 = the last `v` line before the face). Positive indices may refer to vertices defined
/// later in the file. Polygons with n > 3 vertices are fan-triangulated (i_0, i_k, i_{k+1}),
/// keeping their orientation. Every other line (vt, vn, g, o, s, usemtl, mtllib, l, ...) is
/// ignored; '#' starts a comment. All vertices are kept, also those no face uses.
/// @return #V points (file order) and #triangles 0-based vertex triples.
/// @throws GeoLatticeError on a missing/unreadable file, a malformed `v` or `f` line, index 0,
///   an index out of range (with the face's line), or a file without vertices or faces.
TriangleSurface readObj(const std::string& path);

/// Write `surface` as a Wavefront OBJ file: the lines of `comment` (may be empty) as '#'
/// comments, then one `v x y z` line per point (shortest round-trip form, so readObj(path)
/// gives back exactly the same points) and one `f i j k` line per triangle (1-based). Like
/// writeTetFile, the data goes to `path + ".tmp"`, renamed to `path` after a successful write.
/// @throws GeoLatticeError on an empty surface, an index out of range, a non-finite point, or
///   an I/O failure.
void writeObj(const std::string& path, const TriangleSurface& surface,
              const std::string& comment = "");

/// Read a `.tet` file: line 1 `N vertices`, line 2 `M tets`, then N lines `x y z`, then M
/// lines `4 a b c d` (0-based indices). The words after the counts are optional.
/// '#' comments and blank lines are skipped.
/// @return N points and M tets, in file order (orientation as stored).
/// @throws GeoLatticeError as readOff, plus a tet line that does not start with 4.
TetMesh readTetFile(const std::string& path);

/// Read a TetGen mesh given the path of either its `.node` or its `.ele` file; the other file
/// is the same path with the other extension (same letter case). The first point number in
/// the `.node` file (0 or 1) sets the numbering used by the `.ele` file. Point attributes,
/// boundary markers and tet attributes are skipped; for 10-node (quadratic) tets the 4 corner
/// nodes are kept.
/// @throws GeoLatticeError as readOff, plus a dimension other than 3, non-consecutive point
///   numbers, or a path without a .node/.ele extension.
TetMesh readTetGenMesh(const std::string& path);

/// Write `mesh` as a `.tet` file (format of readTetFile, coordinates in shortest round-trip
/// form, so readTetFile(path) gives back exactly the same mesh). The data goes to
/// `path + ".tmp"`, which is renamed to `path` only after a successful write, so a failed
/// write never leaves a partial `path` behind.
/// @throws GeoLatticeError on an empty mesh, an index out of range, or an I/O failure.
void writeTetFile(const std::string& path, const TetMesh& mesh);

}  // namespace geolattice
