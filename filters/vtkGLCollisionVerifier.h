/**
 * @class   vtkGLCollisionVerifier
 * @brief   Independent check that a print never drives the nozzle into material printed
 *          before: reports every station where earlier material lies inside the nozzle.
 *
 * core/collision/CollisionVerifier.h (shares no code with the sequencer's PCG envelopes): every
 * printed point is a nozzle station with its axis and print time; a violation is a point printed
 * strictly earlier that lies inside the nozzle volume at a station (core/nozzle/NozzleModel.h:
 * cone of half-angle NozzleAngle about the axis, apex at the tip, optionally cut at NozzleLength
 * above which the holder is a cylinder of radius HolderRadius; material at most TipClearance mm
 * above the tip is ignored). A collision is a result, not an error.
 *
 * Unavoidable collisions: when the input's field data holds `SkeletonEdges` (written by
 * vtkGLPrintSequencer: (lower, upper) sub-graph ids of the skeleton) and the samples belong to
 * sub-graphs (cell or point array `SubgraphId`), an obstacle of a skeleton ancestor of the
 * station's sub-graph is material that Criterion 1 prints first in every order (a wide nozzle
 * over a curved layer reaching the layers below). Such violations are still reported
 * (CollisionFree stays strict) but flagged, and CollisionOrderFree ignores them: it says whether
 * the order itself is at fault.
 *
 * Input:  vtkPolyData with line cells, point array `NozzleAxis` (3 components: the nozzle axis) and
 *         a print-time array named by TimeArrayName (default `PrintOrder`, as written by
 *         vtkGLPrintSequencer on its Sequenced Lattice output); values must be integers.
 *   - If it is a cell array (looked for first), the material is sampled: every point of each
 *     line cell plus ceil(len / SampleSpacing) - 1 evenly spaced interior points on each segment
 *     (normals interpolated linearly and normalised); every sample gets the time of its cell, and
 *     a point shared by cells of the same time is one sample. A lattice (cell arrays SubgraphId,
 *     LayerId, point array Gamma, one time per sub-graph) is sampled by the same code as the
 *     sequencer (core/sequence/PrintMaterial.h), so both test the same points.
 *   - If it is a point array, every point of the input is one station with that time (a
 *     toolpath: time = index along the path, e.g. `PointIndex` of vtkGLToolpathPlanner). If the
 *     input also has a point array `MoveKind` (a toolpath), points with MoveKind 2 (air moves)
 *     are stations but not material: only print and perimeter points are obstacles.
 * Output: vtkPolyData, per reported violation (at most MaxReported, the first in print time) two
 *   points, the station (the tip) and the obstacle, joined by a line cell, with point data
 *   `ViolationIndex` (int), `Role` (int: 0 station, 1 obstacle; geolattice::collisionrole),
 *   `Height` (obstacle height above the tip along the axis, mm), `Radial` (its distance from the
 *   axis, mm) and `Unavoidable` (int: 1 when every obstacle of the station is a skeleton
 *   ancestor's), all on both points; field data `CollisionFree` (int: 1 or 0),
 *   `CollisionOrderFree` (int: 1 when every violation is unavoidable; = CollisionFree without
 *   SkeletonEdges), `CollisionStations` (points checked), `CollisionViolatingStations`,
 *   `CollisionUnavoidableStations`, `CollisionSeconds` and `NozzleAngleDeg`.
 * Output port 1 (Stations): every station's verdict, point array `Collision` (unsigned char,
 *   geolattice::collisionkind: 0 clear, 1 earlier material inside the nozzle, 2 the build plate):
 *   for point times (a toolpath) the input itself with that array, so the path can be coloured
 *   where it collides; for sampled line cells the samples as vertices. Its field data holds the
 *   verdict arrays of output 0 too.
 * Parameters: TimeArrayName (default "PrintOrder"), the nozzle (vtkGLNozzle: NozzleAngle,
 *   NozzleLength, HolderRadius, TipClearance, TipFaceRadius), SampleSpacing (mm, default 1, > 0),
 *   MaxReported (default 20).
 * Errors (an empty input, missing NozzleAxis or time array, a non-integer or non-finite time, a zero
 * normal, NozzleAngle outside (0, 90) or another bad nozzle, SampleSpacing <= 0, SkeletonEdges
 * without 2 components, with a negative id or a cycle) are reported with vtkErrorMacro and give
 * an empty output without field data.
 */
#ifndef vtkGLCollisionVerifier_h
#define vtkGLCollisionVerifier_h

#include "GeoLatticeFiltersModule.h"
#include "vtkGLNozzleAlgorithm.h"

class GEOLATTICEFILTERS_EXPORT vtkGLCollisionVerifier : public vtkGLNozzleAlgorithm {
public:
  static vtkGLCollisionVerifier* New();
  vtkTypeMacro(vtkGLCollisionVerifier, vtkGLNozzleAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Name of the print-time array, a cell or point array (default "PrintOrder").
  vtkSetStringMacro(TimeArrayName);
  vtkGetStringMacro(TimeArrayName);
  ///@}

  ///@{
  /// Spacing of the samples along the line cells (mm, default 1, > 0; cell time arrays only).
  vtkSetMacro(SampleSpacing, double);
  vtkGetMacro(SampleSpacing, double);
  ///@}

  ///@{
  /// Violations written to the output, the first in print time (default 20).
  vtkSetClampMacro(MaxReported, int, 0, VTK_INT_MAX);
  vtkGetMacro(MaxReported, int);
  ///@}

protected:
  vtkGLCollisionVerifier();
  ~vtkGLCollisionVerifier() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* TimeArrayName = nullptr;
  double SampleSpacing;
  int MaxReported;

private:
  vtkGLCollisionVerifier(const vtkGLCollisionVerifier&) = delete;
  void operator=(const vtkGLCollisionVerifier&) = delete;
};

#endif
