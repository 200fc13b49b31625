/**
 * @class   vtkGLGCodeWriter
 * @brief   Writes a toolpath as 5-axis G-code for a tilting-rotary table machine (A-C or B-C)
 *          with a fixed vertical nozzle.
 *
 * core/program/GCodeWriter.h: for each toolpath point p with nozzle axis n the table angles
 * turn n onto +Z (rotary C about the table normal, then the tilt A about X or B about Y; of the
 * two solutions (c, tilt) and (c + 180°, -tilt) the one nearest to the previous C, C unwrapped,
 * C kept near the pole). Flavor LinuxCNC (default): RS274NGC for LinuxCNC 2.9 (G21 G90 G93,
 * inverse-time F = 1 / minutes on every G1, the extruder's absolute filament position on
 * ExtrusionAxis (default U), G0 air moves, retract / prime as G1 on that axis alone, G94 M2;
 * machines/linuxcnc/ has a matching machine configuration). Flavor RepRap: RepRapFirmware 3
 * (G21 G90 M83, relative E, feed in mm/min so the nozzle moves at the print speed relative to
 * the part; not machine-verified). ToolCentrePoint Controller (default; LinuxCNC only): X Y Z
 * are part coordinates p + PartOffset and the controller's trt kinematics computes the joints;
 * Cam: X Y Z = Pivot + R_tilt R_C (p + PartOffset), the machine positions. Numbers are fixed
 * point with at most 5 decimals (no exponents).
 *
 * Input: vtkPolyData, the output of vtkGLToolpathPlanner (points in point order = printing
 *   order, mm, point arrays `NozzleAxis`, `Extrusion`, `FeedRate`, `MoveKind`, `LayerId`; see
 *   vtkGLURScriptWriter). A time-dependent input is requested at the end of its time range:
 *   the whole toolpath.
 * Output: FileName (e.g. toolpath.gcode or .nc), written to a temporary name first and renamed
 *   when complete: on an error no file (nor partial file) is left and an earlier file of that
 *   name is untouched.
 * Results of the last Write() (reset at its start): GetNumberOfMoves, GetMaxRotaryStepDeg
 *   (largest change of C or the tilt between consecutive points), GetBranchFlips (points where
 *   the other solution was taken to stay inside the tilt limits), GetOutOfLimitsCount,
 *   GetMaxAxisErrorDeg (C may deviate near the pole while the axis stays within 1°, so the
 *   table turns at most 5° per point where possible), GetForcedRotarySteps (points where C had
 *   to turn faster than that).
 * Parameters: Kinematics (0 = AC (default): tilt A about X; 1 = BC: tilt B about Y), Flavor
 *   (default 0 = LinuxCNC), ToolCentrePoint (default 0 = Controller), ExtrusionAxis (default
 *   "U"), Pivot (mm,
 *   machine position of the intersection of the rotary axes, default 0 0 0), PartOffset (mm,
 *   the part frame origin relative to the rotary centre on the table, default 0 0 0),
 *   TiltLimits (degrees, min < max, default -120 120).
 * Errors (no FileName, an empty toolpath, missing arrays, a NaN point or a NaN / zero normal,
 *   bad parameters, points whose nozzle axis needs a tilt outside TiltLimits on both solutions
 *   (naming the count and the first indices), a file that cannot be written) are reported with
 *   vtkErrorMacro; Write() then returns 0 and nothing is written.
 */
#ifndef vtkGLGCodeWriter_h
#define vtkGLGCodeWriter_h

#include "GeoLatticeFiltersModule.h"
#include "vtkGLToolpathWriter.h"

class GEOLATTICEFILTERS_EXPORT vtkGLGCodeWriter : public vtkGLToolpathWriter {
public:
  static vtkGLGCodeWriter* New();
  vtkTypeMacro(vtkGLGCodeWriter, vtkGLToolpathWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum KinematicsType {
    AC = 0,  ///< tilt A about X, then rotary C
    BC = 1   ///< tilt B about Y, then rotary C
  };

  ///@{
  /// Table kinematics: AC (0, default) or BC (1).
  vtkSetClampMacro(Kinematics, int, AC, BC);
  vtkGetMacro(Kinematics, int);
  void SetKinematicsToAC() { this->SetKinematics(AC); }
  void SetKinematicsToBC() { this->SetKinematics(BC); }
  ///@}

  /// Values of Flavor and ToolCentrePoint (= geolattice::GCodeFlavor, ToolCentrePoint).
  enum FlavorType { LINUXCNC = 0, REPRAP = 1 };
  enum ToolCentrePointType { CONTROLLER = 0, CAM = 1 };

  ///@{
  /// G-code dialect: LINUXCNC (0, default) or REPRAP (1); checked when writing.
  vtkSetMacro(Flavor, int);
  vtkGetMacro(Flavor, int);
  ///@}

  ///@{
  /// Who applies the table kinematics: CONTROLLER (0, default; part coordinates, LinuxCNC
  /// trt kinematics) or CAM (1; pre-computed machine coordinates, required by REPRAP).
  vtkSetMacro(ToolCentrePoint, int);
  vtkGetMacro(ToolCentrePoint, int);
  ///@}

  ///@{
  /// LinuxCNC: the axis letter of the extruder (default "U"; U, V, W or the table's free rotary
  /// letter).
  vtkSetStringMacro(ExtrusionAxis);
  vtkGetStringMacro(ExtrusionAxis);
  ///@}

  ///@{
  /// Machine position of the intersection of the two rotary axes (mm, default 0 0 0).
  vtkSetVector3Macro(Pivot, double);
  vtkGetVector3Macro(Pivot, double);
  ///@}

  ///@{
  /// The part frame origin relative to the rotary centre, in the table frame (mm, default 0 0 0).
  vtkSetVector3Macro(PartOffset, double);
  vtkGetVector3Macro(PartOffset, double);
  ///@}

  ///@{
  /// Limits of the tilt axis A or B (degrees, min < max, default -120 120).
  vtkSetVector2Macro(TiltLimits, double);
  vtkGetVector2Macro(TiltLimits, double);
  ///@}

  ///@{
  /// Results of the last Write() (see the class documentation).
  vtkIdType GetNumberOfMoves() const { return this->NumberOfMoves; }
  double GetMaxRotaryStepDeg() const { return this->MaxRotaryStepDeg; }
  vtkIdType GetBranchFlips() const { return this->BranchFlips; }
  /// Largest nozzle-axis error introduced near the pole, where C may deviate (degrees, <= 1).
  double GetMaxAxisErrorDeg() const { return this->MaxAxisErrorDeg; }
  vtkIdType GetForcedRotarySteps() const { return this->ForcedRotarySteps; }
  vtkIdType GetOutOfLimitsCount() const { return this->OutOfLimitsCount; }
  ///@}

protected:
  vtkGLGCodeWriter();
  ~vtkGLGCodeWriter() override;

  void CheckParameters() override;
  void WriteData() override;

  int Kinematics;
  int Flavor;
  int ToolCentrePoint;
  char* ExtrusionAxis = nullptr;
  double Pivot[3];
  double PartOffset[3];
  double TiltLimits[2];

private:
  vtkGLGCodeWriter(const vtkGLGCodeWriter&) = delete;
  void operator=(const vtkGLGCodeWriter&) = delete;

  vtkIdType NumberOfMoves = 0;
  double MaxRotaryStepDeg = 0;
  vtkIdType BranchFlips = 0;
  double MaxAxisErrorDeg = 0;
  vtkIdType ForcedRotarySteps = 0;
  vtkIdType OutOfLimitsCount = 0;
};

#endif
