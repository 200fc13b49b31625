#include "vtkGLGeodesicDistanceFields.h"

#include "vtkGLArrayNames.h"
#include "vtkGLMeshConversion.h"
#include "vtkGLParallel.h"
#include "vtkGLProgress.h"
#include "vtkGLRequest.h"

#include "common/Error.h"
#include "gdf/GeodesicDistanceFields.h"
#include "gdf/HeatSources.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkStringArray.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#include <chrono>

vtkStandardNewMacro(vtkGLGeodesicDistanceFields);

struct vtkGLGeodesicDistanceFields::SolverCache {
  std::unique_ptr<geolattice::GeodesicDistanceFields> Solver;
  vtkMTimeType MeshTime = 0;
  geolattice::GeodesicFieldOptions Options;
  /// Where the solver's progress (0..1 of its set-up, then of each solve) goes in the filter's.
  double ProgressLo = 0, ProgressHi = 1;
};

namespace {
bool sameSetUp(const geolattice::GeodesicFieldOptions& a,
               const geolattice::GeodesicFieldOptions& b) {
  return a.timeFactor == b.timeFactor && a.reference == b.reference &&
         a.referenceParallelDeg == b.referenceParallelDeg && a.turnReference == b.turnReference &&
         a.backend == b.backend;
}

/// The core options of the filter's parameters (checked by RequestInformation).
geolattice::GeodesicFieldOptions fieldOptions(vtkGLGeodesicDistanceFields* f) {
  geolattice::GeodesicFieldOptions o = f->GetOptions();
  const double* r = f->GetReferenceVector();
  o.reference = geolattice::Vec3(r[0], r[1], r[2]);
  o.backend = f->GetUseCholmod() ? geolattice::CholeskyBackend::Cholmod
                                 : geolattice::CholeskyBackend::EigenLDLT;
  return o;
}

}  // namespace

vtkGLGeodesicDistanceFields::vtkGLGeodesicDistanceFields() : Cache(new SolverCache) {
  // Default mask array for MASK_ARRAY mode; ParaView users pick any point array.
  this->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS,
                               geolattice::arrays::HeatSource);
  const geolattice::GeodesicFieldOptions fields;  // the defaults live in core
  const geolattice::BaseOptions base;
  this->SourceMode = LOWEST_Z;
  this->BaseTolerance = base.tolerance;
  this->BaseFlatBand = base.flatBand;
  this->BaseFaceAngle = base.maxFaceAngleDeg;
  for (int k = 0; k < 3; ++k) {
    this->ReferenceVector[k] = fields.reference[k];
  }
  this->UseCholmod = fields.backend == geolattice::CholeskyBackend::Cholmod;
}

vtkGLGeodesicDistanceFields::~vtkGLGeodesicDistanceFields() = default;

void vtkGLGeodesicDistanceFields::ReleaseSolver() {
  this->Cache->Solver.reset();
}

int vtkGLGeodesicDistanceFields::RequestInformation(vtkInformation*, vtkInformationVector**,
                                                    vtkInformationVector*) {
  return geolattice::checkParameters(this, [&] {
    fieldOptions(this).validate();
    if (!(this->BaseTolerance >= 0) || !std::isfinite(this->BaseTolerance)) {
      throw geolattice::GeoLatticeError("base tolerance must be >= 0 mm (got " +
                                        std::to_string(this->BaseTolerance) + ")");
    }
    if (!(this->BaseFlatBand >= 0) || !std::isfinite(this->BaseFlatBand)) {
      throw geolattice::GeoLatticeError("base flat band must be >= 0 mm (got " +
                                        std::to_string(this->BaseFlatBand) + ")");
    }
  });
}

int vtkGLGeodesicDistanceFields::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                             vtkInformationVector* outputVector) {
  namespace gl = geolattice;
  // Collective in an MPI run: the whole tet mesh on one process (vtkGLParallel.h).
  return gl::runRequest(this, inputVector, 1, outputVector, [&](const gl::ParallelInputs& inputs) {
    vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);
    vtkUnstructuredGrid* input = inputs.Get<vtkUnstructuredGrid>(0);
    const auto start = std::chrono::steady_clock::now();
    gl::GeodesicFieldOptions options = fieldOptions(this);
    SolverCache& cache = *this->Cache;
    // The cached solver keeps these callbacks: they read the range of the current step.
    options.progress = [this](double f) {
      const SolverCache& c = *this->Cache;
      this->UpdateProgress(c.ProgressLo + (c.ProgressHi - c.ProgressLo) * f);
    };
    options.shouldAbort = gl::abortFlag(this);

    const vtkMTimeType meshTime = input ? input->GetMTime() : 0;
    // A gathered mesh (parts from several processes) is a new object on every call.
    if (!cache.Solver || inputs.Gathered() || cache.MeshTime != meshTime ||
        !sameSetUp(cache.Options, options)) {
      cache.Solver.reset();
      const gl::TetMesh mesh = gl::toTetMesh(input);
      gl::checkAbort(this, 0.05);
      cache.ProgressLo = 0.05;
      cache.ProgressHi = 0.6;
      cache.Solver = std::make_unique<gl::GeodesicDistanceFields>(mesh, options);
      cache.MeshTime = meshTime;
      cache.Options = options;
    }
    gl::checkAbort(this, 0.6);

    const gl::TetMesh& mesh = cache.Solver->mesh();
    std::vector<int> sources;
    switch (this->SourceMode) {
      case MASK_ARRAY: {
        vtkDataArray* mask = this->GetInputArrayToProcess(0, input);
        if (!mask) {
          throw gl::GeoLatticeError(
              "source mode is MASK_ARRAY but the selected point array is missing");
        }
        std::vector<double> values(mask->GetNumberOfTuples());
        for (vtkIdType i = 0; i < mask->GetNumberOfTuples(); ++i) {
          values[i] = mask->GetComponent(i, 0);
        }
        sources = gl::sourcesFromMask(mesh, values);
        break;
      }
      case DOWNWARD_FACES:
        sources = gl::sourcesFromDownwardFaces(mesh, cache.Solver->topology(), this->BaseFaceAngle);
        break;
      default:
        sources = gl::sourcesNearLowestZ(mesh, this->BaseTolerance, cache.Solver->topology(),
                                         this->BaseFlatBand, this->BaseFaceAngle);
    }
    cache.ProgressLo = 0.6;
    cache.ProgressHi = 0.95;
    const gl::GeodesicFields fields = cache.Solver->solve(sources);
    gl::checkAbort(this, 0.95);

    output->ShallowCopy(input);
    vtkPointData* pd = output->GetPointData();
    pd->AddArray(gl::doubleArray(gl::arrays::Gamma, fields.gamma));
    pd->AddArray(gl::doubleArray(gl::arrays::Alpha, fields.alpha));
    pd->AddArray(gl::doubleArray(gl::arrays::Beta, fields.beta));
    pd->SetActiveScalars(gl::arrays::Gamma);
    vtkNew<vtkUnsignedCharArray> isSource;
    isSource->SetName(gl::arrays::HeatSource);
    isSource->SetNumberOfTuples(input->GetNumberOfPoints());
    isSource->FillValue(0);
    for (int s : sources) {
      isSource->SetValue(s, 1);
    }
    pd->AddArray(isSource);
    vtkCellData* cd = output->GetCellData();
    cd->AddArray(gl::vectorArray(gl::arrays::GammaGradient, fields.gammaDirection));
    cd->AddArray(gl::vectorArray(gl::arrays::AlphaDirection, fields.alphaDirection));
    cd->AddArray(gl::vectorArray(gl::arrays::BetaDirection, fields.betaDirection));

    vtkNew<vtkFieldData> fd;
    fd->DeepCopy(input->GetFieldData());
    gl::addFieldArray(fd, gl::arrays::GammaRange,
                      {fields.gamma.minCoeff(), fields.gamma.maxCoeff()});
    gl::addFieldArray(fd, gl::arrays::AlphaRange,
                      {fields.alpha.minCoeff(), fields.alpha.maxCoeff()});
    gl::addFieldArray(fd, gl::arrays::BetaRange, {fields.beta.minCoeff(), fields.beta.maxCoeff()});
    const double total =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    gl::addFieldArray(
        fd, gl::arrays::GdfTimings,
        {fields.timings.assembly, fields.timings.factorization, fields.timings.solve, total});
    const auto& dev = fields.orthogonalityDeviationDeg;
    gl::addFieldArray(fd, gl::arrays::OrthogonalityDeg, {dev[0], dev[1], dev[2], dev[3]});
    gl::addFieldArray(fd, gl::arrays::ReferenceFallbackTets,
                      {static_cast<double>(fields.referenceFallbackTets)});
    gl::addFieldArray(fd, gl::arrays::ReferenceUsed,
                      {fields.reference.x(), fields.reference.y(), fields.reference.z()});
    if (fields.referenceTurned) {
      gl::addFieldArray(fd, gl::arrays::GivenReferenceFallbackTets,
                        {static_cast<double>(fields.givenReferenceFallbackTets)});
    }
    gl::addFieldArray(fd, gl::arrays::SourceCount, {static_cast<double>(sources.size())});
    output->SetFieldData(fd);
    this->UpdateProgress(1.0);
  });
}

void vtkGLGeodesicDistanceFields::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SourceMode: " << this->SourceMode << "\n";
  os << indent << "BaseTolerance: " << this->BaseTolerance << " mm\n";
  os << indent << "BaseFlatBand: " << this->BaseFlatBand << " mm\n";
  os << indent << "BaseFaceAngle: " << this->BaseFaceAngle << " deg\n";
  os << indent << "TimeFactor: " << this->Options.timeFactor << "\n";
  os << indent << "ReferenceVector: " << this->ReferenceVector[0] << " " << this->ReferenceVector[1]
     << " " << this->ReferenceVector[2] << "\n";
  os << indent << "ReferenceParallelAngle: " << this->Options.referenceParallelDeg << " deg\n";
  os << indent << "TurnReference: " << (this->Options.turnReference ? "on" : "off") << "\n";
  os << indent << "UseCholmod: " << this->UseCholmod << "\n";
}
