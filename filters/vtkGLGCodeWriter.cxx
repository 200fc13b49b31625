#include "vtkGLGCodeWriter.h"

#include "vtkGLMeshConversion.h"
#include "vtkGLOutputFiles.h"
#include "vtkGLParallel.h"
#include "vtkGLProgress.h"
#include "vtkGLRequest.h"

#include "common/Error.h"
#include "program/GCodeWriter.h"

#include <vtkErrorCode.h>
#include <vtkInformation.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include <cctype>
#include <cmath>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkGLGCodeWriter);

namespace {
namespace gl = geolattice;

static_assert(static_cast<int>(gl::TableKinematics::AC) == vtkGLGCodeWriter::AC &&
                  static_cast<int>(gl::TableKinematics::BC) == vtkGLGCodeWriter::BC,
              "vtkGLGCodeWriter::KinematicsType must match core/program/GCodeWriter.h");

constexpr double kPoleToleranceDeg = 0.01;  // = GCodeOptions::poleToleranceDeg

/// Points whose axis needs a tilt outside [lo, hi] on both solutions (tilt = ±τ, τ the angle
/// between the axis and +Z), as the core decides it.
std::vector<vtkIdType> outOfLimits(const std::vector<Eigen::Vector3d>& normals, double lo,
                                   double hi) {
  std::vector<vtkIdType> out;
  for (size_t i = 0; i < normals.size(); ++i) {
    const Eigen::Vector3d& n = normals[i];
    const double tau = std::atan2(std::hypot(n.x(), n.y()), n.z()) * 180.0 / M_PI;
    const bool inside = (tau >= lo && tau <= hi) || (-tau >= lo && -tau <= hi);
    if (!inside) {
      out.push_back(static_cast<vtkIdType>(i));
    }
  }
  return out;
}
}  // namespace

vtkGLGCodeWriter::vtkGLGCodeWriter() {
  const gl::GCodeOptions defaults;  // the defaults live in core
  this->Kinematics = static_cast<int>(defaults.kinematics);
  for (int k = 0; k < 3; ++k) {
    this->Pivot[k] = defaults.pivot[k];
    this->PartOffset[k] = defaults.partOffset[k];
  }
  this->TiltLimits[0] = defaults.tiltMinDeg;
  this->TiltLimits[1] = defaults.tiltMaxDeg;
  this->Flavor = static_cast<int>(defaults.flavor);
  this->ToolCentrePoint = static_cast<int>(defaults.toolCentrePoint);
  const char axis[2] = {defaults.extrusionAxis, '\0'};
  this->SetExtrusionAxis(axis);
}

vtkGLGCodeWriter::~vtkGLGCodeWriter() {
  this->SetExtrusionAxis(nullptr);
}

void vtkGLGCodeWriter::CheckParameters() {
  const double lo = this->TiltLimits[0], hi = this->TiltLimits[1];
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi)) {
    throw gl::GeoLatticeError("G-code writer: the tilt limits must be finite with min < max (got " +
                              std::to_string(lo) + ", " + std::to_string(hi) + ")");
  }
  for (const double* v : {this->Pivot, this->PartOffset}) {
    if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2])) {
      throw gl::GeoLatticeError("G-code writer: the pivot and the part offset must be finite");
    }
  }
  if (this->Flavor != LINUXCNC && this->Flavor != REPRAP) {
    throw gl::GeoLatticeError("G-code writer: Flavor must be 0 (LinuxCNC) or 1 (RepRap), got " +
                              std::to_string(this->Flavor));
  }
  if (this->ToolCentrePoint != CONTROLLER && this->ToolCentrePoint != CAM) {
    throw gl::GeoLatticeError(
        "G-code writer: ToolCentrePoint must be 0 (controller) or 1 (CAM), got " +
        std::to_string(this->ToolCentrePoint));
  }
  const std::string axis = this->ExtrusionAxis ? this->ExtrusionAxis : "";
  if (axis.size() != 1 || !std::isupper(static_cast<unsigned char>(axis[0]))) {
    throw gl::GeoLatticeError("G-code writer: ExtrusionAxis must be one axis letter (got '" + axis +
                              "')");
  }
  gl::GCodeOptions options;  // the core's own checks of the rest
  options.tiltMinDeg = lo;
  options.tiltMaxDeg = hi;
  options.flavor = static_cast<gl::GCodeFlavor>(this->Flavor);
  options.toolCentrePoint = static_cast<gl::ToolCentrePoint>(this->ToolCentrePoint);
  options.extrusionAxis = axis[0];
  options.validate();
}

void vtkGLGCodeWriter::WriteData() {
  this->NumberOfMoves = 0;
  this->MaxRotaryStepDeg = 0;
  this->BranchFlips = 0;
  this->MaxAxisErrorDeg = 0;
  this->ForcedRotarySteps = 0;
  this->OutOfLimitsCount = 0;
  // In an MPI run one process writes: the one with the toolpath (vtkGLParallel.h).
  const gl::ParallelInputs inputs(this);
  if (!inputs.Computes()) {
    return;  // another process writes the G-code
  }
  this->SetErrorCode(gl::runWrite(
      this,
      [&] {
        this->CheckParameters();
        this->CheckFileName("G-code writer");
        const gl::ToolpathArrays path = gl::toToolpathArrays(inputs.Get<vtkPolyData>(0));
        this->CheckCollisionVerdict(inputs.Get<vtkPolyData>(0), "G-code writer");
        gl::checkAbort(this, 0.1);
        const double lo = this->TiltLimits[0], hi = this->TiltLimits[1];
        const std::vector<vtkIdType> out = outOfLimits(path.normals, lo, hi);
        gl::checkAbort(this, 0.2);
        this->OutOfLimitsCount = static_cast<vtkIdType>(out.size());
        if (!out.empty()) {
          std::ostringstream s;
          s << "G-code writer: " << out.size() << " of " << path.points.size()
            << " toolpath points need a tilt outside the limits [" << lo << ", " << hi
            << "] degrees (first:";
          for (size_t i = 0; i < out.size() && i < 10; ++i) {
            s << (i ? ", " : " ") << out[i];
          }
          s << (out.size() > 10 ? ", ...)" : ")") << "; nothing written";
          throw gl::GeoLatticeError(s.str());
        }

        gl::GCodeOptions options;
        options.kinematics =
            this->Kinematics == BC ? gl::TableKinematics::BC : gl::TableKinematics::AC;
        options.pivot = Eigen::Vector3d(this->Pivot[0], this->Pivot[1], this->Pivot[2]);
        options.partOffset =
            Eigen::Vector3d(this->PartOffset[0], this->PartOffset[1], this->PartOffset[2]);
        options.tiltMinDeg = lo;
        options.tiltMaxDeg = hi;
        options.poleToleranceDeg = kPoleToleranceDeg;
        const std::string axis = this->ExtrusionAxis;
        options.flavor = static_cast<gl::GCodeFlavor>(this->Flavor);
        options.toolCentrePoint = static_cast<gl::ToolCentrePoint>(this->ToolCentrePoint);
        options.extrusionAxis = axis[0];
        options.validate();
        gl::AtomicFileSet files;
        const gl::GCodeStats stats =
            gl::writeGCode(path.points, path.normals, path.extrusion, path.feedRate, path.kind,
                           options, files.open(this->FileName));
        if (stats.outOfLimits > 0) {
          throw gl::GeoLatticeError(
              "G-code writer: " + std::to_string(stats.outOfLimits) +
              " toolpath points need a tilt outside the limits; nothing written");
        }
        gl::checkAbort(this, 0.9);
        files.commit();
        this->NumberOfMoves = static_cast<vtkIdType>(stats.moves);
        this->MaxRotaryStepDeg = stats.maxRotaryStepDeg;
        this->BranchFlips = static_cast<vtkIdType>(stats.branchFlips);
        this->MaxAxisErrorDeg = stats.maxAxisErrorDeg;
        this->ForcedRotarySteps = static_cast<vtkIdType>(stats.forcedRotarySteps);
      },
      [this] { this->NumberOfMoves = 0; }, [this] { this->NumberOfMoves = 0; }));
}

void vtkGLGCodeWriter::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Kinematics: " << this->Kinematics
     << (this->Kinematics == BC ? " (B-C)" : " (A-C)") << "\n";
  os << indent << "Flavor: " << this->Flavor
     << (this->Flavor == REPRAP ? " (reprap)" : " (linuxcnc)") << "\n";
  os << indent << "ToolCentrePoint: " << this->ToolCentrePoint
     << (this->ToolCentrePoint == CAM ? " (cam)" : " (controller)") << "\n";
  os << indent << "ExtrusionAxis: " << (this->ExtrusionAxis ? this->ExtrusionAxis : "(none)")
     << "\n";
  os << indent << "Pivot: " << this->Pivot[0] << " " << this->Pivot[1] << " " << this->Pivot[2]
     << " mm\n";
  os << indent << "PartOffset: " << this->PartOffset[0] << " " << this->PartOffset[1] << " "
     << this->PartOffset[2] << " mm\n";
  os << indent << "TiltLimits: " << this->TiltLimits[0] << " " << this->TiltLimits[1] << " deg\n";
  os << indent << "NumberOfMoves: " << this->NumberOfMoves << "\n";
}
