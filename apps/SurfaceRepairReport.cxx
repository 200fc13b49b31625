#include "SurfaceRepairReport.h"

#include "StageReports.h"

#include "vtkGLArrayNames.h"

#include "mesh/SurfaceRepair.h"

#include <iomanip>
#include <sstream>

namespace geolattice {

std::vector<std::string> reportSurfaceRepairs(vtkDataObject* oriented, vtkDataObject* tets,
                                              Json& mesh) {
  auto count = [&](const char* name) {
    return static_cast<int>(fieldValue(oriented, name) + fieldValue(tets, name));
  };
  SurfaceRepairCounts repairs;
  repairs.weldedVertices = count(arrays::WeldedVertices);
  repairs.mergedBodies = count(arrays::MergedBodies);
  repairs.duplicateTriangles = count(arrays::DuplicateTriangles);
  repairs.reorientedTriangles = count(arrays::ReorientedTriangles);
  repairs.degenerateTriangles = count(arrays::DegenerateTrianglesRemoved);
  repairs.invertedBodies = count(arrays::InvertedBodies);
  mesh["merged_bodies"] = repairs.mergedBodies;
  mesh["duplicate_triangles"] = repairs.duplicateTriangles;
  mesh["reoriented_triangles"] = repairs.reorientedTriangles;
  mesh["degenerate_triangles"] = repairs.degenerateTriangles;
  mesh["welded_vertices"] = repairs.weldedVertices;
  mesh["inverted_bodies"] = repairs.invertedBodies;
  std::vector<std::string> notes;
  for (const RepairNote& note : describeRepairs(repairs)) {
    const std::string where = "report.json mesh." + note.reportKey;
    notes.push_back(note.text.back() ==
                            ')'  // "(2 fewer bodies)" -> "(2 fewer bodies; report.json ...)"
                        ? note.text.substr(0, note.text.size() - 1) + "; " + where + ")"
                        : note.text + " (" + where + ")");
  }
  return notes;
}

std::string wrapNote(const Json& input, double wrap) {
  std::ostringstream note;
  if (input.value("wrap_triangles", 0.0) > 0) {
    note << "the surface was replaced by its alpha wrap, " << wrap
         << " mm fine: " << input["wrap_triangles"].get<int>() << " triangles, closed, "
         << wrap / 30
         << " mm outside the part (--wrap; narrower gaps and features are closed: look at "
            "tets.vtu before printing; report.json input.wrap_triangles)";
  }
  return note.str();
}

std::string filledHolesNote(const Json& input) {
  const int holes = input.value("filled_holes", 0.0) > 0 ? input["filled_holes"].get<int>() : 0;
  std::ostringstream note;
  if (holes > 0) {
    note << holes << (holes == 1 ? " hole" : " holes") << " of the surface closed with "
         << input["filled_hole_triangles"].get<int>()
         << " triangles (--fill-holes; a patch is a guess at the part: look at tets.vtu before "
            "printing; report.json input.filled_holes)";
  }
  return note.str();
}

}  // namespace geolattice
