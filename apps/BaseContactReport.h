#pragma once
/// @file BaseContactReport.h
/// @brief The part's contact with the plate, below --min-base-area (what --orient auto asks of a
/// side): it may come loose while printing.
#include <nlohmann/json.hpp>

#include <string>

class vtkDataObject;
class GLPrintPipeline;

namespace geolattice {

using Json = nlohmann::ordered_json;

/// Measures the contact as the orientation search measures a side (baseContactArea: faces
/// facing down within OrientOptions::contactHeight of the lowest point) on the surface that is
/// meshed, so that --orient auto never warns of the side it chose (topopt as placed: 10.8 mm^2
/// so, 0 mm^2 of faces on the base vertices the layers grow from, 0.05 mm); a tet mesh input
/// has no such surface: its base faces (the overhang analysis's output `overhang`) then. Writes
/// overhang.base_contact_mm2 and overhang.small_base into `section`; returns the warning line
/// for stderr, empty when the contact is large enough.
std::string reportBaseContact(GLPrintPipeline& pipeline, vtkDataObject* overhang, Json& section);

}  // namespace geolattice
