#include "gdf/HeatSources.h"

#include "common/Error.h"
#include "mesh/TetMeshTopology.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace geolattice {

namespace {

/// Is the boundary face's outward normal within the angle whose cosine is cosMax of -z?
bool facesDown(const TetMesh& mesh, const BoundaryFace& f, double cosMax) {
  const Vec3& a = mesh.points[f.vertices[0]];
  const Vec3 n = (mesh.points[f.vertices[1]] - a).cross(mesh.points[f.vertices[2]] - a);
  const double len = n.norm();
  return len > 0 && -n.z() / len >= cosMax;
}

/// The cosine of a base face angle, checked to lie within [0, 180] degrees.
double cosOfFaceAngle(double maxAngleDeg) {
  if (!(maxAngleDeg >= 0 && maxAngleDeg <= 180)) {
    throw GeoLatticeError("base face angle must be within [0, 180] degrees (got " +
                          std::to_string(maxAngleDeg) + ")");
  }
  return std::cos(maxAngleDeg * M_PI / 180.0);
}

}  // namespace

std::vector<int> sourcesNearLowestZ(const TetMesh& mesh, double tolerance) {
  if (!(tolerance >= 0)) {
    throw GeoLatticeError("base tolerance must be >= 0 mm (got " + std::to_string(tolerance) + ")");
  }
  if (mesh.points.empty()) {
    throw GeoLatticeError("empty mesh: no vertices to choose the base from");
  }
  double zmin = mesh.points[0].z();
  for (const Vec3& p : mesh.points) {
    zmin = std::min(zmin, p.z());
  }
  std::vector<int> sources;
  for (size_t i = 0; i < mesh.points.size(); ++i) {
    if (mesh.points[i].z() <= zmin + tolerance) {
      sources.push_back(static_cast<int>(i));
    }
  }
  return sources;
}

std::vector<int> sourcesNearLowestZ(const TetMesh& mesh, double tolerance,
                                    const TetMeshTopology& topology, double flatBand,
                                    double maxAngleDeg) {
  std::vector<int> sources = sourcesNearLowestZ(mesh, tolerance);
  if (!(flatBand >= 0)) {
    throw GeoLatticeError("base flat band must be >= 0 mm (got " + std::to_string(flatBand) + ")");
  }
  const double cosMax = cosOfFaceAngle(maxAngleDeg);
  if (flatBand <= tolerance) {
    return sources;
  }
  double zmin = mesh.points[sources.front()].z();
  for (int v : sources) {
    zmin = std::min(zmin, mesh.points[v].z());
  }
  std::vector<char> inBand(mesh.points.size(), 0);
  for (const BoundaryFace& f : topology.boundaryFaces()) {
    bool low = true;
    for (int v : f.vertices) {
      low = low && mesh.points[v].z() <= zmin + flatBand;
    }
    if (low && facesDown(mesh, f, cosMax)) {
      for (int v : f.vertices) {
        inBand[v] = 1;
      }
    }
  }
  for (int v : sources) {
    inBand[v] = 0;
  }
  for (size_t i = 0; i < inBand.size(); ++i) {
    if (inBand[i]) {
      sources.push_back(static_cast<int>(i));
    }
  }
  std::sort(sources.begin(), sources.end());
  return sources;
}

std::vector<int> sourcesFromMask(const TetMesh& mesh, const std::vector<double>& mask) {
  if (mask.size() != mesh.points.size()) {
    throw GeoLatticeError("source mask has " + std::to_string(mask.size()) +
                          " values but the mesh has " + std::to_string(mesh.points.size()) +
                          " points");
  }
  std::vector<int> sources;
  for (size_t i = 0; i < mask.size(); ++i) {
    if (mask[i] != 0.0) {
      sources.push_back(static_cast<int>(i));
    }
  }
  return sources;
}

std::vector<int> sourcesFromDownwardFaces(const TetMesh& mesh, const TetMeshTopology& topology,
                                          double maxAngleDeg) {
  const double cosMax = cosOfFaceAngle(maxAngleDeg);
  std::vector<char> isSource(mesh.points.size(), 0);
  for (const BoundaryFace& f : topology.boundaryFaces()) {
    if (facesDown(mesh, f, cosMax)) {
      for (int v : f.vertices) {
        isSource[v] = 1;
      }
    }
  }
  std::vector<int> sources;
  for (size_t i = 0; i < isSource.size(); ++i) {
    if (isSource[i]) {
      sources.push_back(static_cast<int>(i));
    }
  }
  return sources;
}

}  // namespace geolattice
