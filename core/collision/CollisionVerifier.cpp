#include "collision/CollisionVerifier.h"

#include "common/Error.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>

namespace geolattice {

namespace {

using Vec = Eigen::Vector3d;

/// Static kd-tree over the printed points; every node knows its bounding sphere and the
/// earliest print time below it.
class TimedPointTree {
public:
  struct Node {
    Vec centre = Vec::Zero();
    double radius = 0;
    int minTime = 0;
    int begin = 0, end = 0;  ///< range in order_
    int left = -1, right = -1;
  };

  TimedPointTree(const std::vector<Vec>& points, const std::vector<int>& time) : points_(points), time_(time) {
    order_.resize(points.size());
    std::iota(order_.begin(), order_.end(), 0);
    if (!order_.empty()) {
      nodes_.reserve(2 * points.size() / kLeafSize + 2);
      build(0, static_cast<int>(order_.size()));
    }
  }

  const std::vector<Node>& nodes() const { return nodes_; }
  const std::vector<int>& order() const { return order_; }

private:
  static constexpr int kLeafSize = 8;

  int build(int begin, int end) {
    const int id = static_cast<int>(nodes_.size());
    nodes_.emplace_back();
    Vec lo = Vec::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    int minTime = std::numeric_limits<int>::max();
    for (int i = begin; i < end; ++i) {
      lo = lo.cwiseMin(points_[order_[i]]);
      hi = hi.cwiseMax(points_[order_[i]]);
      minTime = std::min(minTime, time_[order_[i]]);
    }
    const Vec centre = 0.5 * (lo + hi);
    double r2 = 0;
    for (int i = begin; i < end; ++i) {
      r2 = std::max(r2, (points_[order_[i]] - centre).squaredNorm());
    }
    int left = -1, right = -1;
    if (end - begin > kLeafSize) {
      int axis = 0;
      (hi - lo).maxCoeff(&axis);
      const int mid = (begin + end) / 2;
      std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                       [&](int a, int b) { return points_[a][axis] < points_[b][axis]; });
      left = build(begin, mid);
      right = build(mid, end);
    }
    Node& n = nodes_[id];
    n.centre = centre;
    n.radius = std::sqrt(r2);
    n.minTime = minTime;
    n.begin = begin;
    n.end = end;
    n.left = left;
    n.right = right;
    return id;
  }

  const std::vector<Vec>& points_;
  const std::vector<int>& time_;
  std::vector<int> order_;
  std::vector<Node> nodes_;
};

/// The nozzle at one station, as dot-product tests (no angles in the exact test).
struct NozzleAt {
  Vec tip, axis;
  double cos2 = 0;        ///< cos² NA
  double length = 0;      ///< L (∞ allowed)
  double holder2 = 0;     ///< R²
  double clearance = 0;
  double boundSin = 0, boundCos = 1;  ///< of a half-angle that bounds the whole nozzle
  double reach = std::numeric_limits<double>::infinity();  ///< L / cos NA without holder

  /// Exact: is x inside the nozzle volume? Sets height and radial for the report.
  bool contains(const Vec& x, double& height, double& radial) const {
    const Vec d = x - tip;
    const double h = d.dot(axis);
    if (!(h > clearance)) {
      return false;
    }
    const double d2 = d.squaredNorm();
    const double r2 = std::max(0.0, d2 - h * h);
    bool inside;
    if (h <= length) {
      inside = h * h > d2 * cos2;  // angle(d, axis) < NA, h > 0
    } else {
      inside = r2 < holder2;
    }
    if (inside) {
      height = h;
      radial = std::sqrt(r2);
    }
    return inside;
  }

  /// Conservative: can any point of the ball (c, rho) be inside? Bounding cone distance test.
  bool mayTouch(const Vec& c, double rho) const {
    const Vec v = c - tip;
    const double h = v.dot(axis);
    if (h + rho <= clearance) {
      return false;  // the whole ball is at or below the tip plane
    }
    if (v.norm() > rho + reach) {
      return false;  // beyond the end of a nozzle without holder
    }
    const double r = std::sqrt(std::max(0.0, v.squaredNorm() - h * h));
    if (r * boundCos <= h * boundSin) {
      return true;  // centre inside the bounding cone
    }
    const double along = r * boundSin + h * boundCos;
    const double distance = along <= 0 ? v.norm() : r * boundCos - h * boundSin;
    return distance <= rho;
  }
};

} // namespace

CollisionReport verifyNozzleClearance(const std::vector<Vec>& points, const std::vector<Vec>& normals,
                                      const std::vector<int>& time, const NozzleModel& nozzle, int maxReported,
                                      const CollisionExemption* exemption, const std::vector<char>* material) {
  const auto t0 = std::chrono::steady_clock::now();
  nozzle.validate();
  const size_t N = points.size();
  if (normals.size() != N || time.size() != N) {
    throw GeoLatticeError("collision verifier: points, normals and print times must have the same length");
  }
  if (exemption && (exemption->group.size() != N || !exemption->unavoidable)) {
    throw GeoLatticeError("collision verifier: the exemption needs one group per point and a predicate");
  }
  if (material && material->size() != N) {
    throw GeoLatticeError("collision verifier: the material mask needs one flag per point");
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
      s << "collision verifier: the nozzle axis (normal) of point " << i << " is zero or not finite";
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
  const TimedPointTree tree(points, obstacleTime);
  const double na = nozzle.halfAngleDeg * M_PI / 180.0;
  // Bounding half-angle: the holder (h > L, r < R) lies inside the cone of angle atan(R / L).
  const double bound = std::isfinite(nozzle.length) ? std::max(na, std::atan2(nozzle.holderRadius, nozzle.length)) : na;
  NozzleAt at;
  at.cos2 = std::cos(na) * std::cos(na);
  at.length = nozzle.length;
  at.holder2 = nozzle.holderRadius * nozzle.holderRadius;
  at.clearance = nozzle.tipClearance;
  at.boundSin = std::sin(bound);
  at.boundCos = std::cos(bound);
  if (std::isfinite(nozzle.length) && nozzle.holderRadius == 0) {
    at.reach = nozzle.length / std::cos(na);
  }

  // Stations in print-time order, so the reported violations are the first ones.
  std::vector<int> stations(N);
  std::iota(stations.begin(), stations.end(), 0);
  std::stable_sort(stations.begin(), stations.end(), [&](int a, int b) { return time[a] < time[b]; });

  CollisionReport report;
  report.stations = static_cast<long long>(N);
  const auto& nodes = tree.nodes();
  const auto& order = tree.order();
  std::vector<int> stack;
  for (int k : stations) {
    at.tip = points[k];
    at.axis = axis[k];
    const int now = time[k];
    stack.assign(1, 0);
    int hit = -1, exemptHit = -1;
    double height = 0, radial = 0, exemptHeight = 0, exemptRadial = 0;
    while (!stack.empty() && hit < 0 && !nodes.empty()) {
      const auto& node = nodes[stack.back()];
      stack.pop_back();
      if (node.minTime >= now || !at.mayTouch(node.centre, node.radius)) {
        continue;
      }
      if (node.left < 0) {
        for (int i = node.begin; i < node.end; ++i) {
          const int q = order[i];
          if (obstacleTime[q] < now && at.contains(points[q], height, radial)) {
            if (exemption && exemption->unavoidable(exemption->group[k], exemption->group[q])) {
              if (exemptHit < 0) {  // keep looking for an obstacle an order could have avoided
                exemptHit = q;
                exemptHeight = height;
                exemptRadial = radial;
              }
              continue;
            }
            hit = q;
            break;
          }
        }
      } else {
        stack.push_back(node.left);
        stack.push_back(node.right);
      }
    }
    const bool unavoidable = hit < 0 && exemptHit >= 0;
    if (unavoidable) {
      hit = exemptHit;
      height = exemptHeight;
      radial = exemptRadial;
      ++report.unavoidableStations;
    }
    if (hit >= 0) {
      ++report.violatingStations;
      if (static_cast<int>(report.violations.size()) < maxReported) {
        report.violations.push_back({k, hit, points[k], points[hit], height, radial, unavoidable});
      }
    }
  }
  report.collisionFree = report.violatingStations == 0;
  report.orderCollisionFree = report.violatingStations == report.unavoidableStations;
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return report;
}

} // namespace geolattice
