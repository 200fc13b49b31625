#pragma once
/// @file SurfaceRepairReport.h
/// @brief The repairs the part's surface got before it was meshed (core/mesh/SurfaceRepair.h and
/// the union of crossing bodies): the part printed is not exactly the surface as given, so each
/// is said on stderr (even with -q) and counted in report.json.
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

class vtkDataObject;

namespace geolattice {

using Json = nlohmann::ordered_json;

/// Sums each repair's count over the orientation search's output `oriented` (it repairs before
/// it turns the part) and the mesh stage's output `tets` (it repairs what is left), writes
/// mesh.merged_bodies, mesh.duplicate_triangles and mesh.reoriented_triangles into `mesh`, and
/// returns one note per repair done (for stderr, after "geolattice: note: ").
std::vector<std::string> reportSurfaceRepairs(vtkDataObject* oriented, vtkDataObject* tets,
                                              Json& mesh);

/// The note on the wrap --wrap made (report.json input.wrap_triangles), `wrap` mm fine; empty if
/// none.
std::string wrapNote(const Json& input, double wrap);

/// The note on the holes --fill-holes closed (report.json input.filled_holes); empty if none.
std::string filledHolesNote(const Json& input);

}  // namespace geolattice
