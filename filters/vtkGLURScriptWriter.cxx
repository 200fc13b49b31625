#include "vtkGLURScriptWriter.h"

#include "GLPrintheadFile.h"
#include "vtkGLMeshConversion.h"
#include "vtkGLNozzle.h"
#include "vtkGLOutputFiles.h"
#include "vtkGLParallel.h"
#include "vtkGLProgress.h"
#include "vtkGLRequest.h"

#include "common/Error.h"
#include "program/URScriptWriter.h"
#include "robot/CellLayout.h"
#include "robot/Pose.h"
#include "robot/RobotPathSolver.h"

#include <vtkDemandDrivenPipeline.h>
#include <vtkErrorCode.h>
#include <vtkInformation.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include <algorithm>
#include <array>
#include <memory>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <sstream>

vtkStandardNewMacro(vtkGLURScriptWriter);

namespace {
namespace gl = geolattice;

/// The panel is in mm (like every filter); URScript is in metres.
constexpr double kMillimetresPerMetre = 1000.0;

bool allFinite(const double* v, int n) {
  return std::all_of(v, v + n, [](double x) { return std::isfinite(x); });
}

/// m: the arm's surfaces keep this from the nozzle's axis for a printhead of `radius` mm.
double linkNozzleClearanceFor(double radius) {
  return radius / kMillimetresPerMetre + gl::kLinkNozzleMargin;
}

/// "N of M toolpath points are unreachable … (first: a, b, …)".
std::string describeUnreachable(const std::vector<vtkIdType>& unreachable, size_t points,
                                const std::string& robot, const std::string& nozzleClearance) {
  std::ostringstream s;
  s << unreachable.size() << " of " << points << " toolpath points are unreachable for the "
    << robot << " in this cell (out of reach, past a joint limit, or reached only with the arm "
    << "or the part lower than " << kMillimetresPerMetre * gl::RobotPathOptions{}.floorClearance
    << " mm above the floor it stands on, or with the arm nearer than " << nozzleClearance
    << " to the nozzle's axis or nearer than "
    << kMillimetresPerMetre * gl::RobotPathOptions{}.linkPartClearance
    << " mm to the part it holds; first: ";
  const size_t shown = std::min<size_t>(unreachable.size(), 10);
  for (size_t i = 0; i < shown; ++i) {
    s << (i ? ", " : "") << unreachable[i];
  }
  s << (unreachable.size() > shown ? ", ...)" : ")");
  return s.str();
}
}  // namespace

vtkGLURScriptWriter::vtkGLURScriptWriter() {
  // The defaults live in core: the cell, the program and the path solver options.
  const gl::RobotCell cell;
  const gl::URScriptOptions program;
  this->SetRobot(cell.robot.name.c_str());
  const gl::UrPose pose = gl::toUrPose(cell.partOnFlange);
  for (int k = 0; k < 3; ++k) {
    this->NozzleTip[k] = kMillimetresPerMetre * cell.nozzleTip[k];
    this->NozzleAxis[k] = cell.nozzleAxis[k];
    this->PartOnFlangePosition[k] = kMillimetresPerMetre * pose[k];
    this->PartOnFlangeRotation[k] = pose[k + 3] * 180.0 / M_PI;
  }
  this->MaxFileBytes = static_cast<vtkIdType>(program.maxFileBytes);
  this->SpeedFactor = program.speedFactor;
  this->MaxFilamentRate = program.maxFilamentRate;
  this->MaxBlend = kMillimetresPerMetre * program.maxBlend;
  this->MaxJointStep = gl::RobotPathOptions{}.maxJointStepDeg;
  this->AllowUnreachable = false;
  this->SearchCellLayout = gl::CellLayoutOptions{}.search;
  this->Reconfigure = gl::RobotPathOptions{}.reconfigure;
  this->PrintheadRadius = kMillimetresPerMetre * gl::kPrintheadRadius;
}

vtkGLURScriptWriter::~vtkGLURScriptWriter() {
  this->SetRobot(nullptr);
}

void vtkGLURScriptWriter::SetNozzle(vtkGLNozzle* nozzle) {
  if (this->Nozzle != nozzle) {
    this->Nozzle = nozzle;
    this->Modified();
  }
}

gl::RobotPathOptions vtkGLURScriptWriter::PathOptions() const {
  gl::RobotPathOptions o;
  o.maxJointStepDeg = this->MaxJointStep;
  o.reconfigure = this->Reconfigure != 0;
  o.linkNozzleClearance = linkNozzleClearanceFor(this->PrintheadRadiusUsed);
  o.nozzleSections = this->NozzleSectionsUsed;
  return o;
}

double vtkGLURScriptWriter::TallestPart() {
  try {
    this->UsePrinthead();
    return gl::tallestPart(this->MakeCell(), this->PathOptions());
  } catch (const std::exception&) {
    return 0.0;  // the writer's own run (and the nozzle's) report the bad parameter
  }
}

void vtkGLURScriptWriter::UsePrinthead() {
  const char* file = this->Nozzle ? this->Nozzle->GetPrintheadFile() : nullptr;
  this->PrintheadRadiusUsed = this->PrintheadRadius;
  this->NozzleSectionsUsed.clear();
  if (file && *file) {
    const auto head = gl::readPrintheadFile(file);
    this->PrintheadRadiusUsed = head->maxRadius();
    this->NozzleSectionsUsed = gl::nozzleSectionsFor(*head, gl::kLinkNozzleMargin);
  }
}

std::string vtkGLURScriptWriter::ProgramFileName(const std::string& fileName, int k) {
  if (k <= 0) {
    return fileName;
  }
  const std::filesystem::path p(fileName);
  return (p.parent_path() / (p.stem().string() + "_" + std::to_string(k) + p.extension().string()))
      .string();
}

std::string vtkGLURScriptWriter::ProgramName(const std::string& fileName) {
  std::string name = std::filesystem::path(fileName).stem().string();
  for (char& c : name) {
    const unsigned char u = static_cast<unsigned char>(c);
    c = std::isalnum(u) && u < 128 ? static_cast<char>(std::tolower(u)) : '_';
  }
  if (name.empty() || !(name[0] >= 'a' && name[0] <= 'z')) {
    name = "p_" + name;
  }
  return name;
}

std::string vtkGLURScriptWriter::GetFileWritten(int k) const {
  return k >= 0 && k < this->GetNumberOfFilesWritten() ? this->FilesWritten[k] : std::string();
}

const vtkGLURScriptWriter::ReconfigurationResult& vtkGLURScriptWriter::ReconfigurationAt(
    int k) const {
  static const ReconfigurationResult none;
  return k >= 0 && k < this->GetNumberOfReconfigurations() ? this->Reconfigurations[k] : none;
}

vtkIdType vtkGLURScriptWriter::GetUnreachablePoint(vtkIdType i) const {
  return i >= 0 && i < this->GetUnreachableCount() ? this->Unreachable[i] : -1;
}

void vtkGLURScriptWriter::ResetResults() {
  this->FilesWritten.clear();
  this->Unreachable.clear();
  this->Reconfigurations.clear();
  this->NumberOfWaypoints = 0;
  this->NumberOfMoves = 0;
  this->MaxJointStepDeg = 0;
  this->LargeJointSteps = 0;
  this->ViaSegments = 0;
  this->ViaWaypoints = 0;
  this->LayoutChanged = false;
  this->LayoutRotationDeg = 0;
  this->LayoutOffsetAdded = 0;
  this->LayoutsTried = 0;
  std::copy(this->PartOnFlangePosition, this->PartOnFlangePosition + 3, this->UsedPartOnFlange);
  std::copy(this->PartOnFlangeRotation, this->PartOnFlangeRotation + 3, this->UsedPartOnFlange + 3);
  this->MaxTipError = 0;
  this->MaxAxisErrorDeg = 0;
  this->MaxJointSpeedDegS = 0;
  std::fill(this->MinSingularity, this->MinSingularity + 3, 0.0);
  this->LowestArmHeight = 0;
  this->LowestPartHeight = 0;
  this->MinLinkNozzleDistance = 0;
  this->MinLinkPartDistance = 0;
  this->Duration = 0;
  this->MaxLineLength = 0;
  this->IKBranch = -1;
  this->SolveSeconds = 0;
}

void vtkGLURScriptWriter::CheckParameters() {
  gl::robotModelByName(this->Robot ? this->Robot : "");  // throws for an unknown robot
  if (!allFinite(this->NozzleTip, 3)) {
    throw gl::GeoLatticeError("URScript writer: the nozzle tip must be finite");
  }
  // The cell is in millimetres: a tip within 50 mm of the base origin is inside the robot's base,
  // most likely metres typed where millimetres are asked.
  const Eigen::Vector3d tip(this->NozzleTip[0], this->NozzleTip[1], this->NozzleTip[2]);
  if (tip.norm() < 50.0) {
    std::ostringstream s;
    s << "URScript writer: the nozzle tip (" << tip.x() << ", " << tip.y() << ", " << tip.z()
      << ") mm is inside the robot's base; the cell is in millimetres (e.g. 0, -400, 350, not "
         "0, -0.4, 0.3)";
    throw gl::GeoLatticeError(s.str());
  }
  const Eigen::Vector3d axis(this->NozzleAxis[0], this->NozzleAxis[1], this->NozzleAxis[2]);
  if (!axis.allFinite() || !(axis.norm() > 1e-12)) {
    throw gl::GeoLatticeError("URScript writer: the nozzle axis must be a finite, non-zero vector");
  }
  if (!allFinite(this->PartOnFlangePosition, 3) || !allFinite(this->PartOnFlangeRotation, 3)) {
    throw gl::GeoLatticeError("URScript writer: the part-on-flange pose must be finite");
  }
  if (!(this->PrintheadRadius > 0 && this->PrintheadRadius < 1000)) {
    throw gl::GeoLatticeError("URScript writer: PrintheadRadius must be in (0, 1000) mm (got " +
                              std::to_string(this->PrintheadRadius) + ")");
  }
  this->UsePrinthead();  // reads the nozzle's file, if any
  // The program options (checked with the property names; the core checks them again).
  if (this->MaxFileBytes < 10000) {
    throw gl::GeoLatticeError(
        "URScript writer: the maximum file size must be >= 10000 bytes (got " +
        std::to_string(this->MaxFileBytes) + ")");
  }
  if (!(this->SpeedFactor > 0 && this->SpeedFactor <= 1)) {
    throw gl::GeoLatticeError("URScript writer: the speed factor must be in (0, 1] (got " +
                              std::to_string(this->SpeedFactor) + ")");
  }
  if (!(this->MaxFilamentRate > 0) || !std::isfinite(this->MaxFilamentRate)) {
    throw gl::GeoLatticeError("URScript writer: the maximum filament rate must be > 0 mm/s (got " +
                              std::to_string(this->MaxFilamentRate) + ")");
  }
  if (!(this->MaxBlend >= 0) || !std::isfinite(this->MaxBlend)) {
    throw gl::GeoLatticeError("URScript writer: the maximum blend radius must be >= 0 mm (got " +
                              std::to_string(this->MaxBlend) + ")");
  }
  // A larger bound would let a wrist flip into a print move: it is not a way out.
  if (!(this->MaxJointStep > 0) || !(this->MaxJointStep <= 30)) {
    throw gl::GeoLatticeError("URScript writer: MaxJointStep must be in (0, 30] degrees (got " +
                              std::to_string(this->MaxJointStep) + ")");
  }
}

/// What the kept solution was solved for: the toolpath (its data object and modification time)
/// and every parameter of the cell and the path solver.
struct vtkGLURScriptWriter::Solution {
  const void* input = nullptr;
  vtkMTimeType inputTime = 0;
  std::string robot;
  std::array<double, 15> numbers{};  ///< tip, axis, mounting, max step, layout and
                                     ///< reconfigure, printhead radius
  std::vector<double> sections;      ///< the printhead's sections (from, to, clearance)
  gl::CellLayoutResult layout;
  std::string unreachableCell;  ///< the error of an unreachable cell set-up, or ""

  bool sameAs(const Solution& o) const {
    return input == o.input && inputTime == o.inputTime && robot == o.robot &&
           numbers == o.numbers && sections == o.sections;
  }
};

gl::RobotCell vtkGLURScriptWriter::MakeCell() const {
  gl::RobotCell cell;
  cell.robot = gl::robotModelByName(this->Robot ? this->Robot : "");
  // The panel's mm and degrees become URScript's m and rad here (and only here).
  cell.nozzleTip = Eigen::Vector3d(this->NozzleTip[0], this->NozzleTip[1], this->NozzleTip[2]) /
                   kMillimetresPerMetre;
  const Eigen::Vector3d axis(this->NozzleAxis[0], this->NozzleAxis[1], this->NozzleAxis[2]);
  cell.nozzleAxis = axis.normalized();
  const double* p = this->PartOnFlangePosition;
  const double* r = this->PartOnFlangeRotation;
  const double toRad = M_PI / 180.0;
  cell.partOnFlange =
      gl::toIsometry({p[0] / kMillimetresPerMetre, p[1] / kMillimetresPerMetre,
                      p[2] / kMillimetresPerMetre, r[0] * toRad, r[1] * toRad, r[2] * toRad});
  cell.partScale = 0.001;  // toolpath mm -> m
  return cell;
}

const gl::CellLayoutResult& vtkGLURScriptWriter::Solve(vtkPolyData* input,
                                                       const gl::ToolpathArrays& path) {
  auto key = std::make_unique<Solution>();
  key->input = input;
  key->inputTime = input->GetMTime();
  key->robot = this->Robot ? this->Robot : "";
  const double* p = this->PartOnFlangePosition;
  const double* r = this->PartOnFlangeRotation;
  key->numbers = {this->NozzleTip[0],
                  this->NozzleTip[1],
                  this->NozzleTip[2],
                  this->NozzleAxis[0],
                  this->NozzleAxis[1],
                  this->NozzleAxis[2],
                  p[0],
                  p[1],
                  p[2],
                  r[0],
                  r[1],
                  r[2],
                  this->MaxJointStep,
                  static_cast<double>(2 * (this->SearchCellLayout != 0) + (this->Reconfigure != 0)),
                  this->PrintheadRadiusUsed};
  for (const gl::NozzleSection& s : this->NozzleSectionsUsed) {
    key->sections.insert(key->sections.end(), {s.from, s.to, s.clearance});
  }
  if (!this->Solved || !this->Solved->sameAs(*key)) {
    this->Solved.reset();
    // Joints along the path (one core call: progress before and after it).
    const gl::RobotPathOptions pathOptions = this->PathOptions();
    // The cell as given, else the best mounting of the part on the flange that the robot
    // can follow (core/robot/CellLayout.h).
    gl::CellLayoutOptions layoutOptions;
    layoutOptions.search = this->SearchCellLayout != 0;
    try {
      key->layout = gl::solveWithCellLayout(this->MakeCell(), path.points, path.normals,
                                            pathOptions, layoutOptions, path.kind);
    } catch (const gl::GeoLatticeError& e) {
      key->unreachableCell = e.what();  // no layout reaches the path continuously
    }
    this->Solved = std::move(key);
  }
  if (!this->Solved->unreachableCell.empty()) {
    // Every point counts as unreachable.
    this->Unreachable.resize(path.points.size());
    for (size_t i = 0; i < path.points.size(); ++i) {
      this->Unreachable[i] = static_cast<vtkIdType>(i);
    }
    throw gl::GeoLatticeError(std::string("URScript writer: ") + this->Solved->unreachableCell +
                              ": nothing written; move the nozzle tip or the part on the flange");
  }
  return this->Solved->layout;
}

int vtkGLURScriptWriter::SolveRobotPath() {
  this->SolveOnly = true;
  const int written = this->Write();
  this->SolveOnly = false;
  if (!written) {
    return 0;
  }
  return this->LargeJointSteps == 0 &&
                 (this->Unreachable.empty() ||
                  (this->AllowUnreachable && this->GetUnreachableCount() < this->NumberOfWaypoints))
             ? 1
             : 0;
}

void vtkGLURScriptWriter::WriteData() {
  this->ResetResults();
  // In an MPI run one process writes: the one with the toolpath (vtkGLParallel.h).
  const gl::ParallelInputs inputs(this);
  if (!inputs.Computes()) {
    return;  // another process writes the program
  }
  this->SetErrorCode(gl::runWrite(
      this,
      [&] {
        this->CheckParameters();
        vtkPolyData* input = inputs.Get<vtkPolyData>(0);
        const gl::ToolpathArrays path = gl::toToolpathArrays(input);
        this->NumberOfWaypoints = static_cast<vtkIdType>(path.points.size());
        if (!this->SolveOnly) {
          this->CheckFileName("URScript writer");
          this->CheckCollisionVerdict(input, "URScript writer");
        }
        gl::checkAbort(this, 0.1);
        const gl::CellLayoutResult& layout = [&]() -> const gl::CellLayoutResult& {
          try {
            return this->Solve(input, path);
          } catch (const gl::GeoLatticeError&) {
            if (this->SolveOnly) {
              static const gl::CellLayoutResult none;
              return none;  // the robot cannot follow it: said by the results, no error
            }
            throw;
          }
        }();
        if (this->SolveOnly && !this->Solved->unreachableCell.empty()) {
          return;
        }
        const gl::RobotCell& cell = layout.cell;

        gl::URScriptOptions options;
        options.maxFileBytes = static_cast<size_t>(this->MaxFileBytes);
        options.speedFactor = this->SpeedFactor;
        options.maxFilamentRate = this->MaxFilamentRate;
        options.maxBlend = this->MaxBlend / kMillimetresPerMetre;
        options.programName = ProgramName(this->FileName ? this->FileName : "");
        if (layout.changed) {
          std::ostringstream line;
          line << "cell layout: the platform turned by " << layout.rotationDeg
               << " deg about the flange z axis and " << 1000 * layout.offsetAdded
               << " mm further from the flange than asked (the path solver's choice: the cell as "
                  "given flips a joint or does not reach); mount it as set_tcp says";
          options.headerComments.push_back(line.str());
        }
        const gl::RobotPath& robotPath = layout.path;
        this->LayoutChanged = layout.changed;
        this->LayoutRotationDeg = layout.rotationDeg;
        this->LayoutOffsetAdded = kMillimetresPerMetre * layout.offsetAdded;
        this->LayoutsTried = layout.layoutsTried;
        const gl::UrPose mounted = gl::toUrPose(layout.cell.partOnFlange);
        for (int k = 0; k < 3; ++k) {
          this->UsedPartOnFlange[k] = kMillimetresPerMetre * mounted[k];
          this->UsedPartOnFlange[k + 3] = mounted[k + 3] * 180.0 / M_PI;
        }
        for (const gl::Reconfiguration& r : robotPath.reconfigurations) {
          this->Reconfigurations.push_back({r.point, r.atSeam, r.fromBranch, r.toBranch,
                                            kMillimetresPerMetre * r.retreat,
                                            kMillimetresPerMetre * r.clearance});
        }
        if (!robotPath.reconfigurations.empty()) {
          const auto seams =
              std::count_if(robotPath.reconfigurations.begin(), robotPath.reconfigurations.end(),
                            [](const gl::Reconfiguration& r) { return r.atSeam; });
          std::ostringstream line;
          line << robotPath.reconfigurations.size() << " reconfiguration(s), "
               << robotPath.reconfigurations.size() - static_cast<size_t>(seams)
               << " at air moves and " << seams
               << " at seams inside print runs (one IK branch cannot follow the whole path): "
                  "the part moves away from the nozzle, the arm turns in joint space, the part "
                  "comes back; each is commented where it happens";
          options.headerComments.push_back(line.str());
        }
        gl::checkAbort(this, 0.5);
        this->Unreachable.assign(robotPath.unreachable.begin(), robotPath.unreachable.end());
        std::sort(this->Unreachable.begin(), this->Unreachable.end());
        this->IKBranch = robotPath.branch;
        this->MaxJointStepDeg = robotPath.maxJointStepDeg;
        this->MaxTipError = robotPath.maxTipError;
        this->MaxAxisErrorDeg = robotPath.maxAxisErrorDeg;
        this->MinSingularity[0] = robotPath.minSingularity.shoulder;
        this->MinSingularity[1] = robotPath.minSingularity.elbow;
        this->MinSingularity[2] = robotPath.minSingularity.wrist;
        this->LowestArmHeight = kMillimetresPerMetre * robotPath.lowestArm;
        this->LowestPartHeight = kMillimetresPerMetre * robotPath.lowestPart;
        this->MinLinkNozzleDistance = kMillimetresPerMetre * robotPath.minLinkNozzleDistance;
        this->MinLinkPartDistance = kMillimetresPerMetre * robotPath.minLinkPartDistance;
        this->SolveSeconds = robotPath.seconds;
        this->LargeJointSteps = static_cast<vtkIdType>(robotPath.largeSteps.size());
        this->ViaSegments = static_cast<vtkIdType>(robotPath.via.size());
        for (const gl::WaypointsBetween& v : robotPath.via) {
          this->ViaWaypoints += static_cast<vtkIdType>(v.via.joints.size());
        }
        if (this->SolveOnly) {
          return;  // the results say whether the robot can follow it
        }
        if (!this->Unreachable.empty()) {
          const std::string text =
              describeUnreachable(this->Unreachable, path.points.size(), cell.robot.name,
                                  gl::nozzleClearanceText(this->PathOptions()));
          if (!this->AllowUnreachable) {
            throw gl::GeoLatticeError(text +
                                      ": nothing written; move the nozzle tip or the part on the "
                                      "flange (AllowUnreachable writes it anyway)");
          }
          vtkWarningMacro(
              << text
              << ": written anyway (AllowUnreachable); the robot holds still at those points");
        }
        if (!robotPath.largeSteps.empty()) {
          std::ostringstream text;
          text << "URScript writer: a joint of the " << cell.robot.name << " jumps by "
               << robotPath.maxJointStepDeg << " degrees at toolpath point "
               << robotPath.maxJointStepAt << " (" << robotPath.largeSteps.size()
               << " steps above MaxJointStep " << this->MaxJointStep
               << " degrees: a wrist flip or a joint limit"
               << (this->SearchCellLayout ? ", also in the other mountings of the part tried"
                                          : " on this cell layout")
               << "); nothing written: move the nozzle tip or the part on the flange";
          // A step of nearly a whole turn is a joint wound to its +-360 degree limit, not a
          // flip: the path circles the part the same way round layer after layer (a generated
          // mushroom's stem: 359.5 degrees); placed on another side it may wind less.
          if (robotPath.maxJointStepDeg > 330.0) {
            text << ". A step of nearly 360 degrees is a joint wound to its limit: the path "
                    "circles the part the same way round"
                 << (this->Reconfigure
                         ? " with no air move before it where the joint could turn back"
                         : " (reconfiguration, off here, turns it back at an air move)")
                 << "; another orientation of the part may wind less";
          }
          throw gl::GeoLatticeError(text.str());
        }

        // The program files, all-or-nothing.
        std::vector<std::string> names;
        gl::AtomicFileSet files;
        const gl::ProgramInput program{&path.points, &path.extrusion, &path.feedRate, &path.kind};
        const gl::ProgramStats stats = gl::writeURScript(
            layout.cell, robotPath, program, options, [&](size_t k) -> std::ostream& {
              names.push_back(ProgramFileName(this->FileName, static_cast<int>(k)));
              return files.open(names.back());
            });
        gl::checkAbort(this, 0.9);
        files.commit();
        this->FilesWritten = names;
        this->NumberOfMoves = static_cast<vtkIdType>(stats.moves);
        this->MaxJointSpeedDegS = stats.maxJointSpeedDegS;
        this->Duration = stats.duration;
        this->MaxLineLength = static_cast<vtkIdType>(stats.maxLineLength);

        // Numbered files of an earlier, longer program.
        std::error_code ec;
        for (int k = static_cast<int>(names.size());; ++k) {
          const std::string stale = ProgramFileName(this->FileName, k);
          if (!std::filesystem::is_regular_file(stale, ec) || !std::filesystem::remove(stale, ec)) {
            break;
          }
        }
        this->UpdateProgress(1.0);
      },
      [this] { this->FilesWritten.clear(); }, [this] { this->ResetResults(); }));
}

void vtkGLURScriptWriter::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Robot: " << (this->Robot ? this->Robot : "(none)") << "\n";
  os << indent << "NozzleTip: " << this->NozzleTip[0] << " " << this->NozzleTip[1] << " "
     << this->NozzleTip[2] << " mm\n";
  os << indent << "NozzleAxis: " << this->NozzleAxis[0] << " " << this->NozzleAxis[1] << " "
     << this->NozzleAxis[2] << "\n";
  os << indent << "PrintheadRadius: " << this->PrintheadRadius << "\n";
  os << indent << "PartOnFlangePosition: " << this->PartOnFlangePosition[0] << " "
     << this->PartOnFlangePosition[1] << " " << this->PartOnFlangePosition[2] << " mm\n";
  os << indent << "PartOnFlangeRotation: " << this->PartOnFlangeRotation[0] << " "
     << this->PartOnFlangeRotation[1] << " " << this->PartOnFlangeRotation[2] << " deg\n";
  os << indent << "MaxFileBytes: " << this->MaxFileBytes << "\n";
  os << indent << "SpeedFactor: " << this->SpeedFactor << "\n";
  os << indent << "MaxFilamentRate: " << this->MaxFilamentRate << " mm/s\n";
  os << indent << "MaxBlend: " << this->MaxBlend << " mm\n";
  os << indent << "MaxJointStep: " << this->MaxJointStep << " deg\n";
  os << indent << "AllowUnreachable: " << this->AllowUnreachable << "\n";
  os << indent << "SearchCellLayout: " << (this->SearchCellLayout ? "on" : "off") << "\n";
  os << indent << "Reconfigure: " << (this->Reconfigure ? "on" : "off") << "\n";
  os << indent << "FilesWritten: " << this->FilesWritten.size() << "\n";
  os << indent << "UnreachableCount: " << this->Unreachable.size() << "\n";
}
