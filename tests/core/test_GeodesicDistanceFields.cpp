// Accuracy and robustness of the heat-method GDF (paper Eqs. 1-5).
#include "common/Error.h"
#include "gdf/GeodesicDistanceFields.h"
#include "gdf/HeatSources.h"
#include "mesh/AnalyticShapes.h"
#include "mesh/TetMeshTopology.h"
#include "tetrahedralize/TetrahedralizeSurface.h"
#include "../common/ErrorOf.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>

using namespace geolattice;

namespace {

struct ErrorStats {
  double mean = 0;
  double max = 0;
};

template <class Expected>
ErrorStats fieldError(const TetMesh& mesh, const Eigen::VectorXd& field, Expected expected) {
  ErrorStats s;
  for (size_t v = 0; v < mesh.points.size(); ++v) {
    const double e = std::abs(field[v] - expected(mesh.points[v]));
    s.mean += e;
    s.max = std::max(s.max, e);
  }
  s.mean /= static_cast<double>(mesh.points.size());
  return s;
}

// Box 40 x 40 x 60 mm meshed by TetGen with a 1.5 mm target edge length.
const TetMesh& boxMesh() {
  static const TetMesh mesh = [] {
    TetrahedralizeOptions options;
    options.targetEdgeLength = 1.5;
    return tetrahedralizeSurface(boxSurface(Vec3(40, 40, 60), 1.5), options).mesh;
  }();
  return mesh;
}

const GeodesicFields& boxFields() {
  static const GeodesicFields fields =
      computeGeodesicDistanceFields(boxMesh(), sourcesNearLowestZ(boxMesh(), 1e-6));
  return fields;
}

}  // namespace

TEST(TetLaplacian, DivergenceOfGradientIsStiffnessTimesField) {
  const TetMesh mesh = boxTetMesh(Vec3(2, 3, 4), 3, 3, 4);
  const TetOperators ops = buildTetOperators(mesh);
  Eigen::VectorXd f(mesh.points.size());
  for (size_t v = 0; v < mesh.points.size(); ++v) {
    const Vec3& p = mesh.points[v];
    f[v] = p.x() * p.x() - 2 * p.y() + std::sin(p.z());
  }
  std::vector<Vec3> grad(mesh.tets.size());
  for (size_t t = 0; t < mesh.tets.size(); ++t) {
    grad[t] = tetGradient(ops, mesh, static_cast<int>(t), f);
  }
  const Eigen::VectorXd b = integratedDivergence(ops, mesh, grad);
  EXPECT_LT((b - ops.stiffness * f).norm(), 1e-10 * b.norm());
  EXPECT_NEAR(ops.vertexVolumes.sum(), 24.0, 1e-10);
  // Constants are in the null space of K.
  EXPECT_LT((ops.stiffness * Eigen::VectorXd::Ones(f.size())).norm(), 1e-12);
}

TEST(TetLaplacian, RejectsInvertedTet) {
  TetMesh mesh = boxTetMesh(Vec3(1, 1, 1), 1, 1, 1);
  std::swap(mesh.tets[2][0], mesh.tets[2][1]);
  const std::string m = expectedErrorOf([&] { buildTetOperators(mesh); });
  EXPECT_NE(m.find("inverted tet 2"), std::string::npos) << m;
}

TEST(GeodesicDistanceFields, BoxGammaIsHeightAlphaBetaAreAffine) {
  const TetMesh& mesh = boxMesh();
  const std::vector<int> sources = sourcesNearLowestZ(mesh, 1e-6);
  const GeodesicFields& f = boxFields();

  const ErrorStats gamma = fieldError(mesh, f.gamma, [](const Vec3& p) { return p.z(); });
  EXPECT_LT(gamma.mean, 0.005 * 60) << "mean |γ - z|";
  EXPECT_LT(gamma.max, 0.02 * 60) << "max |γ - z|";
  // r = (1,0,0), g_γ = +z: g_α = r × z = -y, g_β = g_α × g_γ = -x (Eq. 3).
  const ErrorStats alpha = fieldError(mesh, f.alpha, [](const Vec3& p) { return 40 - p.y(); });
  const ErrorStats beta = fieldError(mesh, f.beta, [](const Vec3& p) { return 40 - p.x(); });
  EXPECT_LT(alpha.mean, 0.005 * 40);
  EXPECT_LT(alpha.max, 0.02 * 40);
  EXPECT_LT(beta.mean, 0.005 * 40);
  EXPECT_LT(beta.max, 0.02 * 40);
  RecordProperty("gamma_mean_rel_pct", std::to_string(100 * gamma.mean / 60));
  RecordProperty("gamma_max_rel_pct", std::to_string(100 * gamma.max / 60));
  std::printf(
      "box: gamma mean %.4f%% max %.4f%%, alpha mean %.4f%% max %.4f%%, beta mean %.4f%% max "
      "%.4f%%\n",
      100 * gamma.mean / 60, 100 * gamma.max / 60, 100 * alpha.mean / 40, 100 * alpha.max / 40,
      100 * beta.mean / 40, 100 * beta.max / 40);
  for (int s : sources) {
    EXPECT_EQ(f.gamma[s], 0.0);
  }
  EXPECT_NEAR(f.alpha.minCoeff(), 0.0, 1e-12);
  EXPECT_NEAR(f.beta.minCoeff(), 0.0, 1e-12);
}

// Ball of radius 20 mm; the source is the ball of radius 2 mm around the centre. The 2 mm sphere
// is embedded in the tet mesh (an inner closed surface of the PLC), so the source region's
// boundary is a mesh surface and γ can be compared with |x| - 2 directly.
TEST(GeodesicDistanceFields, BallGammaIsDistanceToTheCentralBall) {
  TriangleSurface surface = sphereSurface(Vec3::Zero(), 20, 4);
  const TriangleSurface inner = sphereSurface(Vec3::Zero(), 2, 2);
  const int offset = static_cast<int>(surface.points.size());
  surface.points.insert(surface.points.end(), inner.points.begin(), inner.points.end());
  for (auto t : inner.triangles) {
    for (int& v : t) {
      v += offset;
    }
    surface.triangles.push_back(t);
  }
  TetrahedralizeOptions options;
  options.targetEdgeLength = 1.5;
  const TetMesh mesh = tetrahedralizeSurface(surface, options).mesh;
  std::vector<int> sources;
  for (size_t v = 0; v < mesh.points.size(); ++v) {
    if (mesh.points[v].norm() <= 2 + 1e-9) {
      sources.push_back(static_cast<int>(v));
    }
  }
  ASSERT_GT(sources.size(), 100u);
  const GeodesicFields f = computeGeodesicDistanceFields(mesh, sources);
  double relative = 0;
  int count = 0;
  for (size_t v = 0; v < mesh.points.size(); ++v) {
    const double d = mesh.points[v].norm() - 2;
    if (d > 1e-6) {
      relative += std::abs(f.gamma[v] - d) / d;
      ++count;
    }
  }
  relative /= count;
  std::printf("ball: mean relative error of γ vs |x| - 2: %.3f%% over %d vertices\n",
              100 * relative, count);
  EXPECT_LT(relative, 0.02);
}

TEST(GeodesicDistanceFields, DirectionsAreOrthonormalPerTet) {
  const TetMesh& mesh = boxMesh();
  const GeodesicFields& f = boxFields();
  ASSERT_EQ(f.gammaDirection.size(), mesh.tets.size());
  for (size_t t = 0; t < mesh.tets.size(); ++t) {
    ASSERT_LT(std::abs(f.alphaDirection[t].dot(f.gammaDirection[t])), 1e-9) << t;
    ASSERT_LT(std::abs(f.betaDirection[t].dot(f.gammaDirection[t])), 1e-9) << t;
    ASSERT_LT(std::abs(f.alphaDirection[t].dot(f.betaDirection[t])), 1e-9) << t;
    ASSERT_NEAR(f.gammaDirection[t].norm(), 1.0, 1e-12);
    ASSERT_NEAR(f.alphaDirection[t].norm(), 1.0, 1e-12);
  }
  EXPECT_EQ(f.referenceFallbackTets, 0);
  EXPECT_LT(f.orthogonalityDeviationDeg[1], 5.0);
}

TEST(GeodesicDistanceFields, ReferenceParallelToGammaFallsBackAndIsReported) {
  const TetMesh mesh = boxTetMesh(Vec3(10, 10, 20), 5, 5, 10);
  GeodesicFieldOptions options;
  options.reference = Vec3(0, 0, 1);  // (nearly) parallel to g_γ everywhere
  options.referenceParallelDeg = 45;
  options.turnReference = false;  // as given (the test below turns it)
  const GeodesicFields f =
      computeGeodesicDistanceFields(mesh, sourcesNearLowestZ(mesh, 1e-6), options);
  EXPECT_GT(f.referenceFallbackTets, static_cast<int>(mesh.tets.size()) * 9 / 10);
  for (size_t t = 0; t < mesh.tets.size(); ++t) {
    ASSERT_TRUE(f.alphaDirection[t].allFinite());
    ASSERT_NEAR(f.alphaDirection[t].norm(), 1.0, 1e-9);
    ASSERT_LT(std::abs(f.alphaDirection[t].dot(f.gammaDirection[t])), 1e-9);
  }
  EXPECT_TRUE(f.alpha.allFinite());
  EXPECT_GT(f.alpha.maxCoeff(), 9.0);  // a real field across the box, not zero
}

TEST(GeodesicDistanceFields, AReferenceAlongTheLayersNormalIsTurnedAcrossTheBuildDirection) {
  // A bar lying along x that grows from its x = 0 end (a figure's arm): g_γ is +x everywhere, so
  // the default r = x would leave every tet without lattice directions of its own. It is turned
  // to the horizontal direction across it; a bar growing up keeps r.
  const TetMesh bar = boxTetMesh(Vec3(30, 6, 6), 10, 2, 2);
  std::vector<int> end;
  for (size_t v = 0; v < bar.points.size(); ++v) {
    if (bar.points[v].x() < 1e-9) {
      end.push_back(static_cast<int>(v));
    }
  }
  const GeodesicFields turned = computeGeodesicDistanceFields(bar, end);
  EXPECT_TRUE(turned.referenceTurned);
  EXPECT_GT(turned.givenReferenceFallbackTets, static_cast<int>(bar.tets.size()) / 3);
  EXPECT_EQ(turned.referenceFallbackTets, 0);
  EXPECT_NEAR(turned.reference.norm(), 1.0, 1e-12);
  EXPECT_NEAR(turned.reference.z(), 0.0, 1e-12);   // across the build direction
  EXPECT_LT(std::abs(turned.reference.x()), 0.1);  // and across the bar
  GeodesicFieldOptions asGiven;
  asGiven.turnReference = false;
  const GeodesicFields kept = computeGeodesicDistanceFields(bar, end, asGiven);
  EXPECT_FALSE(kept.referenceTurned);
  EXPECT_EQ(kept.reference, Vec3(1, 0, 0));
  EXPECT_EQ(kept.referenceFallbackTets, turned.givenReferenceFallbackTets);
  const TetMesh column = boxTetMesh(Vec3(6, 6, 30), 2, 2, 10);
  const GeodesicFields upright =
      computeGeodesicDistanceFields(column, sourcesNearLowestZ(column, 1e-6));
  EXPECT_FALSE(upright.referenceTurned);
  EXPECT_EQ(upright.reference, Vec3(1, 0, 0));
}

TEST(GeodesicDistanceFields, SourceSelectionsAgreeOnTheBox) {
  const TetMesh mesh = boxTetMesh(Vec3(10, 10, 20), 5, 5, 10);
  const TetMeshTopology topology(mesh);
  const std::vector<int> lowest = sourcesNearLowestZ(mesh, 1e-6);
  EXPECT_EQ(sourcesFromDownwardFaces(mesh, topology, 10.0), lowest);
  std::vector<double> mask(mesh.points.size(), 0.0);
  for (int v : lowest) {
    mask[v] = 1.0;
  }
  EXPECT_EQ(sourcesFromMask(mesh, mask), lowest);
  EXPECT_THROW(sourcesFromMask(mesh, std::vector<double>(3, 1.0)), GeoLatticeError);
  EXPECT_THROW(sourcesNearLowestZ(mesh, -1.0), GeoLatticeError);
}

// A slab whose flat bottom is 2 degrees off level (rising 1.05 mm over its 30 mm): the band's
// lowest vertices are one edge, and the layers fan out sideways from it; with the flat band the
// bottom up to 0.6 mm is the base too, and the first layers lie along the bottom.
TEST(GeodesicDistanceFields, FlatBandTakesABottomThatIsNotLevel) {
  TetMesh slab = boxTetMesh(Vec3(30, 10, 6), 30, 10, 6);
  const double tilt = 2.0 * M_PI / 180.0;
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(-tilt, Vec3::UnitY()).toRotationMatrix();
  for (Vec3& p : slab.points) {
    p = turn * p;
  }
  const Vec3 up = turn * Vec3::UnitZ();
  const TetMeshTopology topology(slab);
  const BaseOptions base;
  const std::vector<int> edge = sourcesNearLowestZ(slab, base.tolerance);
  const std::vector<int> bottom =
      sourcesNearLowestZ(slab, base.tolerance, topology, base.flatBand, base.maxFaceAngleDeg);
  EXPECT_EQ(sourcesNearLowestZ(slab, base.tolerance, topology, 0.0, base.maxFaceAngleDeg), edge);
  EXPECT_TRUE(std::includes(bottom.begin(), bottom.end(), edge.begin(), edge.end()));
  double zmin = slab.points[edge.front()].z();
  int onBottom = 0;
  for (int v : bottom) {
    EXPECT_LE(slab.points[v].z(), zmin + base.flatBand + 1e-9);
    EXPECT_NEAR(slab.points[v].dot(up), 0.0, 1e-9) << "vertex " << v << " is not on the bottom";
    onBottom += 1;
  }
  // The bottom's vertices of faces lying wholly within 0.6 mm: its columns x = 0..17 mm
  // (0.6 / sin 2° = 17.2 mm), 11 vertices each; within 0.05 mm, x = 0 and 1 mm.
  EXPECT_EQ(onBottom, 18 * 11);
  EXPECT_EQ(edge.size(), 2u * 11u);

  // The first layers' normal over the band: along the slab's up with the flat band, leaning
  // sideways (a fan from the lowest edge) without it.
  const auto leanOverBand = [&](const std::vector<int>& sources) {
    const GeodesicFields f = computeGeodesicDistanceFields(slab, sources);
    double worst = 0;
    for (size_t t = 0; t < slab.tets.size(); ++t) {
      Vec3 c = Vec3::Zero();
      for (int v : slab.tets[t]) {
        c += slab.points[v] / 4.0;
      }
      const Vec3 local = turn.transpose() * c;  // the slab's own frame
      if (local.x() > 4 && local.x() < 14 && local.z() < 2) {
        worst = std::max(worst, std::acos(std::min(1.0, f.gammaDirection[t].dot(up))));
      }
    }
    return worst * 180.0 / M_PI;
  };
  EXPECT_LT(leanOverBand(bottom), 10.0);
  EXPECT_GT(leanOverBand(edge), 30.0);
  EXPECT_THROW(sourcesNearLowestZ(slab, base.tolerance, topology, -1.0, 10.0), GeoLatticeError);
  EXPECT_THROW(sourcesNearLowestZ(slab, base.tolerance, topology, 0.6, 200.0), GeoLatticeError);
}

TEST(GeodesicDistanceFields, BackendsAgree) {
  const TetMesh mesh = boxTetMesh(Vec3(10, 12, 20), 6, 6, 10);
  GeodesicFieldOptions options;
  const auto sources = sourcesNearLowestZ(mesh, 1e-6);
  const GeodesicFields a = computeGeodesicDistanceFields(mesh, sources, options);
  options.backend = CholeskyBackend::EigenLDLT;
  const GeodesicFields b = computeGeodesicDistanceFields(mesh, sources, options);
  EXPECT_LT((a.gamma - b.gamma).lpNorm<Eigen::Infinity>(), 1e-8);
  EXPECT_LT((a.alpha - b.alpha).lpNorm<Eigen::Infinity>(), 1e-8);
  EXPECT_LT((a.beta - b.beta).lpNorm<Eigen::Infinity>(), 1e-8);
}

TEST(GeodesicDistanceFields, DirichletGammaFromThePinnedFactorMatchesItsOwnFactorization) {
  // A few sources that include the lowest vertex (the pinned one): γ is solved with the pinned
  // Laplacian's factor and a 3 x 3 capacitance matrix instead of a factorization of its own.
  const TetMesh mesh = boxTetMesh(Vec3(10, 12, 20), 6, 6, 10);
  std::vector<int> sources = sourcesNearLowestZ(mesh, 1e-6);
  std::sort(sources.begin(), sources.end(), [&](int a, int b) {
    return mesh.points[a].z() < mesh.points[b].z() ||
           (mesh.points[a].z() == mesh.points[b].z() && a < b);
  });
  sources.resize(4);
  GeodesicDistanceFields solver(mesh);
  const GeodesicFields corrected = solver.solve(sources);
  ASSERT_TRUE(corrected.dirichletFromPinned);
  GeodesicFieldOptions eigen;
  eigen.backend = CholeskyBackend::EigenLDLT;
  const GeodesicFields factored = computeGeodesicDistanceFields(mesh, sources, eigen);
  EXPECT_FALSE(factored.dirichletFromPinned);
  EXPECT_LT((corrected.gamma - factored.gamma).lpNorm<Eigen::Infinity>(), 1e-9);
  EXPECT_LT((corrected.alpha - factored.alpha).lpNorm<Eigen::Infinity>(), 1e-9);
  for (int s : sources) {
    EXPECT_EQ(corrected.gamma[s], 0.0);
  }
  // Sources without the lowest vertex: the Dirichlet Laplacian is factored, same answer.
  std::vector<int> others = sourcesNearLowestZ(mesh, 1e-6);
  others.erase(std::find(others.begin(), others.end(), sources.front()));
  const GeodesicFields ownFactor = solver.solve(others);
  EXPECT_FALSE(ownFactor.dirichletFromPinned);
  EXPECT_LT((ownFactor.gamma - computeGeodesicDistanceFields(mesh, others, eigen).gamma)
                .lpNorm<Eigen::Infinity>(),
            1e-9);
  // Back to the first set: the correction again, the same fields.
  const GeodesicFields again = solver.solve(sources);
  EXPECT_TRUE(again.dirichletFromPinned);
  EXPECT_LT((again.gamma - corrected.gamma).lpNorm<Eigen::Infinity>(), 1e-12);
  // The lowest vertex alone (no other source to correct for): the pinned solve itself.
  const std::vector<int> lowest = {sources.front()};
  const GeodesicFields alone = solver.solve(lowest);
  EXPECT_TRUE(alone.dirichletFromPinned);
  EXPECT_LT((alone.gamma - computeGeodesicDistanceFields(mesh, lowest, eigen).gamma)
                .lpNorm<Eigen::Infinity>(),
            1e-9);
}

TEST(GeodesicDistanceFields, SolverIsReusedForNewSources) {
  const TetMesh mesh = boxTetMesh(Vec3(10, 10, 10), 5, 5, 5);
  GeodesicDistanceFields solver(mesh);
  const std::vector<int> bottom = sourcesNearLowestZ(mesh, 1e-6);
  std::vector<int> top;
  for (size_t v = 0; v < mesh.points.size(); ++v) {
    if (mesh.points[v].z() > 10 - 1e-9) {
      top.push_back(static_cast<int>(v));
    }
  }
  const GeodesicFields first = solver.solve(bottom);
  const GeodesicFields fromTop = solver.solve(top);
  const GeodesicFields again = solver.solve(bottom);
  // The cached factorizations give the same answers as a fresh solver.
  EXPECT_LT(
      (fromTop.gamma - computeGeodesicDistanceFields(mesh, top).gamma).lpNorm<Eigen::Infinity>(),
      1e-10);
  EXPECT_LT((again.gamma - first.gamma).lpNorm<Eigen::Infinity>(), 1e-12);
  double meanTop = 0;
  for (int v : top) {
    EXPECT_EQ(fromTop.gamma[v], 0.0);
    meanTop += first.gamma[v] / static_cast<double>(top.size());
  }
  EXPECT_NEAR(meanTop, 10.0, 0.3);  // coarse 2 mm Kuhn mesh: corners are off by up to ~1 mm
}

TEST(GeodesicDistanceFields, PinnedGammaAgreesWithTheDirichletOne) {
  // Without the Dirichlet factorization (the orientation search's set-up) γ is the pinned
  // Poisson solution started at 0: on the box from its bottom face it is the height too.
  const TetMesh mesh = boxTetMesh(Vec3(10, 10, 20), 5, 5, 10);
  const std::vector<int> bottom = sourcesNearLowestZ(mesh, 1e-6);
  GeodesicFieldOptions pinned;
  pinned.dirichletGamma = false;
  const GeodesicFields a = computeGeodesicDistanceFields(mesh, bottom, pinned);
  const GeodesicFields b = computeGeodesicDistanceFields(mesh, bottom);
  EXPECT_NEAR(a.gamma.minCoeff(), 0.0, 1e-12);
  double worst = 0;
  for (size_t v = 0; v < mesh.points.size(); ++v) {
    worst = std::max(worst, std::abs(a.gamma[v] - b.gamma[v]));
  }
  // Measured 1.35 mm (7 % of the height) on this coarse 2 mm mesh: the Neumann boundary bends
  // γ near the box's edges; good enough to rank orientations, not to print.
  EXPECT_LT(worst, 0.1 * 20);
  EXPECT_NEAR(a.gamma.maxCoeff(), b.gamma.maxCoeff(), 1.5);
}

TEST(GeodesicDistanceFields, BadInputIsReported) {
  const TetMesh mesh = boxTetMesh(Vec3(1, 1, 1), 2, 2, 2);
  GeodesicDistanceFields solver(mesh);
  EXPECT_THROW(solver.solve({}), GeoLatticeError);
  EXPECT_THROW(solver.solve({-1}), GeoLatticeError);
  EXPECT_THROW(solver.solve({static_cast<int>(mesh.points.size())}), GeoLatticeError);
  GeodesicFieldOptions zeroTime;
  zeroTime.timeFactor = 0;
  EXPECT_THROW(GeodesicDistanceFields(mesh, zeroTime), GeoLatticeError);
  GeodesicFieldOptions zeroRef;
  zeroRef.reference = Vec3::Zero();
  EXPECT_THROW(GeodesicDistanceFields(mesh, zeroRef), GeoLatticeError);
  EXPECT_THROW(GeodesicDistanceFields(TetMesh{}), GeoLatticeError);

  // Two disjoint boxes, the second 2 mm higher, with sources in only the first: the error says
  // which body floats, and how high, in the words of a print.
  TetMesh two = boxTetMesh(Vec3(1, 1, 1), 1, 1, 1);
  const int n = static_cast<int>(two.points.size());
  const size_t nt = two.tets.size();
  for (int v = 0; v < n; ++v) {
    two.points.push_back(two.points[v] + Vec3(5, 0, 2));
  }
  for (size_t t = 0; t < nt; ++t) {
    auto tet = two.tets[t];
    for (int& v : tet) {
      v += n;
    }
    two.tets.push_back(tet);
  }
  GeodesicDistanceFields twoSolver(two);
  EXPECT_EQ(twoSolver.componentCount(), 2);
  const std::string m = expectedErrorOf([&] { twoSolver.solve({0}); });
  EXPECT_NE(m.find("2 separate bodies and 1 of them does not touch the base"), std::string::npos)
      << m;
  EXPECT_NE(m.find("starts 2 mm above"), std::string::npos) << m;
  EXPECT_NO_THROW(twoSolver.solve({0, n}));
}
