// The toolpath of whole parts (paper Section 3.2): every trimmed lattice edge printed once in
// one closed tour per sub-graph, no self-crossing, thickness capped (Eq. 15), extrusion by
// mass conservation (Eq. 14), safe air moves, and the independent collision verifier on the
// full path including the air moves.
#include "../common/CoreStages.h"
#include "collision/CollisionVerifier.h"
#include "common/Error.h"
#include "gdf/GeodesicDistanceFields.h"
#include "gdf/HeatSources.h"
#include "io/MeshReader.h"
#include "sequence/PotentialCollisions.h"
#include "sequence/PrintMaterial.h"
#include "sequence/PrintSequencer.h"
#include "skeleton/SkeletonTree.h"
#include "slicer/CurvedLayerSlicer.h"
#include "tetrahedralize/TetrahedralizeSurface.h"
#include "robot/RobotPathSolver.h"
#include "toolpath/ToolpathPlanner.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <tuple>
#include <string>

using namespace geolattice;

namespace {

struct Part {
  LatticeGraph lattice;
  SkeletonTree tree;
  PrintSequence sequence;
};

Part buildPart(const std::string& file, double size, double edge, double width,
               double nozzleAngle) {
  fixtures::CoreStageOptions o;
  o.edgeLength = edge;
  o.latticeWidth = width;
  fixtures::CoreStages stages = fixtures::runCoreStages(fixtures::scaledModel(file, size, true), o);
  Part p;
  p.lattice = std::move(stages.lattice);
  p.tree = std::move(stages.tree);
  const MaterialSamples m = sampleLatticeMaterial(p.lattice, 1.0);
  NozzleModel n;
  n.halfAngleDeg = nozzleAngle;
  const PotentialCollisions pcg = computePotentialCollisions(m, n);
  SequenceOptions so;
  so.strategy = SequenceStrategy::Rollout;
  p.sequence = sequencePrint(p.tree, m, &pcg, so);
  return p;
}

void expectGoodToolpath(const char* name, const Part& part, double nozzleAngle) {
  ToolpathOptions o;
  o.nozzle.halfAngleDeg = nozzleAngle;
  const Toolpath path = planToolpath(part.lattice, part.tree, part.sequence.order, o);
  const size_t N = path.points.size();
  ASSERT_GT(N, 0u);
  for (const auto* a : {&path.thickness, &path.width, &path.extrusion, &path.feedRate}) {
    ASSERT_EQ(a->size(), N);
  }
  // Every edge left after trimming printed exactly once: the print length is the lattice length
  // minus the trimmed boundary (rotation steps subdivide segments without changing length).
  double latticeLength = 0;
  for (const auto& e : part.lattice.edges)
    latticeLength += (part.lattice.points[e[0]] - part.lattice.points[e[1]]).norm();
  EXPECT_NEAR(path.printLength, latticeLength - path.trimmedLength, 1e-9 * latticeLength) << name;
  // One continuous path per sub-graph: retractions = tours - 1 = sub-graphs - 1 + extra pieces.
  EXPECT_EQ(path.retractions, path.tours - 1);
  EXPECT_GE(path.tours, static_cast<int>(part.lattice.subgraphs.size()));
  EXPECT_EQ(path.crossings, 0);
  // Thickness never above λφ.
  for (size_t i = 0; i < N; ++i) {
    if (path.kind[i] == MoveKind::Air)
      continue;
    const int l = path.layer[i];
    const double phi = l > 0 ? part.lattice.layerValues[l] - part.lattice.layerValues[l - 1]
                             : part.lattice.layerValues[0];
    ASSERT_LE(path.thickness[i], o.thicknessCap * phi * (1 + 1e-12)) << name << " point " << i;
    ASSERT_GT(path.thickness[i], 0.0);
  }
  // Mass conservation (Eq. 14) recomputed from the output arrays.
  double volume = 0, filament = 0;
  for (size_t i = 1; i < N; ++i) {
    if (path.kind[i] == MoveKind::Air)
      continue;
    const double h0 = path.kind[i - 1] == MoveKind::Air ? path.thickness[i]
                                                        : path.thickness[i - 1];  // as the planner
    volume += o.flowCorrection * path.width[i] * 0.5 * (h0 + path.thickness[i]) *
              (path.points[i] - path.points[i - 1]).norm();
    filament += path.extrusion[i] - path.extrusion[i - 1];
  }
  EXPECT_NEAR(M_PI * o.filamentRadius * o.filamentRadius * filament, volume, 1e-9 * volume) << name;
  // Net extrusion over the whole path: retractions and primes cancel.
  EXPECT_NEAR(path.extrusion.back(), path.filamentLength, 1e-9 * path.filamentLength);
  // Consecutive axes never turn more than the limit, segments are at most maxSegmentLength and
  // the axis stays within the tilt limit of the layer normal.
  for (size_t i = 1; i < N; ++i) {
    ASSERT_LE(std::acos(std::clamp(path.normals[i].dot(path.normals[i - 1]), -1.0, 1.0)),
              o.maxTurnDeg * M_PI / 180 + 1e-9)
        << name << " point " << i;
    ASSERT_LE((path.points[i] - path.points[i - 1]).norm(), o.maxSegmentLength * (1 + 1e-9))
        << name << " point " << i;
  }
  ASSERT_EQ(path.axisTilt.size(), N);
  EXPECT_LE(path.maxAxisTiltDeg, o.clearance.maxTiltDeg + 1e-9);
  EXPECT_EQ(path.unclearedStations, 0) << name;
  // Independent collision check of the whole path, air moves included: time = index, only
  // print points are material; obstacles of a skeleton ancestor are unavoidable.
  std::vector<int> time(N);
  std::vector<char> material(N);
  CollisionExemption ex;
  ex.group.resize(N);
  for (size_t i = 0; i < N; ++i) {
    time[i] = static_cast<int>(i);
    material[i] = path.kind[i] != MoveKind::Air;
    ex.group[i] = path.subgraph[i];
  }
  const SkeletonAncestry ancestry(part.tree);
  ex.unavoidable = [&](int station, int obstacle) {
    return station >= 0 && obstacle >= 0 &&
           (station == obstacle || ancestry.isAncestor(obstacle, station));
  };
  NozzleModel nozzle;
  nozzle.halfAngleDeg = nozzleAngle;
  const CollisionReport r =
      verifyNozzleClearance(path.points, path.normals, time, nozzle, 5, &ex, &material);
  // Without the axis clearance (the paper's axis everywhere) the same path (its tours the usual
  // way) collides where the planner said it would.
  ToolpathOptions paperAxes = o;
  paperAxes.clearance.maxTiltDeg = 0;
  paperAxes.retryTourWays = false;
  const Toolpath untilted = planToolpath(part.lattice, part.tree, part.sequence.order, paperAxes);
  EXPECT_EQ(untilted.maxAxisTiltDeg, 0.0);
  EXPECT_EQ(untilted.unclearedStations, path.collidingStations) << name;
  std::printf(
      "[toolpath] %s: along the layer normal %d stations collide; tilted %d (max %.2f deg) in %d "
      "rounds\n",
      name, path.collidingStations, path.tiltedStations, path.maxAxisTiltDeg, path.clearanceRounds);
  double devSum = 0;
  int devCount = 0;
  for (const auto& l : path.thicknessStats.perLayer) {
    devSum += l.mean * l.vertices;
    devCount += l.vertices;
  }
  std::printf(
      "[toolpath] %s: thickness deviation e = (h - phi) / phi: min %.3f mean %.3f max %.3f over %d "
      "vertices\n",
      name, path.thicknessStats.deviationMin, devSum / devCount, path.thicknessStats.deviationMax,
      devCount);
  EXPECT_GT(path.perimeterLoops, 0);
  EXPECT_GT(path.perimeterLength, 0.0);
  std::printf("[toolpath] %s: perimeter %d loops %.0f mm %d teeth\n", name, path.perimeterLoops,
              path.perimeterLength, path.perimeterTeeth);
  std::printf(
      "[toolpath] %s: %zu points, print %.0f mm, air %.0f mm, %d retractions, %d tours, %d split, "
      "%d rotation steps, filament %.0f mm, thickness deviation %.2f..%.2f (capped %d), verifier "
      "NA %.0f: "
      "%lld/%lld stations collide (%lld unavoidable), %.3f s plan, %.3f s verify\n",
      name, N, path.printLength, path.airLength, path.retractions, path.tours, path.splitSubgraphs,
      path.rotationSteps, path.filamentLength, path.thicknessStats.deviationMin,
      path.thicknessStats.deviationMax, path.thicknessStats.cappedVertices, nozzleAngle,
      r.violatingStations, r.stations, r.unavoidableStations, path.seconds, r.seconds);
  for (const auto& v : r.violations) {
    if (!v.unavoidable) {
      std::printf("  station %d (%s, sub-graph %d) obstacle %d (sub-graph %d) h %.2f r %.2f\n",
                  v.station, path.kind[v.station] == MoveKind::Air ? "air" : "print",
                  path.subgraph[v.station], v.obstacle, path.subgraph[v.obstacle], v.height,
                  v.radial);
    }
  }
  // Strict: no exemption needed, not even inside a sub-graph.
  EXPECT_TRUE(r.collisionFree) << name << ": " << r.violatingStations << " stations";
}

/// The verifier on a whole toolpath, strict (no exemption), the build plate included: every
/// point at its own time, the print points material.
CollisionReport verifyStrictly(const Toolpath& path, const ToolpathOptions& o) {
  const size_t N = path.points.size();
  std::vector<int> time(N);
  std::vector<char> material(N);
  for (size_t i = 0; i < N; ++i) {
    time[i] = static_cast<int>(i);
    material[i] = path.kind[i] != MoveKind::Air;
  }
  return verifyNozzleClearance(path.points, path.normals, time, o.nozzle, 0, nullptr, &material,
                               &o.plate);
}

}  // namespace

TEST(ToolpathPlanner, YShape) {
  expectGoodToolpath("Y", buildPart("y_shape.obj", 52, 2.0, 4.0, 45), 45);
}

TEST(ToolpathPlanner, ThreeBranchTree) {
  expectGoodToolpath("three-branch tree", buildPart("three_branch_tree.obj", 50, 2.0, 4.0, 30), 30);
}

TEST(ToolpathPlanner, ThreeBranchTreeWideNozzle) {
  // NA 45°: the curved tip caps rise into the nozzle inside their own sub-graph along ∇γ.
  expectGoodToolpath("three-branch tree NA 60",
                     buildPart("three_branch_tree.obj", 50, 2.0, 4.0, 60), 60);
}

TEST(ToolpathPlanner, AirMovesWhoseStationsCollideAreLaidAlongTheFinalAxes) {
  // Spot at 40 mm: the axis clearance tilts stations where air moves end, and a move laid along
  // their untilted normals moves the nozzle sideways to its own axis next to the material. Laid
  // again along the final axes, fewer air stations collide (the verifier, strict, with the
  // build plate), the material is the same, and each relaid approach runs along the final axis
  // of the first material point it reaches.
  const Part part = buildPart("spot.obj", 40, 2.0, 4.0, 45);
  ToolpathOptions o;
  const Toolpath aligned = planToolpath(part.lattice, part.tree, part.sequence.order, o);
  o.alignTransitions = false;
  const Toolpath normals = planToolpath(part.lattice, part.tree, part.sequence.order, o);
  EXPECT_GT(aligned.alignedTransitions, 0);
  EXPECT_EQ(normals.alignedTransitions, 0);
  EXPECT_EQ(aligned.printLength, normals.printLength);
  EXPECT_EQ(aligned.perimeterLength, normals.perimeterLength);
  EXPECT_EQ(aligned.retractions, normals.retractions);
  EXPECT_EQ(aligned.points.size(), aligned.axisTilt.size());
  auto collidingAirStations = [&](const Toolpath& path) {
    const CollisionReport r = verifyStrictly(path, o);
    long long air = 0;
    for (int i : r.violatingStationIds)
      air += path.kind[i] == MoveKind::Air;
    EXPECT_EQ(r.violatingStations, path.unclearedStations);  // the planner's count is the verdict
    return air;
  };
  const long long before = collidingAirStations(normals), after = collidingAirStations(aligned);
  // The approaches: the air points from the last one off the approach line (the box's side)
  // to the air point at the next start vertex; relaid, they keep that start's final axis.
  int alongTheAxis = 0, approaches = 0;
  for (size_t i = 1; i + 1 < aligned.points.size(); ++i) {
    if (aligned.kind[i] != MoveKind::Air || aligned.kind[i + 1] == MoveKind::Air)
      continue;
    ++approaches;
    const Vec3& axis = aligned.normals[i + 1];
    const Vec3 back = (aligned.points[i - 1] - aligned.points[i]).normalized();
    if (aligned.normals[i].dot(axis) > std::cos(0.1 * M_PI / 180) &&
        back.dot(axis) > std::cos(0.1 * M_PI / 180))
      ++alongTheAxis;
  }
  std::printf(
      "[toolpath] spot 40 mm: %d air moves relaid, colliding air stations %lld -> %lld; %d of %d "
      "approaches along the first station's final axis\n",
      aligned.alignedTransitions, before, after, alongTheAxis, approaches);
  EXPECT_LT(after, before);
  EXPECT_GE(alongTheAxis, aligned.alignedTransitions);
}

TEST(RobotPath, YShapeInTheUr5Cell) {
  // Every toolpath point of the Y at the nozzle tip with its axis along the nozzle, joints
  // continuous, within speed limits at the planner's feed rates.
  const Part part = buildPart("y_shape.obj", 52, 2.0, 4.0, 45);
  const Toolpath path =
      planToolpath(part.lattice, part.tree, part.sequence.order, ToolpathOptions{});
  for (const RobotModel& robot : {ur5Model(), ur5eModel()}) {
    RobotCell cell;
    cell.robot = robot;
    const RobotPath rp = solveRobotPath(cell, path.points, path.normals);
    EXPECT_TRUE(rp.unreachable.empty())
        << robot.name << ": " << rp.unreachable.size() << " unreachable";
    double worstPosition = 0, worstAxisDeg = 0;
    for (size_t i = 0; i < path.points.size(); ++i) {
      const Isometry part = forwardKinematics(robot, rp.joints[i]) * cell.partOnFlange;
      const Eigen::Vector3d tip = part * (cell.partScale * path.points[i]);
      worstPosition = std::max(worstPosition, (tip - cell.nozzleTip).norm());
      const Eigen::Vector3d axis = part.linear() * path.normals[i].normalized();
      worstAxisDeg = std::max(
          worstAxisDeg, std::acos(std::clamp(axis.dot(cell.nozzleAxis), -1.0, 1.0)) * 180 / M_PI);
    }
    double speedDeg = 0;
    const double ratio = jointSpeedRatio(cell, rp, path.points, path.feedRate, speedDeg);
    std::printf(
        "[robot] %s, Y: %zu points, branch %d, max joint step %.2f deg, max joint speed %.1f deg/s "
        "(ratio %.2f), "
        "min singularity distances shoulder %.3f m elbow %.3f wrist %.3f, tip error %.2e m, axis "
        "error %.2e deg, "
        "%.3f s\n",
        robot.name.c_str(), path.points.size(), rp.branch, rp.maxJointStepDeg, speedDeg, ratio,
        rp.minSingularity.shoulder, rp.minSingularity.elbow, rp.minSingularity.wrist, worstPosition,
        worstAxisDeg, rp.seconds);
    EXPECT_LT(worstPosition, 1e-6);
    EXPECT_LT(worstAxisDeg, 0.01);
    EXPECT_LT(rp.maxJointStepDeg, 20.0);
    EXPECT_TRUE(rp.largeSteps.empty());
    EXPECT_EQ(rp.maxJointStepAt >= 0, true);
  }
}

TEST(ToolpathPlanner, BadInput) {
  LatticeGraph g;
  SkeletonTree tree;
  EXPECT_THROW(planToolpath(g, tree, {}), GeoLatticeError);  // empty lattice
  ToolpathOptions o;
  o.flowCorrection = 1.5;
  EXPECT_THROW(planToolpath(g, tree, {}, o), GeoLatticeError);
  o = ToolpathOptions{};
  o.pathWidth = 0;
  EXPECT_THROW(planToolpath(g, tree, {}, o), GeoLatticeError);
}

TEST(ToolpathPlanner, PiecesArePrintedAsRunsOfTheirTourInTheirPlace) {
  // The Y's largest sub-graph cut in two by a plane through its centroid; its second half printed
  // last. Every kept edge is still printed exactly once (the same print length), the two halves
  // are printed as open runs that meet at the cut vertices, and the half printed last comes
  // after every other sub-graph.
  const Part part = buildPart("y_shape.obj", 52, 2.0, 4.0, 45);
  const LatticeGraph& g = part.lattice;
  int big = 0;
  for (const LatticeSubgraph& s : g.subgraphs) {
    if (s.length > g.subgraphs[big].length)
      big = s.id;
  }
  const int K = static_cast<int>(g.subgraphs.size());
  ToolpathPieces pieces;
  pieces.edgePiece = g.edgeSubgraph;
  const Vec3 c = g.subgraphs[big].centroid;
  int halfEdges = 0;
  for (size_t e = 0; e < g.edges.size(); ++e) {
    if (g.edgeSubgraph[e] == big &&
        0.5 * (g.points[g.edges[e][0]] + g.points[g.edges[e][1]]).x() > c.x()) {
      pieces.edgePiece[e] = K;  // the new piece
      ++halfEdges;
    }
  }
  ASSERT_GT(halfEdges, 3);
  std::vector<int> order = part.sequence.order;
  pieces.pieceOrder = order;
  order.push_back(big);
  pieces.pieceOrder.push_back(K);
  ToolpathOptions o;
  const Toolpath whole = planToolpath(g, part.tree, part.sequence.order, o);
  const Toolpath split = planToolpath(g, part.tree, order, o, &pieces);
  EXPECT_NEAR(split.printLength, whole.printLength, 1e-9 * whole.printLength);
  EXPECT_GT(split.tours, whole.tours);
  EXPECT_GT(split.retractions, whole.retractions);
  // The last print points belong to the big sub-graph, right of the cut.
  int last = static_cast<int>(split.points.size()) - 1;
  while (split.kind[last] == MoveKind::Air)
    --last;
  EXPECT_EQ(split.subgraph[last], big);
  EXPECT_GE(split.points[last].x(), c.x() - 4.0);
  // Bad pieces: an edge in a piece of another sub-graph, a piece listed twice.
  ToolpathPieces wrong = pieces;
  const int other = big == 0 ? 1 : 0;
  for (size_t e = 0; e < g.edges.size(); ++e) {
    if (g.edgeSubgraph[e] == other) {
      wrong.edgePiece[e] = K;
      break;
    }
  }
  EXPECT_THROW(planToolpath(g, part.tree, order, o, &wrong), GeoLatticeError);
  wrong = pieces;
  wrong.pieceOrder.back() = big;
  EXPECT_THROW(planToolpath(g, part.tree, order, o, &wrong), GeoLatticeError);
}

TEST(ToolpathPlanner, ToursWithCollidingStationsArePrintedTheWayFewestCollide) {
  // topopt at 80 mm under a 30° nozzle: some tours come back next to beads they laid shortly
  // before, higher than the tip where the layer curves. Printed backwards or from half-way
  // round, fewer of their stations collide; the material is the same (the same lengths, each
  // lattice vertex reached as often), and the planner's count is the verifier's.
  const Part part = buildPart("topopt_new4_surf.obj", 80, 2.0, 4.0, 30);
  ToolpathOptions o;
  o.nozzle.halfAngleDeg = 30;
  const Toolpath retried = planToolpath(part.lattice, part.tree, part.sequence.order, o);
  o.retryTourWays = false;
  const Toolpath usual = planToolpath(part.lattice, part.tree, part.sequence.order, o);
  std::printf(
      "[toolpath] topopt 80 mm, NA 30: %d tours printed another way, colliding stations %d -> %d\n",
      retried.reorderedTours, usual.unclearedStations, retried.unclearedStations);
  EXPECT_GT(retried.reorderedTours, 0);
  EXPECT_EQ(usual.reorderedTours, 0);
  EXPECT_EQ(retried.unclearedBeforeReorder, usual.unclearedStations);
  EXPECT_LT(retried.unclearedStations, usual.unclearedStations);
  EXPECT_NEAR(retried.printLength, usual.printLength, 1e-9 * usual.printLength);
  EXPECT_NEAR(retried.perimeterLength, usual.perimeterLength, 1e-9 * usual.perimeterLength);
  EXPECT_EQ(retried.retractions, usual.retractions);
  // The same lattice: each lattice vertex reached as often by print moves (once per pair of
  // tour edges at it, whichever way round and from wherever the tour starts).
  auto visits = [&](const Toolpath& path) {
    std::map<std::tuple<double, double, double>, int> count;
    for (const Vec3& x : part.lattice.points) {
      count[{x.x(), x.y(), x.z()}] = 0;
    }
    for (size_t i = 0; i < path.points.size(); ++i) {
      const auto at = count.find({path.points[i].x(), path.points[i].y(), path.points[i].z()});
      if (path.kind[i] == MoveKind::Print && at != count.end()) {
        ++at->second;
      }
    }
    return count;
  };
  EXPECT_TRUE(visits(retried) == visits(usual));
  EXPECT_EQ(verifyStrictly(retried, o).violatingStations, retried.unclearedStations);
}
