#include "program/WaypointCsvWriter.h"

#include "common/Error.h"
#include "program/URScriptWriter.h"  // urNumber: the shortest round-trip decimal

namespace geolattice {

void writeWaypointCsv(const std::vector<Eigen::Vector3d>& points,
                      const std::vector<Eigen::Vector3d>& normals,
                      const std::vector<double>& extrusion, const std::vector<int>& kind,
                      const std::vector<int>& layer, std::ostream& out) {
  const size_t N = points.size();
  if (normals.size() != N || extrusion.size() != N || kind.size() != N || layer.size() != N) {
    throw GeoLatticeError("waypoint CSV: toolpath arrays differ in length");
  }
  out << "x,y,z,nx,ny,nz,e,kind,layer\n";
  for (size_t i = 0; i < N; ++i) {
    const Eigen::Vector3d n = normals[i].normalized();
    out << urNumber(points[i].x()) << ',' << urNumber(points[i].y()) << ','
        << urNumber(points[i].z()) << ',' << urNumber(n.x()) << ',' << urNumber(n.y()) << ','
        << urNumber(n.z()) << ',' << urNumber(extrusion[i]) << ',' << kind[i] << ',' << layer[i]
        << '\n';
  }
}

}  // namespace geolattice
