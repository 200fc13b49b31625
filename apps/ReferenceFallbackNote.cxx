#include "ReferenceFallbackNote.h"

#include <cmath>
#include <sstream>
#include <vector>

namespace geolattice {

namespace {

std::string percent(double part, double whole) {
  std::ostringstream share;
  share.precision(1);
  share << std::fixed << 100.0 * part / whole;
  return share.str();
}

/// x to 0.01 (+ 0.0: no "-0").
double hundredths(double x) {
  return std::round(100 * x) / 100 + 0.0;
}

/// `v` as one would type it on the command line.
std::string vector(const double* v) {
  std::ostringstream s;
  s << hundredths(v[0]) << "," << hundredths(v[1]) << "," << hundredths(v[2]);
  return s.str();
}

}  // namespace

std::string referenceFallbackNote(const Json& gdf, const double* reference, bool turnReference) {
  const double tets = gdf.value("tets", 0.0);
  if (!(tets > 0)) {
    return "";
  }
  if (gdf.contains("given_reference_fallback_tets") && gdf.contains("reference")) {
    std::vector<double> used = gdf["reference"].get<std::vector<double>>();
    used.resize(3, 0.0);
    return "the reference vector of Eq. 3 was turned to " + vector(used.data()) + ": " +
           vector(reference) + " lies along the layers' normal in " +
           percent(gdf["given_reference_fallback_tets"].get<double>(), tets) +
           " % of the tets, which would take their lattice directions from neighbouring tets "
           "(report.json gdf.reference; --reference X,Y,Z is used as given)";
  }
  const double fallback = gdf.value("reference_fallback_tets", 0.0);
  if (!(fallback > kReferenceFallbackNoteShare * tets)) {
    return "";
  }
  return percent(fallback, tets) +
         " % of the tets have the layers' normal along the reference vector (" +
         (turnReference
              ? "no direction across the build direction does better"
              : "--reference " + vector(reference) + "; --reference auto turns it where it does") +
         "): the lattice directions there are taken from neighbouring tets "
         "(report.json gdf.reference_fallback_tets)";
}

}  // namespace geolattice
