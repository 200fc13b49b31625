#include "CliOptions.h"

#include "GLPrintPipeline.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <regex>
#include <sstream>

namespace geolattice {

double parseNumber(const std::string& flag, const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(v)) {
    throw UsageError(flag + " expects a number, got '" + text + "'");
  }
  return v;
}

std::vector<double> parseNumbers(const std::string& flag, const std::string& text, size_t count,
                                 const char* form) {
  std::vector<double> out;
  std::stringstream ss(text);
  std::string part;
  while (std::getline(ss, part, ',')) {
    char* end = nullptr;
    const double v = std::strtod(part.c_str(), &end);
    if (part.empty() || *end != '\0' || !std::isfinite(v) || out.size() == count) {
      throw UsageError(flag + " expects " + form + ", got '" + text + "'");
    }
    out.push_back(v);
  }
  if (out.size() != count || (!text.empty() && text.back() == ',')) {
    throw UsageError(flag + " expects " + form + ", got '" + text + "'");
  }
  return out;
}

namespace {

using P = GLPrintPipeline;
using Setter = std::function<void(P&, RunOptions&, const std::string&)>;
using Getter = std::function<std::string(P&, const RunOptions&)>;

std::string text(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}
std::string text(const double* v, int n) {
  std::string s;
  for (int k = 0; k < n; ++k) {
    s += (k ? "," : "") + text(v[k]);
  }
  return s;
}

/// A whole number in [lo, hi] or UsageError.
long long wholeNumber(const std::string& flag, const std::string& value, double lo, double hi) {
  const double v = parseNumber(flag, value);
  if (v < lo || v > hi || v != std::floor(v)) {
    throw UsageError(flag + " expects a whole number from " + text(lo) + " to " + text(hi) +
                     ", got '" + value + "'");
  }
  return static_cast<long long>(v);
}

/// One of `names` (its index) or UsageError.
int choice(const std::string& flag, const std::string& value,
           const std::vector<std::string>& names) {
  const auto it = std::find(names.begin(), names.end(), value);
  if (it == names.end()) {
    std::string list;
    for (size_t k = 0; k < names.size(); ++k) {
      list += (k ? (k + 1 == names.size() ? " or " : ", ") : "") + names[k];
    }
    throw UsageError(flag + " must be " + list + " (got '" + value + "')");
  }
  return static_cast<int>(it - names.begin());
}

/// A number option bound to `set`/`get` of one filter (the getter gives the default).
template <class F>
CliOption number(const char* flag, const char* value, const char* section, const char* help,
                 const std::string& property, F* (*filter)(P&), void (F::*set)(double),
                 double (F::*get)()) {
  return {flag,
          value,
          section,
          help,
          property,
          [=](P& p, RunOptions&, const std::string& v) { (filter(p)->*set)(parseNumber(flag, v)); },
          [=](P& p, const RunOptions&) {
            return text((filter(p)->*get)());
          }};
}

vtkGLNozzle* nozzle(P& p) {
  return p.Nozzle;
}
vtkGLPlaceOnPlatform* placement(P& p) {
  return p.Placement;
}
vtkGLAutoOrient* orientation(P& p) {
  return p.Orientation;
}
vtkGLTetrahedralizeSurface* tets(P& p) {
  return p.Tetrahedralize;
}
vtkGLGeodesicDistanceFields* fields(P& p) {
  return p.GeodesicFields;
}
vtkGLCurvedLayerSlicer* slicer(P& p) {
  return p.Slicer;
}
vtkGLOverhangAnalysis* overhang(P& p) {
  return p.OverhangAnalysis;
}
vtkGLLatticeInfill* lattice(P& p) {
  return p.LatticeInfill;
}
vtkGLToolpathPlanner* planner(P& p) {
  return p.Planner;
}
vtkGLURScriptWriter* script(P& p) {
  return p.ScriptWriter;
}

const char* const kStageNames = "mesh | gdf | layers | lattice | sequence | toolpath | program";
const std::vector<std::string> kStages = {"mesh",     "gdf",      "layers", "lattice",
                                          "sequence", "toolpath", "program"};
const std::vector<std::string> kStrategies = {"lpt", "dpt", "a4", "best"};  // = Strategy 0..3

std::vector<CliOption> makeTable() {
  const char* general = "General";
  const char* place = "Model placement (models come in arbitrary units; GeoLattice works in mm)";
  const char* mesh = "Tetrahedral meshing (TetGen)";
  const char* gdf = "Geodesic distance fields (heat method, paper Eqs. 1-5)";
  const char* layers = "Curved layers (iso-surfaces of Gamma)";
  const char* latt = "Lattice infill (iso-lines of Alpha and Beta on each layer, Algorithm 1)";
  const char* seq = "Printing sequence (skeleton tree, Section 3.1) and the nozzle";
  const char* path = "Toolpath (Section 3.2: Euler tours, thickness Eq. 15, extrusion Eq. 14)";
  const char* prog =
      "Programs (Section 4: the robot holds the part under a fixed nozzle; robot cell in metres)";
  std::vector<CliOption> t;
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
                     "GLPlaceOnPlatform.Scale", placement, &vtkGLPlaceOnPlatform::SetScale,
                     &vtkGLPlaceOnPlatform::GetScale));
  t.push_back(number("--fit-size", "MM", place,
                     "scale so the largest bounding-box side is MM (0 = use --scale)",
                     "GLPlaceOnPlatform.FitSize", placement, &vtkGLPlaceOnPlatform::SetFitSize,
                     &vtkGLPlaceOnPlatform::GetFitSize));
  t.push_back({"--no-center", "", place,
               "keep x and y as they are (default: bounding box centred on x = y = 0)",
               "GLPlaceOnPlatform.CenterXY",
               [](P& p, RunOptions&, const std::string&) { p.Placement->SetCenterXY(false); },
               [](P& p, const RunOptions&) {
                 return std::string(p.Placement->GetCenterXY() ? "centred" : "kept");
               }});

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
                     "GLAutoOrient.MinBaseArea", orientation, &vtkGLAutoOrient::SetMinBaseArea,
                     &vtkGLAutoOrient::GetMinBaseArea));
  t.push_back({"--orient-candidates", "N", orient,
               "candidate directions from a uniform sphere sample (plus the\n"
               "convex-hull facets and the placement as it is)",
               "GLAutoOrient.SphereCandidates",
               [](P& p, RunOptions&, const std::string& v) {
                 p.Orientation->SetSphereCandidates(
                     static_cast<int>(wholeNumber("--orient-candidates", v, 0, 2000)));
               },
               [](P& p, const RunOptions&) {
                 return text(p.Orientation->GetSphereCandidates());
               }});

  t.push_back(number("--edge-length", "MM", mesh,
                     "target tet edge length; 0 = automatic (see --target-tets)",
                     "GLTetrahedralizeSurface.TargetEdgeLength", tets,
                     &vtkGLTetrahedralizeSurface::SetTargetEdgeLength,
                     &vtkGLTetrahedralizeSurface::GetTargetEdgeLength));
  t.push_back({"--target-tets", "N", mesh, "tet count the automatic edge length aims at",
               "GLTetrahedralizeSurface.TargetTetCount",
               [](P& p, RunOptions&, const std::string& v) {
                 p.Tetrahedralize->SetTargetTetCount(
                     static_cast<int>(wholeNumber("--target-tets", v, 1, 2e9)));
               },
               [](P& p, const RunOptions&) {
                 return text(p.Tetrahedralize->GetTargetTetCount());
               }});
  t.push_back(number("--radius-edge", "R", mesh,
                     "TetGen radius-edge ratio bound (quality; 1.414 = sqrt 2)",
                     "GLTetrahedralizeSurface.RadiusEdgeRatio", tets,
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
                     "GLGeodesicDistanceFields.BaseTolerance", fields,
                     &vtkGLGeodesicDistanceFields::SetBaseTolerance,
                     &vtkGLGeodesicDistanceFields::GetBaseTolerance));
  t.push_back(number("--base-angle", "DEG", gdf,
                     "max angle between a base face's outward normal and -z",
                     "GLGeodesicDistanceFields.BaseFaceAngle", fields,
                     &vtkGLGeodesicDistanceFields::SetBaseFaceAngle,
                     &vtkGLGeodesicDistanceFields::GetBaseFaceAngle));
  t.push_back(number("--time-factor", "F", gdf, "heat time t = F * h^2 (h = mean edge length)",
                     "GLGeodesicDistanceFields.TimeFactor", fields,
                     &vtkGLGeodesicDistanceFields::SetTimeFactor,
                     &vtkGLGeodesicDistanceFields::GetTimeFactor));
  t.push_back({"--reference", "X,Y,Z", gdf, "reference vector r of Eq. 3 (the lattice directions)",
               "GLGeodesicDistanceFields.ReferenceVector",
               [](P& p, RunOptions&, const std::string& v) {
                 const auto r = parseNumbers("--reference", v, 3, "X,Y,Z");
                 p.GeodesicFields->SetReferenceVector(r[0], r[1], r[2]);
               },
               [](P& p, const RunOptions&) {
                 return text(p.GeodesicFields->GetReferenceVector(), 3);
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
      "GLCurvedLayerSlicer.LayerInterval", slicer, &vtkGLCurvedLayerSlicer::SetLayerInterval,
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
      "GLOverhangAnalysis.ThresholdAngle", overhang, &vtkGLOverhangAnalysis::SetThresholdAngle,
      &vtkGLOverhangAnalysis::GetThresholdAngle));

  t.push_back({"--lattice-width", "MM", latt, "distance between lattice lines, both directions",
               "GLLatticeInfill.AlphaWidth",
               [](P& p, RunOptions&, const std::string& v) {
                 const double w = parseNumber("--lattice-width", v);
                 p.LatticeInfill->SetAlphaWidth(w);
                 p.LatticeInfill->SetBetaWidth(w);
               },
               [](P& p, const RunOptions&) {
                 return text(p.LatticeInfill->GetAlphaWidth());
               }});
  t.push_back(number("--alpha-width", "MM", latt, "distance between alpha lines",
                     "GLLatticeInfill.AlphaWidth", lattice, &vtkGLLatticeInfill::SetAlphaWidth,
                     &vtkGLLatticeInfill::GetAlphaWidth));
  t.push_back(number("--beta-width", "MM", latt, "distance between beta lines",
                     "GLLatticeInfill.BetaWidth", lattice, &vtkGLLatticeInfill::SetBetaWidth,
                     &vtkGLLatticeInfill::GetBetaWidth));
  t.push_back(number("--alpha-phase", "MM", latt, "offset of the alpha levels",
                     "GLLatticeInfill.AlphaPhase", lattice, &vtkGLLatticeInfill::SetAlphaPhase,
                     &vtkGLLatticeInfill::GetAlphaPhase));
  t.push_back(number("--beta-phase", "MM", latt, "offset of the beta levels",
                     "GLLatticeInfill.BetaPhase", lattice, &vtkGLLatticeInfill::SetBetaPhase,
                     &vtkGLLatticeInfill::GetBetaPhase));
  t.push_back(number("--min-subgraph", "MM", latt,
                     "drop connected lattice pieces shorter than this",
                     "GLLatticeInfill.MinimumSubgraphLength", lattice,
                     &vtkGLLatticeInfill::SetMinimumSubgraphLength,
                     &vtkGLLatticeInfill::GetMinimumSubgraphLength));
  t.push_back({"--max-elements", "N", latt,
               "refuse a stage estimated to make more elements: layer points + triangles, "
               "lattice vertices + edges, sub-graph pairs, toolpath stations (40e6 ~ 8 GB)",
               "GLLatticeInfill.MaximumElements",
               [](P& p, RunOptions&, const std::string& v) {
                 const double n = parseNumber("--max-elements", v);
                 if (!(n >= 1)) {
                   throw UsageError("--max-elements must be >= 1 (got " + v + ")");
                 }
                 p.Slicer->SetMaximumElements(n);
                 p.LatticeInfill->SetMaximumElements(n);
                 p.Planner->SetMaximumElements(n);
                 p.Sequencer->SetMaximumElements(n);
               },
               [](P& p, const RunOptions&) {
                 return text(p.LatticeInfill->GetMaximumElements());
               }});

  t.push_back({"--strategy", "NAME", seq,
               "lpt | dpt | a4 | best (best = rollout of a4, never worse)",
               "GLPrintSequencer.Strategy",
               [](P& p, RunOptions&, const std::string& v) {
                 p.Sequencer->SetStrategy(choice("--strategy", v, kStrategies));
               },
               [](P& p, const RunOptions&) {
                 return kStrategies.at(p.Sequencer->GetStrategy());
               }});
  t.push_back(number(
      "--nozzle-angle", "DEG", seq, "half-angle NA of the nozzle's bounding cone, in (0, 90)",
      "GLNozzle.NozzleAngle", nozzle, &vtkGLNozzle::SetNozzleAngle, &vtkGLNozzle::GetNozzleAngle));
  t.push_back(number("--nozzle-length", "MM", seq,
                     "cone length; above it the holder (0 = cone only)", "GLNozzle.NozzleLength",
                     nozzle, &vtkGLNozzle::SetNozzleLength, &vtkGLNozzle::GetNozzleLength));
  t.push_back(number("--holder-radius", "MM", seq,
                     "radius of the holder cylinder above the nozzle length",
                     "GLNozzle.HolderRadius", nozzle, &vtkGLNozzle::SetHolderRadius,
                     &vtkGLNozzle::GetHolderRadius));
  t.push_back(number("--tip-clearance", "MM", seq,
                     "ignore material at most this high above the nozzle tip",
                     "GLNozzle.TipClearance", nozzle, &vtkGLNozzle::SetTipClearance,
                     &vtkGLNozzle::GetTipClearance));
  t.push_back(number("--tip-face-radius", "MM", seq,
                     "ignore material this close to the tip (under the nozzle's\n"
                     "flat face, which presses the bead)",
                     "GLNozzle.TipFaceRadius", nozzle, &vtkGLNozzle::SetTipFaceRadius,
                     &vtkGLNozzle::GetTipFaceRadius));
  t.push_back({"--no-plate", "", seq,
               "the build plate is no obstacle (default: it is, like printed material)",
               "GLNozzle.BuildPlate",
               [](P& p, RunOptions&, const std::string&) { p.Nozzle->SetBuildPlate(false); },
               [](P& p, const RunOptions&) {
                 return std::string(p.Nozzle->GetBuildPlate() ? "obstacle" : "none");
               }});
  t.push_back(number(
      "--plate-margin", "MM", seq, "the build plate extends this far beyond the part's footprint",
      "GLNozzle.PlateMargin", nozzle, &vtkGLNozzle::SetPlateMargin, &vtkGLNozzle::GetPlateMargin));
  t.push_back(number("--plate-thickness", "MM", seq, "thickness of the build plate under z = 0",
                     "GLNozzle.PlateThickness", nozzle, &vtkGLNozzle::SetPlateThickness,
                     &vtkGLNozzle::GetPlateThickness));
  t.push_back({"--sample-spacing", "MM", seq,
               "spacing of the material samples tested for collisions",
               "GLPrintSequencer.SampleSpacing",
               [](P& p, RunOptions&, const std::string& v) {
                 const double s = parseNumber("--sample-spacing", v);
                 p.Sequencer->SetSampleSpacing(s);
                 p.SequenceVerifier->SetSampleSpacing(s);
               },
               [](P& p, const RunOptions&) {
                 return text(p.Sequencer->GetSampleSpacing());
               }});

  t.push_back(number("--path-width", "MM", path, "path (bead) width w",
                     "GLToolpathPlanner.PathWidth", planner, &vtkGLToolpathPlanner::SetPathWidth,
                     &vtkGLToolpathPlanner::GetPathWidth));
  t.push_back(number(
      "--filament-diameter", "MM", path, "raw filament diameter; Eq. 14 uses the radius MM / 2",
      "GLToolpathPlanner.FilamentDiameter", planner, &vtkGLToolpathPlanner::SetFilamentDiameter,
      &vtkGLToolpathPlanner::GetFilamentDiameter));
  t.push_back(number("--flow", "MU", path, "flow correction mu of Eq. 14, in (0, 1]",
                     "GLToolpathPlanner.FlowCorrection", planner,
                     &vtkGLToolpathPlanner::SetFlowCorrection,
                     &vtkGLToolpathPlanner::GetFlowCorrection));
  t.push_back(number("--print-speed", "MM/S", path, "nozzle feed rate of print moves",
                     "GLToolpathPlanner.PrintFeedRate", planner,
                     &vtkGLToolpathPlanner::SetPrintFeedRate,
                     &vtkGLToolpathPlanner::GetPrintFeedRate));
  t.push_back(number("--air-speed", "MM/S", path, "nozzle feed rate of air moves",
                     "GLToolpathPlanner.AirFeedRate", planner,
                     &vtkGLToolpathPlanner::SetAirFeedRate, &vtkGLToolpathPlanner::GetAirFeedRate));
  t.push_back(number(
      "--thickness-cap", "L", path, "layer thickness capped at L x the layer interval (Eq. 15)",
      "GLToolpathPlanner.ThicknessCap", planner, &vtkGLToolpathPlanner::SetThicknessCap,
      &vtkGLToolpathPlanner::GetThicknessCap));
  t.push_back(number(
      "--max-turn", "DEG", path, "largest nozzle axis change between points (rotation steps)",
      "GLToolpathPlanner.MaxTurnAngle", planner, &vtkGLToolpathPlanner::SetMaxTurnAngle,
      &vtkGLToolpathPlanner::GetMaxTurnAngle));
  t.push_back(number("--max-segment", "MM", path, "subdivide longer path segments (0 = never)",
                     "GLToolpathPlanner.MaxSegmentLength", planner,
                     &vtkGLToolpathPlanner::SetMaxSegmentLength,
                     &vtkGLToolpathPlanner::GetMaxSegmentLength));
  t.push_back(number("--max-tilt", "DEG", path,
                     "largest tilt of the nozzle axis off the layer normal where\n"
                     "the normal would hit earlier material (0 = never tilt)",
                     "GLToolpathPlanner.MaxAxisTilt", planner,
                     &vtkGLToolpathPlanner::SetMaxAxisTilt, &vtkGLToolpathPlanner::GetMaxAxisTilt));
  t.push_back(number("--tilt-blend", "MM", path, "path length over which such a tilt fades out",
                     "GLToolpathPlanner.TiltBlendLength", planner,
                     &vtkGLToolpathPlanner::SetTiltBlendLength,
                     &vtkGLToolpathPlanner::GetTiltBlendLength));
  t.push_back(number("--safe-margin", "MM", path, "margin of the safe box air moves travel on",
                     "GLToolpathPlanner.SafeMargin", planner, &vtkGLToolpathPlanner::SetSafeMargin,
                     &vtkGLToolpathPlanner::GetSafeMargin));
  t.push_back(number("--lift", "MM", path, "lift along the axis for a hop onto an upper sub-graph",
                     "GLToolpathPlanner.Lift", planner, &vtkGLToolpathPlanner::SetLift,
                     &vtkGLToolpathPlanner::GetLift));
  t.push_back(number("--retraction", "MM", path,
                     "filament retracted before each air move, primed after it",
                     "GLToolpathPlanner.Retraction", planner, &vtkGLToolpathPlanner::SetRetraction,
                     &vtkGLToolpathPlanner::GetRetraction));
  t.push_back(number("--tooth-length", "MM", path,
                     "support perimeter tooth length along trimmed edges, 0 = 2w",
                     "GLToolpathPlanner.ToothLength", planner,
                     &vtkGLToolpathPlanner::SetToothLength, &vtkGLToolpathPlanner::GetToothLength));
  t.push_back({"--no-perimeter", "", path, "no support perimeter where boundary edges were trimmed",
               "GLToolpathPlanner.SupportPerimeter",
               [](P& p, RunOptions&, const std::string&) { p.Planner->SetSupportPerimeter(false); },
               [](P& p, const RunOptions&) {
                 return std::string(p.Planner->GetSupportPerimeter() ? "perimeter" : "none");
               }});
  t.push_back({"--replay-steps", "N", path,
               "step files of the print replay (toolpath.pvd); fewer for long\n"
               "paths (all steps together <= ~2 million points); 0 = none",
               "",
               [](P&, RunOptions& r, const std::string& v) {
                 r.replaySteps = static_cast<int>(wholeNumber("--replay-steps", v, 0, 9999));
               },
               [](P&, const RunOptions& r) {
                 return text(r.replaySteps);
               }});

  t.push_back({"--robot", "NAME", prog, "ur5 | ur5e", "GLURScriptWriter.Robot",
               [](P& p, RunOptions&, const std::string& v) {
                 choice("--robot", v, {"ur5", "ur5e"});
                 p.ScriptWriter->SetRobot(v.c_str());
               },
               [](P& p, const RunOptions&) {
                 return std::string(p.ScriptWriter->GetRobot());
               }});
  t.push_back({"--nozzle-tip", "X,Y,Z", prog, "nozzle tip position (m, robot base frame)",
               "GLURScriptWriter.NozzleTip",
               [](P& p, RunOptions&, const std::string& v) {
                 const auto x = parseNumbers("--nozzle-tip", v, 3, "X,Y,Z (m)");
                 p.ScriptWriter->SetNozzleTip(x[0], x[1], x[2]);
               },
               [](P& p, const RunOptions&) {
                 return text(p.ScriptWriter->GetNozzleTip(), 3);
               }});
  t.push_back({"--nozzle-axis", "X,Y,Z", prog, "nozzle body direction from the tip into the nozzle",
               "GLURScriptWriter.NozzleAxis",
               [](P& p, RunOptions&, const std::string& v) {
                 const auto x = parseNumbers("--nozzle-axis", v, 3, "X,Y,Z");
                 p.ScriptWriter->SetNozzleAxis(x[0], x[1], x[2]);
               },
               [](P& p, const RunOptions&) {
                 return text(p.ScriptWriter->GetNozzleAxis(), 3);
               }});
  t.push_back({"--part-offset", "M", prog,
               "the platform plate M metres in front of the flange, part z\n"
               "along the flange z (TCP = p[0,0,M,0,0,0])",
               "GLURScriptWriter.PartOnFlange",
               [](P& p, RunOptions& r, const std::string& v) {
                 if (r.partOnFlangeGiven) {
                   throw UsageError("--part-offset and --part-on-flange exclude each other");
                 }
                 p.ScriptWriter->SetPartOnFlange(0, 0, parseNumber("--part-offset", v), 0, 0, 0);
                 r.partOffsetGiven = true;
               },
               [](P& p, const RunOptions&) {
                 return text(p.ScriptWriter->GetPartOnFlange()[2]);
               }});
  t.push_back({"--part-on-flange", "X,Y,Z,RX,RY,RZ", prog,
               "the part (platform) frame on the flange as a URScript pose\n"
               "(m, rotation vector in rad); replaces --part-offset",
               "GLURScriptWriter.PartOnFlange",
               [](P& p, RunOptions& r, const std::string& v) {
                 if (r.partOffsetGiven) {
                   throw UsageError("--part-offset and --part-on-flange exclude each other");
                 }
                 const auto x = parseNumbers("--part-on-flange", v, 6, "X,Y,Z,RX,RY,RZ (m, rad)");
                 p.ScriptWriter->SetPartOnFlange(x[0], x[1], x[2], x[3], x[4], x[5]);
                 r.partOnFlangeGiven = true;
               },
               [](P& p, const RunOptions&) {
                 return text(p.ScriptWriter->GetPartOnFlange(), 6);
               }});
  t.push_back({"--max-script-bytes", "N", prog,
               "split the program into files below N bytes, at air moves\n"
               "(UR controllers reject very large scripts)",
               "GLURScriptWriter.MaxFileBytes",
               [](P& p, RunOptions&, const std::string& v) {
                 p.ScriptWriter->SetMaxFileBytes(
                     static_cast<vtkIdType>(wholeNumber("--max-script-bytes", v, 10000, 1e12)));
               },
               [](P& p, const RunOptions&) {
                 return std::to_string(static_cast<long long>(p.ScriptWriter->GetMaxFileBytes()));
               }});
  t.push_back(number("--speed-factor", "F", prog,
                     "fraction of the joint speed limits used, in (0, 1]",
                     "GLURScriptWriter.SpeedFactor", script, &vtkGLURScriptWriter::SetSpeedFactor,
                     &vtkGLURScriptWriter::GetSpeedFactor));
  t.push_back(
      number("--max-filament-rate", "MM/S", prog, "filament rate at analog output 0 level 1 (10 V)",
             "GLURScriptWriter.MaxFilamentRate", script, &vtkGLURScriptWriter::SetMaxFilamentRate,
             &vtkGLURScriptWriter::GetMaxFilamentRate));
  t.push_back(number("--max-blend", "M", prog, "largest movel blend radius (m)",
                     "GLURScriptWriter.MaxBlend", script, &vtkGLURScriptWriter::SetMaxBlend,
                     &vtkGLURScriptWriter::GetMaxBlend));
  t.push_back(number("--max-joint-step", "DEG", prog,
                     "largest joint change between points; the joint path is\n"
                     "re-planned around larger ones",
                     "GLURScriptWriter.MaxJointStep", script, &vtkGLURScriptWriter::SetMaxJointStep,
                     &vtkGLURScriptWriter::GetMaxJointStep));
  t.push_back(
      {"--no-layout-search", "", prog,
       "do not search another mounting of the part on the flange when\n"
       "the robot cannot follow the path as laid out",
       "GLURScriptWriter.SearchCellLayout",
       [](P& p, RunOptions&, const std::string&) { p.ScriptWriter->SetSearchCellLayout(false); },
       [](P& p, const RunOptions&) {
         return std::string(p.ScriptWriter->GetSearchCellLayout() ? "search" : "off");
       }});
  t.push_back(
      {"--allow-unreachable", "", prog,
       "write the program even if points are unreachable (the robot\n"
       "holds still there; for simulation). Default: no program",
       "GLURScriptWriter.AllowUnreachable",
       [](P& p, RunOptions&, const std::string&) { p.ScriptWriter->SetAllowUnreachable(true); },
       [](P& p, const RunOptions&) {
         return std::string(p.ScriptWriter->GetAllowUnreachable() ? "on" : "off");
       }});
  t.push_back(
      {"--gcode", "KIN", prog, "5-axis G-code table kinematics: ac | bc | none",
       "GLGCodeWriter.Kinematics",
       [](P& p, RunOptions& r, const std::string& v) {
         const int k = choice("--gcode", v, {"ac", "bc", "none"});
         r.gcode = k != 2;
         if (k != 2) {
           p.GCodeWriter->SetKinematics(k);
         }
       },
       [](P& p, const RunOptions& r) {
         return std::string(!r.gcode ? "none" : p.GCodeWriter->GetKinematics() ? "bc" : "ac");
       }});
  t.push_back({"--gcode-flavor", "NAME", prog,
               "linuxcnc | reprap: LinuxCNC RS274NGC (G93, extruder axis) or\n"
               "RepRapFirmware 3 (M83, E, mm/min; needs --gcode-tcp cam)",
               "GLGCodeWriter.Flavor",
               [](P& p, RunOptions&, const std::string& v) {
                 p.GCodeWriter->SetFlavor(choice("--gcode-flavor", v, {"linuxcnc", "reprap"}));
               },
               [](P& p, const RunOptions&) {
                 return std::string(p.GCodeWriter->GetFlavor() ? "reprap" : "linuxcnc");
               }});
  t.push_back({"--gcode-tcp", "WHO", prog,
               "controller | cam: the controller's table kinematics turns part\n"
               "coordinates into joints (LinuxCNC trt kins), or machine\n"
               "coordinates are pre-computed here",
               "GLGCodeWriter.ToolCentrePoint",
               [](P& p, RunOptions&, const std::string& v) {
                 p.GCodeWriter->SetToolCentrePoint(choice("--gcode-tcp", v, {"controller", "cam"}));
               },
               [](P& p, const RunOptions&) {
                 return std::string(p.GCodeWriter->GetToolCentrePoint() ? "cam" : "controller");
               }});
  t.push_back({"--extrusion-axis", "LETTER", prog,
               "linuxcnc: the extruder's axis letter (U, V, W or the free rotary\n"
               "letter of the table)",
               "GLGCodeWriter.ExtrusionAxis",
               [](P& p, RunOptions&, const std::string& v) {
                 if (v.size() != 1 || !std::isalpha(static_cast<unsigned char>(v[0]))) {
                   throw UsageError("--extrusion-axis expects one axis letter, got '" + v + "'");
                 }
                 const std::string upper(1, static_cast<char>(std::toupper(v[0])));
                 p.GCodeWriter->SetExtrusionAxis(upper.c_str());
               },
               [](P& p, const RunOptions&) {
                 return std::string(p.GCodeWriter->GetExtrusionAxis());
               }});
  t.push_back({"--gcode-pivot", "X,Y,Z", prog,
               "machine position of the rotary axes' intersection (mm)", "GLGCodeWriter.Pivot",
               [](P& p, RunOptions&, const std::string& v) {
                 const auto x = parseNumbers("--gcode-pivot", v, 3, "X,Y,Z (mm)");
                 p.GCodeWriter->SetPivot(x[0], x[1], x[2]);
               },
               [](P& p, const RunOptions&) {
                 return text(p.GCodeWriter->GetPivot(), 3);
               }});
  t.push_back({"--gcode-offset", "X,Y,Z", prog,
               "part frame origin relative to the rotary centre (mm)", "GLGCodeWriter.PartOffset",
               [](P& p, RunOptions&, const std::string& v) {
                 const auto x = parseNumbers("--gcode-offset", v, 3, "X,Y,Z (mm)");
                 p.GCodeWriter->SetPartOffset(x[0], x[1], x[2]);
               },
               [](P& p, const RunOptions&) {
                 return text(p.GCodeWriter->GetPartOffset(), 3);
               }});
  t.push_back({"--tilt-limits", "MIN,MAX", prog, "limits of the tilt axis A or B (degrees)",
               "GLGCodeWriter.TiltLimits",
               [](P& p, RunOptions&, const std::string& v) {
                 const auto x = parseNumbers("--tilt-limits", v, 2, "MIN,MAX (degrees)");
                 p.GCodeWriter->SetTiltLimits(x[0], x[1]);
               },
               [](P& p, const RunOptions&) {
                 return text(p.GCodeWriter->GetTiltLimits(), 2);
               }});
  return t;
}

const CliOption* findOption(const std::string& flag) {
  const std::string name = flag == "--output" ? "-o" : flag == "--quiet" ? "-q" : flag;
  for (const CliOption& o : runOptionTable()) {
    if (name == o.flag) {
      return &o;
    }
  }
  return nullptr;
}

}  // namespace

const std::vector<CliOption>& runOptionTable() {
  static const std::vector<CliOption> table = makeTable();
  return table;
}

void parseRunArguments(int argc, char** argv, GLPrintPipeline& pipeline, RunOptions& run) {
  if (argc < 2) {
    throw UsageError("missing command (try --help)");
  }
  if (std::string(argv[1]) != "run") {
    throw UsageError("unknown command '" + std::string(argv[1]) + "' (try --help)");
  }
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    if (const CliOption* o = findOption(arg)) {
      std::string value;
      if (*o->value) {
        if (i + 1 >= argc) {
          throw UsageError(arg + " needs a value");
        }
        value = argv[++i];
      }
      o->set(pipeline, run, value);
    } else if (!arg.empty() && arg[0] == '-') {
      throw UsageError("unknown option " + arg);
    } else if (run.model.empty()) {
      run.model = arg;
    } else {
      throw UsageError("unexpected argument '" + arg + "'");
    }
  }
  if (run.model.empty()) {
    throw UsageError("missing MODEL");
  }
  if (run.outDir.empty()) {
    throw UsageError("missing -o OUTDIR");
  }
  if (!run.firstLayerGiven) {
    pipeline.Slicer->SetFirstLayerOffset(pipeline.Slicer->GetLayerInterval());
  }
}

std::string usageText() {
  GLPrintPipeline defaults;
  const RunOptions run;
  std::ostringstream s;
  const char* section = "";
  for (const CliOption& o : runOptionTable()) {
    if (std::string(section) != o.section) {
      section = o.section;
      s << " " << section << ":\n";
    }
    std::string head = std::string("  ") + o.flag + (*o.value ? std::string(" ") + o.value : "");
    if (std::string(o.flag) == "-o") {
      head = "  -o, --output DIR";
    }
    std::stringstream help(o.help);
    std::string line;
    bool first = true;
    while (std::getline(help, line)) {
      s << (first ? head : std::string())
        << std::string(first && head.size() < 26 ? 26 - head.size()
                       : first                   ? 1
                                                 : 26,
                       ' ')
        << line;
      first = false;
      if (help.peek() != EOF) {
        s << "\n";
      }
    }
    const std::string value = o.current(defaults, run);
    if (!value.empty() && std::string(o.flag) != "-o") {
      s << "  [" << value << "]";
    }
    s << "\n";
  }
  return s.str();
}

std::string optionListing() {
  GLPrintPipeline defaults;
  const RunOptions run;
  std::ostringstream s;
  for (const CliOption& o : runOptionTable()) {
    s << o.flag << '\t' << o.property << '\t' << o.current(defaults, run) << '\n';
  }
  return s.str();
}

std::string withFlagNames(const std::string& message) {
  std::string out = message;
  for (const CliOption& o : runOptionTable()) {
    const size_t dot = o.property.find('.');
    if (dot == std::string::npos || o.flag[0] != '-' || o.flag[1] != '-') {
      continue;
    }
    const std::string property = o.property.substr(dot + 1);
    // The first flag that sets a property names it (e.g. AlphaWidth -> --lattice-width is listed
    // first, but --alpha-width is the exact one: prefer an option whose flag spells the property).
    out = std::regex_replace(out, std::regex("\\b" + property + "\\b"), o.flag);
  }
  return out;
}

}  // namespace geolattice
