#include "toolpath/NozzleAxisClearance.h"

#include "collision/TimedPointTree.h"
#include "common/Error.h"
#include "common/ParallelFor.h"
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

/// Earlier material that may enter the nozzle at tip p for some axis within the tilt limit.
struct Obstacles {
  const std::vector<Vec3>& points;
  const NozzleVolume& wide;  ///< the nozzle with the margin added to its angle
  Vec3 tip = Vec3::Zero();
  std::vector<int> ids;

  /// The obstacle deepest inside the wide nozzle at axis n (largest cosine to n), or -1.
  int deepest(const Vec3& n) const {
    int best = -1;
    double bestCos = -2;
    for (int q : ids) {
      if (wide.contains(tip, n, points[q])) {
        const double c = (points[q] - tip).normalized().dot(n);
        if (c > bestCos) {
          bestCos = c;
          best = q;
        }
      }
    }
    return best;
  }
  /// No obstacle inside the wide nozzle at axis n. The blocking obstacle found moves to the
  /// front: neighbouring candidate axes are mostly blocked by the same one.
  bool clear(const Vec3& n) {
    for (size_t i = 0; i < ids.size(); ++i) {
      if (wide.contains(tip, n, points[ids[i]])) {
        std::swap(ids[i], ids[0]);
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
  const NozzleVolume& wide;
  double maxTilt;
  bool mayTouch(const Vec3& c, double rho) const {
    if (!cone.mayTouch(c, rho)) {
      return false;
    }
    const Vec3 v = c - cone.tip;
    const double distance = v.norm();
    if (distance <= rho) {
      return true;
    }
    const double angle = std::acos(std::clamp(v.dot(cone.axis) / distance, -1.0, 1.0)) -
                         std::asin(rho / distance) - maxTilt;
    return angle < wide.maxClearAngleBetween(distance - rho, distance + rho);
  }
};

/// Per distance from the tip, the cosine of (largest clear angle + maxTilt): a point whose angle
/// to the reference axis has a cosine at most this is outside the wide nozzle for every allowed
/// axis. Tabulated once (the largest clear angle over each distance bin, so conservative): the
/// obstacle search tests every gathered point with a lookup instead of an arc cosine.
class OutsideCosine {
public:
  OutsideCosine(const NozzleVolume& wide, double reach, double maxTilt) {
    auto cosine = [maxTilt](double angle) {
      return std::cos(std::min(M_PI, angle + maxTilt));
    };
    if (!std::isfinite(reach)) {  // the cone: one angle at every distance
      constant_ = cosine(wide.maxClearAngleBetween(0, 1));
      return;
    }
    bin_ = reach / kBins;
    table_.resize(kBins + 1);
    for (int j = 0; j <= kBins; ++j) {
      table_[j] = cosine(wide.maxClearAngleBetween(j * bin_, (j + 1) * bin_));
    }
  }
  double at(double distance) const {
    if (table_.empty()) {
      return constant_;
    }
    const int j = static_cast<int>(distance / bin_);
    return j < kBins ? table_[j] : 1.0;  // beyond the reach: outside
  }

private:
  static constexpr int kBins = 4096;
  double constant_ = 1.0, bin_ = 0;
  std::vector<double> table_;
};

/// The least tilt from `reference` (<= maxTilt) whose wide nozzle holds no obstacle; starts from
/// `current`. Returns false when none is found.
bool findClearAxis(Obstacles& obstacles, const Vec3& reference, const Vec3& current, double maxTilt,
                   Vec3& result) {
  // Projection: turn the axis off the deepest obstacle until it sits on the cone's surface. Its
  // answer is clear but not always the least tilt (with a wide limit it can wander far off the
  // reference, and a needless tilt sweeps the nozzle through the neighbours' material): the
  // rings below look for a smaller one first.
  Vec3 n = current;
  bool projected = false;
  double projectedTilt = maxTilt;
  for (int iteration = 0; iteration < 30; ++iteration) {
    const int q = obstacles.deepest(n);
    if (q < 0) {
      projected = true;
      projectedTilt = angleBetween(n, reference);
      break;
    }
    const Vec3 toObstacle = obstacles.points[q] - obstacles.tip;
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
  for (double tilt = step; tilt <= largest; tilt += step) {
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
                                    std::vector<char>* unresolvable, AxisSearchMemo* memo) {
  const auto t0 = std::chrono::steady_clock::now();
  nozzle.validate();
  o.validate();
  const size_t N = points.size();
  if (axes.size() != N || reference.size() != N || material.size() != N ||
      (unresolvable && unresolvable->size() != N)) {
    throw GeoLatticeError(
        "axis clearance: points, axes, reference axes, material and unresolvable flags must have "
        "the same length");
  }
  AxisClearanceResult result;
  // Obstacles: the material points at their index along the path, then the fixed obstacles
  // (present at every station).
  std::vector<Vec3> all = points;
  std::vector<int> obstacleTime(N);
  for (size_t i = 0; i < N; ++i) {
    obstacleTime[i] = material[i] ? static_cast<int>(i) : std::numeric_limits<int>::max();
  }
  if (fixedObstacles) {
    all.insert(all.end(), fixedObstacles->begin(), fixedObstacles->end());
    obstacleTime.resize(all.size(), -1);
  }
  const TimedPointTree tree(all, obstacleTime);

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
  std::vector<std::vector<int>> found(chunks);
  parallelFor(
      chunks, o.threads,
      [&](size_t c, int) {
        NozzleBound bound = detect;
        for (size_t k = c * kChunk; k < std::min(N, (c + 1) * kChunk); ++k) {
          bound.setStation(points[k], axes[k]);
          bool hit = false;
          tree.forEachCandidate(bound, static_cast<int>(k), [&](int q) {
            hit = volume.contains(points[k], axes[k], all[q]);
            return hit;
          });
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
  if (colliding.empty() || o.maxTiltDeg == 0) {
    result.unresolvedStations = result.collidingStations;
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return result;
  }

  // 2. The least clearing tilt of each colliding station.
  const NozzleModel wideModel = nozzle.widened(o.marginDeg);
  const NozzleVolume wide(wideModel);
  const double maxTilt = o.maxTiltDeg * kDeg;
  TiltedNozzleBound gather{
      NozzleBound(wideModel.boundingHalfAngleRad() + maxTilt, wideModel.reach(),
                  -std::numeric_limits<double>::infinity(), wideModel.boundingApexOffset()),
      wide, maxTilt};
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
  const OutsideCosine outside(wide, wideModel.reach(), maxTilt);
  // Each colliding station on its own (its obstacles are fixed): chunks over the workers, the
  // outcome per station, collected in path order afterwards.
  enum Outcome : char { Known, Unresolved, Tilted };
  std::vector<char> outcome(colliding.size(), Known);
  std::vector<Vec3> clearAxis(colliding.size());
  // A station's material ordinal; the memo's searches hold for the stations whose earlier
  // material is the memo's (a common prefix) with the same fixed obstacles and axes.
  std::vector<int> ordinal(N, -1);
  std::vector<Vec3> materialPoints;
  for (size_t i = 0; i < N; ++i) {
    if (material[i]) {
      ordinal[i] = static_cast<int>(materialPoints.size());
      materialPoints.push_back(points[i]);
    }
  }
  std::vector<char> fromMemo(colliding.size(), 0);
  if (memo) {
    const std::vector<Vec3> noFixed;
    const std::vector<Vec3>& fixed = fixedObstacles ? *fixedObstacles : noFixed;
    size_t prefix = 0;
    if (memo->fixed == fixed) {
      const size_t n = std::min(memo->material.size(), materialPoints.size());
      while (prefix < n && memo->material[prefix] == materialPoints[prefix]) {
        ++prefix;
      }
    }
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
  std::vector<Obstacles> scratch(workers, Obstacles{all, wide, Vec3::Zero(), {}});
  std::vector<std::vector<std::pair<double, int>>> byAngleOf(workers);
  parallelFor(
      searchChunks, o.threads,
      [&](size_t c, int w) {
        TiltedNozzleBound bound = gather;
        Obstacles& obstacles = scratch[w];
        std::vector<std::pair<double, int>>& byAngle = byAngleOf[w];
        for (size_t i = c * 64; i < std::min(colliding.size(), (c + 1) * 64); ++i) {
          const int k = colliding[i];
          if (fromMemo[i]) {
            continue;
          }
          if (unresolvable && (*unresolvable)[k]) {
            outcome[i] = Known;
            continue;
          }
          obstacles.tip = points[k];
          obstacles.ids.clear();
          byAngle.clear();
          bound.cone.setStation(points[k], reference[k]);
          bool cannot = false;
          tree.forEachCandidate(bound, k, [&](int q) {
            const Vec3 d = all[q] - points[k];
            const double d2 = d.squaredNorm();
            if (d2 <= face2) {
              return false;
            }
            const double cosine = d.dot(reference[k]) / std::sqrt(d2);  // to the reference
            if (coneOnly && cosine > cosHopeless &&
                d.dot(reference[k]) * std::cos(maxTilt) >
                    nozzle.tipClearance + std::sqrt(d2) * std::sin(maxTilt)) {
              cannot = true;  // above the tip plane for every allowed axis, inside every cone
              return true;
            }
            // Outside the wide nozzle for every axis within maxTilt of the reference.
            if (cosine <= outside.at(std::sqrt(d2))) {
              return false;
            }
            byAngle.emplace_back(-cosine, q);
            return false;
          });
          if (cannot) {
            outcome[i] = Unresolved;
            continue;
          }
          // Those inside the nozzle about the reference first, so a blocked candidate axis is
          // usually rejected by the first few (a partition, not a sort: linear).
          std::partition(byAngle.begin(), byAngle.end(), [&](const std::pair<double, int>& a) {
            return wide.contains(points[k], reference[k], all[a.second]);
          });
          for (const auto& [negCos, q] : byAngle) {
            obstacles.ids.push_back(q);
          }
          outcome[i] = findClearAxis(obstacles, reference[k], axes[k], maxTilt, clearAxis[i])
                           ? Tilted
                           : Unresolved;
        }
      },
      abortPoll);
  if (memo) {  // this pass's searches, for the next one
    memo->material = std::move(materialPoints);
    memo->fixed = fixedObstacles ? *fixedObstacles : std::vector<Vec3>{};
    memo->found.clear();
    for (size_t i = 0; i < colliding.size(); ++i) {
      const int k = colliding[i];
      if (ordinal[k] >= 0 && outcome[i] != Known) {
        memo->found.push_back(
            {ordinal[k], {reference[k], axes[k], outcome[i] == Tilted, clearAxis[i]}});
      }
    }
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
  for (size_t j = 0; j < N; ++j) {
    if (owner[j] < 0) {
      continue;
    }
    const Tilt& t = tilts[owner[j]];
    Vec3 turned = (Eigen::AngleAxisd(fadeAngle[j], t.rotation) * axes[j]).normalized();
    const double fromReference = angleBetween(turned, reference[j]);
    if (fromReference > maxTilt) {  // keep blends inside the tilt limit too
      turned = slerpAxis(reference[j], turned, maxTilt / fromReference);
    }
    axes[j] = turned;
    ++result.blendedPoints;
  }
  for (const Tilt& t : tilts) {
    axes[t.station] = t.axis;
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

}  // namespace geolattice
