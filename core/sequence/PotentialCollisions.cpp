#include "sequence/PotentialCollisions.h"

#include "common/Error.h"
#include "common/ParallelFor.h"
#include "common/Progress.h"
#include "nozzle/NozzleBound.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>

namespace geolattice {

namespace {

/// Bounding-sphere tree over the samples of one sub-graph. A node also bounds the nozzle axes
/// of its samples: all lie within `spread` (radians) of `axis`.
struct SampleTree {
  struct Node {
    Vec3 centre = Vec3::Zero();
    double radius = 0;
    Vec3 axis = Vec3::UnitZ();
    double spread = 0;
    double axisSlack = 0;  ///< 2 sin(spread / 2): |n - axis| for every axis n below
    double cosSpread = -1, sinSpread = 0;
    double coneSin = 0, coneCos = 1;  ///< of the bounding angle + spread (set per search)
    int begin = 0, end = 0;
    int left = -1, right = -1;
  };
  std::vector<int> order;             ///< sample ids
  std::vector<Vec3> points, normals;  ///< of the samples in `order`, contiguous for the leaf tests
  std::vector<Node> nodes;
};

/// Samples per leaf. A larger leaf means fewer node pairs to descend through and more point
/// tests in a leaf pair, which are cheap: on the three-branch tree (bench_sequence BM_Pcg, one
/// thread, medians of 3 runs twice) 8 -> 32 took the cone 107-111 -> 88-89 ms and the example
/// printhead 280-292 -> 209-214 ms (64: slower again); the same pairs.
constexpr int kLeafSize = 32;

int buildNode(SampleTree& tree, const MaterialSamples& m, int begin, int end) {
  const int id = static_cast<int>(tree.nodes.size());
  tree.nodes.emplace_back();
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo,
       axisSum = Vec3::Zero();
  for (int i = begin; i < end; ++i) {
    const int s = tree.order[i];
    lo = lo.cwiseMin(m.points[s]);
    hi = hi.cwiseMax(m.points[s]);
    axisSum += m.normals[s];
  }
  const Vec3 centre = 0.5 * (lo + hi);
  const double axisNorm = axisSum.norm();
  const Vec3 axis = axisNorm > 0 ? Vec3(axisSum / axisNorm) : Vec3::UnitZ();
  double r2 = 0, minCos = 1;
  for (int i = begin; i < end; ++i) {
    const int s = tree.order[i];
    r2 = std::max(r2, (m.points[s] - centre).squaredNorm());
    minCos = std::min(minCos, axis.dot(m.normals[s]));
  }
  int left = -1, right = -1;
  if (end - begin > kLeafSize) {
    int dim = 0;
    (hi - lo).maxCoeff(&dim);
    const int mid = (begin + end) / 2;
    std::nth_element(tree.order.begin() + begin, tree.order.begin() + mid, tree.order.begin() + end,
                     [&](int a, int b) { return m.points[a][dim] < m.points[b][dim]; });
    left = buildNode(tree, m, begin, mid);
    right = buildNode(tree, m, mid, end);
  }
  SampleTree::Node& n = tree.nodes[id];
  n.centre = centre;
  n.radius = std::sqrt(r2);
  n.axis = axis;
  n.spread = axisNorm > 0 ? std::acos(std::clamp(minCos, -1.0, 1.0)) + 1e-12 : M_PI;
  n.axisSlack = 2 * std::sin(0.5 * std::min(n.spread, M_PI));
  n.cosSpread = std::cos(std::min(n.spread, M_PI));
  n.sinSpread = std::sin(std::min(n.spread, M_PI));
  n.begin = begin;
  n.end = end;
  n.left = left;
  n.right = right;
  return id;
}

/// Distance from point v (relative to the apex) to the solid cone with unit axis a and
/// half-angle phi in [0, π] (phi >= π/2 is a half-space or more).
double distanceToCone(const Vec3& v, const Vec3& a, double phi) {
  if (phi >= M_PI) {
    return 0;
  }
  const double h = v.dot(a);
  const double r = std::sqrt(std::max(0.0, v.squaredNorm() - h * h));
  const double psi = std::atan2(r, h);  // angle of v from the axis
  if (psi <= phi) {
    return 0;
  }
  const double len = std::sqrt(r * r + h * h);
  return psi - phi >= M_PI / 2 ? len : len * std::sin(psi - phi);
}

/// Is point v (relative to the apex) farther than `margin` from the solid cone about the node's
/// axis with its half-angle (bounding angle + spread; sine and cosine cached on the node)? Below
/// 90° in dot products (the distance to the cone's surface line), else as distanceToCone.
bool outsideCone(const Vec3& v, const SampleTree::Node& node, double margin) {
  if (node.coneCos <= 0) {
    return distanceToCone(v, node.axis, std::atan2(node.coneSin, node.coneCos)) > margin;
  }
  const double h = v.dot(node.axis);
  const double r = std::sqrt(std::max(0.0, v.squaredNorm() - h * h));
  if (r * node.coneCos <= h * node.coneSin) {
    return false;  // inside the cone
  }
  const double along = r * node.coneSin + h * node.coneCos;
  const double distance = along <= 0 ? v.norm() : r * node.coneCos - h * node.coneSin;
  return distance > margin;
}

struct PairSearch {
  const MaterialSamples& m;
  const NozzleVolume& nozzle;
  double boundAngle;
  double apexOffset;    ///< the bounding cone's apex lies this far below each tip
  double reach;         ///< nothing farther than this from a tip is inside the nozzle
  double clearance;     ///< material with h <= clearance is ignored
  NozzleBound station;  ///< the bound at one station (the leaf-leaf pre-test)
  long long leafTests = 0;

  /// Does any station of tree A (sub-graph i) have material of tree B (sub-graph j) inside its
  /// nozzle? Dual descent; the station cluster's nozzles lie in ball(c, ρ) ⊕ cone(n̄, NA* + δ).
  bool collides(const SampleTree& A, const SampleTree& B) {
    // Depth first on a fixed stack: both trees split at medians, so each is under 30 deep and
    // the stack holds at most their depths together plus one.
    std::array<std::pair<int, int>, 128> stack;
    int top = 0;
    stack[top++] = {0, 0};
    while (top > 0) {
      const auto [ia, ib] = stack[--top];
      const auto& a = A.nodes[ia];
      const auto& b = B.nodes[ib];
      const Vec3 d = b.centre - a.centre;
      const double dn = d.norm();
      // h = (x - p)·n and the distance from the axis for a station p of A with axis n and a
      // point x of B differ from those of the centres along the mean axis by at most `slack`.
      const double axisSlack = a.axisSlack;
      const double slack = a.radius + b.radius + (dn + b.radius) * axisSlack;
      const double h = d.dot(a.axis);
      // Highest h over the clusters: the material lies below every tip plane.
      if (h + slack <= clearance || dn > a.radius + b.radius + reach) {
        continue;
      }
      const double rc = std::sqrt(std::max(0.0, dn * dn - h * h));
      const double rab = a.radius + b.radius;
      if (nozzle.head && a.cosSpread > 0 && dn > rab) {
        // The printhead's clear angle by distance from the tip: every point of B seen from every
        // station of A lies at least θ - σ - δ off the station's axis (θ: d off the mean axis, σ:
        // the axes' spread, δ = asin((ρa + ρb) / |d|)) and at |d| ± (ρa + ρb) from its tip.
        // In cosines and sines (no trigonometry on this path).
        const double sd = rab / dn, cd = std::sqrt(1.0 - sd * sd);
        const double cphi = a.cosSpread * cd - a.sinSpread * sd;  // φ = σ + δ < π
        const double sphi = a.sinSpread * cd + a.cosSpread * sd;
        const double u = h / dn, v = rc / dn;  // cos θ, sin θ
        if (v * cphi - u * sphi > 0 &&         // θ - φ > 0
            u * cphi + v * sphi < nozzle.cosMaxClearAngleBetween(dn - rab, dn + rab)) {
          continue;  // θ - φ beyond the clear angle at those distances
        }
      }
      if (!nozzle.mayContainBall(h, rc, slack)) {
        continue;  // outside the printhead's profile
      }
      // The bounding cone's apexes (apexOffset below each tip) lie within a.radius +
      // apexOffset * axisSlack of the mean apex.
      if (outsideCone(d + apexOffset * a.axis, a, a.radius + apexOffset * axisSlack + b.radius)) {
        continue;
      }
      const bool leafA = a.left < 0, leafB = b.left < 0;
      if (leafA && leafB) {
        for (int i = a.begin; i < a.end; ++i) {
          const Vec3& p = A.points[i];
          const Vec3& n = A.normals[i];
          station.setStation(p, n);  // this station against B's ball
          if (!station.mayTouch(b.centre, b.radius)) {
            continue;
          }
          for (int j = b.begin; j < b.end; ++j) {
            ++leafTests;
            if (nozzle.contains(p, n, B.points[j])) {
              return true;
            }
          }
        }
        continue;
      }
      // Split the larger cluster (a leaf cannot be split).
      if (leafB || (!leafA && a.radius >= b.radius)) {
        stack[top++] = {a.right, ib};
        stack[top++] = {a.left, ib};
      } else {
        stack[top++] = {ia, b.right};
        stack[top++] = {ia, b.left};
      }
    }
    return false;
  }
};

}  // namespace

PotentialCollisions computePotentialCollisions(const MaterialSamples& m, const NozzleModel& model,
                                               int threads) {
  PotentialCollisionOptions options;
  options.threads = threads;
  return computePotentialCollisions(m, model, options);
}

PotentialCollisions computePotentialCollisions(const MaterialSamples& m, const NozzleModel& model,
                                               const PotentialCollisionOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  const int threads = options.threads;
  const ProgressReporter progress(options.progress, options.shouldAbort, "potential collisions");
  model.validate();
  if (m.offset.empty()) {
    throw GeoLatticeError("potential collisions: no sub-graph");
  }
  const int K = static_cast<int>(m.offset.size()) - 1;
  requireValidWorkLimit(options.maxPairs, "the sub-graph pair limit");
  requireWithinWorkLimit(0.5 * K * (K - 1.0), options.maxPairs, "potential collisions",
                         "pairs of sub-graphs", "for " + std::to_string(K) + " sub-graphs",
                         "use a larger layer interval or raise the size limit (MaximumElements)",
                         0.0);
  std::vector<SampleTree> trees(K);
  for (int k = 0; k < K; ++k) {
    SampleTree& t = trees[k];
    t.order.resize(m.offset[k + 1] - m.offset[k]);
    std::iota(t.order.begin(), t.order.end(), m.offset[k]);
    if (!t.order.empty()) {
      buildNode(t, m, 0, static_cast<int>(t.order.size()));
      t.points.reserve(t.order.size());
      t.normals.reserve(t.order.size());
      for (const int s : t.order) {
        t.points.push_back(m.points[s]);
        t.normals.push_back(m.normals[s]);
      }
    }
  }
  const NozzleVolume nozzle(model);
  const double boundAngle = model.boundingHalfAngleRad();
  for (SampleTree& t : trees) {  // the station clusters' bounding cones
    for (SampleTree::Node& n : t.nodes) {
      const double angle = std::min(M_PI, boundAngle + n.spread);
      n.coneSin = std::sin(angle);
      n.coneCos = std::cos(angle);
    }
  }

  PotentialCollisions out;
  out.pcg.resize(K);
  // One pair search per worker; sub-graphs are handed out one at a time.
  const int workers = workerCount(threads, static_cast<size_t>(K));
  std::vector<PairSearch> searches(
      workers, PairSearch{m, nozzle, boundAngle, model.boundingApexOffset(), model.reach(),
                          model.tipClearance, NozzleBound(model, nozzle)});
  progress.report(0.0);
  size_t reported = 0;  // in 64ths
  parallelFor(
      static_cast<size_t>(K), threads,
      [&](size_t item, int w) {
        const int i = static_cast<int>(item);
        if (trees[i].nodes.empty()) {
          return;
        }
        for (int j = 0; j < K; ++j) {
          if (j != i && !trees[j].nodes.empty() && searches[w].collides(trees[i], trees[j])) {
            out.pcg[i].push_back(j);
          }
        }
      },
      [&](size_t finished) {  // about 64 reports; an abort throws here and stops the workers
        if (finished * 64 / K > reported) {
          reported = finished * 64 / K;
          progress.report(static_cast<double>(finished) / K);
        }
      });
  std::vector<long long> tests;
  for (const PairSearch& search : searches) {
    tests.push_back(search.leafTests);
  }
  for (int i = 0; i < K; ++i) {
    out.pairs += static_cast<long long>(out.pcg[i].size());
  }
  out.leafTests = std::accumulate(tests.begin(), tests.end(), 0LL);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  progress.report(1.0);  // the last sub-graphs may have been finished by other workers
  return out;
}

}  // namespace geolattice
