#include "ReferenceFallbackNote.h"

#include <sstream>

namespace geolattice {

std::string referenceFallbackNote(const Json& gdf, const double* reference) {
  const double fallback = gdf.value("reference_fallback_tets", 0.0);
  const double tets = gdf.value("tets", 0.0);
  if (!(tets > 0) || !(fallback > kReferenceFallbackNoteShare * tets)) {
    return "";
  }
  std::ostringstream share;
  share.precision(1);
  share << std::fixed << 100.0 * fallback / tets;
  std::ostringstream note;
  note << share.str()
       << " % of the tets have the layers' normal along the reference vector (--reference "
       << reference[0] << "," << reference[1] << "," << reference[2]
       << "): the lattice directions there are taken from neighbouring tets; a reference across "
          "the build direction (the default 1,0,0) gives the lattice its own directions "
          "(report.json gdf.reference_fallback_tets)";
  return note.str();
}

}  // namespace geolattice
