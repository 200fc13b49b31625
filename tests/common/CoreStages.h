#pragma once
/// @file CoreStages.h
/// @brief The core stages from a surface to the skeleton tree, chained as the filters chain them,
/// for the tests and benchmarks that need a real lattice (core only, no VTK): a bundled model
/// scaled to a size, meshed, its fields (base: the vertices near the lowest z), curved layers,
/// lattice and skeleton.
#include "gdf/GeodesicDistanceFields.h"
#include "gdf/HeatSources.h"
#include "io/MeshReader.h"
#include "lattice/LatticeInfill.h"
#include "skeleton/SkeletonTree.h"
#include "slicer/CurvedLayerSlicer.h"
#include "tetrahedralize/TetrahedralizeSurface.h"

#include <Eigen/Geometry>

#include <string>
#include <vector>

namespace geolattice::fixtures {

/// A model of testdata/ (GEOLATTICE_TESTDATA) scaled uniformly so that its largest side is `size`
/// mm; its bounding box's lowest corner at the origin, or (centred) its footprint centred on x = y
/// = 0 and its lowest point at z = 0.
inline TriangleSurface scaledModel(const std::string& file, double size, bool centred = false) {
  TriangleSurface s = readObj(std::string(GEOLATTICE_TESTDATA) + "/" + file);
  Eigen::AlignedBox3d box;
  for (const Vec3& p : s.points) {
    box.extend(p);
  }
  const double scale = size / box.sizes().maxCoeff();
  const Vec3 origin = centred ? Vec3(box.center().x(), box.center().y(), box.min().z()) : box.min();
  for (Vec3& p : s.points) {
    p = (p - origin) * scale;
  }
  return s;
}

/// The last stage runCoreStages runs.
enum class CoreStage { Fields, Layers, Lattice, Skeleton };

/// How to run the stages: the tet size (an edge length, else a tet count), the base band, the
/// lattice width and where to stop.
struct CoreStageOptions {
  double edgeLength = 0;       ///< TetGen target edge length (mm); 0 = aim at targetTets
  int targetTets = 75000;      ///< used when edgeLength is 0
  double baseTolerance = 0.5;  ///< base = vertices within this of the lowest z (mm)
  double latticeWidth = 4.0;   ///< a = b (mm)
  CoreStage until = CoreStage::Skeleton;
};

/// Every intermediate result, for tests that look at more than the last one.
struct CoreStages {
  TetMesh mesh;
  GeodesicFields fields;
  std::vector<Vec3> normals;  ///< the layer normals at the vertices (∇γ directions)
  CurvedLayers layers;
  LatticeGraph lattice;
  SkeletonTree tree;
};

/// Mesh -> fields -> layers -> lattice -> skeleton (up to o.until) with every other option at
/// its default.
inline CoreStages runCoreStages(TetMesh mesh, const CoreStageOptions& o = {}) {
  CoreStages r;
  r.mesh = std::move(mesh);
  r.fields = computeGeodesicDistanceFields(r.mesh, sourcesNearLowestZ(r.mesh, o.baseTolerance));
  r.normals = vertexGradientDirections(r.mesh, r.fields.gamma);
  if (o.until == CoreStage::Fields) {
    return r;
  }
  r.layers = sliceCurvedLayers(r.mesh, r.fields.gamma, r.fields.alpha, r.fields.beta, r.normals,
                               SlicerOptions{});
  if (o.until == CoreStage::Layers) {
    return r;
  }
  LatticeOptions lo;
  lo.alphaWidth = lo.betaWidth = o.latticeWidth;
  r.lattice = buildLatticeGraph(r.layers, lo);
  if (o.until == CoreStage::Lattice) {
    return r;
  }
  r.tree = buildSkeletonTree(r.mesh, r.fields.gamma, r.lattice);
  return r;
}

/// The same from a surface: meshed first (TetGen, CoreStageOptions' tet size).
inline CoreStages runCoreStages(const TriangleSurface& surface, const CoreStageOptions& o = {}) {
  TetrahedralizeOptions t;
  if (o.edgeLength > 0) {
    t.targetEdgeLength = o.edgeLength;
  } else {
    t.autoTargetTets = o.targetTets;
  }
  return runCoreStages(tetrahedralizeSurface(surface, t).mesh, o);
}

/// The benchmarks' part: the bunny scaled to 100 mm and meshed to ~66k tets (the paper's bunny),
/// base 1 mm above its lowest point, up to `until`.
inline CoreStages paperBunny(CoreStage until, double latticeWidth = 4.0) {
  CoreStageOptions o;
  o.targetTets = 66000;
  o.baseTolerance = 1.0;
  o.latticeWidth = latticeWidth;
  o.until = until;
  return runCoreStages(scaledModel("bunny.obj", 100), o);
}

}  // namespace geolattice::fixtures
