#pragma once
/// @file AnalyticShapes.h
/// @brief Closed, outward-oriented, edge-manifold triangle surfaces and an exact tet mesh,
/// generated in code: test fixtures and simple parts that need no input file.
///
/// Data flow: these shapes feed the tetrahedralizer (surfaces) or the GDF stages directly
/// (boxTetMesh) wherever a test needs a mesh whose geometry is known exactly.
#include "mesh/TetMesh.h"

#include <functional>
#include <utility>
#include <vector>

namespace geolattice {

/// @brief Surface of the axis-aligned box [0,sx] x [0,sy] x [0,sz] (mm).
/// Every face is a regular grid of right triangles; the grid step along each axis is the same
/// on every face that contains that axis, so faces share their boundary vertices (no
/// duplicates). Steps are chosen so that every triangle edge, the diagonals included, is
/// <= maxEdge. Triangles are counter-clockwise seen from outside.
/// @param size   box extents (sx, sy, sz) in mm, each > 0 and finite
/// @param maxEdge upper bound of the triangle edge length in mm, > 0
/// @throws GeoLatticeError on non-positive or non-finite arguments or more than 2^31 vertices.
TriangleSurface boxSurface(const Vec3& size, double maxEdge);

/// @brief Icosphere: a regular icosahedron subdivided subdivisionLevel times (each triangle
/// into 4) with every vertex projected onto the sphere. Level L has 20*4^L triangles and
/// 10*4^L + 2 vertices; counter-clockwise seen from outside.
/// @param centre centre (mm)
/// @param radius radius (mm), > 0
/// @param subdivisionLevel 0..10
/// @throws GeoLatticeError on a non-positive radius or a level outside 0..10.
TriangleSurface sphereSurface(const Vec3& centre, double radius, int subdivisionLevel);

/// @brief Torus lying on its side: the major circle (radius majorRadius about the centre) is in
/// the xz-plane, the axis is +y, and the tube (radius minorRadius) touches z = centre.z -
/// majorRadius - minorRadius at one point. A u-v grid of majorSegments x minorSegments quads,
/// each split into two triangles, counter-clockwise seen from outside. Used as a part whose
/// curved layers split into two arcs and merge again (a skeleton DAG).
/// @throws GeoLatticeError unless 0 < minorRadius < majorRadius and both segment counts are in 3..4096.
TriangleSurface torusSurface(const Vec3& centre, double majorRadius, double minorRadius,
                             int majorSegments, int minorSegments);

/// @brief Surface of revolution about the z axis: the profile's (radius, z) points revolved
/// with `segments` points on each circle; the first and last profile points lie on the axis
/// (radius 0, the poles). Counter-clockwise seen from outside for a profile that runs from the
/// bottom pole outwards and up.
/// @throws GeoLatticeError for fewer than 3 profile points or 3 segments.
TriangleSurface revolvedSurface(const std::vector<std::pair<double, double>>& profile,
                                int segments);

/// @brief Structured tet mesh of the box [0,sx] x [0,sy] x [0,sz] (mm) with nx*ny*nz cells,
/// each cell split into 6 tets along its main diagonal (Kuhn / Freudenthal split). The split
/// is the same in every cell, so the mesh is conforming. Every tet is positively oriented.
/// Vertex (i,j,k) has id i + (nx+1)*(j + (ny+1)*k); #V = (nx+1)(ny+1)(nz+1), #T = 6*nx*ny*nz.
/// @throws GeoLatticeError on non-positive sizes or counts, or more than 2^31 tets.
TetMesh boxTetMesh(const Vec3& size, int nx, int ny, int nz);

/// @brief A conforming voxel solid: the tets of boxTetMesh(size, nx, ny, nz) whose cell centre
/// satisfies `keep`, unused vertices removed (e.g. a T-shaped "mushroom" with a flat overhang).
TetMesh voxelTetMesh(const Vec3& size, int nx, int ny, int nz,
                     const std::function<bool(const Vec3&)>& keep);

}  // namespace geolattice
