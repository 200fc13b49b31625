/**
 * @class   vtkGLNozzle
 * @brief   The nozzle volume that must stay clear of printed material: one parameter block
 *          shared by GL Print Sequencer, GL Collision Verifier and GL Toolpath Planner.
 *
 * core/nozzle/NozzleModel.h: the paper's bounding cone (Section 3.1, Fig. 13a) of half-angle
 * NozzleAngle about the nozzle axis, apex at the tip, optionally cut at NozzleLength above which
 * the holder is a cylinder of radius HolderRadius and length HolderLength (0 = unbounded);
 * material at most TipClearance above the tip
 * (level with the nozzle's flat face) or within TipFaceRadius of it (under the face, the bead
 * being pressed) is not an obstacle. With PrintheadFile (a closed triangle mesh in the nozzle
 * frame: tip at the origin, axis +z, mm; core/nozzle/Printhead.h) the printhead replaces the
 * cone and the holder: material inside the solid it sweeps turning about its axis is an
 * obstacle. The build plate (BuildPlate, PlateMargin, PlateThickness;
 * core/nozzle/BuildPlate.h) is an obstacle like printed material.
 *
 * The filters hold one of these (SetNozzle) and re-execute when it changes. In ParaView it is a
 * sub-proxy whose properties appear in each filter's panel (plugin/xml/GLNozzle.xml); the CLI
 * gives the same object to all three filters. Defaults are those of geolattice::NozzleModel.
 */
#ifndef vtkGLNozzle_h
#define vtkGLNozzle_h

#include "GeoLatticeFiltersModule.h"
#include "vtkObject.h"

class GEOLATTICEFILTERS_EXPORT vtkGLNozzle : public vtkObject {
public:
  static vtkGLNozzle* New();
  vtkTypeMacro(vtkGLNozzle, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Nozzle half-angle NA (degrees, default 45; in (0, 90), checked when a filter runs).
  vtkSetMacro(NozzleAngle, double);
  vtkGetMacro(NozzleAngle, double);
  ///@}

  ///@{
  /// Nozzle length L: the cone is cut at this height above the tip (mm, default 0 = cone only).
  vtkSetMacro(NozzleLength, double);
  vtkGetMacro(NozzleLength, double);
  ///@}

  ///@{
  /// Radius of the holder cylinder above the nozzle length (mm, default 0; used when L > 0).
  vtkSetMacro(HolderRadius, double);
  vtkGetMacro(HolderRadius, double);
  ///@}

  ///@{
  /// Length of the holder above the nozzle length (mm, default 0 = unbounded): with it the
  /// printhead ends NozzleLength + HolderLength above the tip.
  vtkSetMacro(HolderLength, double);
  vtkGetMacro(HolderLength, double);
  ///@}

  ///@{
  /// Material at most this high above the tip along the axis is ignored (mm, default 0.1).
  vtkSetMacro(TipClearance, double);
  vtkGetMacro(TipClearance, double);
  ///@}

  ///@{
  /// Material within this distance of the tip lies under the nozzle's flat face (the bead being
  /// pressed), not inside the nozzle (mm, default 0.5, >= 0).
  vtkSetMacro(TipFaceRadius, double);
  vtkGetMacro(TipFaceRadius, double);
  ///@}

  ///@{
  /// With a printhead: material at most this high above the tip and within the printhead's face
  /// radius + this of the axis is a neighbouring bead the face presses, not an obstacle (mm,
  /// default 0.3, >= 0). Not used by the cone.
  vtkSetMacro(FaceContact, double);
  vtkGetMacro(FaceContact, double);
  ///@}

  ///@{
  /// The build plate is an obstacle for the nozzle (default on): a slab under z = 0 covering the
  /// part's footprint grown by PlateMargin (core/nozzle/BuildPlate.h).
  vtkSetMacro(BuildPlate, vtkTypeBool);
  vtkGetMacro(BuildPlate, vtkTypeBool);
  vtkBooleanMacro(BuildPlate, vtkTypeBool);
  ///@}

  ///@{
  /// How far the build plate extends beyond the part's footprint (mm, default 10, >= 0).
  vtkSetMacro(PlateMargin, double);
  vtkGetMacro(PlateMargin, double);
  ///@}

  ///@{
  /// Thickness of the build plate under z = 0 (mm, default 5, > 0).
  vtkSetMacro(PlateThickness, double);
  vtkGetMacro(PlateThickness, double);
  ///@}

  ///@{
  /// A printhead mesh file (.stl .obj .ply .vtp .off; default empty = the cone model): a closed
  /// triangle mesh in the nozzle frame, the tip at the origin, the axis +z up into the printhead,
  /// millimetres. It replaces NozzleAngle, NozzleLength and the holder; the tip exemptions stay.
  vtkSetFilePathMacro(PrintheadFile);
  vtkGetFilePathMacro(PrintheadFile);
  ///@}

  /// Copies every parameter of `other` (no-op for null).
  void CopyParameters(vtkGLNozzle* other);

protected:
  vtkGLNozzle();
  ~vtkGLNozzle() override;

  double NozzleAngle;
  double NozzleLength;
  double HolderRadius;
  double HolderLength;
  double TipClearance;
  double TipFaceRadius;
  double FaceContact;
  vtkTypeBool BuildPlate;
  double PlateMargin;
  double PlateThickness;
  char* PrintheadFile = nullptr;

private:
  vtkGLNozzle(const vtkGLNozzle&) = delete;
  void operator=(const vtkGLNozzle&) = delete;
};

#endif
