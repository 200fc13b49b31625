#include "toolpath/PathSubdivision.h"

#include <algorithm>
#include <cmath>

namespace geolattice {

Vec3 slerpAxis(const Vec3& a, const Vec3& b, double t) {
  const double angle = std::acos(std::clamp(a.dot(b), -1.0, 1.0));
  if (angle < 1e-12) {
    return a;
  }
  if (angle > M_PI - 1e-9) {  // opposite: turn about any perpendicular
    const Vec3 p = a.unitOrthogonal();
    return (std::cos(t * M_PI) * a + std::sin(t * M_PI) * p).normalized();
  }
  return ((std::sin((1 - t) * angle) * a + std::sin(t * angle) * b) / std::sin(angle)).normalized();
}

SubdivisionCounts subdivideToolpath(Toolpath& p, double maxTurnRad, double maxLength,
                                    std::vector<Vec3>* extra, std::vector<char>* flags) {
  SubdivisionCounts counts;
  const size_t N = p.points.size();
  if (N < 2) {
    return counts;
  }
  // Pieces per segment (segment i ends at point i).
  std::vector<int> pieces(N, 1);
  size_t total = N;
  for (size_t i = 1; i < N; ++i) {
    const double turn = std::acos(std::clamp(p.normals[i - 1].dot(p.normals[i]), -1.0, 1.0));
    const int byTurn = std::max(1, static_cast<int>(std::ceil(turn / maxTurnRad - 1e-9)));
    const int byLength =
        maxLength > 0 ? std::max(1, static_cast<int>(std::ceil(
                                        (p.points[i] - p.points[i - 1]).norm() / maxLength - 1e-9)))
                      : 1;
    pieces[i] = std::max(byTurn, byLength);
    counts.rotationSteps += byTurn - 1;
    total += static_cast<size_t>(pieces[i] - 1);
  }
  if (total == N) {
    return counts;
  }
  counts.inserted = static_cast<int>(total - N);

  Toolpath q;              // the subdivided arrays; report fields stay in p
  q.reservePoints(total);  // each array allocated once, at its size (no doubling)
  std::vector<Vec3> extraOut;
  std::vector<char> flagsOut;
  if (extra) {
    extraOut.reserve(total);
  }
  if (flags) {
    flagsOut.reserve(total);
  }
  auto pushCopy = [&](size_t i) {
    q.appendPointOf(p, i);
    if (extra) {
      extraOut.push_back((*extra)[i]);
    }
    if (flags) {
      flagsOut.push_back((*flags)[i]);
    }
  };
  pushCopy(0);
  for (size_t i = 1; i < N; ++i) {
    const int n = pieces[i];
    const bool deposits = p.kind[i] != MoveKind::Air && p.width[i] > 0;
    // As the planner: a print segment arriving by air has the end's thickness at both ends.
    const double h1 = p.thickness[i];
    const double h0 =
        p.kind[i - 1] == MoveKind::Air || p.kind[i] == MoveKind::Air ? h1 : p.thickness[i - 1];
    const double e0 = p.extrusion[i - 1], e1 = p.extrusion[i];
    for (int s = 1; s < n; ++s) {
      const double t = static_cast<double>(s) / n;
      q.points.push_back((1 - t) * p.points[i - 1] + t * p.points[i]);
      q.normals.push_back(slerpAxis(p.normals[i - 1], p.normals[i], t));
      q.kind.push_back(p.kind[i]);
      q.thickness.push_back(p.kind[i] == MoveKind::Air ? 0.0 : (1 - t) * h0 + t * h1);
      q.width.push_back(p.width[i]);
      // Deposited volume up to t with h linear: ∫0^t (h0 + τ (h1 - h0)) dτ over the whole.
      const double share = deposits && h0 + h1 > 0 ? t * (2 * h0 + t * (h1 - h0)) / (h0 + h1) : t;
      q.extrusion.push_back(e0 + share * (e1 - e0));
      q.feedRate.push_back(p.feedRate[i]);
      q.layer.push_back(p.layer[i]);
      q.subgraph.push_back(p.subgraph[i]);
      q.pathIndex.push_back(p.pathIndex[i]);
      if (extra) {
        extraOut.push_back(slerpAxis((*extra)[i - 1], (*extra)[i], t));
      }
      if (flags) {
        flagsOut.push_back(0);
      }
    }
    pushCopy(i);
  }
  p.swapPoints(q);
  if (extra) {
    extra->swap(extraOut);
  }
  if (flags) {
    flags->swap(flagsOut);
  }
  return counts;
}

}  // namespace geolattice
