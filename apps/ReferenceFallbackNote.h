#pragma once
/// @file ReferenceFallbackNote.h
/// @brief The note when the reference vector r of Eq. 3 (`--reference`) lies along the layers'
/// normal in many tets: there α's direction comes from neighbouring tets (GL Geodesic Distance
/// Fields' fallback), so the lattice directions there are not the user's; or when it was turned
/// for that reason.
#include <nlohmann/json.hpp>

#include <string>

namespace geolattice {

using Json = nlohmann::ordered_json;

/// The share of fallback tets above which the note is given (the bundled models: at most 0.03 %).
constexpr double kReferenceFallbackNoteShare = 0.05;

/// From report.json's `gdf` section (tets, reference_fallback_tets, reference,
/// given_reference_fallback_tets) and the reference as given: the note for stderr when the
/// reference was turned (GL Geodesic Distance Fields' TurnReference) or more than
/// kReferenceFallbackNoteShare of the tets fell back; else empty.
std::string referenceFallbackNote(const Json& gdf, const double* reference, bool turnReference);

}  // namespace geolattice
