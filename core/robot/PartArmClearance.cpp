#include "robot/PartArmClearance.h"

#include "common/SegmentDistance.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace geolattice {

namespace {

/// Voxel edge and diagonal (part units) of the material's samples.
constexpr double kVoxel = 2.0;
const double kVoxelDiagonal = kVoxel * std::sqrt(3.0);

/// Part units: PartArmClearance::Sweep's least is at most this much above the least distance.
constexpr double kSweepTolerance = 1.0;

struct VoxelHash {
  size_t operator()(const std::array<long long, 3>& k) const {
    return static_cast<size_t>(k[0] * 73856093LL ^ k[1] * 19349663LL ^ k[2] * 83492791LL);
  }
};

/// The TimedPointTree bound of a query: the spheres nearer to the capsule's surface than the
/// best distance found so far (part units).
struct NearCapsule {
  const Capsule& c;
  const double& best;
  bool mayTouch(const Eigen::Vector3d& centre, double radius) const {
    return segmentDistance(c.a, c.b, centre, centre) - c.radius - radius < best;
  }
};

double surfaceDistance(const Capsule& c, const Eigen::Vector3d& p) {
  return segmentDistance(c.a, c.b, p, p) - c.radius;
}

}  // namespace

PartArmClearance::PartArmClearance(const RobotCell& cell,
                                   const std::vector<Eigen::Vector3d>& points,
                                   const std::vector<int>& kind)
    : partOnFlange_(cell.partOnFlange), scale_(cell.partScale) {
  Eigen::AlignedBox3d all;
  for (const Eigen::Vector3d& p : points) {
    all.extend(p);
  }
  // The material: one sample per occupied voxel (its first point, at its time: the voxel's
  // earliest), a tenth of the points or fewer on a lattice printed at ~0.5 mm spacing.
  std::unordered_map<std::array<long long, 3>, size_t, VoxelHash> first;
  for (size_t i = 0; i < points.size(); ++i) {
    if (!kind.empty() && kind[i] == 2) {
      continue;
    }
    const Eigen::Vector3d v = (points[i] - all.min()) / kVoxel;
    const std::array<long long, 3> key{static_cast<long long>(std::floor(v.x())),
                                       static_cast<long long>(std::floor(v.y())),
                                       static_cast<long long>(std::floor(v.z()))};
    if (first.emplace(key, samples_.size()).second) {
      samples_.push_back(points[i]);
      time_.push_back(static_cast<int>(i));
    }
  }
  material_ = samples_.size();
  if (!all.isEmpty()) {  // the plate: the footprint at the lowest z, from the start
    const Eigen::Vector3d lo = all.min(), hi = all.max();
    const int nx = std::max(1, static_cast<int>(std::ceil((hi.x() - lo.x()) / kPlateSpacing)));
    const int ny = std::max(1, static_cast<int>(std::ceil((hi.y() - lo.y()) / kPlateSpacing)));
    for (int a = 0; a <= nx; ++a) {
      for (int b = 0; b <= ny; ++b) {
        samples_.emplace_back(lo.x() + (hi.x() - lo.x()) * a / nx,
                              lo.y() + (hi.y() - lo.y()) * b / ny, lo.z());
        time_.push_back(0);
      }
    }
  }
  tree_ = std::make_unique<TimedPointTree>(samples_, time_);
}

PartArmClearance::~PartArmClearance() = default;

PartArmClearance::Body PartArmClearance::inPart(const Isometry& flange,
                                                const ArmCapsules& arm) const {
  const Isometry toPart = (flange * partOnFlange_).inverse();
  Body body;
  for (int k = 0; k < kParts; ++k) {
    const Capsule& c = arm[kFirstNearPart + k];
    body[k] = {(toPart * c.a) / scale_, (toPart * c.b) / scale_, c.radius / scale_};
  }
  return body;
}

double PartArmClearance::nearestSample(const Body& body, size_t i, double bound,
                                       double stop) const {
  double best = bound;
  const int now = static_cast<int>(std::min<size_t>(i, static_cast<size_t>(INT32_MAX - 1))) + 1;
  for (int k = 0; k < kParts && !(best < stop); ++k) {
    const Capsule& c = body[k];
    tree_->forEachCandidate(NearCapsule{c, best}, now, [&](int q) {
      best = std::min(best, surfaceDistance(c, samples_[q]));
      return best < stop;
    });
  }
  return best;
}

double PartArmClearance::nearest(const Isometry& flange, const ArmCapsules& arm, size_t i,
                                 double limit, bool firstBelow) const {
  // A point of a voxel is within its diagonal of the voxel's sample.
  const double bound = limit / scale_ + kVoxelDiagonal;
  const double best = nearestSample(inPart(flange, arm), i, bound, firstBelow ? bound : 0.0);
  return std::max(0.0, best - kVoxelDiagonal) * scale_;
}

void PartArmClearance::Sweep::add(const Isometry& flange, const ArmCapsules& arm, size_t i) {
  const Body body = part_.inPart(flange, arm);
  const double bound = least_ / part_.scale_ + kVoxelDiagonal;  // samples beyond cannot count
  double lower = -std::numeric_limits<double>::infinity();
  if (have_ && i > index_) {
    // Every point of a capsule's segment moves at most as far as its ends do.
    double moved = 0;
    for (int k = 0; k < kParts; ++k) {
      moved = std::max({moved, (body[k].a - body_[k].a).norm(), (body[k].b - body_[k].b).norm()});
    }
    lower = raw_ - moved;
    // The material printed after the state before: samples with times in (index_, i].
    const auto* t = part_.time_.data();
    const auto* first = std::upper_bound(t, t + part_.material_, static_cast<int>(index_));
    const auto* last = std::upper_bound(t, t + part_.material_, static_cast<int>(i));
    for (const auto* s = first; s != last; ++s) {
      const Eigen::Vector3d& p = part_.samples_[static_cast<size_t>(s - t)];
      for (const Capsule& c : body) {
        lower = std::min(lower, surfaceDistance(c, p));
      }
    }
  }
  // Searched where the bound may beat the least so far by more than kSweepTolerance; else the
  // bound is the state's.
  if (lower < bound - kSweepTolerance) {
    raw_ = part_.nearestSample(body, i, bound, 0.0);
    least_ = std::min(least_, std::max(0.0, raw_ - kVoxelDiagonal) * part_.scale_);
  } else {
    raw_ = lower;  // not below the least by more than the tolerance: the least stands
  }
  body_ = body;
  index_ = i;
  have_ = true;
}

}  // namespace geolattice
