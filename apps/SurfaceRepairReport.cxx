#include "SurfaceRepairReport.h"

#include "StageReports.h"

#include "vtkGLArrayNames.h"

#include <ostream>

namespace geolattice {

void reportSurfaceRepairs(vtkDataObject* oriented, vtkDataObject* tets, Json& mesh,
                          std::ostream& err) {
  auto count = [&](const char* name) {
    return static_cast<int>(fieldValue(oriented, name) + fieldValue(tets, name));
  };
  const int merged = count(arrays::MergedBodies);
  const int duplicates = count(arrays::DuplicateTriangles);
  const int reoriented = count(arrays::ReorientedTriangles);
  mesh["merged_bodies"] = merged;
  mesh["duplicate_triangles"] = duplicates;
  mesh["reoriented_triangles"] = reoriented;
  if (merged > 0) {
    err << "geolattice: note: bodies of the surface touch or cross each other; meshed as their "
           "union ("
        << merged << " fewer bodies, report.json mesh.merged_bodies)\n";
  }
  if (duplicates > 0) {
    err << "geolattice: note: " << duplicates
        << (duplicates == 1 ? " triangle of the surface repeats"
                            : " triangles of the surface repeat")
        << " another one (the same face twice); meshed without the copies (report.json "
           "mesh.duplicate_triangles)\n";
  }
  if (reoriented > 0) {
    err << "geolattice: note: " << reoriented
        << (reoriented == 1
                ? " triangle of the surface ran against its neighbours; turned to agree "
                  "with them"
                : " triangles of the surface ran against their neighbours; turned to "
                  "agree with them")
        << " (report.json mesh.reoriented_triangles)\n";
  }
}

}  // namespace geolattice
