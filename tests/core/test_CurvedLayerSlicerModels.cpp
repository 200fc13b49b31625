// Curved layers of real parts (the bunny and the branching Y): every layer is an edge-manifold,
// consistently oriented mesh with no zero-area triangle, its points lie exactly on γ = φ_i, and
// no two layers intersect (checked geometrically with CGAL's AABB tree).
#include "gdf/GeodesicDistanceFields.h"
#include "gdf/HeatSources.h"
#include "io/MeshReader.h"
#include "slicer/CurvedLayerSlicer.h"
#include "tetrahedralize/TetrahedralizeSurface.h"

#include "LayerChecks.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <gtest/gtest.h>

using namespace geolattice;

namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Triangle = Kernel::Triangle_3;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, std::vector<Triangle>::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

/// Triangles of different layers that intersect (touching included).
long countLayerIntersections(const CurvedLayers& layers) {
  std::vector<Triangle> triangles;
  triangles.reserve(layers.triangles.size());
  for (const auto& t : layers.triangles) {
    auto p = [&](int i) {
      return Kernel::Point_3(layers.points[i].x(), layers.points[i].y(), layers.points[i].z());
    };
    triangles.emplace_back(p(t[0]), p(t[1]), p(t[2]));
  }
  Tree tree(triangles.cbegin(), triangles.cend());
  long bad = 0;
  std::vector<Primitive::Id> hits;
  for (size_t k = 0; k < triangles.size(); ++k) {
    hits.clear();
    tree.all_intersected_primitives(triangles[k], std::back_inserter(hits));
    for (const auto& id : hits) {
      const size_t other = static_cast<size_t>(id - triangles.cbegin());
      if (layers.triangleLayer[other] != layers.triangleLayer[k]) {
        ++bad;
      }
    }
  }
  return bad;
}

void checkModel(const std::string& file, double fitHeight, double edgeLength,
                double baseTolerance) {
  TriangleSurface surface = readObj(std::string(GEOLATTICE_TESTDATA) + "/" + file);
  Eigen::AlignedBox3d box;
  for (const Vec3& p : surface.points) {
    box.extend(p);
  }
  const double scale = fitHeight / box.sizes().maxCoeff();
  for (Vec3& p : surface.points) {
    p = (p - Vec3(0, 0, box.min().z())) * scale;
  }
  TetrahedralizeOptions meshing;
  meshing.targetEdgeLength = edgeLength;
  const TetMesh mesh = tetrahedralizeSurface(surface, meshing).mesh;
  const GeodesicFields f =
      computeGeodesicDistanceFields(mesh, sourcesNearLowestZ(mesh, baseTolerance));
  SlicerOptions options;  // 0.6 mm layers
  const CurvedLayers layers = sliceCurvedLayers(mesh, f.gamma, f.alpha, f.beta,
                                                vertexGradientDirections(mesh, f.gamma), options);
  const double gmax = f.gamma.maxCoeff();
  ASSERT_EQ(static_cast<int>(layers.layerValues.size()),
            static_cast<int>(std::floor((gmax - 0.6) / 0.6)) + 1);
  for (size_t p = 0; p < layers.points.size(); ++p) {
    const auto [a, b] = layers.sourceEdge[p];
    const double t = layers.edgeParameter[p];
    ASSERT_LT(
        std::abs((1 - t) * f.gamma[a] + t * f.gamma[b] - layers.layerValues[layers.pointLayer[p]]),
        1e-9 * gmax);
  }
  for (const auto& t : layers.triangles) {
    ASSERT_GT((layers.points[t[1]] - layers.points[t[0]])
                  .cross(layers.points[t[2]] - layers.points[t[0]])
                  .norm(),
              0.0);
  }
  for (size_t l = 0; l < layers.layerValues.size(); ++l) {
    expectEdgeManifoldAndOriented(layers, static_cast<int>(l));
  }
  const long intersections = countLayerIntersections(layers);
  std::printf(
      "%s: %zu tets, %zu layers, %zu triangles, %ld intersecting triangle pairs between layers\n",
      file.c_str(), mesh.tets.size(), layers.layerValues.size(), layers.triangles.size(),
      intersections);
  EXPECT_EQ(intersections, 0);
}

}  // namespace

TEST(CurvedLayerSlicerModels, Bunny) {
  checkModel("bunny.obj", 80.0, 3.0, 0.5);
}

TEST(CurvedLayerSlicerModels, BranchingY) {
  checkModel("y_shape.obj", 45.0, 2.0, 0.05);
}
