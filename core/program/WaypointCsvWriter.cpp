#include "program/WaypointCsvWriter.h"

#include "common/Error.h"
#include "common/FixedNumber.h"

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
  std::string rows;  // written every 4096 rows: one stream call per block, not per number
  for (size_t i = 0; i < N; ++i) {
    const Eigen::Vector3d n = normals[i].normalized();
    for (double v :
         {points[i].x(), points[i].y(), points[i].z(), n.x(), n.y(), n.z(), extrusion[i]}) {
      appendFixed(rows, v, 6);  // as urNumber (URScriptWriter.h)
      rows += ',';
    }
    rows += std::to_string(kind[i]);
    rows += ',';
    rows += std::to_string(layer[i]);
    rows += '\n';
    if (i % 4096 == 4095 || i + 1 == N) {
      out.write(rows.data(), static_cast<std::streamsize>(rows.size()));
      rows.clear();
    }
  }
}

}  // namespace geolattice
