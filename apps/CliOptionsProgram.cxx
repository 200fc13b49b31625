// The options of the machine programs: the UR5 cell (URScript) and the 5-axis G-code.
#include "CliOptionTable.h"

namespace geolattice::cli {

void addProgramOptions(std::vector<CliOption>& t) {
  const char* prog =
      "Programs (Section 4: the robot holds the part under a fixed nozzle; robot cell in mm)";
  t.push_back({"--robot", "NAME", prog, "ur5 | ur5e", "GLURScriptWriter.Robot",
               [](P& p, RunOptions&, const std::string& v) {
                 choice("--robot", v, {"ur5", "ur5e"});
                 p.ScriptWriter->SetRobot(v.c_str());
               },
               [](P& p, const RunOptions&) {
                 return std::string(p.ScriptWriter->GetRobot());
               }});
  t.push_back({"--nozzle-tip", "X,Y,Z", prog, "nozzle tip position (mm, robot base frame)",
               "GLURScriptWriter.NozzleTip",
               [](P& p, RunOptions&, const std::string& v) {
                 const auto x = parseNumbers("--nozzle-tip", v, 3, "X,Y,Z (mm)");
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
  t.push_back({"--part-offset", "MM", prog,
               "the platform plate MM in front of the flange, part z\n"
               "along the flange z (TCP = p[0,0,MM/1000,0,0,0])",
               "GLURScriptWriter.PartOnFlangePosition",
               [](P& p, RunOptions& r, const std::string& v) {
                 if (r.partOnFlangeGiven) {
                   throw UsageError("--part-offset and --part-on-flange exclude each other");
                 }
                 p.ScriptWriter->SetPartOnFlangePosition(0, 0, parseNumber("--part-offset", v));
                 p.ScriptWriter->SetPartOnFlangeRotation(0, 0, 0);
                 r.partOffsetGiven = true;
               },
               [](P& p, const RunOptions&) {
                 return text(p.ScriptWriter->GetPartOnFlangePosition()[2]);
               }});
  t.push_back({"--part-on-flange", "X,Y,Z,RX,RY,RZ", prog,
               "the part (platform) frame on the flange: position (mm) and\n"
               "rotation vector (deg); replaces --part-offset",
               "GLURScriptWriter.PartOnFlangePosition+PartOnFlangeRotation",
               [](P& p, RunOptions& r, const std::string& v) {
                 if (r.partOffsetGiven) {
                   throw UsageError("--part-offset and --part-on-flange exclude each other");
                 }
                 const auto x = parseNumbers("--part-on-flange", v, 6, "X,Y,Z,RX,RY,RZ (mm, deg)");
                 p.ScriptWriter->SetPartOnFlangePosition(x[0], x[1], x[2]);
                 p.ScriptWriter->SetPartOnFlangeRotation(x[3], x[4], x[5]);
                 r.partOnFlangeGiven = true;
               },
               [](P& p, const RunOptions&) {
                 return text(p.ScriptWriter->GetPartOnFlangePosition(), 3) + "," +
                        text(p.ScriptWriter->GetPartOnFlangeRotation(), 3);
               }});
  t.push_back(integer("--max-script-bytes", "N", prog,
                      "split the program into files below N bytes, at air moves\n"
                      "(UR controllers reject very large scripts)",
                      "GLURScriptWriter.MaxFileBytes", &P::ScriptWriter,
                      &vtkGLURScriptWriter::SetMaxFileBytes, &vtkGLURScriptWriter::GetMaxFileBytes,
                      10000, 1e12));
  t.push_back(number("--speed-factor", "F", prog,
                     "fraction of the joint speed limits used, in (0, 1]",
                     "GLURScriptWriter.SpeedFactor", &P::ScriptWriter,
                     &vtkGLURScriptWriter::SetSpeedFactor, &vtkGLURScriptWriter::GetSpeedFactor));
  t.push_back(
      number("--max-filament-rate", "MM/S", prog, "filament rate at analog output 0 level 1 (10 V)",
             "GLURScriptWriter.MaxFilamentRate", &P::ScriptWriter,
             &vtkGLURScriptWriter::SetMaxFilamentRate, &vtkGLURScriptWriter::GetMaxFilamentRate));
  t.push_back(number("--max-blend", "MM", prog, "largest movel blend radius (mm)",
                     "GLURScriptWriter.MaxBlend", &P::ScriptWriter,
                     &vtkGLURScriptWriter::SetMaxBlend, &vtkGLURScriptWriter::GetMaxBlend));
  t.push_back(number("--max-joint-step", "DEG", prog,
                     "largest joint change between points; the joint path is\n"
                     "re-planned around larger ones",
                     "GLURScriptWriter.MaxJointStep", &P::ScriptWriter,
                     &vtkGLURScriptWriter::SetMaxJointStep, &vtkGLURScriptWriter::GetMaxJointStep));
  t.push_back(toggle("--no-layout-search", prog,
                     "do not search another mounting of the part on the flange when\n"
                     "the robot cannot follow the path as laid out",
                     "GLURScriptWriter.SearchCellLayout", &P::ScriptWriter,
                     &vtkGLURScriptWriter::SetSearchCellLayout,
                     &vtkGLURScriptWriter::GetSearchCellLayout, false, "search", "off"));
  t.push_back(toggle("--no-reconfiguration", prog,
                     "do not change the robot's configuration at air moves (away from\n"
                     "the part) when one IK branch cannot follow the whole path",
                     "GLURScriptWriter.Reconfigure", &P::ScriptWriter,
                     &vtkGLURScriptWriter::SetReconfigure, &vtkGLURScriptWriter::GetReconfigure,
                     false));
  t.push_back(toggle("--allow-unreachable", prog,
                     "write the program even if points are unreachable (the robot\n"
                     "holds still there; for simulation). Default: no program",
                     "GLURScriptWriter.AllowUnreachable", &P::ScriptWriter,
                     &vtkGLURScriptWriter::SetAllowUnreachable,
                     &vtkGLURScriptWriter::GetAllowUnreachable, true));
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
}

}  // namespace geolattice::cli
