#include "overhang/OverhangAnalysis.h"

#include "common/Error.h"
#include "mesh/TetMeshTopology.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace geolattice {

namespace {

constexpr double kRadToDeg = 180.0 / 3.14159265358979323846;

std::string vecText(const Vec3& v) {
  return "(" + std::to_string(v.x()) + ", " + std::to_string(v.y()) + ", " + std::to_string(v.z()) +
         ")";
}

}  // namespace

double overhangAngleDeg(const Vec3& nozzle, const Vec3& normal) {
  const double c = nozzle.dot(normal) / normal.norm();
  return std::acos(std::clamp(c, -1.0, 1.0)) * kRadToDeg;
}

void OverhangOptions::validate() const {
  if (!(this->thresholdDeg > 90.0 && this->thresholdDeg <= 180.0)) {
    throw GeoLatticeError("overhang analysis: threshold angle must be in (90, 180] degrees, got " +
                          std::to_string(this->thresholdDeg));
  }
}

OverhangResult analyzeOverhang(const TetMesh& mesh, const TetMeshTopology& topology,
                               const std::vector<Vec3>& nozzleDirections,
                               const std::vector<std::uint8_t>& baseVertex,
                               const OverhangOptions& options) {
  options.validate();
  const double threshold = options.thresholdDeg;
  const size_t numTets = mesh.tets.size();
  const size_t numPoints = mesh.points.size();
  if (nozzleDirections.size() != numTets) {
    throw GeoLatticeError("overhang analysis: " + std::to_string(nozzleDirections.size()) +
                          " nozzle directions for " + std::to_string(numTets) +
                          " tets (one per tet needed)");
  }
  if (baseVertex.size() != numPoints) {
    throw GeoLatticeError("overhang analysis: " + std::to_string(baseVertex.size()) +
                          " base flags for " + std::to_string(numPoints) +
                          " vertices (one per vertex needed)");
  }
  if (topology.neighbors().size() != numTets) {
    throw GeoLatticeError("overhang analysis: the topology has " +
                          std::to_string(topology.neighbors().size()) + " tets but the mesh " +
                          std::to_string(numTets) + " (topology of another mesh?)");
  }
  const std::vector<BoundaryFace>& faces = topology.boundaryFaces();
  if (faces.empty()) {
    throw GeoLatticeError("overhang analysis: the mesh has no boundary faces");
  }

  OverhangResult r;
  r.thresholdDeg = threshold;
  const size_t numFaces = faces.size();
  r.planarDeg.resize(numFaces);
  r.curvedDeg.resize(numFaces);
  r.onBase.resize(numFaces);
  r.area.resize(numFaces);
  const Vec3 up(0, 0, 1);
  double maxPlanar = -1.0;
  double maxCurved = -1.0;
  for (size_t f = 0; f < numFaces; ++f) {
    const BoundaryFace& face = faces[f];
    for (int id : face.vertices) {
      if (id < 0 || static_cast<size_t>(id) >= numPoints) {
        throw GeoLatticeError("overhang analysis: boundary face " + std::to_string(f) +
                              " has vertex index " + std::to_string(id) + " out of range [0, " +
                              std::to_string(numPoints) + ")");
      }
    }
    // Each tet is checked when one of its faces is analysed: interior tets never matter.
    Vec3 d = nozzleDirections[face.tet];
    const double length = d.norm();
    if (!std::isfinite(length) || std::abs(length - 1.0) > 1e-3) {
      throw GeoLatticeError("overhang analysis: nozzle direction of tet " +
                            std::to_string(face.tet) + " is " + vecText(d) + " (length " +
                            std::to_string(length) + "), expected a unit vector");
    }
    d /= length;
    const Vec3& a = mesh.points[face.vertices[0]];
    const Vec3& b = mesh.points[face.vertices[1]];
    const Vec3& c = mesh.points[face.vertices[2]];
    const Vec3 n = (b - a).cross(c - a);  // outward (BoundaryFace orientation), |n| = 2 * area
    const double nn = n.norm();
    r.onBase[f] = baseVertex[face.vertices[0]] && baseVertex[face.vertices[1]] &&
                  baseVertex[face.vertices[2]];
    if (!(nn > 0.0) || !std::isfinite(nn)) {
      // No normal: neutral angle, and no area to count anywhere.
      r.planarDeg[f] = r.curvedDeg[f] = 90.0;
      r.area[f] = 0.0;
      ++r.zeroAreaFaces;
      continue;
    }
    r.area[f] = 0.5 * nn;
    r.planarDeg[f] = overhangAngleDeg(up, n);
    r.curvedDeg[f] = overhangAngleDeg(d, n);
    r.totalArea += r.area[f];
    if (r.onBase[f]) {
      r.baseArea += r.area[f];
      continue;
    }
    maxPlanar = std::max(maxPlanar, r.planarDeg[f]);
    maxCurved = std::max(maxCurved, r.curvedDeg[f]);
    if (r.planarDeg[f] > threshold) {
      r.planarOverhangArea += r.area[f];
    }
    if (r.curvedDeg[f] > threshold) {
      r.curvedOverhangArea += r.area[f];
    }
  }
  const double offBaseArea = r.totalArea - r.baseArea;
  if (!(offBaseArea > 0.0)) {
    throw GeoLatticeError("overhang analysis: every boundary face lies on the base (total area " +
                          std::to_string(r.totalArea) + " mm^2); nothing to analyse");
  }
  r.planarFraction = std::min(1.0, r.planarOverhangArea / offBaseArea);
  r.curvedFraction = std::min(1.0, r.curvedOverhangArea / offBaseArea);
  r.maxPlanarDeg = std::max(0.0, maxPlanar);
  r.maxCurvedDeg = std::max(0.0, maxCurved);
  return r;
}

}  // namespace geolattice
