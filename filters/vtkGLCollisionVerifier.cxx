#include "vtkGLCollisionVerifier.h"

#include "vtkGLArrayNames.h"
#include "vtkGLMeshConversion.h"
#include "vtkGLParallel.h"
#include "vtkGLProgress.h"
#include "vtkGLRequest.h"

#include "collision/CollisionVerifier.h"
#include "common/Error.h"
#include "lattice/LatticeInfill.h"
#include "nozzle/NozzleModel.h"
#include "sequence/PrintMaterial.h"
#include "skeleton/SkeletonTree.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
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
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkGLCollisionVerifier);

namespace {
namespace gl = geolattice;

static_assert(gl::collisionrole::Station == 0 && gl::collisionrole::Obstacle == 1, "Role values");

/// Printed points with their nozzle axes, print times and sub-graphs (-1: none).
struct Stations {
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector3d> normals;
  std::vector<int> time;
  std::vector<int> group;
  std::vector<char> material;  ///< per point: 1 = printed material; empty = all are
};

/// A non-negative integer id, else -1.
int idOf(vtkDataArray* a, vtkIdType tuple) {
  if (!a) {
    return -1;
  }
  const double v = a->GetComponent(tuple, 0);
  return std::isfinite(v) && v >= 0 && v == std::floor(v) && v <= 1e9 ? static_cast<int>(v) : -1;
}

/// The ancestor relation of the skeleton stored by vtkGLPrintSequencer in the field array
/// SkeletonEdges ((lower, upper) sub-graph ids); nodes = 0 .. K-1 with K = 1 + the largest id.
std::unique_ptr<gl::SkeletonAncestry> ancestryOf(vtkDataArray* edges, int& K) {
  if (edges->GetNumberOfComponents() != 2) {
    throw gl::GeoLatticeError(std::string("the field array '") + gl::arrays::SkeletonEdges +
                              "' must have 2 components (lower, upper sub-graph id)");
  }
  std::vector<std::array<int, 2>> pairs;
  K = 0;
  for (vtkIdType e = 0; e < edges->GetNumberOfTuples(); ++e) {
    std::array<int, 2> pair;
    for (int j = 0; j < 2; ++j) {
      const double v = edges->GetComponent(e, j);
      if (!std::isfinite(v) || v < 0 || v != std::floor(v) || v > 1e8) {
        throw gl::GeoLatticeError(std::string("the field array '") + gl::arrays::SkeletonEdges +
                                  "' has the node id " + std::to_string(v) + " at edge " +
                                  std::to_string(e) + "; node ids must be integers >= 0");
      }
      pair[j] = static_cast<int>(v);
      K = std::max(K, pair[j] + 1);
    }
    pairs.push_back(pair);
  }
  gl::SkeletonTree tree;
  tree.nodes.resize(K);
  std::vector<int> lowerLeft(K, 0);
  for (const auto& [lower, upper] : pairs) {
    tree.nodes[upper].lower.push_back(lower);
    tree.nodes[lower].upper.push_back(upper);
    ++lowerLeft[upper];
  }
  // Layers = longest path from a root, so that lower nodes come first (Kahn's order).
  std::vector<int> queue;
  for (int k = 0; k < K; ++k) {
    if (lowerLeft[k] == 0) {
      queue.push_back(k);
    }
  }
  for (size_t i = 0; i < queue.size(); ++i) {
    const gl::SkeletonNode& n = tree.nodes[queue[i]];
    for (int u : n.upper) {
      tree.nodes[u].layer = std::max(tree.nodes[u].layer, n.layer + 1);
      if (--lowerLeft[u] == 0) {
        queue.push_back(u);
      }
    }
  }
  if (static_cast<int>(queue.size()) != K) {
    throw gl::GeoLatticeError(std::string("the field array '") + gl::arrays::SkeletonEdges +
                              "' has a cycle");
  }
  return std::make_unique<gl::SkeletonAncestry>(tree);
}

/// The integer time of a tuple; throws for a non-finite or fractional value.
int timeValue(vtkDataArray* time, vtkIdType tuple, const char* where) {
  const double t = time->GetComponent(tuple, 0);
  if (!std::isfinite(t) || t != std::floor(t) || std::abs(t) > 2e9) {
    throw gl::GeoLatticeError(std::string("the time array '") + time->GetName() +
                              "' has the value " + std::to_string(t) + " at " + where + " " +
                              std::to_string(tuple) + "; print times must be integers");
  }
  return static_cast<int>(t);
}

Eigen::Vector3d tupleOf(vtkDataArray* a, vtkIdType i) {
  return Eigen::Vector3d(a->GetComponent(i, 0), a->GetComponent(i, 1), a->GetComponent(i, 2));
}

/// A lattice with one time per sub-graph: the samples of core/sequence/PrintMaterial.h, exactly
/// those the sequencer tests. False (nothing added) when the input is not such a lattice.
bool sampleLattice(vtkPolyData* input, vtkDataArray* cellTime, double spacing, Stations& out) {
  vtkCellData* cd = input->GetCellData();
  vtkDataArray* subgraph = cd->GetArray(gl::arrays::SubgraphId);
  if (!subgraph || !cd->GetArray(gl::arrays::LayerId) ||
      !input->GetPointData()->GetArray(gl::arrays::Gamma)) {
    return false;
  }
  std::vector<int> subgraphTime;
  std::vector<char> known;
  const vtkIdType firstLine = input->GetNumberOfVerts();
  for (vtkIdType c = firstLine; c < firstLine + input->GetNumberOfLines(); ++c) {
    const double s = subgraph->GetComponent(c, 0);
    if (!std::isfinite(s) || s < 0 || s != std::floor(s) || s > 1e9) {
      return false;
    }
    const size_t id = static_cast<size_t>(s);
    const int t = timeValue(cellTime, c, "cell");
    if (id >= known.size()) {
      known.resize(id + 1, 0);
      subgraphTime.resize(id + 1, 0);
    }
    if (known[id] && subgraphTime[id] != t) {
      return false;  // not one time per sub-graph
    }
    known[id] = 1;
    subgraphTime[id] = t;
  }
  gl::LatticeGraph graph;
  try {
    graph = gl::toLatticeGraph(input);
  } catch (const gl::GeoLatticeError&) {
    return false;  // not a lattice as the lattice filter writes it: sample the cells
  }
  const gl::MaterialSamples material = gl::sampleLatticeMaterial(graph, spacing);
  out.points = material.points;
  out.normals = material.normals;
  out.group = material.subgraph;
  out.time.resize(material.subgraph.size());
  for (size_t i = 0; i < material.subgraph.size(); ++i) {
    out.time[i] = subgraphTime[material.subgraph[i]];
  }
  return true;
}

/// Any line cells: their points once per time, plus interior points on each segment; the group of
/// a sample is the cell's SubgraphId, if there is such a cell array.
void sampleCells(vtkPolyData* input, vtkDataArray* normals, vtkDataArray* cellTime, double spacing,
                 Stations& out) {
  vtkDataArray* cellGroup = input->GetCellData()->GetArray(gl::arrays::SubgraphId);
  int group = -1;
  std::vector<std::vector<int>> emitted(
      input->GetNumberOfPoints());  // times a point was sampled with
  auto addPoint = [&](vtkIdType p, int t) {
    std::vector<int>& times = emitted[p];
    if (std::find(times.begin(), times.end(), t) != times.end()) {
      return;
    }
    times.push_back(t);
    double x[3];
    input->GetPoint(p, x);
    out.points.emplace_back(x[0], x[1], x[2]);
    out.normals.push_back(tupleOf(normals, p));
    out.time.push_back(t);
    out.group.push_back(group);
  };
  gl::forEachLine(input, [&](vtkIdType cell, vtkIdType n, const vtkIdType* ids) {
    const int t = timeValue(cellTime, cell, "cell");
    group = idOf(cellGroup, cell);
    for (vtkIdType k = 0; k < n; ++k) {
      addPoint(ids[k], t);
    }
    for (vtkIdType k = 0; k + 1 < n; ++k) {
      double a[3], b[3];
      input->GetPoint(ids[k], a);
      input->GetPoint(ids[k + 1], b);
      const Eigen::Vector3d pa(a[0], a[1], a[2]), pb(b[0], b[1], b[2]);
      const Eigen::Vector3d na = tupleOf(normals, ids[k]).normalized();
      const Eigen::Vector3d nb = tupleOf(normals, ids[k + 1]).normalized();
      const int segments = static_cast<int>(std::ceil((pb - pa).norm() / spacing));
      for (int j = 1; j < segments; ++j) {
        const double s = static_cast<double>(j) / segments;
        out.points.push_back((1 - s) * pa + s * pb);
        const Eigen::Vector3d nrm = (1 - s) * na + s * nb;
        out.normals.push_back(nrm.norm() > 0 ? Eigen::Vector3d(nrm.normalized()) : nrm);
        out.time.push_back(t);
        out.group.push_back(group);
      }
    }
  });
}

void buildOutput(const gl::CollisionReport& report, double nozzleAngle, vtkPolyData* out) {
  const vtkIdType R = static_cast<vtkIdType>(report.violations.size());
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(2 * R);
  vtkNew<vtkIntArray> index, role, unavoidable;
  index->SetName(gl::arrays::ViolationIndex);
  index->SetNumberOfTuples(2 * R);
  role->SetName(gl::arrays::Role);
  role->SetNumberOfTuples(2 * R);
  unavoidable->SetName(gl::arrays::Unavoidable);
  unavoidable->SetNumberOfTuples(2 * R);
  vtkNew<vtkDoubleArray> height, radial;
  height->SetName(gl::arrays::Height);
  height->SetNumberOfTuples(2 * R);
  radial->SetName(gl::arrays::Radial);
  radial->SetNumberOfTuples(2 * R);
  vtkNew<vtkCellArray> lines;
  lines->AllocateExact(R, 2 * R);
  for (vtkIdType k = 0; k < R; ++k) {
    const gl::CollisionViolation& v = report.violations[k];
    const vtkIdType ids[2] = {2 * k, 2 * k + 1};
    points->SetPoint(ids[0], v.stationPoint.data());
    points->SetPoint(ids[1], v.obstaclePoint.data());
    for (int j = 0; j < 2; ++j) {
      index->SetValue(ids[j], static_cast<int>(k));
      role->SetValue(ids[j], j == 0 ? gl::collisionrole::Station : gl::collisionrole::Obstacle);
      height->SetValue(ids[j], v.height);
      radial->SetValue(ids[j], v.radial);
      unavoidable->SetValue(ids[j], v.unavoidable ? 1 : 0);
    }
    lines->InsertNextCell(2, ids);
  }
  out->SetPoints(points);
  out->SetLines(lines);
  vtkPointData* pd = out->GetPointData();
  pd->AddArray(index);
  pd->AddArray(role);
  pd->AddArray(height);
  pd->AddArray(radial);
  pd->AddArray(unavoidable);
  pd->SetActiveScalars(gl::arrays::Role);

  vtkFieldData* fd = out->GetFieldData();
  for (const auto& [name, value] :
       {std::pair<const char*, bool>{gl::arrays::CollisionFree, report.collisionFree},
        {gl::arrays::CollisionOrderFree, report.orderCollisionFree}}) {
    vtkNew<vtkIntArray> flag;
    flag->SetName(name);
    flag->InsertNextValue(value ? 1 : 0);
    fd->AddArray(flag);
  }
  gl::addFieldArray(fd, gl::arrays::CollisionStations, {static_cast<double>(report.stations)});
  gl::addFieldArray(fd, gl::arrays::CollisionViolatingStations,
                    {static_cast<double>(report.violatingStations)});
  gl::addFieldArray(fd, gl::arrays::CollisionUnavoidableStations,
                    {static_cast<double>(report.unavoidableStations)});
  gl::addFieldArray(fd, gl::arrays::CollisionSeconds, {report.seconds});
  gl::addFieldArray(fd, gl::arrays::CollisionPlateStations,
                    {static_cast<double>(report.plateStations)});
  gl::addFieldArray(fd, gl::arrays::NozzleAngleDeg, {nozzleAngle});
}
}  // namespace

vtkGLCollisionVerifier::vtkGLCollisionVerifier() {
  this->SetNumberOfOutputPorts(2);
  this->SetTimeArrayName(geolattice::arrays::PrintOrder);
  this->SampleSpacing = gl::MaterialSampling{}.spacing;
  this->MaxReported = gl::VerifierOptions{}.maxReported;
}

vtkGLCollisionVerifier::~vtkGLCollisionVerifier() {
  this->SetTimeArrayName(nullptr);
}

int vtkGLCollisionVerifier::RequestInformation(vtkInformation* request,
                                               vtkInformationVector** inputs,
                                               vtkInformationVector* outputs) {
  return this->Superclass::RequestInformation(request, inputs, outputs) &&
         gl::checkParameters(this, [&] {
           if (this->MaxReported < 0) {
             throw gl::GeoLatticeError("collision verifier: MaxReported must be >= 0 (got " +
                                       std::to_string(this->MaxReported) + ")");
           }
         });
}

namespace {
/// Output 1: every station's verdict (gl::arrays::Collision). A toolpath (point times) is the
/// input itself with the array, ready to colour; sampled line cells are the samples as vertices.
void buildStations(vtkPolyData* input, bool pointStations, const Stations& stations,
                   const gl::CollisionReport& report, vtkPolyData* out) {
  vtkNew<vtkUnsignedCharArray> kind;
  kind->SetName(gl::arrays::Collision);
  kind->SetNumberOfTuples(static_cast<vtkIdType>(stations.points.size()));
  kind->Fill(gl::collisionkind::Clear);
  for (int k : report.violatingStationIds) {
    kind->SetValue(k, gl::collisionkind::Material);
  }
  for (int k : report.plateStationIds) {
    kind->SetValue(k, gl::collisionkind::Plate);
  }
  if (pointStations) {
    out->ShallowCopy(input);
  } else {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    vtkNew<vtkCellArray> vertices;
    for (const gl::Vec3& p : stations.points) {
      const vtkIdType id = points->InsertNextPoint(p.data());
      vertices->InsertNextCell(1, &id);
    }
    out->SetPoints(points);
    out->SetVerts(vertices);
  }
  out->GetPointData()->AddArray(kind);
}
}  // namespace

int vtkGLCollisionVerifier::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                        vtkInformationVector* outputVector) {
  // Collective in an MPI run: all the printed points on one process (vtkGLParallel.h).
  return gl::runRequest(this, inputVector, 1, outputVector, [&](const gl::ParallelInputs& inputs) {
    vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
    vtkPolyData* verdicts = vtkPolyData::GetData(outputVector, 1);
    vtkPolyData* input = inputs.Get<vtkPolyData>(0);
    const gl::NozzleModel nozzle = gl::nozzleModel(this->Nozzle);
    const gl::BuildPlate plate = gl::buildPlate(this->Nozzle);

    if (!input || input->GetNumberOfPoints() == 0) {
      throw gl::GeoLatticeError("empty input: no printed points to verify");
    }
    vtkPointData* pd = input->GetPointData();
    vtkDataArray* normals = gl::nozzleAxisOf(pd);
    if (!normals) {
      throw gl::GeoLatticeError(std::string("input has no ") + gl::arrays::NozzleAxis +
                                " point array with 3 components (the nozzle directions)");
    }
    const std::string name = this->TimeArrayName ? this->TimeArrayName : "";
    vtkDataArray* cellTime = name.empty() ? nullptr : input->GetCellData()->GetArray(name.c_str());
    vtkDataArray* pointTime = name.empty() ? nullptr : pd->GetArray(name.c_str());
    if (!cellTime && !pointTime) {
      throw gl::GeoLatticeError(
          "input has no cell or point array '" + name +
          "' (the print time, e.g. PrintOrder of GL Print Sequencer; set TimeArrayName)");
    }

    gl::checkAbort(this, 0.05);
    Stations stations;
    if (cellTime) {
      if (input->GetNumberOfLines() == 0) {
        throw gl::GeoLatticeError("input has no line cells to sample (the time array '" + name +
                                  "' is a cell array)");
      }
      if (!(this->SampleSpacing > 0)) {
        throw gl::GeoLatticeError("sample spacing must be > 0 mm, got " +
                                  std::to_string(this->SampleSpacing));
      }
      if (!sampleLattice(input, cellTime, this->SampleSpacing, stations)) {
        sampleCells(input, normals, cellTime, this->SampleSpacing, stations);
      }
    } else {
      vtkDataArray* pointGroup = pd->GetArray(gl::arrays::SubgraphId);
      vtkDataArray* moveKind =
          pd->GetArray(gl::arrays::MoveKind);  // a toolpath: air points are no material
      const vtkIdType V = input->GetNumberOfPoints();
      for (vtkIdType v = 0; v < V; ++v) {
        double x[3];
        input->GetPoint(v, x);
        stations.points.emplace_back(x[0], x[1], x[2]);
        stations.normals.push_back(tupleOf(normals, v));
        stations.time.push_back(timeValue(pointTime, v, "point"));
        stations.group.push_back(idOf(pointGroup, v));
        if (moveKind) {
          stations.material.push_back(moveKind->GetComponent(v, 0) != gl::movekind::Air ? 1 : 0);
        }
      }
    }
    // Obstacles of a skeleton ancestor of the station's sub-graph are unavoidable (Criterion 1
    // prints them first in every order).
    gl::CollisionExemption exemption;
    std::unique_ptr<gl::SkeletonAncestry> ancestry;
    int K = 0;
    if (vtkDataArray* edges = input->GetFieldData()->GetArray(gl::arrays::SkeletonEdges)) {
      ancestry = ancestryOf(edges, K);
      exemption.group = stations.group;
      exemption.unavoidable = [&ancestry, K](int station, int obstacle) {
        return station >= 0 && obstacle >= 0 && station < K && obstacle < K &&
               ancestry->isAncestor(obstacle, station);
      };
    }
    // The check itself is one core call: progress before and after it.
    gl::checkAbort(this, 0.2);
    const gl::CollisionReport report =
        gl::verifyNozzleClearance(stations.points, stations.normals, stations.time, nozzle,
                                  this->MaxReported, ancestry ? &exemption : nullptr,
                                  stations.material.empty() ? nullptr : &stations.material, &plate);
    gl::checkAbort(this, 0.9);
    buildOutput(report, nozzle.halfAngleDeg, output);
    buildStations(input, pointTime != nullptr, stations, report, verdicts);

    // Where on the part the collisions are: the layer range of the violating stations.
    vtkDataArray* layer = pointTime ? pd->GetArray(gl::arrays::LayerId) : nullptr;
    if (layer && !report.violatingStationIds.empty()) {
      double lo = VTK_DOUBLE_MAX, hi = VTK_DOUBLE_MIN;
      for (int k : report.violatingStationIds) {
        const double l = layer->GetComponent(k, 0);
        if (l >= 0) {  // air points carry -1
          lo = std::min(lo, l);
          hi = std::max(hi, l);
        }
      }
      if (lo <= hi) {
        gl::addFieldArray(output->GetFieldData(), gl::arrays::CollisionLayerRange, {lo, hi});
      }
    }
    // Both outputs carry the verdict (CollisionFree, the counts, the layer range).
    vtkFieldData* fd = output->GetFieldData();
    for (int i = 0; i < fd->GetNumberOfArrays(); ++i) {
      verdicts->GetFieldData()->AddArray(fd->GetAbstractArray(i));
    }
    this->UpdateProgress(1.0);
  });
}

void vtkGLCollisionVerifier::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TimeArrayName: " << (this->TimeArrayName ? this->TimeArrayName : "(none)")
     << "\n";
  os << indent << "SampleSpacing: " << this->SampleSpacing << " mm\n";
  os << indent << "MaxReported: " << this->MaxReported << "\n";
}
