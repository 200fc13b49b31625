#include "collision/CollisionVerifier.h"

#include "collision/TimedPointTree.h"

#include "common/Error.h"
#include "common/ParallelFor.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <numeric>
#include <sstream>

namespace geolattice {

using Vec = Eigen::Vector3d;

namespace {

/// A nozzle bound cut to the ball of radius r about c.
struct WithinBall {
  const NozzleBound& bound;
  const Vec& c;
  double r;
  bool mayTouch(const Vec& centre, double radius) const {
    return (centre - c).squaredNorm() <= (r + radius) * (r + radius) &&
           bound.mayTouch(centre, radius);
  }
};

}  // namespace

CollisionReport verifyNozzleClearance(const std::vector<Vec>& points,
                                      const std::vector<Vec>& normals, const std::vector<int>& time,
                                      const NozzleModel& nozzle, int maxReported,
                                      const CollisionExemption* exemption,
                                      const std::vector<char>* material, const BuildPlate* plate,
                                      const std::vector<char>* checked) {
  const auto t0 = std::chrono::steady_clock::now();
  nozzle.validate();
  const size_t N = points.size();
  if (normals.size() != N || time.size() != N) {
    throw GeoLatticeError(
        "collision verifier: points, normals and print times must have the same length");
  }
  if (exemption && (exemption->group.size() != N || !exemption->unavoidable)) {
    throw GeoLatticeError(
        "collision verifier: the exemption needs one group per point and a predicate");
  }
  if (material && material->size() != N) {
    throw GeoLatticeError("collision verifier: the material mask needs one flag per point");
  }
  if (checked && checked->size() != N) {
    throw GeoLatticeError("collision verifier: the station mask needs one flag per point");
  }
  std::vector<Vec> axis(N);
  for (size_t i = 0; i < N; ++i) {
    if (!points[i].allFinite()) {
      std::ostringstream s;
      s << "collision verifier: point " << i << " is not finite";
      throw GeoLatticeError(s.str());
    }
    const double len = normals[i].norm();
    if (!(len > 0) || !std::isfinite(len)) {
      std::ostringstream s;
      s << "collision verifier: the nozzle axis (normal) of point " << i
        << " is zero or not finite";
      throw GeoLatticeError(s.str());
    }
    axis[i] = normals[i] / len;
  }

  // Obstacles: the material points (all points without a mask). Non-material points get a time
  // no station can exceed, so the tree never reports them.
  std::vector<int> obstacleTime(time);
  if (material) {
    for (size_t i = 0; i < N; ++i) {
      if (!(*material)[i]) {
        obstacleTime[i] = std::numeric_limits<int>::max();
      }
    }
  }
  // The build plate: its samples after the points, present from the start.
  std::vector<Vec> all = points;
  Vec partLo = Vec::Constant(std::numeric_limits<double>::infinity()), partHi = -partLo;
  if (plate && plate->enabled) {
    std::vector<Vec> part;
    for (size_t i = 0; i < N; ++i) {
      if (!material || (*material)[i]) {
        part.push_back(points[i]);
        partLo = partLo.cwiseMin(points[i]);
        partHi = partHi.cwiseMax(points[i]);
      }
    }
    const std::vector<Vec> samples = buildPlateSamples(*plate, part);
    all.insert(all.end(), samples.begin(), samples.end());
    obstacleTime.resize(all.size(), std::numeric_limits<int>::min());
  }
  // One tree; with the plate its root's children are the material and the plate's samples, so
  // each kind is searched alone where that is cheaper (one build instead of three: topopt's two
  // verifications built 0.12 s of trees for the kinds alone).
  const TimedPointTree tree(all, obstacleTime, static_cast<int>(N));
  // With an exemption, a station whose first obstacle is the plate or exempt material is still
  // searched for material some order could have kept out. Low over a long part its nozzle holds
  // much of the material printed before, nearly all of it exempt (a skeleton ancestor's): on a
  // 240 mm bar, 98 % of the 553 M points that search visited. So it runs on a second tree, built
  // on first need, whose material is grouped as the exemption groups it, and skips exempt groups
  // whole (that bar's sequence verifier: 4.5 s -> 0.16 s). The first search stays on the median
  // tree: grouped subtrees are flat sheets (a sub-graph's part of a layer) that a cone opens
  // more of (the three-branch tree's verifier was 1.5x slower on the grouped tree alone).
  std::vector<int> treeGroup;
  std::once_flag groupedOnce;
  std::unique_ptr<TimedPointTree> grouped;
  auto groupedMaterial = [&]() -> const TimedPointTree& {
    std::call_once(groupedOnce, [&] {
      treeGroup.assign(all.size(), TimedPointTree::kNoGroup);
      std::copy(exemption->group.begin(), exemption->group.end(), treeGroup.begin());
      grouped =
          std::make_unique<TimedPointTree>(all, obstacleTime, static_cast<int>(N), &treeGroup);
    });
    return *grouped;
  };
  const bool withPlate = all.size() > N;
  const int materialRoot = withPlate ? tree.firstChild() : 0;
  // The plate's samples alone, for the nearest of them to a station's tip (through the whole
  // tree, that search would open every ball of material near the tip too).
  const int plateRoot = withPlate ? tree.secondChild() : -1;
  const int plateFirst = static_cast<int>(N);
  const NozzleVolume volume(nozzle);
  NozzleBound bound(nozzle, volume);
  // The obstacle reported for a violating station: the one nearest its tip (ties: the lowest
  // index) among the obstacles of its kind (accept), so the report does not depend on the order
  // the tree happens to visit them. hit (one of them) bounds the search.
  auto nearestOfItsKind = [&](const NozzleBound& station, int k, int& hit, double& height,
                              double& radial, auto&& accept, int root) {
    hit = tree.nearestCandidate(
        station, points[k], time[k], hit,
        [&](int q) { return accept(q) && volume.contains(points[k], axis[k], all[q]); }, root);
    volume.contains(points[k], axis[k], all[hit], &height, &radial);
  };

  // Without an exemption the obstacle reported is the nearest to the tip of either kind, and its
  // kind decides whether the station is a plate station. A nearest search through the whole
  // tree costs as much again as the first search (a nozzle that reaches the plate holds
  // thousands of its samples), so: the plate's nearest sample inside the nozzle, then whether
  // any material inside lies as near. Returns whether `hit` is then the nearest obstacle (always
  // when it is the plate's); a material hit is located later only if it is reported.
  auto nearerOfTheKinds = [&](const NozzleBound& station, int k, int& hit, double& height,
                              double& radial) {
    const int plateHit = tree.nearestCandidate(
        station, points[k], time[k], -1,
        [&](int q) { return volume.contains(points[k], axis[k], all[q]); }, plateRoot);
    if (plateHit < 0) {
      return false;  // material only
    }
    const double plateD2 = (all[plateHit] - points[k]).squaredNorm();
    // Ties go to the lower index, the material's.
    if (hit < plateFirst && (all[hit] - points[k]).squaredNorm() <= plateD2) {
      return false;
    }
    int material = -1;
    tree.forEachCandidate(WithinBall{station, points[k], std::sqrt(plateD2)}, time[k], [&](int q) {
      if (q < plateFirst && (points[q] - points[k]).squaredNorm() <= plateD2 &&
          volume.contains(points[k], axis[k], points[q])) {
        material = q;
      }
      return material >= 0;
    });
    if (material >= 0) {
      hit = material;
      return false;
    }
    hit = plateHit;
    volume.contains(points[k], axis[k], all[hit], &height, &radial);
    return true;
  };

  // Stations in print-time order, so the reported violations are the first ones.
  std::vector<int> stations;
  stations.reserve(N);
  for (size_t i = 0; i < N; ++i) {
    if (!checked || (*checked)[i]) {
      stations.push_back(static_cast<int>(i));
    }
  }
  std::stable_sort(stations.begin(), stations.end(),
                   [&](int a, int b) { return time[a] < time[b]; });

  CollisionReport report;
  report.stations = static_cast<long long>(N);
  // One station's verdict (stations are independent: chunks of them over the workers, the
  // verdicts merged in print time order afterwards). hit is an obstacle of the verdict's kind;
  // the one nearest the tip is searched only for the reported violations (kind Located: hit,
  // height and radial are that one already).
  enum class Kind : char { Located, Any, Avoidable, Exempt, PlateSample };
  struct Verdict {
    int station, hit;
    double height, radial;
    bool unavoidable, onPlate;
    Kind kind;
  };
  // An obstacle of station k that no order keeps out (with an exemption).
  auto exempt = [&](int k, int group) {
    return exemption->unavoidable(exemption->group[k], group);
  };
  constexpr size_t kChunk = 2048;
  const size_t chunks = (stations.size() + kChunk - 1) / kChunk;
  std::vector<std::vector<Verdict>> verdicts(chunks);
  parallelFor(chunks, 0, [&](size_t c, int) {
    NozzleBound station = bound;
    for (size_t i = c * kChunk; i < std::min(stations.size(), (c + 1) * kChunk); ++i) {
      const int k = stations[i];
      station.setStation(points[k], axis[k]);
      auto inside = [&](int q) {
        return volume.contains(points[k], axis[k], all[q]);
      };
      // The first obstacle inside the nozzle that `take` takes, in the subtree `root` of `t`
      // with the groups `prune` says skipped, or -1.
      auto firstInside = [&](const TimedPointTree& t, auto&& take, int root, auto&& prune) {
        int found = -1;
        t.forEachCandidate(
            station, time[k],
            [&](int q) {
              if (!inside(q) || !take(q)) {
                return false;
              }
              found = q;
              return true;
            },
            root, prune);
        return found;
      };
      auto any = [](int) {
        return true;
      };
      const TimedPointTree::KeepEveryGroup everyGroup;
      Verdict v{k, -1, 0.0, 0.0, false, false, Kind::Any};
      if (!exemption) {  // one kind: material or plate, the nearest to the tip decides
        v.hit = firstInside(tree, any, 0, everyGroup);
        if (v.hit >= 0 && nearerOfTheKinds(station, k, v.hit, v.height, v.radial)) {
          v.kind = Kind::Located;
        }
      } else {
        // With an order to judge, the first kind present decides: material some order could
        // have kept out (avoidable), the build plate (no order moves it; it outranks the rest),
        // material no order keeps out (exempt: a skeleton ancestor's). The first search stops at
        // the first obstacle of any kind. If it is not avoidable, the material is searched for
        // an avoidable one with exempt groups skipped, and then, past exempt material, the
        // plate's samples for one inside.
        int plateHit = -1, exemptHit = -1;
        tree.forEachCandidate(station, time[k], [&](int q) {
          if (!inside(q)) {
            return false;
          }
          (q >= plateFirst ? plateHit : exempt(k, exemption->group[q]) ? exemptHit : v.hit) = q;
          return true;
        });
        if (plateHit >= 0 || exemptHit >= 0) {
          const TimedPointTree& material = groupedMaterial();
          v.hit = firstInside(
              material, [&](int q) { return !exempt(k, exemption->group[q]); },
              withPlate ? material.firstChild() : 0, [&](int g) { return exempt(k, g); });
        }
        if (v.hit < 0 && exemptHit >= 0 && withPlate) {
          plateHit = firstInside(tree, any, plateRoot, everyGroup);
        }
        if (v.hit >= 0) {
          v.kind = Kind::Avoidable;
        } else if (plateHit >= 0) {
          v.hit = plateHit;
          v.kind = Kind::PlateSample;
        } else {
          v.hit = exemptHit;
          v.kind = Kind::Exempt;
        }
        v.unavoidable = v.hit >= 0 && v.kind != Kind::Avoidable;
      }
      if (v.hit < 0 && plate && tipInsidePlate(*plate, partLo, partHi, points[k])) {
        v.unavoidable = true;
        v.hit = static_cast<int>(all.size());  // the tip itself is in the plate
        v.kind = Kind::Located;
      }
      if (v.hit >= 0) {
        v.onPlate = v.hit >= plateFirst;
        verdicts[c].push_back(v);
      }
    }
  });
  for (std::vector<Verdict>& chunk : verdicts) {
    for (Verdict& v : chunk) {
      report.unavoidableStations += v.unavoidable;
      ++report.violatingStations;
      report.violatingStationIds.push_back(v.station);
      report.plateStations += v.onPlate;
      if (v.onPlate) {
        report.plateStationIds.push_back(v.station);
      }
      if (static_cast<int>(report.violations.size()) < maxReported) {
        const int k = v.station;
        NozzleBound station = bound;
        station.setStation(points[k], axis[k]);
        switch (v.kind) {
          case Kind::Located:
            break;
          case Kind::Any:
            nearestOfItsKind(
                station, k, v.hit, v.height, v.radial, [](int) { return true; }, 0);
            break;
          case Kind::Avoidable:
            nearestOfItsKind(
                station, k, v.hit, v.height, v.radial,
                [&](int q) { return !exempt(k, exemption->group[q]); }, materialRoot);
            break;
          case Kind::Exempt:
            nearestOfItsKind(
                station, k, v.hit, v.height, v.radial,
                [&](int q) { return exempt(k, exemption->group[q]); }, materialRoot);
            break;
          case Kind::PlateSample:
            nearestOfItsKind(
                station, k, v.hit, v.height, v.radial, [](int) { return true; }, plateRoot);
            break;
        }
        const Vec obstacle = v.hit == static_cast<int>(all.size())
                                 ? Vec(points[k].x(), points[k].y(), 0.0)
                                 : all[v.hit];
        report.violations.push_back({k, v.hit >= plateFirst ? -1 : v.hit, points[k], obstacle,
                                     v.height, v.radial, v.unavoidable});
      }
    }
  }
  report.collisionFree = report.violatingStations == 0;
  report.orderCollisionFree = report.violatingStations == report.unavoidableStations;
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return report;
}

}  // namespace geolattice
