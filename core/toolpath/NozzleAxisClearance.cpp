#include "toolpath/NozzleAxisClearance.h"

#include "collision/TimedPointTree.h"
#include "common/Error.h"
#include "common/ParallelFor.h"
#include "toolpath/PathObstacleTrees.h"
#include "toolpath/PathSubdivision.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

namespace geolattice {

namespace {

constexpr double kDeg = M_PI / 180.0;

double angleBetween(const Vec3& a, const Vec3& b) {
  return std::acos(std::clamp(a.dot(b), -1.0, 1.0));
}

/// cos(beta + asin(s)) for beta >= 0 and s in [0, 1] given cos beta and sin beta, or -1 when that
/// sum is pi or more: the cosine threshold of an angle plus a ball's angular radius, without
/// inverse trigonometry.
double cosOfSum(double cosBeta, double sinBeta, double s) {
  if (cosBeta < 0 && s >= sinBeta) {
    return -1.0;  // asin(s) >= pi - beta
  }
  return cosBeta * std::sqrt(std::max(0.0, 1 - s * s)) - sinBeta * s;
}

/// The wide nozzle's largest clear angle over a range of distances from the tip, plus `extra`,
/// as its cosine and sine: one constant for the cone, a table lookup for a printhead.
struct ClearAngle {
  const NozzleVolume& wide;
  double extra;
  double cosConstant = 0, sinConstant = 0;
  ClearAngle(const NozzleVolume& w, double extraRad) : wide(w), extra(extraRad) {
    if (!wide.head) {
      cosConstant = std::cos(wide.coneAngle + extra);
      sinConstant = std::sin(wide.coneAngle + extra);
    }
  }
  void between(double rho0, double rho1, double& c, double& s) const {
    if (!wide.head) {
      c = cosConstant;
      s = sinConstant;
      return;
    }
    const double angle = wide.maxClearAngleBetween(rho0, rho1) + extra;
    c = std::cos(angle);
    s = std::sin(angle);
  }
};

/// Earlier material that may enter the nozzle at tip p for some axis within the tilt limit, held
/// as clusters of the kd-trees: leaves near the tip, whole nodes far away (angularly small seen
/// from the tip). A cluster whose ball lies outside the wide nozzle at an axis is passed over
/// with one dot product (its angular radius plus the largest clear angle over its distances,
/// the bound TiltedNozzleBound uses); every other point is tested exactly, so each answer is
/// that of testing every point one by one.
struct Obstacles {
  struct Cluster {
    Vec3 direction;     ///< unit vector from the tip to the ball's centre
    double cosOutside;  ///< direction·n <= this: the whole ball is outside the wide nozzle at n
    double cosSpread;   ///< cosine of the ball's angular radius seen from the tip
    double sinSpread;   ///< its sine
    bool around;        ///< the tip is inside the ball: never passed over
    int tree;           ///< which of the PathObstacleTrees
    const TimedPointTree::Node* node;  ///< its points: the tree's pointAt(i), i in [begin, end)
  };
  const PathObstacleTrees& trees;
  const NozzleVolume& wide;      ///< the nozzle with the margin added to its angle
  const ClearAngle& clearAngle;  ///< wide's clear angle
  Vec3 tip = Vec3::Zero();
  /// The station's time in each tree: material with an earlier time is an obstacle.
  std::array<int, PathObstacleTrees::kTrees> now{};
  std::vector<Cluster> clusters;
  std::vector<std::pair<double, int>> ranked;  ///< deepest()'s scratch: clusters by bound
  /// The points that blocked the latest candidate axes, most recent first: neighbouring
  /// candidates (around a ring of tilts) are mostly blocked by one of a few.
  std::array<Vec3, 8> blockers;
  int blockerCount = 0;

  /// For the station at path index k with its tip at p.
  void setStation(int k, const Vec3& p) {
    tip = p;
    for (int s = 0; s < PathObstacleTrees::kTrees; ++s) {
      now[static_cast<size_t>(s)] = trees.now(s, k);
    }
    clusters.clear();
    blockerCount = 0;
  }
  /// A node with at most this many points is scanned, not descended (cheaper).
  static constexpr int kScanPoints = 16;
  /// A node of tree s as seen from the tip.
  Cluster clusterOf(const TimedPointTree::Node& node, int s) const {
    Cluster c{Vec3::UnitZ(), -2.0, -1.0, 0.0, true, s, &node};
    const Vec3 v = node.centre - tip;
    const double distance = v.norm();
    if (distance > node.radius * (1 + 1e-12) && distance > 0) {
      c.around = false;
      c.direction = v / distance;
      c.sinSpread = node.radius / distance;
      c.cosSpread = std::sqrt(std::max(0.0, 1 - c.sinSpread * c.sinSpread));
      double cosClear, sinClear;
      clearAngle.between(distance - node.radius, distance + node.radius, cosClear, sinClear);
      c.cosOutside = cosOfSum(cosClear, sinClear, c.sinSpread);
    }
    return c;
  }
  void add(const TimedPointTree::Node& node, int s) { clusters.push_back(clusterOf(node, s)); }
  /// Calls f(x, i) for the earlier material x of the points [begin, end) of a cluster's tree
  /// (i: its position there); stops when f returns true.
  template <class F>
  bool scan(int s, const TimedPointTree::Node& node, F&& f) const {
    const TimedPointTree& tree = trees.tree(s);
    const std::vector<Vec3>& x = trees.points(s);
    for (int i = node.begin; i < node.end; ++i) {
      const int q = tree.pointAt(i);
      if (tree.timeOf(q) < now[static_cast<size_t>(s)] && f(x[q], i)) {
        return true;
      }
    }
    return false;
  }
  /// Calls f(x) for the earlier material of a cluster, in the tree's order; stops when f returns
  /// true.
  template <class F>
  bool anyPoint(const Cluster& c, F&& f) const {
    return scan(c.tree, *c.node, [&](const Vec3& x, int) { return f(x); });
  }
  /// anyPoint, but a large cluster is descended instead of scanned: a sub-ball that
  /// skip(its cluster) rules out is passed over (it holds no point f is looking for). The
  /// points left are visited in the same order. A far cluster can hold thousands of points of
  /// which a few lie inside the nozzle (e.g. the build plate seen from a tilted station).
  template <class Skip, class F>
  bool anyPoint(const Cluster& c, Skip&& skip, F&& f) const {
    const TimedPointTree& tree = trees.tree(c.tree);
    const int before = now[static_cast<size_t>(c.tree)];
    std::array<const TimedPointTree::Node*, 64> stack;  // depth < 34, see TimedPointTree
    int top = 0;
    stack[top++] = c.node;
    while (top > 0) {
      const TimedPointTree::Node& node = *stack[--top];
      if (node.minTime >= before || (&node != c.node && skip(clusterOf(node, c.tree)))) {
        continue;
      }
      if (node.left < 0 || node.end - node.begin <= kScanPoints) {
        if (scan(c.tree, node, [&](const Vec3& x, int) { return f(x); })) {
          return true;
        }
        continue;
      }
      stack[top++] = &tree.node(node.right);  // the left half first: the tree's order
      stack[top++] = &tree.node(node.left);
    }
    return false;
  }
  /// The largest cosine to n a point of cluster c can have (its angle to n less its angular
  /// radius), or 2 around the tip; dot = c.direction·n.
  static double upperCosine(const Cluster& c, double dot) {
    if (c.around) {
      return 2.0;
    }
    if (dot >= c.cosSpread) {
      return 1.0;  // n points into the ball
    }
    return dot * c.cosSpread + std::sqrt(std::max(0.0, 1 - dot * dot)) * c.sinSpread;
  }
  /// The obstacle deepest inside the wide nozzle at axis n (largest cosine to n; of equals, the
  /// first in the clusters' order, then the tree's), or null. Best first: clusters and then
  /// sub-balls by the largest cosine their points can have, so once a deep obstacle is known
  /// the rest is passed over (a plate seen from a tilted station has thousands of points inside
  /// the nozzle; scanning them in order found the deepest after ~1000 each).
  const Vec3* deepest(const Vec3& n) {
    // A bound this much below the best cannot hide an equal point (rounding of the bound).
    constexpr double kSlack = 1e-12;
    ranked.clear();
    for (size_t j = 0; j < clusters.size(); ++j) {
      const Cluster& c = clusters[j];
      const double dot = c.direction.dot(n);
      if (c.around || dot > c.cosOutside) {
        ranked.push_back({upperCosine(c, dot), static_cast<int>(j)});
      }
    }
    std::sort(ranked.begin(), ranked.end(), [](const auto& x, const auto& y) {
      return x.first > y.first || (x.first == y.first && x.second < y.second);
    });
    const Vec3* best = nullptr;
    std::pair<int, int> bestAt{0, 0};  // (cluster, position in its tree) of the best
    double bestCos = -2;
    std::array<std::pair<const TimedPointTree::Node*, double>, 64> stack;  // depth < 34
    for (const auto& [bound, j] : ranked) {
      if (bound < bestCos - kSlack) {
        break;  // sorted: no later cluster holds a deeper point
      }
      const Cluster& c = clusters[static_cast<size_t>(j)];
      const TimedPointTree& tree = trees.tree(c.tree);
      const int before = now[static_cast<size_t>(c.tree)];
      int top = 0;
      stack[top++] = {c.node, bound};
      while (top > 0) {
        const auto [node, upper] = stack[--top];
        if (node->minTime >= before || upper < bestCos - kSlack) {
          continue;
        }
        if (node->left < 0 || node->end - node->begin <= kScanPoints) {
          scan(c.tree, *node, [&](const Vec3& x, int i) {
            if (wide.contains(tip, n, x)) {
              const double cq = (x - tip).normalized().dot(n);
              if (cq > bestCos || (cq == bestCos && std::make_pair(j, i) < bestAt)) {
                bestCos = cq;
                bestAt = {j, i};
                best = &x;
              }
            }
            return false;
          });
          continue;
        }
        // The child that may hold the deeper point is taken first.
        std::array<std::pair<const TimedPointTree::Node*, double>, 2> children;
        int count = 0;
        for (const int id : {node->left, node->right}) {
          const TimedPointTree::Node& child = tree.node(id);
          const Cluster cc = clusterOf(child, c.tree);
          const double dot = cc.direction.dot(n);
          if (cc.around || dot > cc.cosOutside) {
            children[count++] = {&child, upperCosine(cc, dot)};
          }
        }
        if (count == 2 && children[0].second > children[1].second) {
          std::swap(children[0], children[1]);
        }
        for (int k = 0; k < count; ++k) {
          stack[top++] = children[k];
        }
      }
    }
    return best;
  }
  /// No obstacle inside the wide nozzle at axis n.
  bool clear(const Vec3& n) {
    for (int b = 0; b < blockerCount; ++b) {
      if (wide.contains(tip, n, blockers[b])) {
        std::rotate(blockers.begin(), blockers.begin() + b, blockers.begin() + b + 1);
        return false;
      }
    }
    auto outside = [&](const Cluster& c) {
      return !c.around && c.direction.dot(n) <= c.cosOutside;
    };
    for (const Cluster& c : clusters) {
      if (outside(c)) {
        continue;
      }
      if (anyPoint(c, outside, [&](const Vec3& x) {
            if (!wide.contains(tip, n, x)) {
              return false;
            }
            blockerCount = std::min<int>(blockerCount + 1, static_cast<int>(blockers.size()));
            std::rotate(blockers.begin(), blockers.begin() + blockerCount - 1,
                        blockers.begin() + blockerCount);
            blockers[0] = x;
            return true;
          })) {
        return false;
      }
    }
    return true;
  }
};

/// Conservative test for the obstacle search: can a ball hold a point inside the wide nozzle
/// for some axis within maxTilt of the reference? Besides the bounding cone widened by maxTilt,
/// the ball's points lie at least (angle of its centre) - asin(radius / distance) from the
/// reference, so at least that minus maxTilt from every allowed axis: none is inside when that
/// is at least the largest clear angle over the ball's distances.
struct TiltedNozzleBound {
  NozzleBound cone;
  const ClearAngle& clearPlusTilt;  ///< the wide nozzle's clear angle + maxTilt
  bool mayTouch(const Vec3& c, double rho) const {
    if (!cone.mayTouch(c, rho)) {
      return false;
    }
    const Vec3 v = c - cone.tip;
    const double distance = v.norm();
    if (distance <= rho) {
      return true;
    }
    // angle(v, axis) - asin(rho / distance) - maxTilt < clear angle, in cosines
    double cosBeta, sinBeta;
    clearPlusTilt.between(distance - rho, distance + rho, cosBeta, sinBeta);
    return v.dot(cone.axis) / distance > cosOfSum(cosBeta, sinBeta, rho / distance);
  }
};

/// The least tilt from `reference` (<= maxTilt) whose wide nozzle holds no obstacle; starts from
/// `current`. Returns false when none is found.
/// coneAngle: the wide nozzle's half-angle when it is a cone (then a point far enough from the
/// tip is inside exactly when its angle to the axis is below it), else 0.
bool findClearAxis(Obstacles& obstacles, const Vec3& reference, const Vec3& current, double maxTilt,
                   double coneAngle, Vec3& result) {
  // Projection: turn the axis off the deepest obstacle until it sits on the cone's surface. Its
  // answer is clear but not always the least tilt (with a wide limit it can wander far off the
  // reference, and a needless tilt sweeps the nozzle through the neighbours' material): the
  // rings below look for a smaller one first.
  Vec3 n = current;
  bool projected = false;
  double projectedTilt = maxTilt;
  const Vec3* deepestAtCurrent = nullptr;
  for (int iteration = 0; iteration < 30; ++iteration) {
    const Vec3* q = obstacles.deepest(n);
    if (iteration == 0) {
      deepestAtCurrent = q;
    }
    if (!q) {
      projected = true;
      projectedTilt = angleBetween(n, reference);
      break;
    }
    const Vec3 toObstacle = *q - obstacles.tip;
    const Vec3 u = toObstacle.normalized();
    Vec3 w = n - u.dot(n) * u;
    if (w.norm() < 1e-12) {
      w = u.unitOrthogonal();
    }
    w.normalize();
    const double theta = obstacles.wide.clearAngleAt(toObstacle.norm()) + 1e-6;
    n = (std::cos(theta) * u + std::sin(theta) * w).normalized();
    if (angleBetween(n, reference) > maxTilt) {
      break;
    }
  }
  // Rings of tilts around the reference, smallest first; on a ring the axis nearest the current.
  const Vec3 e1 = reference.unitOrthogonal();
  const Vec3 e2 = reference.cross(e1);
  const double step = 0.5 * kDeg;
  constexpr int azimuths = 48;
  static const std::array<std::pair<double, double>, azimuths> ring = [] {
    std::array<std::pair<double, double>, azimuths> r;
    for (int a = 0; a < azimuths; ++a) {
      r[a] = {std::cos(2 * M_PI * a / azimuths), std::sin(2 * M_PI * a / azimuths)};
    }
    return r;
  }();
  const double largest = projected ? projectedTilt - 1e-9 : maxTilt + 1e-12;
  // Cone: the obstacle nearest the reference direction, at angle θ, lies inside the cone about
  // every axis of a ring of tilt t < NA - θ (its angle to such an axis is at most θ + t), so
  // those rings hold no clear axis (with a margin: the skipped rings are blocked for certain).
  double blockedBelow = 0;
  if (coneAngle > 0 && step <= largest) {  // only where a ring is tried
    // Untilted stations (most of them in a first round) have it from the projection's start.
    const Vec3* q = current == reference ? deepestAtCurrent : obstacles.deepest(reference);
    if (q) {
      const Vec3 d = *q - obstacles.tip;
      if (d.norm() * std::cos(coneAngle) > obstacles.wide.clearance) {
        blockedBelow = coneAngle - angleBetween(d.normalized(), reference) - 1e-9;
      }
    }
  }
  for (double tilt = step; tilt <= largest; tilt += step) {
    if (tilt < blockedBelow) {
      continue;
    }
    double bestDot = -2;
    const double cosTilt = std::cos(tilt), sinTilt = std::sin(tilt);
    for (const auto& [cosPhi, sinPhi] : ring) {
      const Vec3 candidate = cosTilt * reference + sinTilt * (cosPhi * e1 + sinPhi * e2);
      if (candidate.dot(current) > bestDot && obstacles.clear(candidate)) {
        bestDot = candidate.dot(current);
        result = candidate;
      }
    }
    if (bestDot > -2) {
      return true;
    }
  }
  if (projected) {
    result = n;
    return true;
  }
  return false;
}

}  // namespace

void AxisClearanceOptions::validate() const {
  if (!(this->maxTiltDeg >= 0 && this->maxTiltDeg <= 60)) {
    throw GeoLatticeError("axis clearance: the largest tilt must be in [0, 60] degrees (got " +
                          std::to_string(this->maxTiltDeg) + ")");
  }
  if (!(this->marginDeg >= 0 && this->marginDeg < 10)) {
    throw GeoLatticeError("axis clearance: the margin must be in [0, 10) degrees (got " +
                          std::to_string(this->marginDeg) + ")");
  }
  if (!(this->blendLength >= 0) || !std::isfinite(this->blendLength)) {
    throw GeoLatticeError("axis clearance: the blend length must be >= 0 mm (got " +
                          std::to_string(this->blendLength) + ")");
  }
}

AxisClearanceResult clearNozzleAxes(const std::vector<Vec3>& points, std::vector<Vec3>& axes,
                                    const std::vector<Vec3>& reference,
                                    const std::vector<char>& material, const NozzleModel& nozzle,
                                    const AxisClearanceOptions& o,
                                    const std::vector<Vec3>* fixedObstacles,
                                    std::vector<char>* unresolvable, AxisSearchMemo* memo,
                                    KnownClear* known, PathObstacleTrees* obstacleTrees) {
  const auto t0 = std::chrono::steady_clock::now();
  nozzle.validate();
  o.validate();
  const size_t N = points.size();
  if (axes.size() != N || reference.size() != N || material.size() != N ||
      (unresolvable && unresolvable->size() != N) ||
      (known && (known->clear.size() != N || known->inserted.size() != N))) {
    throw GeoLatticeError(
        "axis clearance: points, axes, reference axes, material, unresolvable and known-clear "
        "flags must have the same length");
  }
  AxisClearanceResult result;
  // Obstacles: the material before each station and the fixed obstacles (present at every
  // station), indexed once per pass or kept from an earlier pass (PathObstacleTrees).
  PathObstacleTrees ownTrees;
  PathObstacleTrees& trees = obstacleTrees ? *obstacleTrees : ownTrees;
  trees.index(points, material, fixedObstacles);

  // With a memo: each station's material ordinal, and the material and the axes it is checked
  // at, by ordinal. The memo's answers hold for the stations whose earlier material is the
  // memo's (a common prefix of the material) with the same fixed obstacles and axes.
  std::vector<int> ordinal;
  std::vector<Vec3> materialPoints, detectAxis;
  enum Outcome : char { Known, Unresolved, Tilted };  // of a colliding station's search
  size_t prefix = 0;
  if (memo) {
    ordinal.assign(N, -1);
    // Exact sizes: a memo that is kept holds them to the stage's end (grown by doubling they
    // took up to twice the memory, all of it fresh pages).
    const size_t count = static_cast<size_t>(
        std::count_if(material.begin(), material.end(), [](char m) { return m != 0; }));
    materialPoints.reserve(count);
    detectAxis.reserve(count);
    for (size_t i = 0; i < N; ++i) {
      if (material[i]) {
        ordinal[i] = static_cast<int>(materialPoints.size());
        materialPoints.push_back(points[i]);
        detectAxis.push_back(axes[i]);
      }
    }
    const std::vector<Vec3> noFixed;
    if (memo->fixed == (fixedObstacles ? *fixedObstacles : noFixed)) {
      const size_t n = std::min(memo->material.size(), materialPoints.size());
      while (prefix < n && memo->material[prefix] == materialPoints[prefix]) {
        ++prefix;
      }
    }
  }
  auto inMemo = [&](size_t k) {
    return prefix > 0 && ordinal[k] >= 0 && static_cast<size_t>(ordinal[k]) < prefix;
  };

  // 1. Stations with earlier material inside the nozzle: chunks of stations over the workers.
  const NozzleVolume volume(nozzle);
  const NozzleBound detect(nozzle, volume);
  constexpr size_t kChunk = 4096;
  const size_t chunks = (N + kChunk - 1) / kChunk;
  auto abortPoll = [&](size_t) {  // on the calling thread; a throw stops the workers
    if (o.shouldAbort && o.shouldAbort()) {
      throw GeoLatticeError("nozzle axis clearance aborted");
    }
  };
  // A station known clear needs only the material inserted since: a small tree over it.
  std::vector<Vec3> insertedPoints;
  std::vector<int> insertedTime;
  if (known) {
    for (size_t i = 0; i < N; ++i) {
      if (known->inserted[i] && material[i]) {
        insertedPoints.push_back(points[i]);
        insertedTime.push_back(static_cast<int>(i));
      }
    }
  }
  const TimedPointTree insertedTree(insertedPoints, insertedTime);
  std::vector<std::vector<int>> found(chunks);
  parallelFor(
      chunks, o.threads,
      [&](size_t c, int) {
        NozzleBound bound = detect;
        for (size_t k = c * kChunk; k < std::min(N, (c + 1) * kChunk); ++k) {
          bound.setStation(points[k], axes[k]);
          bool hit = false;
          if (inMemo(k) && memo->detectAxis[static_cast<size_t>(ordinal[k])] == axes[k]) {
            if (memo->detectHit[static_cast<size_t>(ordinal[k])]) {
              found[c].push_back(static_cast<int>(k));
            }
            continue;
          }
          if (known && known->clear[k]) {
            insertedTree.forEachCandidate(bound, static_cast<int>(k), [&](int q) {
              hit = volume.contains(points[k], axes[k], insertedPoints[q]);
              return hit;
            });
          } else {
            trees.forEachCandidate(bound, static_cast<int>(k), [&](const Vec3& x) {
              hit = volume.contains(points[k], axes[k], x);
              return hit;
            });
          }
          if (hit) {
            found[c].push_back(static_cast<int>(k));
          }
        }
      },
      abortPoll);
  std::vector<int> colliding;
  for (const std::vector<int>& f : found) {
    colliding.insert(colliding.end(), f.begin(), f.end());
  }
  result.collidingStations = static_cast<int>(colliding.size());
  result.colliding = colliding;
  // This pass's detection for the memo (stored with its searches below).
  std::vector<char> detectHit;
  if (memo) {
    detectHit.assign(materialPoints.size(), 0);
    for (int k : colliding) {
      if (ordinal[k] >= 0) {
        detectHit[static_cast<size_t>(ordinal[k])] = 1;
      }
    }
  }
  auto storeMemo = [&](const std::vector<char>& outcomes, const std::vector<Vec3>& clearAxes) {
    memo->material = std::move(materialPoints);
    memo->fixed = fixedObstacles ? *fixedObstacles : std::vector<Vec3>{};
    memo->detectAxis = std::move(detectAxis);
    memo->detectHit = std::move(detectHit);
    memo->found.clear();
    for (size_t i = 0; i < outcomes.size(); ++i) {
      const int k = colliding[i];
      if (ordinal[k] >= 0 && outcomes[i] != Known) {
        memo->found.push_back(
            {ordinal[k], {reference[k], axes[k], outcomes[i] == Tilted, clearAxes[i]}});
      }
    }
  };
  if (known) {  // the tilts below clear the entries of the points they turn
    std::fill(known->clear.begin(), known->clear.end(), 1);
    for (int k : colliding) {
      known->clear[static_cast<size_t>(k)] = 0;
    }
  }
  if (colliding.empty() || o.maxTiltDeg == 0) {
    if (memo) {
      storeMemo({}, {});
    }
    result.unresolvedStations = result.collidingStations;
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return result;
  }

  // 2. The least clearing tilt of each colliding station.
  const NozzleModel wideModel = nozzle.widened(o.marginDeg);
  const NozzleVolume wide(wideModel);
  const double maxTilt = o.maxTiltDeg * kDeg;
  const ClearAngle clearAngle(wide, 0.0), clearPlusTilt(wide, maxTilt);
  TiltedNozzleBound gather{
      NozzleBound(wideModel.boundingHalfAngleRad() + maxTilt, wideModel.reach(),
                  -std::numeric_limits<double>::infinity(), wideModel.boundingApexOffset()),
      clearPlusTilt};
  const double face2 = nozzle.tipFaceRadius * nozzle.tipFaceRadius;
  struct Tilt {
    int station;
    Vec3 axis;      ///< the clearing axis
    Vec3 rotation;  ///< unit rotation axis from the old to the new axis
    double angle;   ///< rotation angle (rad)
  };
  // An obstacle closer to the reference axis than NA + margin - maxTilt is inside the cone for
  // every allowed axis (cone-only nozzle): the station cannot be cleared, stop looking.
  const double hopeless = wideModel.halfAngleDeg * kDeg - maxTilt;
  const bool coneOnly = nozzle.isConeOnly();
  const double cosHopeless = hopeless > 0 ? std::cos(hopeless) : 2.0;
  const double sinHopeless = hopeless > 0 ? std::sin(hopeless) : 0.0;
  // Each colliding station on its own (its obstacles are fixed): chunks over the workers, the
  // outcome per station, collected in path order afterwards.
  std::vector<char> outcome(colliding.size(), Known);
  std::vector<Vec3> clearAxis(colliding.size());
  std::vector<char> fromMemo(colliding.size(), 0);
  if (memo) {
    for (size_t i = 0; i < colliding.size(); ++i) {
      const int j = ordinal[colliding[i]];
      if (j < 0 || static_cast<size_t>(j) >= prefix ||
          (unresolvable && (*unresolvable)[colliding[i]])) {
        continue;
      }
      const auto at = std::lower_bound(
          memo->found.begin(), memo->found.end(), j,
          [](const std::pair<int, AxisSearchMemo::Entry>& e, int v) { return e.first < v; });
      const int k = colliding[i];
      if (at == memo->found.end() || at->first != j || at->second.reference != reference[k] ||
          at->second.axis != axes[k]) {
        continue;
      }
      fromMemo[i] = 1;
      outcome[i] = at->second.cleared ? Tilted : Unresolved;
      clearAxis[i] = at->second.clearAxis;
      ++memo->reused;
    }
  }
  const size_t searchChunks = (colliding.size() + 63) / 64;
  const int workers = workerCount(o.threads, searchChunks);
  std::vector<Obstacles> scratch(
      workers, Obstacles{trees, wide, clearAngle, Vec3::Zero(), {}, {}, {}, {}, 0});
  // Clusters: a node is kept whole when it looks smaller than this from the tip. topopt's
  // toolpath stage (before KnownClear): 13.9 s at 0.5°, 9.3 s at 2°, 8.4 s at 4°, 7.2 s at 8°,
  // 8.0 s at 15° (docs/performance.md).
  const double sinSmall = std::sin(8.0 * kDeg);
  parallelFor(
      searchChunks, o.threads,
      [&](size_t c, int w) {
        TiltedNozzleBound bound = gather;
        Obstacles& obstacles = scratch[w];
        for (size_t i = c * 64; i < std::min(colliding.size(), (c + 1) * 64); ++i) {
          const int k = colliding[i];
          if (fromMemo[i]) {
            continue;
          }
          if (unresolvable && (*unresolvable)[k]) {
            outcome[i] = Known;
            continue;
          }
          obstacles.setStation(k, points[k]);
          bound.cone.setStation(points[k], reference[k]);
          const Vec3& r = reference[k];
          // A point above the tip plane for every allowed axis and inside every allowed cone
          // (cone-only nozzle): the station cannot be cleared, stop looking.
          auto hopelessPoint = [&](const Vec3& x) {
            const Vec3 d = x - points[k];
            const double d2 = d.squaredNorm();
            if (d2 <= face2) {
              return false;
            }
            const double length = std::sqrt(d2);
            return d.dot(r) / length > cosHopeless &&
                   d.dot(r) * std::cos(maxTilt) > nozzle.tipClearance + length * std::sin(maxTilt);
          };
          // A ball none of whose points can be hopeless: all of it at least the hopeless
          // angle from the reference (a far cluster holds thousands of points, few or none of
          // them in that cone: its sub-balls outside it are passed over).
          auto outsideHopeless = [&](const Obstacles::Cluster& c) {
            return !c.around &&
                   c.direction.dot(r) <= cosOfSum(cosHopeless, sinHopeless, c.sinSpread);
          };
          bool cannot = false;
          for (int t = 0; t < PathObstacleTrees::kTrees && !cannot; ++t) {
            trees.tree(t).forEachCluster(
                bound, trees.now(t, k),
                [&](const Vec3& centre, double radius) {
                  return radius <= sinSmall * (centre - points[k]).norm();
                },
                [&](const TimedPointTree::Node& node) {
                  obstacles.add(node, t);
                  const Obstacles::Cluster& cl = obstacles.clusters.back();
                  if (coneOnly && cosHopeless < 2 && !outsideHopeless(cl)) {
                    cannot = obstacles.anyPoint(cl, outsideHopeless, hopelessPoint);
                  }
                  return cannot;
                });
          }
          if (cannot) {
            outcome[i] = Unresolved;
            continue;
          }
          outcome[i] = findClearAxis(obstacles, reference[k], axes[k], maxTilt,
                                     coneOnly ? wideModel.halfAngleDeg * kDeg : 0.0, clearAxis[i])
                           ? Tilted
                           : Unresolved;
        }
      },
      abortPoll);
  if (memo) {  // this pass's detection and searches, for the next one
    storeMemo(outcome, clearAxis);
  }
  std::vector<Tilt> tilts;
  for (size_t i = 0; i < colliding.size(); ++i) {
    const int k = colliding[i];
    if (outcome[i] != Tilted) {
      ++result.unresolvedStations;
      if (outcome[i] == Unresolved && unresolvable) {
        (*unresolvable)[k] = 1;
      }
      continue;
    }
    ++result.tiltedStations;
    const Vec3 c = axes[k].cross(clearAxis[i]);
    const double angle = std::atan2(c.norm(), axes[k].dot(clearAxis[i]));
    tilts.push_back(
        {k, clearAxis[i], c.norm() > 1e-15 ? Vec3(c.normalized()) : Vec3::Zero(), angle});
  }

  // 3. Fade each tilt out along the path; the largest faded tilt wins, stations keep their own.
  std::vector<double> arc(N, 0.0);
  for (size_t i = 1; i < N; ++i) {
    arc[i] = arc[i - 1] + (points[i] - points[i - 1]).norm();
  }
  std::vector<char> isStation(N, 0);
  for (const Tilt& t : tilts) {
    isStation[t.station] = 1;
  }
  std::vector<double> fadeAngle(N, 0.0);
  std::vector<int> owner(N, -1);
  for (size_t c = 0; c < tilts.size(); ++c) {
    const Tilt& t = tilts[c];
    if (o.blendLength <= 0 || t.rotation.isZero()) {
      continue;
    }
    auto visit = [&](long j) {
      const double d = std::abs(arc[j] - arc[t.station]);
      if (d >= o.blendLength) {
        return false;
      }
      const double a = t.angle * (1 - d / o.blendLength);
      if (!isStation[j] && a > fadeAngle[j]) {
        fadeAngle[j] = a;
        owner[j] = static_cast<int>(c);
      }
      return true;
    };
    for (long j = t.station - 1; j >= 0 && visit(j); --j) {
    }
    for (long j = t.station + 1; j < static_cast<long>(N) && visit(j); ++j) {
    }
  }
  // With fadeOnlyWhereClear, a faded axis that would put earlier material into the nozzle is not
  // taken: the point keeps its clear axis (the rotation steps still bound the turn between
  // neighbours; result.keptPoints counts those points).
  std::vector<int> faded;
  for (size_t j = 0; j < N; ++j) {
    if (owner[j] >= 0) {
      faded.push_back(static_cast<int>(j));
    }
  }
  std::vector<Vec3> fadedAxis(faded.size());
  std::vector<char> fadedClear(faded.size(), 0);
  const size_t fadeChunks = (faded.size() + kChunk - 1) / kChunk;
  parallelFor(
      fadeChunks, o.threads,
      [&](size_t c, int) {
        NozzleBound bound = detect;
        for (size_t f = c * kChunk; f < std::min(faded.size(), (c + 1) * kChunk); ++f) {
          const int j = faded[f];
          const Tilt& t = tilts[owner[j]];
          Vec3 turned = (Eigen::AngleAxisd(fadeAngle[j], t.rotation) * axes[j]).normalized();
          const double fromReference = angleBetween(turned, reference[j]);
          if (fromReference > maxTilt) {  // keep blends inside the tilt limit too
            turned = slerpAxis(reference[j], turned, maxTilt / fromReference);
          }
          fadedAxis[f] = turned;
          bool hit = false;
          if (o.fadeOnlyWhereClear) {
            bound.setStation(points[j], turned);
            trees.forEachCandidate(bound, j, [&](const Vec3& x) {
              hit = volume.contains(points[j], turned, x);
              return hit;
            });
          }
          fadedClear[f] = !hit;
        }
      },
      abortPoll);
  for (size_t f = 0; f < faded.size(); ++f) {
    if (!fadedClear[f]) {
      ++result.keptPoints;
      continue;
    }
    const int j = faded[f];
    axes[j] = fadedAxis[f];
    ++result.blendedPoints;
    if (known) {
      known->clear[j] = 0;
    }
  }
  for (const Tilt& t : tilts) {
    axes[t.station] = t.axis;
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

}  // namespace geolattice
