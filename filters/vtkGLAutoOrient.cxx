#include "vtkGLAutoOrient.h"

#include "vtkGLArrayNames.h"
#include "vtkGLMeshConversion.h"
#include "vtkGLParallel.h"
#include "vtkGLProgress.h"
#include "vtkGLRequest.h"

#include "common/Error.h"
#include "mesh/SurfaceRepair.h"
#include "orient/AutoOrient.h"

#include <algorithm>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

vtkStandardNewMacro(vtkGLAutoOrient);

namespace gl = geolattice;

struct vtkGLAutoOrient::SearchCache {
  gl::OrientResult result;
  vtkMTimeType filterTime = 0;  ///< this filter's MTime when it ran (the nozzle included)
  vtkMTimeType inputTime = 0;   ///< the input's
  std::vector<int> byRank;      ///< candidate index of each rank
};

vtkGLAutoOrient::~vtkGLAutoOrient() = default;

void vtkGLAutoOrient::SetCandidateRank(int rank) {
  rank = std::max(0, rank);
  if (rank == this->CandidateRank) {
    return;
  }
  // A rank change alone keeps the search: its time moves with the filter's.
  const bool current = this->Cache && this->Cache->filterTime == this->GetMTime();
  this->CandidateRank = rank;
  this->Modified();
  if (current) {
    this->Cache->filterTime = this->GetMTime();
  }
}

vtkGLAutoOrient::vtkGLAutoOrient() {
  this->SetNumberOfOutputPorts(2);
  this->Orient = KEEP;
}

namespace {

/// Output 1: the candidates as points on a sphere around the part, coloured by their scores.
void buildCandidates(const gl::OrientResult& r, const double bounds[6], vtkPolyData* out) {
  const gl::Vec3 centre(0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
                        0.5 * (bounds[4] + bounds[5]));
  const double radius =
      0.75 * std::max({bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]});
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> verts;
  auto intArray = [](const char* name) {
    auto a = vtkSmartPointer<vtkIntArray>::New();
    a->SetName(name);
    return a;
  };
  auto doubleArray = [](const char* name) {
    auto a = vtkSmartPointer<vtkDoubleArray>::New();
    a->SetName(name);
    return a;
  };
  auto rank = intArray(gl::arrays::OrientRank), colliding = intArray(gl::arrays::CollidingStations),
       plate = intArray(gl::arrays::PlateStations), forced = intArray(gl::arrays::ForcedSteps),
       layers = intArray(gl::arrays::LayerCount), feasible = intArray(gl::arrays::Feasible),
       evaluated = intArray(gl::arrays::Evaluated);
  auto refined = intArray(gl::arrays::Refined),
       coarse = intArray(gl::arrays::CoarseCollidingStations);
  auto pedestal = doubleArray(gl::arrays::Pedestal);
  auto area = doubleArray(gl::arrays::BaseArea),
       overhang = doubleArray(gl::arrays::OverhangFraction),
       seconds = doubleArray(gl::arrays::OrientSeconds), up = doubleArray(gl::arrays::OrientUp);
  up->SetNumberOfComponents(3);
  auto stations = intArray(gl::arrays::CollisionStations);
  vtkNew<vtkStringArray> source;
  source->SetName(gl::arrays::OrientSource);
  for (const gl::OrientCandidate& c : r.candidates) {
    // the up direction; candidates on a pedestal on a larger sphere
    const gl::Vec3 p = centre - (c.pedestal > 0 ? 1.15 : 1.0) * radius * c.down;
    const vtkIdType id = points->InsertNextPoint(p.data());
    verts->InsertNextCell(1, &id);
    rank->InsertNextValue(c.rank);
    colliding->InsertNextValue(static_cast<int>(c.collidingStations));
    plate->InsertNextValue(static_cast<int>(c.plateStations));
    forced->InsertNextValue(c.forcedSteps);
    layers->InsertNextValue(c.layers);
    feasible->InsertNextValue(c.feasible ? 1 : 0);
    evaluated->InsertNextValue(c.evaluated ? 1 : 0);
    area->InsertNextValue(c.baseArea);
    overhang->InsertNextValue(c.overhangFraction);
    seconds->InsertNextValue(c.seconds);
    up->InsertNextTuple3(-c.down.x(), -c.down.y(), -c.down.z());
    stations->InsertNextValue(static_cast<int>(c.stations));
    pedestal->InsertNextValue(c.pedestal);
    refined->InsertNextValue(c.refined ? 1 : 0);
    coarse->InsertNextValue(static_cast<int>(c.coarseCollidingStations));
    source->InsertNextValue(c.error.empty() ? c.source : c.source + ": " + c.error);
  }
  out->SetPoints(points);
  out->SetVerts(verts);
  vtkPointData* pd = out->GetPointData();
  for (vtkDataArray* a : {static_cast<vtkDataArray*>(rank), static_cast<vtkDataArray*>(colliding),
                          static_cast<vtkDataArray*>(plate), static_cast<vtkDataArray*>(forced),
                          static_cast<vtkDataArray*>(layers), static_cast<vtkDataArray*>(feasible),
                          static_cast<vtkDataArray*>(evaluated), static_cast<vtkDataArray*>(area),
                          static_cast<vtkDataArray*>(overhang), static_cast<vtkDataArray*>(seconds),
                          static_cast<vtkDataArray*>(up), static_cast<vtkDataArray*>(stations),
                          static_cast<vtkDataArray*>(pedestal), static_cast<vtkDataArray*>(refined),
                          static_cast<vtkDataArray*>(coarse)}) {
    pd->AddArray(a);
  }
  pd->AddArray(source);
  pd->SetActiveScalars(gl::arrays::OrientRank);
}

/// The core options of the filter's parameters (checked by RequestInformation).
gl::OrientOptions orientOptions(vtkGLAutoOrient* f) {
  gl::OrientOptions o = f->GetOptions();
  o.nozzle = gl::nozzleModel(f->GetNozzle());
  o.plate = gl::buildPlate(f->GetNozzle());
  return o;
}

}  // namespace

int vtkGLAutoOrient::RequestInformation(vtkInformation* request, vtkInformationVector** inputs,
                                        vtkInformationVector* outputs) {
  return this->Superclass::RequestInformation(request, inputs, outputs) &&
         (this->Orient == KEEP ||
          gl::checkParameters(this, [&] { orientOptions(this).validate(); }));
}

int vtkGLAutoOrient::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                 vtkInformationVector* outputVector) {
  // Collective in an MPI run: the whole surface on one process (vtkGLParallel.h).
  return gl::runRequest(this, inputVector, 1, outputVector, [&](const gl::ParallelInputs& inputs) {
    vtkPolyData* input = inputs.Get<vtkPolyData>(0);
    vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
    vtkPolyData* candidates = vtkPolyData::GetData(outputVector, 1);
    if (!input || input->GetNumberOfPolys() == 0) {
      throw gl::GeoLatticeError("empty input: no surface to orient");
    }
    if (this->Orient == KEEP) {
      output->ShallowCopy(input);
      gl::addFieldText(output->GetFieldData(), gl::arrays::OrientMode, "keep");
      return;
    }
    gl::OrientOptions options = orientOptions(this);
    gl::TriangleSurface surface = gl::toTriangleSurface(input);
    // Bodies the reader welded where they touch along a face: one solid before it is turned (a
    // union of faces that are coplanar as read; turned, they may not be exactly).
    const gl::SurfaceRepairCounts repaired = gl::repairSurface(surface);
    if (!this->Cache || this->Cache->filterTime != this->GetMTime() ||
        this->Cache->inputTime != input->GetMTime()) {
      this->Cache.reset();
      options.progress = gl::progressRange(this, 0.0, 0.95);
      options.shouldAbort = gl::abortFlag(this);
      auto cache = std::make_unique<SearchCache>();
      cache->result = gl::searchOrientation(surface, options);
      cache->byRank.resize(cache->result.candidates.size());
      for (size_t i = 0; i < cache->byRank.size(); ++i) {
        cache->byRank[cache->result.candidates[i].rank] = static_cast<int>(i);
      }
      cache->filterTime = this->GetMTime();
      cache->inputTime = input->GetMTime();
      this->Cache = std::move(cache);
    }
    gl::checkAbort(this, 0.95);
    const gl::OrientResult& r = this->Cache->result;
    const int rank =
        std::min(this->CandidateRank, static_cast<int>(this->Cache->byRank.size()) - 1);
    const gl::OrientCandidate& chosen = r.candidates[this->Cache->byRank[rank]];
    const gl::TriangleSurface placed = gl::orientSurface(surface, chosen.rotation);
    if (repaired.any()) {
      gl::fromTriangleSurface(placed, output);  // new triangles: the input's arrays do not fit
    } else {
      output->ShallowCopy(input);
      vtkNew<vtkPoints> points;
      points->SetDataTypeToDouble();
      points->SetNumberOfPoints(static_cast<vtkIdType>(placed.points.size()));
      for (size_t i = 0; i < placed.points.size(); ++i) {
        points->SetPoint(static_cast<vtkIdType>(i), placed.points[i].data());
      }
      output->SetPoints(points);  // the same triangles, rotated points (the triangle ids match)
    }
    vtkNew<vtkFieldData> fd;
    fd->ShallowCopy(input->GetFieldData());
    gl::addFieldText(fd, gl::arrays::OrientMode, "auto");
    const gl::Vec3 up = -chosen.down;
    std::vector<double> rotation(9);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        rotation[3 * i + j] = chosen.rotation(i, j);
      }
    }
    gl::addFieldArray(fd, gl::arrays::OrientUp, {up.x(), up.y(), up.z()});
    gl::addFieldArray(fd, gl::arrays::OrientRotation, rotation);
    gl::addFieldArray(fd, gl::arrays::OrientCandidates, {static_cast<double>(r.candidates.size())});
    gl::addFieldArray(fd, gl::arrays::OrientSeconds, {r.seconds});
    gl::addFieldArray(fd, gl::arrays::OrientBefore,
                      {static_cast<double>(r.candidates[0].collidingStations)});
    gl::addFieldArray(fd, gl::arrays::OrientAfter, {static_cast<double>(chosen.collidingStations)});
    gl::addFieldArray(fd, gl::arrays::OrientEvaluationTets,
                      {static_cast<double>(r.evaluationTets)});
    gl::addFieldArray(fd, gl::arrays::OrientEvaluationScale, {r.evaluationScale});
    gl::addFieldArray(fd, gl::arrays::OrientRefined, {static_cast<double>(r.refined)});
    gl::addFieldArray(fd, gl::arrays::OrientChosenRank, {static_cast<double>(rank)});
    gl::addFieldArray(fd, gl::arrays::OrientPedestalHeight, {chosen.pedestal});
    if (repaired.any()) {  // as GL Tetrahedralize Surface says it
      gl::addSurfaceRepairArrays(fd, repaired);
    }
    gl::addFieldArray(fd, gl::arrays::OrientPedestalContactHeight, {options.pedestalContactHeight});
    output->SetFieldData(fd);
    double bounds[6];
    output->GetBounds(bounds);
    buildCandidates(r, bounds, candidates);
    candidates->GetFieldData()->PassData(fd);
    this->UpdateProgress(1.0);
  });
}

void vtkGLAutoOrient::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Orient: " << this->Orient << (this->Orient == AUTO ? " (auto)" : " (keep)")
     << "\n";
  os << indent << "MinBaseArea: " << this->Options.minBaseArea << " mm2\n";
  os << indent << "MaxHeight: " << this->Options.maxHeight << " mm\n";
  os << indent << "SphereCandidates: " << this->Options.sphereCandidates << "\n";
  os << indent << "HullCandidates: " << this->Options.hullCandidates << "\n";
  os << indent << "EvaluationTets: " << this->Options.evaluationTets << "\n";
  os << indent << "EvaluationLayerInterval: " << this->Options.layerInterval << " mm\n";
  os << indent << "EvaluationLatticeWidth: " << this->Options.latticeWidth << " mm\n";
  os << indent << "Pedestal: " << this->GetPedestal() << "\n";
  os << indent << "PedestalHeight: " << this->Options.pedestalHeight << " mm\n";
  os << indent << "PedestalContactHeight: " << this->Options.pedestalContactHeight << " mm\n";
  os << indent << "RefineCandidates: " << this->Options.refineCandidates << "\n";
  os << indent << "RefineLayerInterval: " << this->Options.refineLayerInterval << " mm\n";
  os << indent << "RefineLatticeWidth: " << this->Options.refineLatticeWidth << " mm\n";
  os << indent << "BaseFlatBand: " << this->Options.baseFlatBand << " mm\n";
  os << indent << "RefineStrategy: " << this->GetRefineStrategy() << "\n";
  os << indent << "MaxAxisTilt: " << this->Options.maxTiltDeg << " deg\n";
  os << indent << "CandidateRank: " << this->CandidateRank << "\n";
  os << indent << "NumberOfThreads: " << this->Options.threads << "\n";
}
