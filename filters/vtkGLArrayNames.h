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
// Curved layer slicer output (vtkGLCurvedLayerSlicer).
constexpr const char* Normals = "Normals";               ///< point data: unit nozzle direction (+∇γ)
constexpr const char* SourceEdge = "SourceEdge";         ///< point data: tet-mesh edge (2 point ids)
constexpr const char* EdgeParameter = "EdgeParameter";   ///< point data: t along SourceEdge
constexpr const char* LayerId = "LayerId";               ///< cell data: layer index i
constexpr const char* LayerComponent = "LayerComponent"; ///< cell data: connected piece within the layer
constexpr const char* LayerValues = "LayerValues";       ///< field data: φ_i per extracted layer (mm)
constexpr const char* LayerComponents = "LayerComponents"; ///< field data: pieces per layer
constexpr const char* LayerArea = "LayerArea";           ///< field data: area per layer (mm^2)
constexpr const char* LayerSpacingMin = "LayerSpacingMin";   ///< field data: per layer (mm)
constexpr const char* LayerSpacingMean = "LayerSpacingMean"; ///< field data: per layer (mm)
constexpr const char* LayerSpacingMax = "LayerSpacingMax";   ///< field data: per layer (mm)
// Field data of vtkGLTetrahedralizeSurface (its cell data is TetQuality above).
constexpr const char* TargetEdgeLength = "TargetEdgeLength"; ///< 1 value: edge length used (mm), automatic or set
constexpr const char* MeanEdgeLength = "MeanEdgeLength";     ///< 1 value: mean unique-edge length of the tets (mm)
constexpr const char* TetCount = "TetCount";                 ///< 1 value: number of tets
constexpr const char* TetrahedralizeSeconds = "TetrahedralizeSeconds"; ///< 1 value: wall time (s), all TetGen runs
// Overhang analysis (vtkGLOverhangAnalysis): cell data on the boundary surface.
constexpr const char* OverhangPlanar = "OverhangPlanar"; ///< θ for d = +z, planar 2.5-axis slicing (degrees)
constexpr const char* OverhangCurved = "OverhangCurved"; ///< θ for d = GammaGradient, curved layers (degrees)
constexpr const char* OnBase = "OnBase";                 ///< uint8: 1 = face rests on the platform
// Field data of vtkGLOverhangAnalysis.
constexpr const char* OverhangPlanarFraction = "OverhangPlanarFraction"; ///< area with θ_planar > threshold / off-base area
constexpr const char* OverhangCurvedFraction = "OverhangCurvedFraction"; ///< area with θ_curved > threshold / off-base area
constexpr const char* OverhangThresholdDeg = "OverhangThresholdDeg";     ///< threshold used (degrees)
constexpr const char* OverhangBaseArea = "OverhangBaseArea";             ///< area of the on-base faces (mm^2)
constexpr const char* OverhangTotalArea = "OverhangTotalArea";           ///< area of all boundary faces (mm^2)
// Lattice infill output (vtkGLLatticeInfill): one line cell per graph edge.
constexpr const char* VertexKind = "VertexKind";     ///< point data (int): a latticekind::Vertex* value
constexpr const char* Degree = "Degree";             ///< point data (int): number of edges at the vertex
constexpr const char* EdgeKind = "EdgeKind";         ///< cell data (int): a latticekind::Edge* value
constexpr const char* SubgraphId = "SubgraphId";     ///< cell + point data (int): connected sub-graph G_{i,j}, numbered over all layers
constexpr const char* IsolineLevel = "IsolineLevel"; ///< cell data: iso-value of an α/β edge (mm), NaN on boundary edges
// Field data of vtkGLLatticeInfill (1 value each unless noted).
constexpr const char* LatticeVertices = "LatticeVertices";
constexpr const char* LatticeEdges = "LatticeEdges";
constexpr const char* LatticeSubgraphs = "LatticeSubgraphs";
constexpr const char* LatticeCrossings = "LatticeCrossings";
constexpr const char* LatticeBoundaryHits = "LatticeBoundaryHits";
constexpr const char* LatticeIsolineEdges = "LatticeIsolineEdges";         ///< α + β edges; 0 = empty lattice
constexpr const char* LatticeDroppedSubgraphs = "LatticeDroppedSubgraphs"; ///< shorter than MinimumSubgraphLength
constexpr const char* LatticeIrregularVertices = "LatticeIrregularVertices"; ///< degree != 4 / 3 / 2 (exact tangential touches)
constexpr const char* LatticeAlphaLevels = "LatticeAlphaLevels";           ///< Ψ^α used (mm), one value per level
constexpr const char* LatticeBetaLevels = "LatticeBetaLevels";             ///< Ψ^β used (mm), one value per level
constexpr const char* SubgraphLayer = "SubgraphLayer";                     ///< per sub-graph: layer index i
constexpr const char* SubgraphLength = "SubgraphLength";                   ///< per sub-graph: total edge length (mm)
constexpr const char* SubgraphCentroid = "SubgraphCentroid";               ///< per sub-graph: 3 values, length-weighted (mm)
} // namespace arrays

/// Values of the VertexKind and EdgeKind arrays (= geolattice::LatticeVertexKind / LatticeEdgeKind).
namespace latticekind {
constexpr int VertexIsolinePoint = 0; ///< α- or β-isoline point on a layer-mesh edge or layer point (degree 2)
constexpr int VertexCrossing = 1;     ///< α-isoline meets β-isoline (degree 4)
constexpr int VertexBoundaryHit = 2;  ///< an isoline meets the layer boundary (degree 3)
constexpr int VertexBoundary = 3;     ///< layer boundary point (degree 2)
constexpr int EdgeAlpha = 0;          ///< piece of an α-isoline
constexpr int EdgeBeta = 1;           ///< piece of a β-isoline
constexpr int EdgeBoundary = 2;       ///< piece of the layer boundary
} // namespace latticekind
} // namespace geolattice
#endif
