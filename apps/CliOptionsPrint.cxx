// The options of the lattice, the print sequence and its nozzle, and the toolpath.
#include "CliOptionTable.h"
#include "ToolpathOutput.h"

namespace geolattice::cli {

void addPrintOptions(std::vector<CliOption>& t) {
  const char* latt = "Lattice infill (iso-lines of Alpha and Beta on each layer, Algorithm 1)";
  const char* seq = "Printing sequence (skeleton tree, Section 3.1) and the nozzle";
  const char* path = "Toolpath (Section 3.2: Euler tours, thickness Eq. 15, extrusion Eq. 14)";
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
                     "GLLatticeInfill.AlphaWidth", &P::LatticeInfill,
                     &vtkGLLatticeInfill::SetAlphaWidth, &vtkGLLatticeInfill::GetAlphaWidth));
  t.push_back(number("--beta-width", "MM", latt, "distance between beta lines",
                     "GLLatticeInfill.BetaWidth", &P::LatticeInfill,
                     &vtkGLLatticeInfill::SetBetaWidth, &vtkGLLatticeInfill::GetBetaWidth));
  t.push_back(number("--alpha-phase", "MM", latt, "offset of the alpha levels",
                     "GLLatticeInfill.AlphaPhase", &P::LatticeInfill,
                     &vtkGLLatticeInfill::SetAlphaPhase, &vtkGLLatticeInfill::GetAlphaPhase));
  t.push_back(number("--beta-phase", "MM", latt, "offset of the beta levels",
                     "GLLatticeInfill.BetaPhase", &P::LatticeInfill,
                     &vtkGLLatticeInfill::SetBetaPhase, &vtkGLLatticeInfill::GetBetaPhase));
  t.push_back(number("--min-subgraph", "MM", latt,
                     "drop connected lattice pieces shorter than this",
                     "GLLatticeInfill.MinimumSubgraphLength", &P::LatticeInfill,
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
               "lpt | dpt | a4 | best (best = rollout of a4, never worse; with --orient\n"
               "auto, when its toolpath collides, the lpt and dpt orders are tried through\n"
               "the toolpath and the one that collides least is printed)",
               "GLPrintSequencer.Strategy",
               [](P& p, RunOptions&, const std::string& v) {
                 p.Sequencer->SetStrategy(choice("--strategy", v, kStrategies));
               },
               [](P& p, const RunOptions&) {
                 return kStrategies.at(p.Sequencer->GetStrategy());
               }});
  t.push_back(integer("--split-rounds", "N", seq,
                      "rounds of splitting sub-graphs that block each other into pieces\n"
                      "(a4, best; 0 = never split)",
                      "GLPrintSequencer.SplitRounds", &P::Sequencer,
                      &vtkGLPrintSequencer::SetSplitRounds, &vtkGLPrintSequencer::GetSplitRounds, 0,
                      100));
  t.push_back(number("--nozzle-angle", "DEG", seq,
                     "half-angle NA of the nozzle's bounding cone, in (0, 90)",
                     "GLNozzle.NozzleAngle", &P::Nozzle, &vtkGLNozzle::SetNozzleAngle,
                     &vtkGLNozzle::GetNozzleAngle));
  t.push_back(number("--nozzle-length", "MM", seq,
                     "cone length; above it the holder (0 = cone only)", "GLNozzle.NozzleLength",
                     &P::Nozzle, &vtkGLNozzle::SetNozzleLength, &vtkGLNozzle::GetNozzleLength));
  t.push_back(number("--holder-radius", "MM", seq,
                     "radius of the holder cylinder above the nozzle length",
                     "GLNozzle.HolderRadius", &P::Nozzle, &vtkGLNozzle::SetHolderRadius,
                     &vtkGLNozzle::GetHolderRadius));
  t.push_back(
      number("--holder-length", "MM", seq,
             "holder length above the nozzle length: the printhead ends there (0 = unbounded)",
             "GLNozzle.HolderLength", &P::Nozzle, &vtkGLNozzle::SetHolderLength,
             &vtkGLNozzle::GetHolderLength));
  t.push_back(number("--tip-clearance", "MM", seq,
                     "ignore material at most this high above the nozzle tip",
                     "GLNozzle.TipClearance", &P::Nozzle, &vtkGLNozzle::SetTipClearance,
                     &vtkGLNozzle::GetTipClearance));
  t.push_back(number("--tip-face-radius", "MM", seq,
                     "ignore material this close to the tip (under the nozzle's\n"
                     "flat face, which presses the bead)",
                     "GLNozzle.TipFaceRadius", &P::Nozzle, &vtkGLNozzle::SetTipFaceRadius,
                     &vtkGLNozzle::GetTipFaceRadius));
  t.push_back(number("--face-contact", "MM", seq,
                     "with --printhead: ignore neighbouring beads at most this high above\n"
                     "the tip under the face's rim (within its radius + MM of the axis)",
                     "GLNozzle.FaceContact", &P::Nozzle, &vtkGLNozzle::SetFaceContact,
                     &vtkGLNozzle::GetFaceContact));
  t.push_back(toggle("--no-plate", seq,
                     "the build plate is no obstacle (default: it is, like printed material)",
                     "GLNozzle.BuildPlate", &P::Nozzle, &vtkGLNozzle::SetBuildPlate,
                     &vtkGLNozzle::GetBuildPlate, false, "obstacle", "none"));
  t.push_back(number("--plate-margin", "MM", seq,
                     "the build plate extends this far beyond the part's footprint",
                     "GLNozzle.PlateMargin", &P::Nozzle, &vtkGLNozzle::SetPlateMargin,
                     &vtkGLNozzle::GetPlateMargin));
  t.push_back(number("--plate-thickness", "MM", seq, "thickness of the build plate under z = 0",
                     "GLNozzle.PlateThickness", &P::Nozzle, &vtkGLNozzle::SetPlateThickness,
                     &vtkGLNozzle::GetPlateThickness));
  t.push_back({"--printhead", "FILE", seq,
               "printhead mesh (.stl .obj .ply .vtp .off; tip at the origin, axis +z,\n"
               "mm) instead of the cone and holder, e.g. testdata/printhead_slim.obj",
               "GLNozzle.PrintheadFile",
               [](P& p, RunOptions&, const std::string& v) {
                 if (v.empty()) {
                   throw UsageError("--printhead needs a file name");
                 }
                 p.Nozzle->SetPrintheadFile(v.c_str());
               },
               [](P& p, const RunOptions&) {
                 const char* f = p.Nozzle->GetPrintheadFile();
                 return std::string(f && *f ? f : "none");
               }});
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
                     "GLToolpathPlanner.PathWidth", &P::Planner,
                     &vtkGLToolpathPlanner::SetPathWidth, &vtkGLToolpathPlanner::GetPathWidth));
  t.push_back(number(
      "--filament-diameter", "MM", path, "raw filament diameter; Eq. 14 uses the radius MM / 2",
      "GLToolpathPlanner.FilamentDiameter", &P::Planner, &vtkGLToolpathPlanner::SetFilamentDiameter,
      &vtkGLToolpathPlanner::GetFilamentDiameter));
  t.push_back(number("--flow", "MU", path, "flow correction mu of Eq. 14, in (0, 1]",
                     "GLToolpathPlanner.FlowCorrection", &P::Planner,
                     &vtkGLToolpathPlanner::SetFlowCorrection,
                     &vtkGLToolpathPlanner::GetFlowCorrection));
  t.push_back(number("--print-speed", "MM/S", path, "nozzle feed rate of print moves",
                     "GLToolpathPlanner.PrintFeedRate", &P::Planner,
                     &vtkGLToolpathPlanner::SetPrintFeedRate,
                     &vtkGLToolpathPlanner::GetPrintFeedRate));
  t.push_back(number("--air-speed", "MM/S", path, "nozzle feed rate of air moves",
                     "GLToolpathPlanner.AirFeedRate", &P::Planner,
                     &vtkGLToolpathPlanner::SetAirFeedRate, &vtkGLToolpathPlanner::GetAirFeedRate));
  t.push_back(number(
      "--thickness-cap", "L", path, "layer thickness capped at L x the layer interval (Eq. 15)",
      "GLToolpathPlanner.ThicknessCap", &P::Planner, &vtkGLToolpathPlanner::SetThicknessCap,
      &vtkGLToolpathPlanner::GetThicknessCap));
  t.push_back(number(
      "--max-turn", "DEG", path, "largest nozzle axis change between points (rotation steps)",
      "GLToolpathPlanner.MaxTurnAngle", &P::Planner, &vtkGLToolpathPlanner::SetMaxTurnAngle,
      &vtkGLToolpathPlanner::GetMaxTurnAngle));
  t.push_back(number("--max-segment", "MM", path, "subdivide longer path segments (0 = never)",
                     "GLToolpathPlanner.MaxSegmentLength", &P::Planner,
                     &vtkGLToolpathPlanner::SetMaxSegmentLength,
                     &vtkGLToolpathPlanner::GetMaxSegmentLength));
  t.push_back(number("--max-tilt", "DEG", path,
                     "largest tilt of the nozzle axis off the layer normal where\n"
                     "the normal would hit earlier material (0 = never tilt)",
                     "GLToolpathPlanner.MaxAxisTilt", &P::Planner,
                     &vtkGLToolpathPlanner::SetMaxAxisTilt, &vtkGLToolpathPlanner::GetMaxAxisTilt));
  t.push_back(number("--tilt-blend", "MM", path, "path length over which such a tilt fades out",
                     "GLToolpathPlanner.TiltBlendLength", &P::Planner,
                     &vtkGLToolpathPlanner::SetTiltBlendLength,
                     &vtkGLToolpathPlanner::GetTiltBlendLength));
  t.push_back(number("--safe-margin", "MM", path, "margin of the safe box air moves travel on",
                     "GLToolpathPlanner.SafeMargin", &P::Planner,
                     &vtkGLToolpathPlanner::SetSafeMargin, &vtkGLToolpathPlanner::GetSafeMargin));
  t.push_back(number("--lift", "MM", path, "lift along the axis for a hop onto an upper sub-graph",
                     "GLToolpathPlanner.Lift", &P::Planner, &vtkGLToolpathPlanner::SetLift,
                     &vtkGLToolpathPlanner::GetLift));
  t.push_back(number("--retraction", "MM", path,
                     "filament retracted before each air move, primed after it",
                     "GLToolpathPlanner.Retraction", &P::Planner,
                     &vtkGLToolpathPlanner::SetRetraction, &vtkGLToolpathPlanner::GetRetraction));
  t.push_back(number("--tooth-length", "MM", path,
                     "support perimeter tooth length along trimmed edges, 0 = 2w",
                     "GLToolpathPlanner.ToothLength", &P::Planner,
                     &vtkGLToolpathPlanner::SetToothLength, &vtkGLToolpathPlanner::GetToothLength));
  t.push_back(toggle(
      "--no-perimeter", path, "no support perimeter where boundary edges were trimmed",
      "GLToolpathPlanner.SupportPerimeter", &P::Planner, &vtkGLToolpathPlanner::SetSupportPerimeter,
      &vtkGLToolpathPlanner::GetSupportPerimeter, false, "perimeter", "none"));
  t.push_back({"--replay-steps", "N", path,
               "steps of the print replay (toolpath.pvd: step k adds the piece\n"
               "printed between progress (k-1)/N and k/N; all pieces together\n"
               "are the toolpath's size); at most 500; 0 = none",
               "",
               [](P&, RunOptions& r, const std::string& v) {
                 r.replaySteps =
                     static_cast<int>(wholeNumber("--replay-steps", v, 0, kMaxReplaySteps));
               },
               [](P&, const RunOptions& r) {
                 return text(r.replaySteps);
               }});
}

}  // namespace geolattice::cli
