#include "vtkGLPrintPart.h"

#include "GLPrintPipeline.h"
#include "vtkGLArrayNames.h"
#include "vtkGLMeshConversion.h"
#include "vtkGLRequest.h"

#include "common/Error.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkDataObject.h>
#include <vtkDemandDrivenPipeline.h>
#include <vtkExecutive.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkTable.h>
#include <vtkUnstructuredGrid.h>

#include <string>

vtkStandardNewMacro(vtkGLPrintPart);

namespace gl = geolattice;

namespace {
/// The text annotation of the Verdict output: the summary's verdict in words (a line break before
/// its first parenthesis and after each clause) and, when the toolpath collides, the layers and how to see the stations.
vtkSmartPointer<vtkStringArray> VerdictText(vtkDataObject* summary, vtkDataObject* verifier) {
  std::string text = "GeoLattice: ";
  auto* verdict = vtkStringArray::SafeDownCast(
      summary->GetFieldData()->GetAbstractArray(gl::arrays::SummaryVerdict));
  std::string words = verdict && verdict->GetNumberOfValues() > 0 ? verdict->GetValue(0) : "";
  // The verdict on the first line, its numbers below, a line per clause: one line is wider than
  // the view.
  const size_t details = words.find(" (");
  if (details != std::string::npos) {
    words[details] = '\n';
    for (const char* clause : {"; ", "): "}) {
      for (size_t at = words.find(clause, details); at != std::string::npos;
           at = words.find(clause, at + 1)) {
        words[at + std::string(clause).size() - 1] = '\n';
      }
    }
  }
  text += words.empty() ? "no verdict" : words;
  vtkDataArray* layers = verifier->GetFieldData()->GetArray(gl::arrays::CollisionLayerRange);
  vtkDataArray* colliding =
      verifier->GetFieldData()->GetArray(gl::arrays::CollisionViolatingStations);
  if (layers && colliding && colliding->GetTuple1(0) > 0 && layers->GetNumberOfValues() >= 2) {
    const int nc = layers->GetNumberOfComponents();
    auto value = [&](int k) {
      return std::to_string(static_cast<long long>(layers->GetComponent(k / nc, k % nc)));
    };
    text += "\ncollisions in layers " + value(0) + "-" + value(1) +
            ": colour the Toolpath by Collision; try Orient Auto or a Printhead File";
  }
  auto column = vtkSmartPointer<vtkStringArray>::New();
  column->SetName("Text");
  column->InsertNextValue(text);
  return column;
}
}  // namespace

struct vtkGLPrintPart::Internals {
  GLPrintPipeline pipeline;
  vtkNew<vtkPolyData> input;  ///< the input surface, copied only when it changed
  vtkMTimeType inputTime = 0;
  vtkDataObject* inputObject = nullptr;
  /// The first error a stage filter reported (caught instead of printed: the composite reports
  /// it once, naming the stage).
  std::string error;
  vtkNew<vtkCallbackCommand> onError;

  Internals() {
    onError->SetClientData(this);
    onError->SetCallback([](vtkObject*, unsigned long, void* self, void* text) {
      auto* in = static_cast<Internals*>(self);
      if (in->error.empty() && text) {
        // vtkErrorMacro's text: "ERROR: In FILE, line N\nCLASS (0x...): MESSAGE\n\n".
        std::string message = static_cast<const char*>(text);
        const size_t start = message.find("): ");
        if (start != std::string::npos) {
          message = message.substr(start + 3);
        }
        while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) {
          message.pop_back();
        }
        in->error = message;
      }
    });
    for (int s = GLPrintPipeline::Place; s < GLPrintPipeline::NumberOfStages; ++s) {
      pipeline.Filter(static_cast<GLPrintPipeline::Stage>(s))
          ->AddObserver(vtkCommand::ErrorEvent, onError);
    }
    pipeline.Placement->SetInputData(input);
  }
};

vtkGLPrintPart::vtkGLPrintPart() : Internal(new Internals) {
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(NumberOfPorts);
}

vtkGLPrintPart::~vtkGLPrintPart() = default;

GLPrintPipeline& vtkGLPrintPart::Pipeline() {
  return this->Internal->pipeline;
}

// Each parameter lives in its stage filter (its default is that filter's); the setters forward
// and mark this filter modified, the getters read back.
#define GL_FORWARD(Type, Name, Filter, Member)         \
  void vtkGLPrintPart::Set##Name(Type v) {             \
    if (this->Pipeline().Filter->Get##Member() != v) { \
      this->Pipeline().Filter->Set##Member(v);         \
      this->Modified();                                \
    }                                                  \
  }                                                    \
  Type vtkGLPrintPart::Get##Name() {                   \
    return this->Pipeline().Filter->Get##Member();     \
  }
GL_FORWARD(double, Scale, Placement, Scale)
GL_FORWARD(double, FitSize, Placement, FitSize)
GL_FORWARD(int, Orient, Orientation, Orient)
GL_FORWARD(double, TargetEdgeLength, Tetrahedralize, TargetEdgeLength)
GL_FORWARD(int, Strategy, Sequencer, Strategy)
GL_FORWARD(double, NozzleAngle, Nozzle, NozzleAngle)
#undef GL_FORWARD

void vtkGLPrintPart::SetOrientTries(int v) {
  if (this->Pipeline().OrientationTries != v) {
    this->Pipeline().OrientationTries = v;
    this->Modified();
  }
}

int vtkGLPrintPart::GetOrientTries() {
  return this->Pipeline().OrientationTries;
}

void vtkGLPrintPart::SetPedestalHeight(double v) {
  if (this->Pipeline().GetPedestalRequest() != v) {
    this->Pipeline().SetPedestalRequest(v);
    this->Modified();
  }
}

double vtkGLPrintPart::GetPedestalHeight() {
  return this->Pipeline().GetPedestalRequest();
}

void vtkGLPrintPart::SetLatticeWidth(double v) {
  GLPrintPipeline& p = this->Pipeline();
  if (p.LatticeInfill->GetAlphaWidth() != v || p.LatticeInfill->GetBetaWidth() != v) {
    p.LatticeInfill->SetAlphaWidth(v);
    p.LatticeInfill->SetBetaWidth(v);
    this->Modified();
  }
}

double vtkGLPrintPart::GetLatticeWidth() {
  return this->Pipeline().LatticeInfill->GetAlphaWidth();
}

// The first layer follows the interval, as on the command line (--layer-interval).
void vtkGLPrintPart::SetLayerInterval(double v) {
  GLPrintPipeline& p = this->Pipeline();
  if (p.Slicer->GetLayerInterval() != v || p.Slicer->GetFirstLayerOffset() != v) {
    p.Slicer->SetLayerInterval(v);
    p.Slicer->SetFirstLayerOffset(v);
    this->Modified();
  }
}

double vtkGLPrintPart::GetLayerInterval() {
  return this->Pipeline().Slicer->GetLayerInterval();
}

void vtkGLPrintPart::SetPrintheadFile(const char* path) {
  const std::string now = this->GetPrintheadFile() ? this->GetPrintheadFile() : "";
  if (now != (path ? path : "")) {
    this->Pipeline().Nozzle->SetPrintheadFile(path);
    this->Modified();
  }
}

const char* vtkGLPrintPart::GetPrintheadFile() {
  return this->Pipeline().Nozzle->GetPrintheadFile();
}

void vtkGLPrintPart::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Scale: " << this->GetScale() << "\n";
  os << indent << "FitSize: " << this->GetFitSize() << " mm\n";
  os << indent << "Orient: " << this->GetOrient() << "\n";
  os << indent << "OrientTries: " << this->GetOrientTries() << "\n";
  os << indent << "PedestalHeight: " << this->GetPedestalHeight() << " mm\n";
  os << indent << "TargetEdgeLength: " << this->GetTargetEdgeLength() << " mm\n";
  os << indent << "LayerInterval: " << this->GetLayerInterval() << " mm\n";
  os << indent << "LatticeWidth: " << this->GetLatticeWidth() << " mm\n";
  os << indent << "Strategy: " << this->GetStrategy() << "\n";
  os << indent << "NozzleAngle: " << this->GetNozzleAngle() << " deg\n";
  os << indent << "PrintheadFile: " << (this->GetPrintheadFile() ? this->GetPrintheadFile() : "")
     << "\n";
}

int vtkGLPrintPart::FillInputPortInformation(int, vtkInformation* info) {
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

int vtkGLPrintPart::FillOutputPortInformation(int port, vtkInformation* info) {
  const char* type = port == SummaryPort || port == VerdictPort ? "vtkTable"
                     : port == PartPort                         ? "vtkUnstructuredGrid"
                                                                : "vtkPolyData";
  info->Set(vtkDataObject::DATA_TYPE_NAME(), type);
  return 1;
}

vtkTypeBool vtkGLPrintPart::ProcessRequest(vtkInformation* request, vtkInformationVector** in,
                                           vtkInformationVector* out) {
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA())) {
    return this->RequestData(request, in, out);
  }
  return this->Superclass::ProcessRequest(request, in, out);
}

int vtkGLPrintPart::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                vtkInformationVector* outputVector) {
  gl::clearOutputs(outputVector);
  Internals& I = *this->Internal;
  GLPrintPipeline& p = I.pipeline;
  return gl::runRequest(this, outputVector, [&] {
    vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
    if (!input || input->GetNumberOfPolys() == 0) {
      throw gl::GeoLatticeError(
          "empty input: GL Print Part needs a closed triangle surface (open "
          "the model with File > Open or GL Mesh Reader)");
    }
    // Cleaned only when it changed: a parameter change then re-runs only the stages after it.
    // Cleaned as GL Mesh Reader cleans a file, so a part opened with ParaView's own reader (its
    // own point order, split vertices) prints as the command line prints the same file.
    if (input != I.inputObject || input->GetMTime() != I.inputTime) {
      vtkSmartPointer<vtkAlgorithm> clean = gl::newSurfaceCleaner(input);
      clean->Update();
      I.input->ShallowCopy(clean->GetOutputDataObject(0));
      I.inputObject = input;
      I.inputTime = input->GetMTime();
    }
    p.MatchOrientationToPrint();
    p.Orientation->SetCandidateRank(0);    // the search's best first
    p.Sequencer->SetStrategyOverride(-1);  // and the order of the Strategy asked for
    p.Pedestal->SetHeightOverride(-1);     // and the search's pedestal
    GLPrintPipeline::ClearStopRequest();
    I.error.clear();
    // Orient Auto: the part on its own base first, where as good; else the placement first,
    // where the search may have misjudged it (GLPrintPipeline.h)
    if (p.PreferTheBaseToAPedestal() < 0) {
      p.PreferThePlacementToATallerPrint();
    }
    I.error.clear();  // (a failing search is reported by its stage below)
    // Each stage in order, so a failure names its stage.
    auto stages = [&] {
      for (GLPrintPipeline::Stage s :
           {GLPrintPipeline::Place, GLPrintPipeline::Orient, GLPrintPipeline::Raise,
            GLPrintPipeline::Mesh, GLPrintPipeline::Fields, GLPrintPipeline::Layers,
            GLPrintPipeline::Lattice, GLPrintPipeline::Skeleton, GLPrintPipeline::Sequence,
            GLPrintPipeline::Toolpath, GLPrintPipeline::ToolpathVerify, GLPrintPipeline::Summary}) {
        vtkAlgorithm* stage = p.Filter(s);
        if (!stage->GetExecutive()->Update() || !I.error.empty()) {
          throw gl::GeoLatticeError(std::string(GLPrintPipeline::StageName(s)) + ": " +
                                    (I.error.empty() ? "the stage failed" : I.error));
        }
        gl::checkAbort(this, static_cast<double>(s) / GLPrintPipeline::NumberOfStages);
      }
    };
    stages();
    // Where the toolpath collides, other orientations, pedestals and orders (Orient Auto only).
    // A try that fails is skipped, so its errors are not this filter's.
    p.FindAPrintableSetUp([&](GLPrintPipeline::SetUpStep) {
      I.error.clear();
      stages();  // every stage at the chosen set-up (cached when it was the last tried)
    });
    vtkPolyData::GetData(outputVector, ToolpathPort)  // with the verifier's Collision array
        ->ShallowCopy(p.ToolpathVerifier->GetOutputDataObject(1));
    vtkTable::GetData(outputVector, SummaryPort)
        ->ShallowCopy(p.PrintSummary->GetOutputDataObject(0));
    vtkPolyData::GetData(outputVector, LatticePort)
        ->ShallowCopy(p.Sequencer->GetOutputDataObject(0));
    vtkPolyData::GetData(outputVector, LayersPort)->ShallowCopy(p.Slicer->GetOutputDataObject(0));
    vtkUnstructuredGrid::GetData(outputVector, PartPort)
        ->ShallowCopy(p.GeodesicFields->GetOutputDataObject(0));
    vtkTable::GetData(outputVector, VerdictPort)
        ->AddColumn(VerdictText(p.PrintSummary->GetOutputDataObject(0),
                                p.ToolpathVerifier->GetOutputDataObject(0)));
    this->UpdateProgress(1.0);
  });
}
