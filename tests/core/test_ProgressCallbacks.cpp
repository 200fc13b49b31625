// The progress and abort callbacks of the long core algorithms (common/Progress.h) on the
// branching Y: the fractions never go back and end at 1, the results are exactly those of a run
// without callbacks, and an abort stops with a GeoLatticeError "... aborted" (a solver whose
// solve() was aborted stays usable).
#include "common/Error.h"
#include "common/Progress.h"
#include "gdf/GeodesicDistanceFields.h"
#include "gdf/HeatSources.h"
#include "io/MeshReader.h"
#include "lattice/LatticeInfill.h"
#include "sequence/PotentialCollisions.h"
#include "sequence/PrintMaterial.h"
#include "sequence/PrintSequencer.h"
#include "skeleton/SkeletonTree.h"
#include "slicer/CurvedLayerSlicer.h"
#include "tetrahedralize/TetrahedralizeSurface.h"

#include <gtest/gtest.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

using namespace geolattice;

namespace {

/// Records the progress values; abortAfter >= 0: shouldAbort returns true once that many values
/// were reported.
struct Recorder {
  std::vector<double> values;
  int abortAfter = -1;
  int polls = 0;
  std::function<void(double)> progress() {
    return [this](double f) {
      values.push_back(f);
    };
  }
  std::function<bool()> shouldAbort() {
    return [this] {
      ++polls;
      return abortAfter >= 0 && static_cast<int>(values.size()) >= abortAfter;
    };
  }
  /// Gives a stage's options this recorder's progress and abort callbacks.
  template <class Options>
  void attach(Options& options) {
    options.progress = progress();
    options.shouldAbort = shouldAbort();
  }
  /// Non-decreasing, in [0, 1], ending at 1, with at least minDistinct distinct values.
  void expectComplete(size_t minDistinct) const {
    ASSERT_FALSE(values.empty());
    std::vector<double> distinct;
    for (size_t i = 0; i < values.size(); ++i) {
      EXPECT_GE(values[i], 0.0);
      EXPECT_LE(values[i], 1.0);
      if (i > 0) {
        EXPECT_GE(values[i], values[i - 1]) << "at " << i;
      }
      if (distinct.empty() || distinct.back() != values[i]) {
        distinct.push_back(values[i]);
      }
    }
    EXPECT_EQ(values.back(), 1.0);
    EXPECT_GE(distinct.size(), minDistinct);
    EXPECT_GT(polls, 0);
  }
};

template <class F>
std::string abortMessage(F&& f) {
  try {
    f();
  } catch (const GeoLatticeError& e) {
    return e.what();
  }
  return "(no exception)";
}

/// The branching Y up to the material samples, without callbacks (the reference).
struct YPart {
  TriangleSurface surface;
  TetMesh mesh;
  std::vector<int> sources;
  GeodesicFields fields;
  CurvedLayers layers;
  LatticeGraph lattice;
  SkeletonTree tree;
  MaterialSamples material;
  NozzleModel nozzle;
};

const YPart& yPart() {
  static const std::unique_ptr<YPart> part = [] {
    auto p = std::make_unique<YPart>();
    p->surface = readObj(std::string(GEOLATTICE_TESTDATA) + "/y_shape.obj");
    TetrahedralizeOptions t;
    t.targetEdgeLength = 2.5;
    p->mesh = tetrahedralizeSurface(p->surface, t).mesh;
    p->sources = sourcesNearLowestZ(p->mesh, 0.5);
    p->fields = computeGeodesicDistanceFields(p->mesh, p->sources);
    p->layers =
        sliceCurvedLayers(p->mesh, p->fields.gamma, p->fields.alpha, p->fields.beta,
                          vertexGradientDirections(p->mesh, p->fields.gamma), SlicerOptions{});
    LatticeOptions lo;
    lo.alphaWidth = lo.betaWidth = 4.0;
    p->lattice = buildLatticeGraph(p->layers, lo);
    p->tree = buildSkeletonTree(p->mesh, p->fields.gamma, p->lattice);
    p->material = sampleLatticeMaterial(p->lattice, 1.0);
    return p;
  }();
  return *part;
}

}  // namespace

TEST(ProgressReporter, MapsPartsAndThrowsOnAbort) {
  Recorder r;
  const std::function<void(double)> progress = r.progress();
  const std::function<bool()> shouldAbort = r.shouldAbort();
  const ProgressReporter whole(progress, shouldAbort, "test");
  whole.report(0.5);
  const ProgressReporter half = whole.part(0.5, 1.0);
  half.report(0.5);
  half.part(0.5, 1.0).report(2.0);  // clamped to the part's end
  for (size_t i = 0; i < 1000; ++i) {
    whole.part(0.0, 0.1).loop(i, 1000);
  }
  EXPECT_EQ(r.values[0], 0.5);
  EXPECT_EQ(r.values[1], 0.75);
  EXPECT_EQ(r.values[2], 1.0);
  EXPECT_LE(r.values.size(), 3u + 64u);  // a long loop reports at most 64 times
  EXPECT_GE(r.values.size(), 3u + 60u);
  r.abortAfter = 0;
  EXPECT_EQ(abortMessage([&] { whole.report(0.9); }), "test aborted");
  // No callbacks: nothing happens.
  const std::function<void(double)> none;
  const std::function<bool()> never;
  EXPECT_NO_THROW(ProgressReporter(none, never, "test").report(1.0));
}

TEST(ProgressCallbacks, TetrahedralizeReportsEveryRunAndAborts) {
  const YPart& y = yPart();
  Recorder r;
  TetrahedralizeOptions t;
  t.targetEdgeLength = 2.5;
  r.attach(t);
  const TetMesh mesh = tetrahedralizeSurface(y.surface, t).mesh;
  r.expectComplete(2);
  EXPECT_EQ(mesh.points, y.mesh.points);
  EXPECT_EQ(mesh.tets, y.mesh.tets);
  // The automatic edge length reports after each TetGen run.
  Recorder automatic;
  TetrahedralizeOptions a;
  a.autoTargetTets = 5000;
  automatic.attach(a);
  const TetrahedralizeResult result = tetrahedralizeSurface(y.surface, a);
  automatic.expectComplete(2);
  // (plus the surface preparation's, when this coarse target remeshes the Y's finer surface)
  EXPECT_EQ(automatic.values.size(),
            static_cast<size_t>(result.attempts) + 1 + (result.simplified ? 1 : 0));
  // Abort while TetGen runs (the first poll).
  Recorder stop;
  stop.abortAfter = 0;
  stop.attach(t);
  EXPECT_EQ(abortMessage([&] { tetrahedralizeSurface(y.surface, t); }),
            "tetrahedralization aborted");
}

TEST(ProgressCallbacks, GeodesicFieldsSetUpAndSolveReportAndAbort) {
  const YPart& y = yPart();
  Recorder r;
  GeodesicFieldOptions o;
  r.attach(o);
  GeodesicDistanceFields solver(y.mesh, o);
  r.expectComplete(4);  // set-up: assembly, two factorizations, topology
  r.values.clear();
  const GeodesicFields f = solver.solve(y.sources);
  r.expectComplete(6);  // Dirichlet factorization, heat solve, γ, directions, α and β, statistics
  EXPECT_EQ(f.gamma, y.fields.gamma);
  EXPECT_EQ(f.alpha, y.fields.alpha);
  EXPECT_EQ(f.beta, y.fields.beta);

  // Aborted in the set-up.
  Recorder stop;
  stop.abortAfter = 2;
  stop.attach(o);
  EXPECT_EQ(abortMessage([&] { GeodesicDistanceFields aborted(y.mesh, o); }),
            "geodesic distance fields aborted");
  // Aborted in a solve (after the Dirichlet factorization), then solved again.
  stop.abortAfter = -1;
  stop.values.clear();
  GeodesicDistanceFields second(y.mesh, o);
  stop.abortAfter = static_cast<int>(stop.values.size()) + 2;
  EXPECT_EQ(abortMessage([&] { second.solve(y.sources); }), "geodesic distance fields aborted");
  stop.abortAfter = -1;
  const GeodesicFields again = second.solve(y.sources);
  EXPECT_EQ(again.gamma, y.fields.gamma);
  EXPECT_EQ(again.alpha, y.fields.alpha);
}

TEST(ProgressCallbacks, SlicerReportsPerTetAndAborts) {
  const YPart& y = yPart();
  Recorder r;
  SlicerOptions o;
  r.attach(o);
  const std::vector<Vec3> normals = vertexGradientDirections(y.mesh, y.fields.gamma);
  const CurvedLayers layers =
      sliceCurvedLayers(y.mesh, y.fields.gamma, y.fields.alpha, y.fields.beta, normals, o);
  r.expectComplete(40);
  EXPECT_EQ(layers.points, y.layers.points);
  EXPECT_EQ(layers.triangles, y.layers.triangles);
  EXPECT_EQ(layers.alpha, y.layers.alpha);
  Recorder stop;
  stop.abortAfter = 10;
  stop.attach(o);
  EXPECT_EQ(abortMessage([&] {
              sliceCurvedLayers(y.mesh, y.fields.gamma, y.fields.alpha, y.fields.beta, normals, o);
            }),
            "curved layer slicing aborted");
  EXPECT_EQ(stop.values.size(), 10u);  // stopped at the first poll after the 10th report
}

TEST(ProgressCallbacks, SkeletonTreeReportsAndAborts) {
  const YPart& y = yPart();
  Recorder r;
  SkeletonTreeOptions o;
  r.attach(o);
  const SkeletonTree tree = buildSkeletonTree(y.mesh, y.fields.gamma, y.lattice, o);
  r.expectComplete(20);
  EXPECT_EQ(tree.edges, y.tree.edges);
  EXPECT_EQ(tree.roots, y.tree.roots);
  Recorder stop;
  stop.abortAfter = 5;
  stop.attach(o);
  EXPECT_EQ(abortMessage([&] { buildSkeletonTree(y.mesh, y.fields.gamma, y.lattice, o); }),
            "skeleton tree aborted");
}

TEST(ProgressCallbacks, PotentialCollisionsOnWorkerThreadsReportAndAbort) {
  const YPart& y = yPart();
  const PotentialCollisions reference = computePotentialCollisions(y.material, y.nozzle, 2);
  for (int threads : {1, 2}) {
    SCOPED_TRACE(threads);
    Recorder r;
    PotentialCollisionOptions o;
    o.threads = threads;
    r.attach(o);
    const PotentialCollisions pcg = computePotentialCollisions(y.material, y.nozzle, o);
    r.expectComplete(threads == 1 ? 20 : 10);
    EXPECT_EQ(pcg.pcg, reference.pcg);
    EXPECT_EQ(pcg.pairs, reference.pairs);
    Recorder stop;
    stop.abortAfter = 3;
    stop.attach(o);
    EXPECT_EQ(abortMessage([&] { computePotentialCollisions(y.material, y.nozzle, o); }),
              "potential collisions aborted");
  }
}

TEST(ProgressCallbacks, SequencerReportsEveryStrategyAndAborts) {
  const YPart& y = yPart();
  const PotentialCollisions pcg = computePotentialCollisions(y.material, y.nozzle, 2);
  for (SequenceStrategy s : {SequenceStrategy::LayerPriority, SequenceStrategy::DepthPriority,
                             SequenceStrategy::Greedy, SequenceStrategy::Rollout}) {
    SCOPED_TRACE(sequenceStrategyName(s));
    SequenceOptions plain;
    plain.strategy = s;
    const PrintSequence reference = sequencePrint(y.tree, y.material, &pcg, plain);
    Recorder r;
    SequenceOptions o = plain;
    r.attach(o);
    const PrintSequence seq = sequencePrint(y.tree, y.material, &pcg, o);
    r.expectComplete(20);
    EXPECT_EQ(seq.order, reference.order);
    EXPECT_EQ(seq.retractions, reference.retractions);
    EXPECT_EQ(seq.airLength, reference.airLength);
    Recorder stop;
    stop.abortAfter = 8;
    stop.attach(o);
    EXPECT_EQ(abortMessage([&] { sequencePrint(y.tree, y.material, &pcg, o); }),
              "print sequencing aborted");
  }
}
