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
constexpr const char* Gamma = "Gamma";            ///< γ-GDF: geodesic distance to the base (mm)
constexpr const char* Alpha = "Alpha";            ///< α-GDF (mm), min 0
constexpr const char* Beta = "Beta";              ///< β-GDF (mm), min 0
constexpr const char* HeatSource = "HeatSource";  ///< 1 at source vertices (output), mask (input)
// Cell data on the tet grid (GDF output): unit vectors of Eq. 3.
constexpr const char* GammaGradient = "GammaGradient";
constexpr const char* AlphaDirection = "AlphaDirection";
constexpr const char* BetaDirection = "BetaDirection";
// Field data of the GDF output.
constexpr const char* GammaRange = "GammaRange";
constexpr const char* AlphaRange = "AlphaRange";
constexpr const char* BetaRange = "BetaRange";
constexpr const char* GdfTimings =
    "GdfTimings";  ///< seconds: assembly, factorization, solve, total
constexpr const char* GdfTimingNames = "GdfTimingNames";
constexpr const char* OrthogonalityDeg =
    "OrthogonalityDeviationDeg";  ///< median/p95 of |90°-angle|, αγ and βγ
constexpr const char* ReferenceFallbackTets = "ReferenceFallbackTets";
/// The unit r Eq. 3 used (x, y, z): ReferenceVector's, or turned (TurnReference).
constexpr const char* ReferenceUsed = "ReferenceUsed";
/// With TurnReference: the tets ReferenceVector lay along g_γ in, when it was turned.
constexpr const char* GivenReferenceFallbackTets = "GivenReferenceFallbackTets";
constexpr const char* SourceCount = "SourceCount";
// Tetrahedralization output.
constexpr const char* TetQuality = "RadiusEdgeRatio";
// GL Surface Check output: the defect edges and the verdict on the surface.
constexpr const char* DefectKind = "DefectKind";        ///< cell data: gl::SurfaceDefectEdge::Kind
constexpr const char* SurfaceClosed = "SurfaceClosed";  ///< 1: GL Tetrahedralize Surface accepts it
constexpr const char* BoundaryEdges = "BoundaryEdges";
constexpr const char* NonManifoldEdges = "NonManifoldEdges";
constexpr const char* InconsistentEdges = "InconsistentEdges";
constexpr const char* DegenerateTriangles = "DegenerateTriangles";
constexpr const char* SignedVolume = "SignedVolume";      ///< enclosed volume, input units³
constexpr const char* SurfaceVerdict = "SurfaceVerdict";  ///< string: "closed manifold" or why not
// Field data of vtkGLPlaceOnPlatform: p_out = PlacementScale * p_in + PlacementTranslation.
constexpr const char* PlacementScale = "PlacementScale";  ///< 1 value, uniform scale factor
/// With FillHoles: the holes closed and the triangles of their patches, 1 value each.
constexpr const char* FilledHoles = "FilledHoles";
constexpr const char* FilledHoleTriangles = "FilledHoleTriangles";
/// With FillCavities: the closed inner cavities filled (their shells removed), 1 value.
constexpr const char* FilledCavities = "FilledCavities";
/// With Wrap > 0: the triangles of the wrap that replaced the surface (1 value).
constexpr const char* WrapTriangles = "WrapTriangles";
constexpr const char* PlacementTranslation =
    "PlacementTranslation";  ///< 3 values (mm), applied after scaling
// Curved layer slicer output (vtkGLCurvedLayerSlicer).
constexpr const char* Normals =
    "Normals";  ///< point data: unit layer normal = nozzle direction (+∇γ)
/// Lattice and toolpath point data: the unit nozzle axis. Not named Normals (and not the active
/// normals) on lines: ParaView lights lines with their normals, and layers facing away from the
/// camera would render black. Readers accept Normals too (files written before the rename).
constexpr const char* NozzleAxis = "NozzleAxis";
constexpr const char* SourceEdge = "SourceEdge";        ///< point data: tet-mesh edge (2 point ids)
constexpr const char* EdgeParameter = "EdgeParameter";  ///< point data: t along SourceEdge
constexpr const char* LayerId = "LayerId";              ///< cell data: layer index i
constexpr const char* LayerComponent =
    "LayerComponent";                               ///< cell data: connected piece within the layer
constexpr const char* LayerValues = "LayerValues";  ///< field data: φ_i per extracted layer (mm)
constexpr const char* LayerComponents = "LayerComponents";    ///< field data: pieces per layer
constexpr const char* LayerArea = "LayerArea";                ///< field data: area per layer (mm^2)
constexpr const char* LayerSpacingMin = "LayerSpacingMin";    ///< field data: per layer (mm)
constexpr const char* LayerSpacingMean = "LayerSpacingMean";  ///< field data: per layer (mm)
constexpr const char* LayerSpacingMax = "LayerSpacingMax";    ///< field data: per layer (mm)
// Field data of vtkGLTetrahedralizeSurface (its cell data is TetQuality above).
constexpr const char* TargetEdgeLength =
    "TargetEdgeLength";  ///< 1 value: edge length used (mm), automatic or set
constexpr const char* MeanEdgeLength =
    "MeanEdgeLength";                         ///< 1 value: mean unique-edge length of the tets (mm)
constexpr const char* TetCount = "TetCount";  ///< 1 value: number of tets
constexpr const char* TetrahedralizeSeconds =
    "TetrahedralizeSeconds";  ///< 1 value: wall time (s), all TetGen runs
/// Surface simplification before TetGen (core/mesh/SurfaceSimplification.h), 1 value each:
constexpr const char* InputTriangles = "InputTriangles";    ///< triangles of the input surface
constexpr const char* MeshedTriangles = "MeshedTriangles";  ///< triangles given to TetGen
constexpr const char* SimplificationDistance =
    "SimplificationDistance";  ///< largest input-vertex distance to the meshed surface (mm)
constexpr const char* SimplificationSeconds = "SimplificationSeconds";  ///< its wall time (s)
constexpr const char* SimplificationEdgeLength =
    "SimplificationEdgeLength";  ///< edge the meshed surface was prepared for (mm; 0: input kept)
/// vtkStringArray: why the surface remeshed for the target edge was refused (empty: it was not)
constexpr const char* SimplificationRefused = "SimplificationRefused";
/// Bodies merged into another one they cross (core/mesh/OverlappingBodies.h), 1 value.
constexpr const char* MergedBodies = "MergedBodies";
/// Triangles dropped as copies of another one (core/mesh/SurfaceRepair.h), 1 value.
constexpr const char* DuplicateTriangles = "DuplicateTriangles";
constexpr const char* DegenerateTrianglesRemoved = "DegenerateTrianglesRemoved";
constexpr const char* WeldedVertices = "WeldedVertices";
/// Bodies written inside out turned outward (core/mesh/SurfaceRepair.h), 1 value.
constexpr const char* InvertedBodies = "InvertedBodies";
/// Triangles turned to agree with their neighbours (core/mesh/SurfaceRepair.h), 1 value.
constexpr const char* ReorientedTriangles = "ReorientedTriangles";
/// Closed inner cavities of the solid (TetGen regions outside the surface, removed), 1 value.
constexpr const char* CavityRegions = "CavityRegions";
constexpr const char* TetGenRuns = "TetGenRuns";  ///< TetGen runs (edge search and retries)
constexpr const char* TetGenSpeculativeRun =
    "TetGenSpeculativeRun";  ///< 1: a longer edge was meshed beside the first automatic run
constexpr const char* TetGenSurfaceBoundCount =
    "TetGenSurfaceBoundCount";  ///< 1: the count stays above the target whatever the edge
constexpr const char* RemovedFlatTets = "RemovedFlatTets";  ///< zero-volume slivers dropped
/// 1: no quality-bounded TetGen run finished in time; the mesh has no radius-edge bound.
constexpr const char* TetGenQualityBoundDropped = "TetGenQualityBoundDropped";
// Overhang analysis (vtkGLOverhangAnalysis): cell data on the boundary surface.
constexpr const char* OverhangPlanar =
    "OverhangPlanar";  ///< θ for d = +z, planar 2.5-axis slicing (degrees)
constexpr const char* OverhangCurved =
    "OverhangCurved";                     ///< θ for d = GammaGradient, curved layers (degrees)
constexpr const char* OnBase = "OnBase";  ///< uint8: 1 = face rests on the platform
// Field data of vtkGLOverhangAnalysis.
constexpr const char* OverhangPlanarFraction =
    "OverhangPlanarFraction";  ///< area with θ_planar > threshold / off-base area
constexpr const char* OverhangCurvedFraction =
    "OverhangCurvedFraction";  ///< area with θ_curved > threshold / off-base area
constexpr const char* OverhangThresholdDeg = "OverhangThresholdDeg";  ///< threshold used (degrees)
constexpr const char* OverhangBaseArea = "OverhangBaseArea";  ///< area of the on-base faces (mm^2)
constexpr const char* OverhangTotalArea =
    "OverhangTotalArea";  ///< area of all boundary faces (mm^2)
// Lattice infill output (vtkGLLatticeInfill): one line cell per graph edge.
constexpr const char* VertexKind =
    "VertexKind";                             ///< point data (int): a latticekind::Vertex* value
constexpr const char* Degree = "Degree";      ///< point data (int): number of edges at the vertex
constexpr const char* EdgeKind = "EdgeKind";  ///< cell data (int): a latticekind::Edge* value
constexpr const char* SubgraphId =
    "SubgraphId";  ///< cell + point data (int): connected sub-graph G_{i,j}, numbered over all layers
constexpr const char* IsolineLevel =
    "IsolineLevel";  ///< cell data: iso-value of an α/β edge (mm), NaN on boundary edges
// Field data of vtkGLLatticeInfill (1 value each unless noted).
constexpr const char* LatticeVertices = "LatticeVertices";
constexpr const char* LatticeEdges = "LatticeEdges";
constexpr const char* LatticeSubgraphs = "LatticeSubgraphs";
constexpr const char* LatticeCrossings = "LatticeCrossings";
constexpr const char* LatticeBoundaryHits = "LatticeBoundaryHits";
constexpr const char* LatticeIsolineEdges =
    "LatticeIsolineEdges";  ///< α + β edges; 0 = empty lattice
constexpr const char* LatticeDroppedSubgraphs =
    "LatticeDroppedSubgraphs";  ///< shorter than MinimumSubgraphLength
constexpr const char* LatticeIrregularVertices =
    "LatticeIrregularVertices";  ///< degree != 4 / 3 / 2 (exact tangential touches)
constexpr const char* LatticeAlphaLevels =
    "LatticeAlphaLevels";  ///< Ψ^α used (mm), one value per level
constexpr const char* LatticeBetaLevels =
    "LatticeBetaLevels";                                  ///< Ψ^β used (mm), one value per level
constexpr const char* SubgraphLayer = "SubgraphLayer";    ///< per sub-graph: layer index i
constexpr const char* SubgraphLength = "SubgraphLength";  ///< per sub-graph: total edge length (mm)
constexpr const char* SubgraphCentroid =
    "SubgraphCentroid";  ///< per sub-graph: 3 values, length-weighted (mm)
// Skeleton tree output (vtkGLSkeletonTree): one point per node = sub-graph G_{i,j} at its
// centroid, one line cell (lower, upper) per edge. Its point data also holds LayerId (here the
// lattice layer 0..L-1), SubgraphId (= NodeId), Gamma (φ of the layer, mm) and SubgraphLength (mm).
constexpr const char* NodeId = "NodeId";  ///< point data (int): node index = sub-graph id
constexpr const char* LowerCount =
    "LowerCount";  ///< point data (int): adjacent nodes on the layer below
constexpr const char* UpperCount =
    "UpperCount";  ///< point data (int): adjacent nodes on the layer above
// Field data of vtkGLSkeletonTree (1 value each; LayerValues above holds φ per lattice layer).
constexpr const char* SkeletonRoots = "SkeletonRoots";  ///< nodes without lower node
constexpr const char* SkeletonFloatingNodes =
    "SkeletonFloatingNodes";  ///< roots above the lowest layer (support dropped)
constexpr const char* SkeletonMergeNodes =
    "SkeletonMergeNodes";  ///< nodes with more than one lower node
constexpr const char* SkeletonSplitNodes =
    "SkeletonSplitNodes";                                   ///< nodes with more than one upper node
constexpr const char* SkeletonSeconds = "SkeletonSeconds";  ///< wall time (s)
// Print sequencer (vtkGLPrintSequencer).
constexpr const char* PrintOrder =
    "PrintOrder";  ///< cell + point data (int): position of the sub-graph in the printing order
constexpr const char* Retraction =
    "Retraction";  ///< cell data of the order polyline (int): 1 = the transition retracts
// Field data of vtkGLPrintSequencer, on all three outputs (1 value each unless noted).
constexpr const char* SequenceStrategy =
    "SequenceStrategy";  ///< vtkStringArray: "lpt", "dpt", "a4" or "best"
constexpr const char* SequenceRetractions =
    "SequenceRetractions";  ///< transitions that are not to an upper node
constexpr const char* SequenceAirLength =
    "SequenceAirLength";  ///< straight air moves end -> start summed (mm)
constexpr const char* SequenceForcedSteps =
    "SequenceForcedSteps";  ///< steps that violated Criterion 2 (mutual PCGs: a collision)
constexpr const char* SequenceSeconds = "SequenceSeconds";  ///< wall time of the ordering (s)
constexpr const char* SequencePcgPairs =
    "SequencePcgPairs";  ///< potential collision pairs (0 for LPT, DPT)
constexpr const char* SequencePcgSeconds = "SequencePcgSeconds";  ///< wall time of the PCGs (s)
/// PCG entries j of i where j is a skeleton ancestor of i: collisions no order avoids (Criterion 1
/// prints j first), left out of Criterion 2.
constexpr const char* SequenceUnavoidablePairs = "SequenceUnavoidablePairs";
/// 2 values per skeleton edge: (lower, upper) sub-graph ids. The collision verifier uses it to
/// recognise obstacles of a skeleton ancestor (unavoidable collisions).
constexpr const char* SkeletonEdges = "SkeletonEdges";
constexpr const char* NozzleAngleDeg = "NozzleAngleDeg";  ///< nozzle half-angle NA used (degrees)
constexpr const char* SequenceOrder = "SequenceOrder";    ///< per position: sub-graph id
/// With split sub-graphs (sequence/SubgraphSplitting.h): per position the piece printed there;
/// the lattice's cell array PieceId gives each edge's piece.
constexpr const char* SequencePieceOrder = "SequencePieceOrder";
constexpr const char* PieceId = "PieceId";  ///< cell data: the piece of a split sub-graph
constexpr const char* SequencePieces = "SequencePieces";  ///< pieces printed (>= sub-graphs)
constexpr const char* SequenceSplitSubgraphs =
    "SequenceSplitSubgraphs";  ///< sub-graphs printed as more than one piece
constexpr const char* SequenceForcedStepsBefore =
    "SequenceForcedStepsBefore";  ///< forced steps of the order of whole sub-graphs
constexpr const char* SequenceStart =
    "SequenceStart";  ///< per position: 3 values, first printed point (mm)
constexpr const char* SequenceEnd =
    "SequenceEnd";  ///< per position: 3 values, last printed point (mm)
// Collision verifier (vtkGLCollisionVerifier): per reported violation a station and an
// obstacle point joined by a line.
constexpr const char* ViolationIndex =
    "ViolationIndex";  ///< point data (int): index of the violation (0 = first in print time)
constexpr const char* Role = "Role";  ///< point data (int): a collisionrole::* value
constexpr const char* Height =
    "Height";  ///< point data: obstacle height above the tip along the nozzle axis (mm)
constexpr const char* Radial =
    "Radial";  ///< point data: obstacle distance from the nozzle axis (mm)
constexpr const char* Unavoidable =
    "Unavoidable";  ///< point data (int): 1 = all obstacles of the station are skeleton ancestors
// Field data of vtkGLCollisionVerifier (1 value each).
constexpr const char* CollisionFree = "CollisionFree";  ///< int: 1 = no violation, 0 = collision
constexpr const char* CollisionStations =
    "CollisionStations";  ///< nozzle stations (sample points) checked
constexpr const char* CollisionViolatingStations =
    "CollisionViolatingStations";  ///< stations with earlier material inside the nozzle
/// Of the violating stations, those where the nozzle meets the build plate (or its tip is in it).
constexpr const char* CollisionPlateStations = "CollisionPlateStations";
/// 2 values: the smallest and largest LayerId (input point array) of the violating stations; only
/// when the input has a LayerId point array and a station collides.
constexpr const char* CollisionLayerRange = "CollisionLayerRange";
/// GL Collision Verifier's Stations output: per station 0 = clear, 1 = earlier material inside
/// the nozzle, 2 = the build plate (geolattice::collisionkind).
constexpr const char* Collision = "Collision";
constexpr const char* CollisionUnavoidableStations =
    "CollisionUnavoidableStations";  ///< of those, stations whose obstacles are all skeleton ancestors
constexpr const char* CollisionOrderFree =
    "CollisionOrderFree";  ///< int: 1 = no violation except unavoidable ones
constexpr const char* CollisionSeconds = "CollisionSeconds";  ///< wall time (s)
// Toolpath planner (vtkGLToolpathPlanner): the points in printing order, one polyline cell per
// run of moves of the same kind on the same path. Its point data also holds NozzleAxis (nozzle
// axis), LayerId (the lattice's LayerId, -1 on air moves) and SubgraphId (-1 on air moves); its
// cell data MoveKind, PathIndex, LayerId and SubgraphId of the run.
constexpr const char* Thickness =
    "Thickness";  ///< point data: layer thickness h of the move ending there (mm), 0 on air moves
constexpr const char* Width = "Width";  ///< point data: path width w (mm), 0 on air moves
constexpr const char* Extrusion =
    "Extrusion";  ///< point data: cumulative filament length E (mm), after retractions and primes
constexpr const char* FeedRate =
    "FeedRate";  ///< point data: nozzle feed rate of the move ending there (mm/s)
constexpr const char* MoveKind = "MoveKind";  ///< point + cell data (int): a movekind::* value
constexpr const char* PathIndex =
    "PathIndex";  ///< point + cell data (int): continuous print path (tour); air moves carry the next one
constexpr const char* PointIndex =
    "PointIndex";  ///< point data (int): position along the toolpath (print time for the verifier)
/// Field data of vtkGLToolpathReplay: the last printed point index at the shown time (-1: none).
constexpr const char* ReplayLastPoint = "ReplayLastPoint";
constexpr const char* AxisTilt =
    "AxisTilt";  ///< point data: angle between the nozzle axis and the layer normal ∇γ (degrees)
// Field data of vtkGLToolpathPlanner (1 value each unless noted).
constexpr const char* ToolpathPrintLength =
    "ToolpathPrintLength";  ///< mm of lattice print moves (MoveKind 0)
constexpr const char* ToolpathPerimeterLength =
    "ToolpathPerimeterLength";  ///< mm of support perimeter moves incl. connectors (MoveKind 1)
constexpr const char* ToolpathPerimeterLoops =
    "ToolpathPerimeterLoops";  ///< support perimeter loops
constexpr const char* ToolpathPerimeterTeeth =
    "ToolpathPerimeterTeeth";  ///< teeth of the jagged perimeters along trimmed edges
constexpr const char* ToolpathAirLength = "ToolpathAirLength";  ///< mm of air moves
constexpr const char* ToolpathRetractions =
    "ToolpathRetractions";  ///< air moves (each retracts and primes)
constexpr const char* ToolpathTours =
    "ToolpathTours";  ///< continuous print paths (closed Euler tours)
constexpr const char* ToolpathCrossings =
    "ToolpathCrossings";  ///< self-crossings of the tours (0 expected)
constexpr const char* ToolpathSplitSubgraphs =
    "ToolpathSplitSubgraphs";  ///< sub-graphs printed as more than one tour
constexpr const char* ToolpathContractedEdges =
    "ToolpathContractedEdges";  ///< zero-length lattice edges contracted
constexpr const char* ToolpathTrimmedEdges =
    "ToolpathTrimmedEdges";  ///< boundary edges left out to make the sub-graphs Eulerian
constexpr const char* ToolpathTrimmedLength = "ToolpathTrimmedLength";  ///< mm of those edges
constexpr const char* ToolpathFilament =
    "ToolpathFilament";  ///< filament length extruded (mm, Eq. 14)
constexpr const char* ToolpathFilamentDiameter =
    "ToolpathFilamentDiameter";                           ///< the planner's filament diameter (mm)
constexpr const char* ToolpathVolume = "ToolpathVolume";  ///< deposited volume (mm^3)
constexpr const char* ToolpathThicknessDeviation =
    "ToolpathThicknessDeviation";  ///< 2 values: min, max of e = (h - φ)/φ (Eq. 15)
/// 3 components (min, mean, max of e) per lattice layer 0..L-1 (the lattice's LayerId values ascending).
constexpr const char* ToolpathThicknessDeviationPerLayer = "ToolpathThicknessDeviationPerLayer";
constexpr const char* ToolpathCappedVertices =
    "ToolpathCappedVertices";  ///< vertices whose h was capped at λφ
constexpr const char* ToolpathUnsupportedVertices =
    "ToolpathUnsupportedVertices";  ///< vertices without a lower node above the first layer
constexpr const char* ToolpathRotationSteps =
    "ToolpathRotationSteps";  ///< points inserted to limit the nozzle axis turn
constexpr const char* ToolpathSubdivisionPoints =
    "ToolpathSubdivisionPoints";  ///< all inserted points (axis turn and segment length)
constexpr const char* ToolpathCollidingStations =
    "ToolpathCollidingStations";  ///< stations where the nozzle along ∇γ hits earlier material
constexpr const char* ToolpathTiltedStations =
    "ToolpathTiltedStations";  ///< of those, cleared by tilting the axis
constexpr const char* ToolpathUnclearedStations =
    "ToolpathUnclearedStations";  ///< stations still colliding after tilting
/// 1 when the planner's own final check found no station colliding (nozzle or build plate), else
/// 0: the verdict the program writers check before writing (vtkGLCollisionVerifier re-checks it
/// independently).
constexpr const char* ToolpathCollisionFree = "ToolpathCollisionFree";
constexpr const char* ToolpathMaxAxisTilt = "ToolpathMaxAxisTilt";  ///< largest AxisTilt (degrees)
constexpr const char* ToolpathReplannedHops =
    "ToolpathReplannedHops";  ///< hops onto an upper node sent over the safe box (they collided)
/// transitions whose air stations collided, planned again along their stations' final axes
constexpr const char* ToolpathAlignedTransitions = "ToolpathAlignedTransitions";
/// tours printed from another start or the other way round, because fewer of their stations
/// collide so (core/toolpath/TourWays.h), and the stations colliding before that
constexpr const char* ToolpathReorderedTours = "ToolpathReorderedTours";
constexpr const char* ToolpathUnclearedBeforeReorder = "ToolpathUnclearedBeforeReorder";
constexpr const char* ToolpathSeconds = "ToolpathSeconds";  ///< wall time of the planning (s)

/// Field data of vtkGLPrintSummary's table: the verdict in words (one string).
constexpr const char* SummaryVerdict = "SummaryVerdict";

// GL Pedestal (vtkGLPedestal.h): field data of the raised surface.
constexpr const char* PedestalHeight = "PedestalHeight";  ///< mm the part is raised (0 = none)
constexpr const char* PedestalFootprintArea = "PedestalFootprintArea";      ///< mm²
constexpr const char* PedestalFootprintPieces = "PedestalFootprintPieces";  ///< boundary loops

// GL Auto Orient (vtkGLAutoOrient.h): field data of the oriented surface and point data of the
// candidates.
constexpr const char* OrientMode = "OrientMode";  ///< "keep" or "auto"
constexpr const char* OrientUp = "OrientUp";      ///< 3: the input's direction that now points up
constexpr const char* OrientRotation = "OrientRotation";  ///< 9, row major: input -> output
constexpr const char* OrientCandidates = "OrientCandidates";
constexpr const char* OrientSeconds = "OrientSeconds";
constexpr const char* OrientBefore = "OrientBefore";  ///< colliding stations as placed
constexpr const char* OrientAfter = "OrientAfter";    ///< colliding stations as chosen
constexpr const char* OrientEvaluationTets = "OrientEvaluationTets";
/// factor on the evaluation's layer interval, lattice width and samples (1: as given; a large part)
constexpr const char* OrientEvaluationScale = "OrientEvaluationScale";
/// mm of pedestal the search chose (0: none; GL Pedestal builds it, see its UseOrientation)
constexpr const char* OrientPedestalHeight = "OrientPedestalHeight";
constexpr const char* OrientPedestalContactHeight =
    "OrientPedestalContactHeight";                            ///< its reach, mm
constexpr const char* OrientChosenRank = "OrientChosenRank";  ///< rank of the candidate shown
constexpr const char* OrientRefined =
    "OrientRefined";                          ///< candidates scored at the print's resolution
constexpr const char* Pedestal = "Pedestal";  ///< per candidate: mm of pedestal (0 = none)
constexpr const char* Refined =
    "Refined";  ///< per candidate: 1 when scored at the print's resolution
constexpr const char* CoarseCollidingStations = "CoarseCollidingStations";  ///< its coarse pass
constexpr const char* OrientRank = "OrientRank";      ///< 0 = the chosen candidate
constexpr const char* OrientSource = "OrientSource";  ///< "keep", "hull", "sphere" (+ an error)
constexpr const char* CollidingStations = "CollidingStations";
constexpr const char* PlateStations = "PlateStations";
constexpr const char* ForcedSteps = "ForcedSteps";
constexpr const char* BaseArea = "BaseArea";  ///< mm²
constexpr const char* OverhangFraction = "OverhangFraction";
constexpr const char* LayerCount = "LayerCount";
constexpr const char* Feasible = "Feasible";
constexpr const char* Evaluated = "Evaluated";

}  // namespace arrays

/// Values of the VertexKind and EdgeKind arrays (= geolattice::LatticeVertexKind / LatticeEdgeKind).
namespace latticekind {
constexpr int VertexIsolinePoint =
    0;  ///< α- or β-isoline point on a layer-mesh edge or layer point (degree 2)
constexpr int VertexCrossing = 1;     ///< α-isoline meets β-isoline (degree 4)
constexpr int VertexBoundaryHit = 2;  ///< an isoline meets the layer boundary (degree 3)
constexpr int VertexBoundary = 3;     ///< layer boundary point (degree 2)
constexpr int EdgeAlpha = 0;          ///< piece of an α-isoline
constexpr int EdgeBeta = 1;           ///< piece of a β-isoline
constexpr int EdgeBoundary = 2;       ///< piece of the layer boundary
}  // namespace latticekind

/// Values of the Role array of vtkGLCollisionVerifier.
namespace collisionrole {
constexpr int Station = 0;   ///< the nozzle tip (the point being printed)
constexpr int Obstacle = 1;  ///< earlier material inside the nozzle volume there
}  // namespace collisionrole

/// Values of the Collision array of GL Collision Verifier's Stations output.
namespace collisionkind {
constexpr int Clear = 0;     ///< no earlier material and no plate inside the nozzle
constexpr int Material = 1;  ///< earlier material inside the nozzle
constexpr int Plate = 2;     ///< the build plate inside the nozzle (or the tip in it)
}  // namespace collisionkind

/// Values of the MoveKind array of vtkGLToolpathPlanner (= geolattice::MoveKind).
namespace movekind {
constexpr int Print = 0;      ///< printing a lattice edge
constexpr int Perimeter = 1;  ///< printing the support perimeter
constexpr int Air = 2;        ///< air move (no extrusion; not material for the collision verifier)
}  // namespace movekind
}  // namespace geolattice
#endif
