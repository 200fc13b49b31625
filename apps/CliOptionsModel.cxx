// The general options and those of the model placement, &P::Orientation, meshing, fields and layers.
#include "CliOptionTable.h"

namespace geolattice::cli {

void addModelOptions(std::vector<CliOption>& t) {
  const char* general = "General";
  const char* place = "Model placement (models come in arbitrary units; GeoLattice works in mm)";
  const char* mesh = "Tetrahedral meshing (TetGen)";
  const char* gdf = "Geodesic distance fields (heat method, paper Eqs. 1-5)";
  const char* layers = "Curved layers (iso-surfaces of Gamma)";
  t.push_back({"-o", "DIR", general, "output directory (created if missing) [required]", "",
               [](P&, RunOptions& r, const std::string& v) { r.outDir = v; },
               [](P&, const RunOptions& r) {
                 return r.outDir;
               }});
  t.push_back({"--until", "STAGE", general, kStageNames, "",
               [](P&, RunOptions& r, const std::string& v) {
                 r.until = kStages[choice("--until", v, kStages)];
               },
               [](P&, const RunOptions& r) {
                 return r.until;
               }});
  t.push_back({"--allow-collisions", "", general,
               "write the machine programs even if the toolpath collides (the warning stays)", "",
               [](P&, RunOptions& r, const std::string&) { r.allowCollisions = true; },
               [](P&, const RunOptions& r) {
                 return r.allowCollisions ? "on" : "off";
               }});
  t.push_back({"-q", "", general, "no progress lines on stdout (also --quiet)", "",
               [](P&, RunOptions& r, const std::string&) { r.quiet = true; },
               [](P&, const RunOptions& r) {
                 return r.quiet ? "on" : "off";
               }});

  t.push_back(number("--scale", "F", place, "uniform scale factor applied to the model",
                     "GLPlaceOnPlatform.Scale", &P::Placement, &vtkGLPlaceOnPlatform::SetScale,
                     &vtkGLPlaceOnPlatform::GetScale));
  t.push_back(number("--fit-size", "MM", place,
                     "scale so the largest bounding-box side is MM (0 = use --scale)",
                     "GLPlaceOnPlatform.FitSize", &P::Placement, &vtkGLPlaceOnPlatform::SetFitSize,
                     &vtkGLPlaceOnPlatform::GetFitSize));
  t.push_back(toggle(
      "--no-center", place, "keep x and y as they are (default: bounding box centred on x = y = 0)",
      "GLPlaceOnPlatform.CenterXY", &P::Placement, &vtkGLPlaceOnPlatform::SetCenterXY,
      &vtkGLPlaceOnPlatform::GetCenterXY, false, "centred", "kept"));

  t.push_back(toggle("--fill-holes", place,
                     "close the holes of an open surface (a scan) before placing it: each gets\n"
                     "a patch faired into the surface around it (look at it before printing)",
                     "GLPlaceOnPlatform.FillHoles", &P::Placement,
                     &vtkGLPlaceOnPlatform::SetFillHoles, &vtkGLPlaceOnPlatform::GetFillHoles,
                     true));
  t.push_back(toggle("--fill-cavities", place,
                     "fill the part's sealed inner voids before placing it: it is printed solid\n"
                     "there (no nozzle reaches inside a sealed void)",
                     "GLPlaceOnPlatform.FillCavities", &P::Placement,
                     &vtkGLPlaceOnPlatform::SetFillCavities, &vtkGLPlaceOnPlatform::GetFillCavities,
                     true));
  t.push_back(number("--wrap", "MM", place,
                     "replace the surface by a closed wrap of it, MM fine (CGAL alpha wrap), for\n"
                     "surfaces nothing else repairs: crossing facets, non-manifold edges; it\n"
                     "grows by MM/30 and closes gaps narrower than MM (0 = off; e.g. 1)",
                     "GLPlaceOnPlatform.Wrap", &P::Placement, &vtkGLPlaceOnPlatform::SetWrap,
                     &vtkGLPlaceOnPlatform::GetWrap));

  const char* orient = "Orientation (which side of the part faces the plate)";
  t.push_back({"--orient", "MODE", orient,
               "keep | auto: keep the placement, or search the best orientation\n"
               "(candidates scored with the real stages on a coarse mesh;\n"
               "orientation.csv lists them)",
               "GLAutoOrient.Orient",
               [](P& p, RunOptions&, const std::string& v) {
                 p.Orientation->SetOrient(choice("--orient", v, {"keep", "auto"}));
               },
               [](P& p, const RunOptions&) {
                 return std::string(p.Orientation->GetOrient() ? "auto" : "keep");
               }});
  t.push_back(number("--min-base-area", "MM2", orient,
                     "contact area with the plate an orientation needs (mm^2)",
                     "GLAutoOrient.MinBaseArea", &P::Orientation, &vtkGLAutoOrient::SetMinBaseArea,
                     &vtkGLAutoOrient::GetMinBaseArea));
  t.push_back({"--pedestal", "auto|MM", orient,
               "raise the part on a printed column of its footprint, MM tall, so\n"
               "overhangs right above the plate can be printed; auto: --orient auto\n"
               "puts it on a 10 mm one where that prints better (20 or 30 mm when its\n"
               "toolpath still meets the plate; none with keep); 0 = never",
               "GLPrintPart.PedestalHeight",
               [](P& p, RunOptions&, const std::string& v) {
                 if (v == "auto") {
                   p.SetPedestalRequest(-1);
                   return;
                 }
                 const double mm = parseNumber("--pedestal", v);
                 if (mm < 0) {
                   p.Pedestal->SetHeight(mm);  // refused with its range by the parameter check
                 } else {
                   p.SetPedestalRequest(mm);
                 }
               },
               [](P& p, const RunOptions&) {
                 const double mm = p.GetPedestalRequest();
                 return mm < 0 ? std::string("auto") : text(mm);
               }});
  t.push_back({"--orient-tries", "N", orient,
               "with --orient auto, when the best candidate's toolpath collides (or the\n"
               "robot cannot follow it), run up to N candidates of the search (it scores\n"
               "at least N at the print's resolution) and the placement through the\n"
               "toolpath (and the robot's path solver) and print the first that passes,\n"
               "else the one that collides least (1 = the search's best only)",
               "GLPrintPart.OrientTries",
               [](P& p, RunOptions&, const std::string& v) {
                 p.OrientationTries = static_cast<int>(wholeNumber("--orient-tries", v, 1, 20));
               },
               [](P& p, const RunOptions&) {
                 return text(p.OrientationTries);
               }});
  t.push_back(integer("--orient-candidates", "N", orient,
                      "candidate directions from a uniform sphere sample (plus the\n"
                      "convex-hull facets and the placement as it is)",
                      "GLAutoOrient.SphereCandidates", &P::Orientation,
                      &vtkGLAutoOrient::SetSphereCandidates, &vtkGLAutoOrient::GetSphereCandidates,
                      0, 2000));

  t.push_back(number("--edge-length", "MM", mesh,
                     "target tet edge length; 0 = automatic (see --target-tets)",
                     "GLTetrahedralizeSurface.TargetEdgeLength", &P::Tetrahedralize,
                     &vtkGLTetrahedralizeSurface::SetTargetEdgeLength,
                     &vtkGLTetrahedralizeSurface::GetTargetEdgeLength));
  t.push_back(integer("--target-tets", "N", mesh, "tet count the automatic edge length aims at",
                      "GLTetrahedralizeSurface.TargetTetCount", &P::Tetrahedralize,
                      &vtkGLTetrahedralizeSurface::SetTargetTetCount,
                      &vtkGLTetrahedralizeSurface::GetTargetTetCount, 1, 2e9));
  t.push_back(number("--radius-edge", "R", mesh,
                     "TetGen radius-edge ratio bound (quality; 1.414 = sqrt 2)",
                     "GLTetrahedralizeSurface.RadiusEdgeRatio", &P::Tetrahedralize,
                     &vtkGLTetrahedralizeSurface::SetRadiusEdgeRatio,
                     &vtkGLTetrahedralizeSurface::GetRadiusEdgeRatio));

  t.push_back({"--base", "MODE", gdf,
               "base (heat source): lowest | faces\n"
               "lowest: vertices within --base-tolerance of the lowest z;\n"
               "faces: vertices of boundary faces facing down within --base-angle",
               "GLGeodesicDistanceFields.SourceMode",
               [](P& p, RunOptions&, const std::string& v) {
                 p.GeodesicFields->SetSourceMode(choice("--base", v, {"lowest", "faces"}) == 0
                                                     ? vtkGLGeodesicDistanceFields::LOWEST_Z
                                                     : vtkGLGeodesicDistanceFields::DOWNWARD_FACES);
               },
               [](P& p, const RunOptions&) {
                 return std::string(p.GeodesicFields->GetSourceMode() ==
                                            vtkGLGeodesicDistanceFields::DOWNWARD_FACES
                                        ? "faces"
                                        : "lowest");
               }});
  t.push_back(number("--base-tolerance", "MM", gdf,
                     "height band above the lowest point that is the base",
                     "GLGeodesicDistanceFields.BaseTolerance", &P::GeodesicFields,
                     &vtkGLGeodesicDistanceFields::SetBaseTolerance,
                     &vtkGLGeodesicDistanceFields::GetBaseTolerance));
  t.push_back(number("--base-flat-band", "MM", gdf,
                     "lowest: also the faces facing down within --base-angle up to MM above\n"
                     "the lowest point (a near-flat bottom that is not level); 0 = off",
                     "GLGeodesicDistanceFields.BaseFlatBand", &P::GeodesicFields,
                     &vtkGLGeodesicDistanceFields::SetBaseFlatBand,
                     &vtkGLGeodesicDistanceFields::GetBaseFlatBand));
  t.push_back(number("--base-angle", "DEG", gdf,
                     "max angle between a base face's outward normal and -z",
                     "GLGeodesicDistanceFields.BaseFaceAngle", &P::GeodesicFields,
                     &vtkGLGeodesicDistanceFields::SetBaseFaceAngle,
                     &vtkGLGeodesicDistanceFields::GetBaseFaceAngle));
  t.push_back(number("--time-factor", "F", gdf, "heat time t = F * h^2 (h = mean edge length)",
                     "GLGeodesicDistanceFields.TimeFactor", &P::GeodesicFields,
                     &vtkGLGeodesicDistanceFields::SetTimeFactor,
                     &vtkGLGeodesicDistanceFields::GetTimeFactor));
  t.push_back({"--reference", "auto|X,Y,Z", gdf,
               "reference vector r of Eq. 3 (the lattice directions), used as given;\n"
               "auto: 1,0,0, turned across the build direction where it lies along the\n"
               "layers' normal in more than 1 % of the tets",
               "GLGeodesicDistanceFields.TurnReference",
               [](P& p, RunOptions&, const std::string& v) {
                 if (v == "auto") {
                   const GeodesicFieldOptions defaults;
                   p.GeodesicFields->SetReferenceVector(defaults.reference.data());
                   p.GeodesicFields->SetTurnReference(defaults.turnReference);
                   return;
                 }
                 const auto r = parseNumbers("--reference", v, 3, "auto or X,Y,Z");
                 p.GeodesicFields->SetReferenceVector(r[0], r[1], r[2]);
                 p.GeodesicFields->SetTurnReference(false);
               },
               [](P& p, const RunOptions&) {
                 return p.GeodesicFields->GetTurnReference()
                            ? std::string("auto")
                            : text(p.GeodesicFields->GetReferenceVector(), 3);
               }});
  t.push_back({"--solver", "NAME", gdf, "cholmod | eigen (sparse Cholesky back end)",
               "GLGeodesicDistanceFields.UseCholmod",
               [](P& p, RunOptions&, const std::string& v) {
                 p.GeodesicFields->SetUseCholmod(choice("--solver", v, {"cholmod", "eigen"}) == 0);
               },
               [](P& p, const RunOptions&) {
                 return std::string(p.GeodesicFields->GetUseCholmod() ? "cholmod" : "eigen");
               }});

  t.push_back(number(
      "--layer-interval", "MM", layers, "gamma distance between layers (nominal layer thickness)",
      "GLCurvedLayerSlicer.LayerInterval", &P::Slicer, &vtkGLCurvedLayerSlicer::SetLayerInterval,
      &vtkGLCurvedLayerSlicer::GetLayerInterval));
  t.push_back({"--first-layer", "MM", layers, "gamma of the first layer (default: the interval)",
               "GLCurvedLayerSlicer.FirstLayerOffset",
               [](P& p, RunOptions& r, const std::string& v) {
                 p.Slicer->SetFirstLayerOffset(parseNumber("--first-layer", v));
                 r.firstLayerGiven = true;
               },
               [](P& p, const RunOptions&) {
                 return text(p.Slicer->GetFirstLayerOffset());
               }});
  t.push_back(number(
      "--overhang-threshold", "DEG", layers, "overhang angle above which a surface needs support",
      "GLOverhangAnalysis.ThresholdAngle", &P::OverhangAnalysis,
      &vtkGLOverhangAnalysis::SetThresholdAngle, &vtkGLOverhangAnalysis::GetThresholdAngle));
}

}  // namespace geolattice::cli
