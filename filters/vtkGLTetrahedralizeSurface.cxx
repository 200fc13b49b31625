#include "vtkGLTetrahedralizeSurface.h"

#include "vtkGLArrayNames.h"
#include "vtkGLMeshConversion.h"
#include "vtkGLParallel.h"
#include "vtkGLProgress.h"
#include "vtkGLRequest.h"

#include "common/Error.h"
#include "tetrahedralize/TetrahedralizeSurface.h"

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>

#include <string>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>

vtkStandardNewMacro(vtkGLTetrahedralizeSurface);

namespace gl = geolattice;

vtkGLTetrahedralizeSurface::vtkGLTetrahedralizeSurface() = default;

namespace {
// Circumradius / shortest edge of tet (a, b, c, d); infinity for a flat tet.
double radiusEdgeRatio(const gl::Vec3& a, const gl::Vec3& b, const gl::Vec3& c, const gl::Vec3& d) {
  // Circumcentre x - a solves 2 (p - a) . (x - a) = |p - a|^2 for p = b, c, d.
  Eigen::Matrix3d m;
  m.row(0) = 2.0 * (b - a).transpose();
  m.row(1) = 2.0 * (c - a).transpose();
  m.row(2) = 2.0 * (d - a).transpose();
  const Eigen::Vector3d rhs((b - a).squaredNorm(), (c - a).squaredNorm(), (d - a).squaredNorm());
  const double det = m.determinant();
  if (det == 0.0) {
    return std::numeric_limits<double>::infinity();
  }
  const double radius = m.partialPivLu().solve(rhs).norm();
  const double shortest =
      std::sqrt(std::min({(b - a).squaredNorm(), (c - a).squaredNorm(), (d - a).squaredNorm(),
                          (c - b).squaredNorm(), (d - b).squaredNorm(), (d - c).squaredNorm()}));
  return radius / shortest;
}

}  // namespace

void vtkGLTetrahedralizeSurface::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TargetEdgeLength: " << this->Options.targetEdgeLength << " mm (0 = automatic)\n";
  os << indent << "TargetTetCount: " << this->Options.autoTargetTets << "\n";
  os << indent << "RadiusEdgeRatio: " << this->Options.radiusEdgeRatio << "\n";
}

int vtkGLTetrahedralizeSurface::FillInputPortInformation(int, vtkInformation* info) {
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

int vtkGLTetrahedralizeSurface::RequestInformation(vtkInformation*, vtkInformationVector**,
                                                   vtkInformationVector*) {
  return gl::checkParameters(this, [&] { this->Options.validate(); });
}

int vtkGLTetrahedralizeSurface::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                            vtkInformationVector* outputVector) {
  // Collective in an MPI run: the whole surface on one process (vtkGLParallel.h).
  return gl::runRequest(this, inputVector, 1, outputVector, [&](const gl::ParallelInputs& inputs) {
    vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);
    vtkPolyData* input = inputs.Get<vtkPolyData>(0);
    if (!input) {
      throw gl::GeoLatticeError("input must be a vtkPolyData surface");
    }
    const gl::TriangleSurface surface = gl::toTriangleSurface(input);
    gl::checkAbort(this, 0.05);

    gl::TetrahedralizeOptions options = this->Options;
    // After each TetGen run (the automatic edge length may need several) and at the end.
    double reported = 0.05;
    options.progress = [this, &reported](double f) {
      reported = 0.05 + 0.75 * f;
      this->UpdateProgress(reported);
    };
    // Polled about every 50 ms while TetGen runs in its child process; firing ProgressEvent
    // (with the last fraction, so progress never goes back) lets ParaView's progress handler
    // set AbortExecute.
    options.shouldAbort = [this, &reported]() {
      if (!this->GetAbortExecute()) {
        this->UpdateProgress(reported);
      }
      return this->GetAbortExecute() != 0;
    };
    const gl::TetrahedralizeResult result = [&] {
      try {
        return gl::tetrahedralizeSurface(surface, options);
      } catch (const gl::GeoLatticeError& e) {
        // Where to see the edges the message counts (ParaView users; the CLI prints the first).
        const std::string what = e.what();
        for (const char* edges : {"open surface", "non-manifold surface", "inconsistently"}) {
          if (what.rfind(edges, 0) == 0) {
            throw gl::GeoLatticeError(what +
                                      " (GL Surface Check on this input shows every such "
                                      "edge: colour it by DefectKind)");
          }
        }
        throw;
      }
    }();
    gl::checkAbort(this, 0.8);

    gl::fromTetMesh(result.mesh, output);
    vtkNew<vtkDoubleArray> quality;
    quality->SetName(gl::arrays::TetQuality);
    quality->SetNumberOfValues(static_cast<vtkIdType>(result.mesh.tets.size()));
    const size_t tetCount = result.mesh.tets.size();
    const size_t stride = std::max<size_t>(1, tetCount / 16);
    for (size_t t = 0; t < tetCount; ++t) {
      if (t % stride == 0) {
        gl::checkAbort(this, 0.8 + 0.15 * static_cast<double>(t) / tetCount);
      }
      const auto& tet = result.mesh.tets[t];
      const auto& p = result.mesh.points;
      quality->SetValue(static_cast<vtkIdType>(t),
                        radiusEdgeRatio(p[tet[0]], p[tet[1]], p[tet[2]], p[tet[3]]));
    }
    output->GetCellData()->AddArray(quality);

    vtkFieldData* fd = output->GetFieldData();
    gl::addFieldArray(fd, gl::arrays::TargetEdgeLength, {result.targetEdgeLength});
    gl::addFieldArray(fd, gl::arrays::MeanEdgeLength, {result.meanEdgeLength});
    vtkNew<vtkIntArray> count;
    count->SetName(gl::arrays::TetCount);
    count->InsertNextValue(result.tetCount);
    fd->AddArray(count);
    gl::addFieldArray(fd, gl::arrays::TetrahedralizeSeconds, {result.seconds});
    gl::addFieldArray(fd, gl::arrays::InputTriangles, {static_cast<double>(result.inputTriangles)});
    gl::addFieldArray(fd, gl::arrays::MeshedTriangles,
                      {static_cast<double>(result.meshedTriangles)});
    gl::addFieldArray(fd, gl::arrays::SimplificationDistance, {result.simplificationDistance});
    gl::addFieldArray(fd, gl::arrays::SimplificationSeconds, {result.simplificationSeconds});
    gl::addFieldArray(fd, gl::arrays::SimplificationEdgeLength, {result.simplificationEdgeLength});
    gl::addFieldText(fd, gl::arrays::SimplificationRefused, result.simplificationRefused);
    gl::addFieldArray(fd, gl::arrays::TetGenRuns,
                      {static_cast<double>(result.attempts + result.tetgenRetries)});
    gl::addFieldArray(fd, gl::arrays::TetGenSpeculativeRun, {result.speculativeRun ? 1.0 : 0.0});
    gl::addFieldArray(fd, gl::arrays::TetGenSurfaceBoundCount,
                      {result.surfaceBoundCount ? 1.0 : 0.0});
    gl::addFieldArray(fd, gl::arrays::RemovedFlatTets,
                      {static_cast<double>(result.removedFlatTets)});
    gl::addFieldArray(fd, gl::arrays::TetGenQualityBoundDropped,
                      {result.qualityBoundDropped ? 1.0 : 0.0});
    gl::addSurfaceRepairArrays(fd, result.repairs);
    gl::addFieldArray(fd, gl::arrays::CavityRegions,
                      {static_cast<double>(result.removedCavityRegions)});
    for (const gl::RepairNote& note : gl::describeRepairs(result.repairs)) {
      vtkWarningMacro(<< note.text);
    }
    if (result.qualityBoundDropped) {
      vtkWarningMacro(<< gl::qualityBoundDroppedNote(result.tetCount));
    }
    if (!result.simplificationRefused.empty() && !result.simplified) {
      vtkWarningMacro(<< "the simplified surface was not used (" << result.simplificationRefused
                      << "): TetGen meshed all " << result.inputTriangles << " input triangles");
    }
    this->UpdateProgress(1.0);
  });
}
