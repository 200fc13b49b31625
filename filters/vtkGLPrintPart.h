/**
 * @class   vtkGLPrintPart
 * @brief   The whole GeoLattice pipeline in one filter: a surface in, the toolpath, its summary
 *          and the stages a user inspects out (ParaView's "one Apply").
 *
 * Runs GLPrintPipeline (filters/GLPrintPipeline.h: the same filters, the same wiring and the same
 * defaults as the command-line tool) from the placement on: place on the platform, orient,
 * pedestal, tetrahedralize, fields, layers, lattice, skeleton, order, toolpath, its verifier and
 * the summary. A parameter change re-runs only the stages from the one it belongs to (each stage
 * keeps its output until its input or parameters change).
 *
 * Input:  vtkPolyData, a closed triangle surface (any units the placement scales; mm after it).
 * Outputs: 0 `Toolpath` (vtkGLToolpathPlanner's, with point array `Collision` of the strict
 *   verifier: 0 clear, 1 material, 2 build plate), 1 `Summary` (vtkTable: vtkGLPrintSummary's, with
 *   the strict verifier), 2 `Sequenced Lattice` (PrintOrder), 3 `Layers`, 4 `Part` (the tet mesh with
 *   Gamma, Alpha, Beta), 5 `Verdict` (vtkTable, one row of string column `Text`: "GeoLattice: " and
 *   the summary's verdict in words, a line break before its numbers, with where to look when it
 *   collides; ParaView shows it as a text annotation in the render view). On Apply ParaView shows
 *   the toolpath, the verdict and the summary (spreadsheet view); the other outputs on request
 *   (plugin/xml/GLPrintPart.xml's View hints).
 *
 * The input is cleaned as vtkGLMeshReader cleans a file (gl::newSurfaceCleaner): a part opened
 * with ParaView's own reader prints as the command line prints the file.
 *
 * Parameters (each read from and written to the stage filter it belongs to, so the defaults are
 * those filters' = the CLI's): Scale, FitSize (GL Place On Platform), Orient (0 keep, 1 auto),
 * OrientTries (with Orient Auto, candidates run through the toolpath when the best one's
 * collides: GLPrintPipeline::ChooseOrientationByToolpath; default 3), PedestalHeight (mm; -1 = the
 * orientation search decides, 0 = none: GLPrintPipeline::
 * SetPedestalRequest), TargetEdgeLength (mm, 0 = automatic), LayerInterval (mm; the first layer
 * follows it, as on the command line), LatticeWidth (mm, α and β), Strategy (0 LPT .. 3 Best;
 * with Best and Orient Auto, when the toolpath of its order collides, the LPT and DPT orders are run through the
 * toolpath too and the one that collides least is printed: GLPrintPipeline::
 * ChooseOrderByToolpath), NozzleAngle (degrees), PrintheadFile (empty = the parametric cone).
 * Those tries (orientations, then taller pedestals, then orders) are
 * GLPrintPipeline::FindAPrintableSetUp, the sequence the command line runs too; before them the
 * part on its own base or as placed is put first where the search may have misjudged it
 * (GLPrintPipeline::PreferTheBaseToAPedestal, PreferThePlacementToATallerPrint).
 *
 * Errors (vtkErrorMacro naming the stage and its message, empty outputs, RequestData returns 0):
 * whatever a stage rejects.
 */
#ifndef vtkGLPrintPart_h
#define vtkGLPrintPart_h

#include "GeoLatticeFiltersModule.h"
#include "vtkAlgorithm.h"

#include <memory>

class GLPrintPipeline;

class GEOLATTICEFILTERS_EXPORT vtkGLPrintPart : public vtkAlgorithm {
public:
  static vtkGLPrintPart* New();
  vtkTypeMacro(vtkGLPrintPart, vtkAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum OutputPorts {
    ToolpathPort = 0,
    SummaryPort,
    LatticePort,
    LayersPort,
    PartPort,
    VerdictPort,
    NumberOfPorts
  };

  void SetScale(double v);
  double GetScale();
  void SetFitSize(double v);
  double GetFitSize();
  void SetOrient(int v);
  int GetOrient();
  void SetOrientTries(int v);
  int GetOrientTries();
  void SetPedestalHeight(double v);
  double GetPedestalHeight();
  void SetTargetEdgeLength(double v);
  double GetTargetEdgeLength();
  void SetLayerInterval(double v);
  double GetLayerInterval();
  void SetLatticeWidth(double v);
  double GetLatticeWidth();
  void SetStrategy(int v);
  int GetStrategy();
  void SetNozzleAngle(double v);
  double GetNozzleAngle();
  void SetPrintheadFile(const char* path);
  const char* GetPrintheadFile();

  /// The internal pipeline's filters (for C++ callers that tune more than the properties above;
  /// call Modified() on this filter afterwards).
  GLPrintPipeline& Pipeline();

  vtkTypeBool ProcessRequest(vtkInformation*, vtkInformationVector**,
                             vtkInformationVector*) override;

protected:
  vtkGLPrintPart();
  ~vtkGLPrintPart() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*);

private:
  vtkGLPrintPart(const vtkGLPrintPart&) = delete;
  void operator=(const vtkGLPrintPart&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
