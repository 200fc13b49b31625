#include "SurfaceRepairReport.h"

#include "StageReports.h"

#include "vtkGLArrayNames.h"

#include <sstream>

namespace geolattice {

std::vector<std::string> reportSurfaceRepairs(vtkDataObject* oriented, vtkDataObject* tets,
                                              Json& mesh) {
  auto count = [&](const char* name) {
    return static_cast<int>(fieldValue(oriented, name) + fieldValue(tets, name));
  };
  const int merged = count(arrays::MergedBodies);
  const int duplicates = count(arrays::DuplicateTriangles);
  const int reoriented = count(arrays::ReorientedTriangles);
  const int degenerate = count(arrays::DegenerateTrianglesRemoved);
  const int welded = count(arrays::WeldedVertices);
  mesh["merged_bodies"] = merged;
  mesh["duplicate_triangles"] = duplicates;
  mesh["reoriented_triangles"] = reoriented;
  mesh["degenerate_triangles"] = degenerate;
  mesh["welded_vertices"] = welded;
  std::vector<std::string> notes;
  if (welded > 0) {
    std::ostringstream note;
    note << welded << (welded == 1 ? " vertex" : " vertices")
         << " of the surface welded across seams as wide as rounding (open edges whose two sides "
            "differ in the last digits, as float32 STL corners do; report.json "
            "mesh.welded_vertices)";
    notes.push_back(note.str());
  }
  if (merged > 0) {
    std::ostringstream note;
    note << "bodies of the surface touch or cross each other; meshed as their "
            "union ("
         << merged << " fewer bodies, report.json mesh.merged_bodies)";
    notes.push_back(note.str());
  }
  if (duplicates > 0) {
    std::ostringstream note;
    note << duplicates
         << (duplicates == 1 ? " triangle of the surface repeats"
                             : " triangles of the surface repeat")
         << " another one (the same face twice); meshed without the copies (report.json "
            "mesh.duplicate_triangles)";
    notes.push_back(note.str());
  }
  if (reoriented > 0) {
    std::ostringstream note;
    note << reoriented
         << (reoriented == 1
                 ? " triangle of the surface ran against its neighbours; turned to agree "
                   "with them"
                 : " triangles of the surface ran against their neighbours; turned to "
                   "agree with them")
         << " (report.json mesh.reoriented_triangles)";
    notes.push_back(note.str());
  }
  if (degenerate > 0) {
    std::ostringstream note;
    note << degenerate << (degenerate == 1 ? " degenerate triangle" : " degenerate triangles")
         << " of the surface (area ~0, e.g. marching-cubes slivers) mended by collapsing or "
            "flipping an edge (report.json mesh.degenerate_triangles)";
    notes.push_back(note.str());
  }
  return notes;
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
