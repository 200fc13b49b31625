#include "collision/CollisionVerifier.h"

#include "collision/TimedPointTree.h"

#include "common/Error.h"
#include "common/ParallelFor.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
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
  const bool withPlate = all.size() > N;
  const int materialRoot = withPlate ? tree.firstChild() : 0;
  // The plate's samples alone, for the nearest of them to a station's tip (through the whole
  // tree, that search would open every ball of material near the tip too).
  const int plateRoot = withPlate ? tree.secondChild() : -1;
  // With an exemption, a station whose nozzle reaches the plate must still be searched to its
  // end for material some order could have kept out, but not through the plate's samples (a cone
  // that reaches the plate holds thousands of them): after its first plate sample that search
  // runs on the material alone.
  const bool searchPastThePlate = exemption && withPlate;
  const NozzleVolume volume(nozzle);
  NozzleBound bound(nozzle, volume);
  // The reported obstacle of a violating station: the one nearest its tip (ties: the lowest
  // index) among the obstacles of the reported kind (sameKind), so the report does not depend
  // on the order the tree happens to visit them. hit (one of them) bounds the search.
  auto nearestOfItsKind = [&](const NozzleBound& station, int k, int& hit, double& height,
                              double& radial, auto&& sameKind) {
    hit = tree.nearestCandidate(station, points[k], time[k], hit, [&](int q) {
      return sameKind(q) && volume.contains(points[k], axis[k], all[q]);
    });
    volume.contains(points[k], axis[k], all[hit], &height, &radial);
  };
  auto nearestPlateSample = [&](const NozzleBound& station, int k, int& hit, double& height,
                                double& radial) {
    hit = tree.nearestCandidate(
        station, points[k], time[k], hit,
        [&](int q) { return volume.contains(points[k], axis[k], all[q]); }, plateRoot);
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
    if (hit < static_cast<int>(N) && (all[hit] - points[k]).squaredNorm() <= plateD2) {
      return false;
    }
    int material = -1;
    tree.forEachCandidate(WithinBall{station, points[k], std::sqrt(plateD2)}, time[k], [&](int q) {
      if (q < static_cast<int>(N) && (points[q] - points[k]).squaredNorm() <= plateD2 &&
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
  // verdicts merged in print time order afterwards).
  struct Verdict {
    int station, hit;
    double height, radial;
    bool unavoidable, onPlate, located;
  };
  constexpr size_t kChunk = 2048;
  const size_t chunks = (stations.size() + kChunk - 1) / kChunk;
  std::vector<std::vector<Verdict>> verdicts(chunks);
  parallelFor(chunks, 0, [&](size_t c, int) {
    NozzleBound station = bound;
    for (size_t i = c * kChunk; i < std::min(stations.size(), (c + 1) * kChunk); ++i) {
      const int k = stations[i];
      station.setStation(points[k], axis[k]);
      // hit: material some order could have kept out of the nozzle; exemptHit: material no
      // order keeps out (a skeleton ancestor's); plateHit: the build plate (no order moves it).
      // The verdict takes the first kind present in that order (without an exemption material
      // and plate are one kind), and reports its obstacle nearest the tip.
      const int plateFirst = static_cast<int>(N);
      int hit = -1, exemptHit = -1, plateHit = -1;
      double height = 0, radial = 0, exemptHeight = 0, exemptRadial = 0;
      double exemptD2 = 0;
      bool materialLeft = false;  // the plate was found first: search the material alone
      tree.forEachCandidate(station, time[k], [&](int q) {
        double h = 0, r = 0;
        if (!volume.contains(points[k], axis[k], all[q], &h, &r)) {
          return false;
        }
        const bool onPlate = q >= plateFirst;
        if (!exemption ||
            (!onPlate && !exemption->unavoidable(exemption->group[k], exemption->group[q]))) {
          hit = q;
          return true;
        }
        if (onPlate) {  // outranks exempt material: only an avoidable obstacle is left to find
          plateHit = q;
          materialLeft = searchPastThePlate;
          return true;
        }
        // Exempt material: the search goes on to its end (unless an avoidable obstacle or the
        // plate turns up), so its nearest obstacle is found on the way.
        const double d2 = (all[q] - points[k]).squaredNorm();
        if (exemptHit < 0 || d2 < exemptD2 || (d2 == exemptD2 && q < exemptHit)) {
          exemptHit = q;
          exemptD2 = d2;
          exemptHeight = h;
          exemptRadial = r;
        }
        return false;
      });
      if (materialLeft) {  // an avoidable obstacle, if any (the plate outranks exempt material)
        tree.forEachCandidate(
            station, time[k],
            [&](int q) {
              if (!volume.contains(points[k], axis[k], points[q]) ||
                  exemption->unavoidable(exemption->group[k], exemption->group[q])) {
                return false;
              }
              hit = q;
              return true;
            },
            materialRoot);
      }
      bool unavoidable = false;
      bool located = true;  // hit is the obstacle nearest the tip (height, radial are its)
      if (hit >= 0) {
        if (!exemption) {  // one kind: material or plate
          located = nearerOfTheKinds(station, k, hit, height, radial);
        } else {
          nearestOfItsKind(station, k, hit, height, radial, [&](int q) {
            return q < plateFirst &&
                   !exemption->unavoidable(exemption->group[k], exemption->group[q]);
          });
        }
      } else if (plateHit >= 0) {
        unavoidable = true;
        hit = plateHit;
        nearestPlateSample(station, k, hit, height, radial);
      } else if (exemptHit >= 0) {
        unavoidable = true;
        hit = exemptHit;
        height = exemptHeight;
        radial = exemptRadial;
      } else if (plate && tipInsidePlate(*plate, partLo, partHi, points[k])) {
        unavoidable = true;
        hit = static_cast<int>(all.size());  // the tip itself is in the plate
      }
      if (hit >= 0) {
        const bool onPlate = hit >= plateFirst;
        verdicts[c].push_back({k, hit, height, radial, unavoidable, onPlate, located});
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
        if (!v.located) {
          NozzleBound station = bound;
          station.setStation(points[k], axis[k]);
          nearestOfItsKind(station, k, v.hit, v.height, v.radial, [](int) { return true; });
        }
        const Vec obstacle = v.hit == static_cast<int>(all.size())
                                 ? Vec(points[k].x(), points[k].y(), 0.0)
                                 : all[v.hit];
        report.violations.push_back({k, v.hit >= static_cast<int>(N) ? -1 : v.hit, points[k],
                                     obstacle, v.height, v.radial, v.unavoidable});
      }
    }
  }
  report.collisionFree = report.violatingStations == 0;
  report.orderCollisionFree = report.violatingStations == report.unavoidableStations;
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return report;
}

}  // namespace geolattice
