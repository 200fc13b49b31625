#include "StageReports.h"

#include "GLPrintPipeline.h"
#include "GLPrintheadFile.h"
#include "vtkGLArrayNames.h"

#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkFieldData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkTable.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <vector>

namespace geolattice {

namespace {

long long count(vtkDataObject* data, const char* name) {
  return static_cast<long long>(fieldValue(data, name));
}

long long points(vtkDataObject* data) {
  vtkDataSet* d = vtkDataSet::SafeDownCast(data);
  return d ? static_cast<long long>(d->GetNumberOfPoints()) : 0;
}

long long cells(vtkDataObject* data) {
  vtkDataSet* d = vtkDataSet::SafeDownCast(data);
  return d ? static_cast<long long>(d->GetNumberOfCells()) : 0;
}

std::vector<double> vec(const double* v, int n) {
  return std::vector<double>(v, v + n);
}

/// Smallest or largest non-NaN value of a field array (NaN marks "no value" per layer).
double extremum(vtkDataObject* data, const char* name, bool wantMin) {
  vtkDataArray* a = data->GetFieldData()->GetArray(name);
  double best =
      wantMin ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
  for (vtkIdType i = 0; a && i < a->GetNumberOfTuples(); ++i) {
    const double v = a->GetTuple1(i);
    if (!std::isnan(v)) {
      best = wantMin ? std::min(best, v) : std::max(best, v);
    }
  }
  return std::isfinite(best) ? best : 0.0;
}

/// The printhead of the nozzle block, if any: its file and size (read once, cached).
void reportPrinthead(vtkGLNozzle* n, Json& s) {
  const char* file = n->GetPrintheadFile();
  if (!file || !*file) {
    s["printhead"] = nullptr;
    return;
  }
  const auto head = readPrintheadFile(file);
  s["printhead"] = {{"file", std::filesystem::absolute(head->name()).string()},
                    {"height_mm", head->height()},
                    {"max_radius_mm", head->maxRadius()},
                    {"reach_mm", head->reach()},
                    {"face_radius_mm", head->faceRadius()},
                    {"volume_mm3", head->volume()},
                    {"triangles", head->triangles()}};
}

}  // namespace

double fieldValue(vtkDataObject* data, const char* name, int component) {
  vtkDataArray* a =
      data ? vtkDataArray::SafeDownCast(data->GetFieldData()->GetAbstractArray(name)) : nullptr;
  if (!a || a->GetNumberOfValues() <= component) {
    return 0.0;
  }
  return a->GetComponent(component / a->GetNumberOfComponents(),
                         component % a->GetNumberOfComponents());
}

void reportInput(vtkDataObject* placed, bool tetMesh, Json& s) {
  s["points"] = points(placed);
  s[tetMesh ? "tets" : "triangles"] = cells(placed);
  s["scale"] = fieldValue(placed, arrays::PlacementScale);
  s["translation"] = {fieldValue(placed, arrays::PlacementTranslation, 0),
                      fieldValue(placed, arrays::PlacementTranslation, 1),
                      fieldValue(placed, arrays::PlacementTranslation, 2)};
  double b[6];
  vtkDataSet::SafeDownCast(placed)->GetBounds(b);
  s["size_mm"] = {b[1] - b[0], b[3] - b[2], b[5] - b[4]};
  s["bounds_mm"] = vec(b, 6);
  s["filled_holes"] = fieldValue(placed, arrays::FilledHoles);
  s["filled_hole_triangles"] = fieldValue(placed, arrays::FilledHoleTriangles);
  s["filled_cavities"] = fieldValue(placed, arrays::FilledCavities);
  s["wrap_triangles"] = fieldValue(placed, arrays::WrapTriangles);
}

void reportMesh(vtkDataObject* tets, bool meshed, Json& s) {
  s["meshed"] = meshed;
  if (meshed) {
    s["target_edge_length_mm"] = fieldValue(tets, arrays::TargetEdgeLength);
    s["mean_edge_length_mm"] = fieldValue(tets, arrays::MeanEdgeLength);
    s["tetgen_seconds"] = fieldValue(tets, arrays::TetrahedralizeSeconds);
    s["input_triangles"] = fieldValue(tets, arrays::InputTriangles);
    s["meshed_triangles"] = fieldValue(tets, arrays::MeshedTriangles);
    s["simplified"] =
        fieldValue(tets, arrays::MeshedTriangles) < fieldValue(tets, arrays::InputTriangles);
    s["simplification_distance_mm"] = fieldValue(tets, arrays::SimplificationDistance);
    s["simplification_seconds"] = fieldValue(tets, arrays::SimplificationSeconds);
    s["simplification_edge_mm"] = fieldValue(tets, arrays::SimplificationEdgeLength);
    auto* refused = vtkStringArray::SafeDownCast(
        tets->GetFieldData()->GetAbstractArray(arrays::SimplificationRefused));
    s["simplification_refused"] =
        refused && refused->GetNumberOfValues() > 0 ? refused->GetValue(0) : std::string();
    s["tetgen_runs"] = fieldValue(tets, arrays::TetGenRuns);
    s["tetgen_speculative_run"] = fieldValue(tets, arrays::TetGenSpeculativeRun) != 0;
    s["tetgen_count_set_by_surface"] = fieldValue(tets, arrays::TetGenSurfaceBoundCount) != 0;
    s["removed_flat_tets"] = fieldValue(tets, arrays::RemovedFlatTets);
    s["tetgen_quality_bound_dropped"] = fieldValue(tets, arrays::TetGenQualityBoundDropped) != 0;
    s["cavities"] = fieldValue(tets, arrays::CavityRegions);
  }
  s["points"] = points(tets);
  s["tets"] = cells(tets);
}

void reportOrientation(vtkDataObject* o, Json& s) {
  s["mode"] = "auto";
  s["up"] = {fieldValue(o, arrays::OrientUp, 0), fieldValue(o, arrays::OrientUp, 1),
             fieldValue(o, arrays::OrientUp, 2)};
  std::vector<double> rotation;
  for (int k = 0; k < 9; ++k) {
    rotation.push_back(fieldValue(o, arrays::OrientRotation, k));
  }
  s["rotation"] = rotation;
  s["candidates"] = count(o, arrays::OrientCandidates);
  s["search_seconds"] = fieldValue(o, arrays::OrientSeconds);
  s["evaluation_tets"] = count(o, arrays::OrientEvaluationTets);
  s["evaluation_scale"] = fieldValue(o, arrays::OrientEvaluationScale);
  s["refined_candidates"] = count(o, arrays::OrientRefined);
  s["chosen_rank"] = count(o, arrays::OrientChosenRank);
  s["pedestal_mm"] = fieldValue(o, arrays::OrientPedestalHeight);
  s["before"] = {{"colliding_stations", count(o, arrays::OrientBefore)}};
  s["after"] = {{"colliding_stations", count(o, arrays::OrientAfter)}};
  s["candidates_file"] = "orientation.csv";
}

void reportPedestal(vtkDataObject* raised, Json& s) {
  s["height_mm"] = fieldValue(raised, arrays::PedestalHeight);
  s["footprint_area_mm2"] = fieldValue(raised, arrays::PedestalFootprintArea);
  s["footprint_loops"] = count(raised, arrays::PedestalFootprintPieces);
}

void reportFields(vtkDataObject* fields, Json& s) {
  s["points"] = points(fields);
  s["tets"] = cells(fields);
  s["sources"] = count(fields, arrays::SourceCount);
  s["gamma_max"] = fieldValue(fields, arrays::GammaRange, 1);
  s["alpha_max"] = fieldValue(fields, arrays::AlphaRange, 1);
  s["beta_max"] = fieldValue(fields, arrays::BetaRange, 1);
  s["assembly_seconds"] = fieldValue(fields, arrays::GdfTimings, 0);
  s["factorization_seconds"] = fieldValue(fields, arrays::GdfTimings, 1);
  s["solve_seconds"] = fieldValue(fields, arrays::GdfTimings, 2);
  s["reference_fallback_tets"] = count(fields, arrays::ReferenceFallbackTets);
  s["reference"] = {fieldValue(fields, arrays::ReferenceUsed, 0),
                    fieldValue(fields, arrays::ReferenceUsed, 1),
                    fieldValue(fields, arrays::ReferenceUsed, 2)};
  if (vtkDataArray* given = fields->GetFieldData()->GetArray(arrays::GivenReferenceFallbackTets)) {
    s["given_reference_fallback_tets"] = static_cast<long long>(given->GetTuple1(0));
  }
  s["orthogonality_deviation_deg"] = {
      {"alpha_gamma_median", fieldValue(fields, arrays::OrthogonalityDeg, 0)},
      {"alpha_gamma_p95", fieldValue(fields, arrays::OrthogonalityDeg, 1)},
      {"beta_gamma_median", fieldValue(fields, arrays::OrthogonalityDeg, 2)},
      {"beta_gamma_p95", fieldValue(fields, arrays::OrthogonalityDeg, 3)}};
}

void reportLayers(GLPrintPipeline& p, vtkDataObject* layers, Json& s) {
  vtkDataArray* values = layers->GetFieldData()->GetArray(arrays::LayerValues);
  s["count"] = values ? static_cast<long long>(values->GetNumberOfTuples()) : 0;
  s["interval"] = p.Slicer->GetLayerInterval();
  s["first_layer"] = p.Slicer->GetFirstLayerOffset();
  s["points"] = points(layers);
  s["triangles"] = cells(layers);
  s["components_max"] = static_cast<long long>(extremum(layers, arrays::LayerComponents, false));
  s["spacing_mm"] = {{"min", extremum(layers, arrays::LayerSpacingMin, true)},
                     {"mean_min", extremum(layers, arrays::LayerSpacingMean, true)},
                     {"mean_max", extremum(layers, arrays::LayerSpacingMean, false)},
                     {"max", extremum(layers, arrays::LayerSpacingMax, false)}};
}

void reportOverhang(vtkDataObject* surface, Json& s) {
  s["threshold_deg"] = fieldValue(surface, arrays::OverhangThresholdDeg);
  s["planar_fraction"] = fieldValue(surface, arrays::OverhangPlanarFraction);
  s["curved_fraction"] = fieldValue(surface, arrays::OverhangCurvedFraction);
  s["surface_area_mm2"] = fieldValue(surface, arrays::OverhangTotalArea);
  s["base_area_mm2"] = fieldValue(surface, arrays::OverhangBaseArea);
}

void reportLattice(GLPrintPipeline& p, vtkDataObject* graph, Json& s) {
  s["alpha_width"] = p.LatticeInfill->GetAlphaWidth();
  s["beta_width"] = p.LatticeInfill->GetBetaWidth();
  s["vertices"] = count(graph, arrays::LatticeVertices);
  s["edges"] = count(graph, arrays::LatticeEdges);
  s["subgraphs"] = count(graph, arrays::LatticeSubgraphs);
  s["crossings"] = count(graph, arrays::LatticeCrossings);
  s["boundary_hits"] = count(graph, arrays::LatticeBoundaryHits);
  s["isoline_edges"] = count(graph, arrays::LatticeIsolineEdges);
  s["dropped_subgraphs"] = count(graph, arrays::LatticeDroppedSubgraphs);
  s["irregular_vertices"] = count(graph, arrays::LatticeIrregularVertices);
}

void reportSkeleton(vtkDataObject* tree, Json& s) {
  s["nodes"] = points(tree);
  s["edges"] = cells(tree);
  s["roots"] = count(tree, arrays::SkeletonRoots);
  s["split_nodes"] = count(tree, arrays::SkeletonSplitNodes);
  s["merge_nodes"] = count(tree, arrays::SkeletonMergeNodes);
  s["floating_nodes"] = count(tree, arrays::SkeletonFloatingNodes);
}

void reportSequence(GLPrintPipeline& p, vtkDataObject* sequenced, Json& s) {
  static const char* const names[] = {"lpt", "dpt", "a4", "best"};
  // The strategy whose order this is (the one chosen by the toolpath in place of Best, if any),
  // and the one asked for.
  const int used = p.Sequencer->GetStrategyOverride();
  s["strategy"] = names[used >= 0 ? used : p.Sequencer->GetStrategy()];
  s["requested_strategy"] = names[p.Sequencer->GetStrategy()];
  vtkGLNozzle* n = p.Nozzle;
  s["nozzle_angle_deg"] = n->GetNozzleAngle();
  s["nozzle_length_mm"] = n->GetNozzleLength();
  s["holder_radius_mm"] = n->GetHolderRadius();
  s["holder_length_mm"] = n->GetHolderLength();
  s["tip_clearance_mm"] = n->GetTipClearance();
  s["tip_face_radius_mm"] = n->GetTipFaceRadius();
  s["face_contact_mm"] = n->GetFaceContact();
  s["build_plate"] = n->GetBuildPlate() != 0;
  s["plate_margin_mm"] = n->GetPlateMargin();
  s["plate_thickness_mm"] = n->GetPlateThickness();
  reportPrinthead(n, s);
  s["sample_spacing_mm"] = p.Sequencer->GetSampleSpacing();
  s["subgraphs"] = count(sequenced, arrays::LatticeSubgraphs);
  s["retractions"] = count(sequenced, arrays::SequenceRetractions);
  s["air_length_mm"] = fieldValue(sequenced, arrays::SequenceAirLength);
  s["pcg_pairs"] = count(sequenced, arrays::SequencePcgPairs);
  s["pcg_seconds"] = fieldValue(sequenced, arrays::SequencePcgSeconds);
  s["unavoidable_pcg_pairs"] = count(sequenced, arrays::SequenceUnavoidablePairs);
  s["forced_steps"] = count(sequenced, arrays::SequenceForcedSteps);
  s["forced_steps_before_split"] = count(sequenced, arrays::SequenceForcedStepsBefore);
  s["pieces"] = count(sequenced, arrays::SequencePieces);
  s["split_for_order"] = count(sequenced, arrays::SequenceSplitSubgraphs);
  s["split_rounds"] = p.Sequencer->GetSplitRounds();
}

void reportToolpath(GLPrintPipeline& p, vtkDataObject* t, Json& s) {
  vtkGLToolpathPlanner* f = p.Planner;
  s["path_width_mm"] = f->GetPathWidth();
  s["filament_diameter_mm"] = f->GetFilamentDiameter();
  s["flow"] = f->GetFlowCorrection();
  s["print_speed_mm_s"] = f->GetPrintFeedRate();
  s["air_speed_mm_s"] = f->GetAirFeedRate();
  s["thickness_cap"] = f->GetThicknessCap();
  s["max_turn_deg"] = f->GetMaxTurnAngle();
  s["safe_margin_mm"] = f->GetSafeMargin();
  s["lift_mm"] = f->GetLift();
  s["retraction_mm"] = f->GetRetraction();
  s["tooth_length_mm"] = f->GetToothLength();
  s["max_segment_mm"] = f->GetMaxSegmentLength();
  s["max_tilt_deg"] = f->GetMaxAxisTilt();
  s["tilt_blend_mm"] = f->GetTiltBlendLength();
  s["support_perimeter"] = f->GetSupportPerimeter() != 0;
  s["points"] = points(t);
  s["cells"] = cells(t);
  s["print_length_mm"] = fieldValue(t, arrays::ToolpathPrintLength);
  s["perimeter_length_mm"] = fieldValue(t, arrays::ToolpathPerimeterLength);
  s["air_length_mm"] = fieldValue(t, arrays::ToolpathAirLength);
  s["retractions"] = count(t, arrays::ToolpathRetractions);
  s["tours"] = count(t, arrays::ToolpathTours);
  s["crossings"] = count(t, arrays::ToolpathCrossings);
  s["split_subgraphs"] = count(t, arrays::ToolpathSplitSubgraphs);
  s["contracted_edges"] = count(t, arrays::ToolpathContractedEdges);
  s["trimmed_edges"] = count(t, arrays::ToolpathTrimmedEdges);
  s["trimmed_length_mm"] = fieldValue(t, arrays::ToolpathTrimmedLength);
  s["perimeter_loops"] = count(t, arrays::ToolpathPerimeterLoops);
  s["perimeter_teeth"] = count(t, arrays::ToolpathPerimeterTeeth);
  s["rotation_steps"] = count(t, arrays::ToolpathRotationSteps);
  s["subdivision_points"] = count(t, arrays::ToolpathSubdivisionPoints);
  s["colliding_stations_along_normal"] = count(t, arrays::ToolpathCollidingStations);
  s["tilted_stations"] = count(t, arrays::ToolpathTiltedStations);
  s["uncleared_stations"] = count(t, arrays::ToolpathUnclearedStations);
  s["max_axis_tilt_deg"] = fieldValue(t, arrays::ToolpathMaxAxisTilt);
  s["replanned_hops"] = count(t, arrays::ToolpathReplannedHops);
  s["aligned_transitions"] = count(t, arrays::ToolpathAlignedTransitions);
  s["reordered_tours"] = count(t, arrays::ToolpathReorderedTours);
  s["uncleared_before_reorder"] = count(t, arrays::ToolpathUnclearedBeforeReorder);
  s["thickness_dev_min"] = fieldValue(t, arrays::ToolpathThicknessDeviation, 0);
  s["thickness_dev_max"] = fieldValue(t, arrays::ToolpathThicknessDeviation, 1);
  s["capped_vertices"] = count(t, arrays::ToolpathCappedVertices);
  s["unsupported_vertices"] = count(t, arrays::ToolpathUnsupportedVertices);
  s["filament_mm"] = fieldValue(t, arrays::ToolpathFilament);
  s["volume_mm3"] = fieldValue(t, arrays::ToolpathVolume);
  s["planning_seconds"] = fieldValue(t, arrays::ToolpathSeconds);
}

void reportCollisions(vtkDataObject* v, Json& s) {
  s["collision_free"] = fieldValue(v, arrays::CollisionFree) != 0;
  s["order_collision_free"] = fieldValue(v, arrays::CollisionOrderFree) != 0;
  s["stations"] = count(v, arrays::CollisionStations);
  s["violating_stations"] = count(v, arrays::CollisionViolatingStations);
  s["unavoidable_stations"] = count(v, arrays::CollisionUnavoidableStations);
  s["plate_stations"] = count(v, arrays::CollisionPlateStations);
  if (v->GetFieldData()->GetArray(arrays::CollisionLayerRange)) {
    s["violating_layers"] = {count(v, arrays::CollisionLayerRange),
                             static_cast<long long>(fieldValue(v, arrays::CollisionLayerRange, 1))};
  }
}

void reportSummary(vtkDataObject* summary, Json& s) {
  vtkTable* table = vtkTable::SafeDownCast(summary);
  if (!table) {
    return;
  }
  auto* key = vtkStringArray::SafeDownCast(table->GetColumnByName("Key"));
  vtkDataArray* value = vtkDataArray::SafeDownCast(table->GetColumnByName("Value"));
  for (vtkIdType r = 0; key && value && r < table->GetNumberOfRows(); ++r) {
    s[key->GetValue(r)] = value->GetTuple1(r);
  }
  if (auto* verdict = vtkStringArray::SafeDownCast(
          table->GetFieldData()->GetAbstractArray(arrays::SummaryVerdict))) {
    s["verdict"] = verdict->GetValue(0);
  }
}

void reportScript(GLPrintPipeline& p, Json& s) {
  vtkGLURScriptWriter* w = p.ScriptWriter;
  s["robot"] = w->GetRobot();
  s["nozzle_tip_mm"] = vec(w->GetNozzleTip(), 3);
  s["nozzle_axis"] = vec(w->GetNozzleAxis(), 3);
  // Position (mm) then rotation vector (deg), as --part-on-flange takes it.
  std::vector<double> mounting = vec(w->GetPartOnFlangePosition(), 3);
  for (double v : vec(w->GetPartOnFlangeRotation(), 3)) {
    mounting.push_back(v);
  }
  s["part_on_flange"] = mounting;
  s["max_script_bytes"] = static_cast<long long>(w->GetMaxFileBytes());
  s["speed_factor"] = w->GetSpeedFactor();
  s["max_filament_rate_mm_s"] = w->GetMaxFilamentRate();
  s["max_blend_mm"] = w->GetMaxBlend();
  s["max_joint_step_limit_deg"] = w->GetMaxJointStep();
  s["allow_unreachable"] = w->GetAllowUnreachable() != 0;
  s["waypoints"] = static_cast<long long>(w->GetNumberOfWaypoints());
  s["moves"] = static_cast<long long>(w->GetNumberOfMoves());
  s["unreachable"] = static_cast<long long>(w->GetUnreachableCount());
  std::vector<long long> first;
  for (vtkIdType i = 0; i < std::min<vtkIdType>(w->GetUnreachableCount(), 10); ++i) {
    first.push_back(static_cast<long long>(w->GetUnreachablePoint(i)));
  }
  s["unreachable_first"] = first;
  std::vector<std::string> files;
  for (int k = 0; k < w->GetNumberOfFilesWritten(); ++k) {
    const std::string f = w->GetFileWritten(k);
    files.push_back(f.substr(f.find_last_of('/') + 1));
  }
  s["files"] = files;
  s["ik_branch"] = w->GetIKBranch();
  s["layout"] = {{"searched", w->GetSearchCellLayout() != 0},
                 {"changed", w->GetLayoutChanged()},
                 {"rotation_about_flange_z_deg", w->GetLayoutRotationDeg()},
                 {"offset_added_mm", w->GetLayoutOffsetAdded()},
                 {"layouts_tried", w->GetLayoutsTried()},
                 {"part_on_flange_used", vec(w->GetUsedPartOnFlange(), 6)}};
  Json reconfigurations = Json::array();
  for (int k = 0; k < w->GetNumberOfReconfigurations(); ++k) {
    reconfigurations.push_back({{"point", static_cast<long long>(w->GetReconfigurationPoint(k))},
                                {"at_seam", w->GetReconfigurationAtSeam(k)},
                                {"from_branch", w->GetReconfigurationFromBranch(k)},
                                {"to_branch", w->GetReconfigurationToBranch(k)},
                                {"retreat_mm", w->GetReconfigurationRetreat(k)},
                                {"clearance_mm", w->GetReconfigurationClearance(k)}});
  }
  s["reconfigure"] = w->GetReconfigure() != 0;
  s["reconfigurations"] = reconfigurations;
  s["max_joint_step_deg"] = w->GetMaxJointStepDeg();
  s["large_joint_steps"] = static_cast<long long>(w->GetLargeJointSteps());
  s["via_segments"] = static_cast<long long>(w->GetViaSegments());
  s["via_waypoints"] = static_cast<long long>(w->GetViaWaypoints());
  s["max_tip_error_m"] = w->GetMaxTipError();
  s["max_axis_error_deg"] = w->GetMaxAxisErrorDeg();
  s["min_singularity"] = {{"shoulder_m", w->GetMinShoulderSingularity()},
                          {"elbow", w->GetMinElbowSingularity()},
                          {"wrist", w->GetMinWristSingularity()}};
  s["lowest_arm_height_mm"] = w->GetLowestArmHeight();
  s["lowest_part_height_mm"] = w->GetLowestPartHeight();
  s["printhead_radius_mm"] = w->GetPrintheadRadiusUsed();
  s["min_link_nozzle_distance_mm"] = w->GetMinLinkNozzleDistance();
  s["min_link_part_distance_mm"] = w->GetMinLinkPartDistance();
  s["max_joint_speed_deg_s"] = w->GetMaxJointSpeedDegS();
  s["duration_s"] = w->GetDuration();
  s["max_line_length"] = static_cast<long long>(w->GetMaxLineLength());
  s["solve_seconds"] = w->GetSolveSeconds();
}

void reportGCode(GLPrintPipeline& p, Json& g) {
  vtkGLGCodeWriter* w = p.GCodeWriter;
  g["flavor"] = w->GetFlavor() ? "reprap" : "linuxcnc";
  g["tool_centre_point"] = w->GetToolCentrePoint() ? "cam" : "controller";
  if (!w->GetFlavor()) {
    g["extrusion_axis"] = w->GetExtrusionAxis();
  }
  g["pivot_mm"] = vec(w->GetPivot(), 3);
  g["part_offset_mm"] = vec(w->GetPartOffset(), 3);
  g["tilt_limits_deg"] = vec(w->GetTiltLimits(), 2);
  g["moves"] = static_cast<long long>(w->GetNumberOfMoves());
  g["max_rotary_step_deg"] = w->GetMaxRotaryStepDeg();
  g["branch_flips"] = static_cast<long long>(w->GetBranchFlips());
  g["max_axis_error_deg"] = w->GetMaxAxisErrorDeg();
  g["forced_rotary_steps"] = static_cast<long long>(w->GetForcedRotarySteps());
}

}  // namespace geolattice
