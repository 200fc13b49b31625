#ifndef vtkGLArrayNames_h
#define vtkGLArrayNames_h
/**
 * @file vtkGLArrayNames.h
 * @brief Every array and field-data name GeoLattice reads or writes, in one place.
 * Filters, tests, the CLI and the pvpython scripts use these constants (pvpython via the
 * same literal names, checked by the pvpython tests).
 */
namespace geolattice {
namespace arrays {
// Point data on the tet grid (GDF output).
constexpr const char* Gamma = "Gamma";             ///< γ-GDF: geodesic distance to the base (mm)
constexpr const char* Alpha = "Alpha";             ///< α-GDF (mm), min 0
constexpr const char* Beta = "Beta";               ///< β-GDF (mm), min 0
constexpr const char* HeatSource = "HeatSource";   ///< 1 at source vertices (output), mask (input)
// Cell data on the tet grid (GDF output): unit vectors of Eq. 3.
constexpr const char* GammaGradient = "GammaGradient";
constexpr const char* AlphaDirection = "AlphaDirection";
constexpr const char* BetaDirection = "BetaDirection";
// Field data of the GDF output.
constexpr const char* GammaRange = "GammaRange";
constexpr const char* AlphaRange = "AlphaRange";
constexpr const char* BetaRange = "BetaRange";
constexpr const char* GdfTimings = "GdfTimings";   ///< seconds: assembly, factorization, solve, total
constexpr const char* GdfTimingNames = "GdfTimingNames";
constexpr const char* OrthogonalityDeg = "OrthogonalityDeviationDeg"; ///< median/p95 of |90°-angle|, αγ and βγ
constexpr const char* ReferenceFallbackTets = "ReferenceFallbackTets";
constexpr const char* SourceCount = "SourceCount";
// Tetrahedralization output.
constexpr const char* TetQuality = "RadiusEdgeRatio";
// Field data of vtkGLPlaceOnPlatform: p_out = PlacementScale * p_in + PlacementTranslation.
constexpr const char* PlacementScale = "PlacementScale";             ///< 1 value, uniform scale factor
constexpr const char* PlacementTranslation = "PlacementTranslation"; ///< 3 values (mm), applied after scaling
} // namespace arrays
} // namespace geolattice
#endif
