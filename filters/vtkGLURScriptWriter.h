/**
 * @class   vtkGLURScriptWriter
 * @brief   Writes the URScript program that prints a toolpath in the robot cell of the paper (a
 *          UR5 / UR5e holds the part under a fixed nozzle), split into numbered files below a
 *          size limit.
 *
 * Paper Section 4 (Fig. 19), core/robot/RobotPathSolver.h and core/program/URScriptWriter.h:
 * for every toolpath point the robot puts the part so that the point is at the nozzle tip with
 * its nozzle axis along the nozzle body; the free rotation ψ about the nozzle axis is chosen
 * along the path (dynamic programming over the 8 IK branches), joints stay continuous. The
 * program is `def NAME(): … end` with set_tcp (the part frame on the flange), one time-based
 * movel per toolpath segment (its time keeps every joint within SpeedFactor × its speed limit),
 * blending up to MaxBlend, and the extrusion rate on standard analog output 0 (level 0..1 =
 * 0..MaxFilamentRate mm/s of filament; 0 on air moves; retractions and primes as waits).
 *
 * Input: vtkPolyData, the output of vtkGLToolpathPlanner: its points in point order (the
 *   printing order; cells are not used), in mm in the platform (part) frame, with the point
 *   arrays `NozzleAxis` (3 components, nozzle axis), `Extrusion` (cumulative filament, mm),
 *   `FeedRate` (mm/s), `MoveKind` (0 print, 1 perimeter, 2 air) and `LayerId`. A time-dependent
 *   input (the planner's print replay) is requested at the end of its time range, i.e. the
 *   whole toolpath, whatever time the pipeline asks for: a program is always of the whole path.
 * Output files (FileName = DIR/STEM.EXT, e.g. part.script):
 *   - program file 0 is FileName itself, program file k >= 1 is DIR/STEM_k.EXT (part_1.script,
 *     part_2.script, …), so that file STEM_k.EXT holds `def NAME_k():` (the core numbers the
 *     programs the same way); NAME is the file stem made a URScript identifier (lower case,
 *     characters other than a-z 0-9 _ replaced by _, prefixed by p_ if it does not start with a
 *     letter). A program is split only at air moves, each file below MaxFileBytes; each file
 *     restates set_tcp and the analog output and starts with a movej to its first pose, so the
 *     files are run one after the other.
 *   - every file is written to a temporary name in the same directory first and renamed only
 *     when all of them are complete: on an error nothing (no partial file) is left and earlier
 *     files of that name are untouched. After a successful write, numbered files STEM_k.EXT of an
 *     earlier, longer program (k = the new file count, k + 1, … as long as they exist) are
 *     removed, so the directory holds exactly the new program.
 * Unreachable points: a point at which no IK solution is found (after retrying nearby ψ) is
 *   reported with vtkErrorMacro naming the count and the first (up to 10) point indices, and
 *   nothing is written, unless AllowUnreachable is on: then the program is written with a
 *   vtkWarningMacro of the same text (the robot keeps the previous joints at those points: for
 *   simulation only). A cell in which no IK branch reaches the path at all ("unreachable cell
 *   set-up") is always an error.
 * Results of the last Write() (reset at its start; kept on an error as far as computed):
 *   GetNumberOfFilesWritten / GetFileWritten(k) (full paths), GetNumberOfWaypoints,
 *   GetNumberOfMoves (movel), GetUnreachableCount / GetUnreachablePoint(i) (all indices,
 *   ascending), GetMaxJointStepDeg (largest change of a joint between consecutive points),
 *   GetMaxJointSpeedDegS (with the segment times), GetMinShoulderSingularity (distance of
 *   the wrist centre from the shoulder singularity cylinder, m), GetMinElbowSingularity (|sin θ3|),
 *   GetMinWristSingularity (|sin θ5|), the smallest along the path, GetDuration (s, sum of
 *   segment times), GetMaxLineLength (characters), GetIKBranch, GetSolveSeconds.
 * Parameters (in mm and degrees like every GeoLattice filter; the writer converts to URScript's
 *   metres and radians): Robot ("ur5" default, or "ur5e"), NozzleTip (mm, robot base frame,
 *   default (0, -400, 350)), NozzleAxis (from the tip into the nozzle, base frame, default
 *   (0, 0, 1), normalized), PrintheadRadius (mm, default 28: the printhead's largest distance
 *   from its axis; the arm's surfaces keep 7 mm more from the axis; with SetNozzle and a nozzle
 *   whose PrintheadFile is set, that file's largest radius instead), PartOnFlangePosition (mm)
 *   and PartOnFlangeRotation (rotation vector,
 *   degrees, as the UR teach pendant shows it): the part (platform) frame in the flange frame =
 *   the TCP, default (0, 0, 40) and (0, 0, 0): the platform plate 40 mm in front of the flange;
 *   MaxFileBytes (default 4000000, >= 10000), SpeedFactor (fraction of
 *   the joint speed limits used, default 0.5, in (0, 1]), MaxFilamentRate (mm/s of filament at
 *   analog level 1 (10 V), default 5, > 0), MaxBlend (blend radius limit, mm, default 0.5,
 *   >= 0), MaxJointStep (degrees, default 20, > 0: a larger jump of a joint between consecutive
 *   points is refined away or refused), AllowUnreachable (default off). The toolpath's mm are
 *   scaled by 0.001 to metres.
 * Errors (no FileName, an empty toolpath, missing arrays, a NaN point or a NaN / zero normal,
 *   a bad parameter (unknown robot, zero nozzle axis, …), an unreachable cell set-up or
 *   unreachable points, a joint jump above MaxJointStep, one print run longer than MaxFileBytes,
 *   a file that cannot be written)
 *   are reported with vtkErrorMacro; Write() then returns 0 and no file is left behind.
 */
#ifndef vtkGLURScriptWriter_h
#define vtkGLURScriptWriter_h

#include "GeoLatticeFiltersModule.h"
#include "vtkGLToolpathWriter.h"
#include "vtkSmartPointer.h"  // for the nozzle

#include <memory>  // for the kept solution
#include <string>  // for the file names
#include <vector>  // for the results

class vtkGLNozzle;
class vtkPolyData;
namespace geolattice {
struct CellLayoutResult;
struct NozzleSection;
struct RobotCell;
struct RobotPathOptions;
struct ToolpathArrays;
}  // namespace geolattice

class GEOLATTICEFILTERS_EXPORT vtkGLURScriptWriter : public vtkGLToolpathWriter {
public:
  static vtkGLURScriptWriter* New();
  vtkTypeMacro(vtkGLURScriptWriter, vtkGLToolpathWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Robot model: "ur5" (CB3, default) or "ur5e".
  vtkSetStringMacro(Robot);
  vtkGetStringMacro(Robot);
  ///@}

  ///@{
  /// Nozzle tip in the robot base frame (mm, default (0, -400, 350)).
  vtkSetVector3Macro(NozzleTip, double);
  vtkGetVector3Macro(NozzleTip, double);
  ///@}

  ///@{
  /// Nozzle body axis from the tip into the nozzle, base frame (default (0, 0, 1); normalized).
  vtkSetVector3Macro(NozzleAxis, double);
  vtkGetVector3Macro(NozzleAxis, double);
  ///@}

  ///@{
  /// The printhead's largest distance from its axis (mm, default 28 = core's
  /// kPrintheadRadius, > 0): the arm's surfaces keep kLinkNozzleMargin (7 mm) more than this
  /// from the nozzle's axis. A nozzle given with SetNozzle whose PrintheadFile is set
  /// overrides it with that file's profile: its radius + 7 mm in sections along the axis
  /// (core's nozzleSectionsFor: the slim end near the tip is kept less far off than the
  /// carriage), its largest radius (GetPrintheadRadiusUsed) + 7 mm above its top.
  vtkSetMacro(PrintheadRadius, double);
  vtkGetMacro(PrintheadRadius, double);
  ///@}

  /// The nozzle the toolpath was planned for (optional, not owned beyond a reference; e.g.
  /// GLPrintPipeline's): its PrintheadFile, when set, gives the printhead's radius.
  void SetNozzle(vtkGLNozzle* nozzle);
  /// The printhead radius of the last solve (mm): PrintheadRadius or the nozzle file's.
  double GetPrintheadRadiusUsed() const { return this->PrintheadRadiusUsed; }

  ///@{
  /// The part (platform) frame in the flange frame, the TCP of the program: its origin (mm,
  /// default (0, 0, 40)) and its rotation vector (axis times angle, degrees, default (0, 0, 0)).
  vtkSetVector3Macro(PartOnFlangePosition, double);
  vtkGetVector3Macro(PartOnFlangePosition, double);
  vtkSetVector3Macro(PartOnFlangeRotation, double);
  vtkGetVector3Macro(PartOnFlangeRotation, double);
  ///@}

  ///@{
  /// Largest size of one program file (bytes, default 4000000, >= 10000).
  vtkSetMacro(MaxFileBytes, vtkIdType);
  vtkGetMacro(MaxFileBytes, vtkIdType);
  ///@}

  ///@{
  /// Fraction of the joint speed limits the motion may use (default 0.5, in (0, 1]).
  vtkSetMacro(SpeedFactor, double);
  vtkGetMacro(SpeedFactor, double);
  ///@}

  ///@{
  /// Filament feed rate at analog output level 1 (10 V), mm/s (default 5, > 0).
  vtkSetMacro(MaxFilamentRate, double);
  vtkGetMacro(MaxFilamentRate, double);
  ///@}

  ///@{
  /// Largest blend radius (mm, default 0.5, >= 0).
  vtkSetMacro(MaxBlend, double);
  vtkGetMacro(MaxBlend, double);
  ///@}

  ///@{
  /// Largest change of any joint between consecutive toolpath points (degrees, default 20, > 0).
  /// The joint path is refined where a step is larger (RobotPathSolver.h); a step left above it
  /// is an error naming the point, and nothing is written.
  vtkSetMacro(MaxJointStep, double);
  vtkGetMacro(MaxJointStep, double);
  ///@}

  ///@{
  /// Write the program even if some points are unreachable (default off: error, nothing written).
  vtkSetMacro(AllowUnreachable, vtkTypeBool);
  vtkGetMacro(AllowUnreachable, vtkTypeBool);
  vtkBooleanMacro(AllowUnreachable, vtkTypeBool);
  ///@}

  ///@{
  /// When the robot cannot follow the path in the cell as given (a joint flip or limit,
  /// unreachable points), search how the part is mounted on the flange: its rotation about the
  /// flange z axis and its distance in front of it (core/robot/CellLayout.h; default on).
  vtkSetMacro(SearchCellLayout, vtkTypeBool);
  vtkGetMacro(SearchCellLayout, vtkTypeBool);
  vtkBooleanMacro(SearchCellLayout, vtkTypeBool);
  ///@}

  ///@{
  /// When one IK branch cannot follow the whole path, change the robot's configuration at air
  /// moves, or at a seam inside a print run where the wrist swings round or a joint reaches its
  /// limit: the part moves straight away from the nozzle, the arm turns in joint space, the part
  /// comes back (core/robot/RobotPathSolver.h, step 4; tried in each layout before the next;
  /// default on).
  vtkSetMacro(Reconfigure, vtkTypeBool);
  vtkGetMacro(Reconfigure, vtkTypeBool);
  vtkBooleanMacro(Reconfigure, vtkTypeBool);
  ///@}

  ///@{
  /// Solves the joint path of the current input in this cell as Write() does (the input brought
  /// up to date; the cell layout search, the results below), without writing anything and
  /// without a FileName, and keeps the solution: the next Write() of the same toolpath with the
  /// same cell and path parameters writes it without solving again. Returns 1 when the robot
  /// can follow the path (every point reached, or AllowUnreachable with some reached, and no
  /// joint step above MaxJointStep), 0 when it cannot (nothing reported) or on an error (bad
  /// input or parameters: reported as by Write()). Used by GLPrintPipeline to try other
  /// orientations of a part before its program is refused.
  int SolveRobotPath();
  ///@}

  /// File name of program file k: FileName for k = 0, else STEM_k.EXT next to it.
  static std::string ProgramFileName(const std::string& fileName, int k);
  /// The def name used for FileName: its stem as a URScript identifier.
  static std::string ProgramName(const std::string& fileName);

  ///@{
  /// Results of the last Write() (see the class documentation).
  int GetNumberOfFilesWritten() const { return static_cast<int>(this->FilesWritten.size()); }
  std::string GetFileWritten(int k) const;
  vtkIdType GetNumberOfWaypoints() const { return this->NumberOfWaypoints; }
  vtkIdType GetNumberOfMoves() const { return this->NumberOfMoves; }
  vtkIdType GetUnreachableCount() const { return static_cast<vtkIdType>(this->Unreachable.size()); }
  vtkIdType GetUnreachablePoint(vtkIdType i) const;
  double GetMaxJointStepDeg() const { return this->MaxJointStepDeg; }
  /// Joint steps above MaxJointStep that the path solver could not avoid (then nothing is
  /// written: a wrist flip or a joint limit on this cell layout).
  vtkIdType GetLargeJointSteps() const { return this->LargeJointSteps; }
  /// Segments written with waypoints between their two points (the wrist near its singularity
  /// turns joints 4 and 6 by more than MaxJointStep where the part turns less; the controller's
  /// move is continuous, core/robot/StraightMove.h), and those waypoints.
  vtkIdType GetViaSegments() const { return this->ViaSegments; }
  vtkIdType GetViaWaypoints() const { return this->ViaWaypoints; }
  /// The cell layout of the last Write(): whether the path solver changed the mounting of the
  /// part (SearchCellLayout), the rotation it added about the flange z axis (degrees), the
  /// distance it added in front of the flange (mm), the layouts it tried, and the mounting used
  /// (the program's set_tcp: position x, y, z in mm, rotation vector in degrees).
  bool GetLayoutChanged() const { return this->LayoutChanged; }
  double GetLayoutRotationDeg() const { return this->LayoutRotationDeg; }
  double GetLayoutOffsetAdded() const { return this->LayoutOffsetAdded; }
  int GetLayoutsTried() const { return this->LayoutsTried; }
  const double* GetUsedPartOnFlange() const { return this->UsedPartOnFlange; }
  /// Forward-kinematics check of the written joints: largest distance of a toolpath point from
  /// the nozzle tip (m) and largest angle between its axis and the nozzle axis (degrees).
  double GetMaxTipError() const { return this->MaxTipError; }
  double GetMaxAxisErrorDeg() const { return this->MaxAxisErrorDeg; }
  double GetMaxJointSpeedDegS() const { return this->MaxJointSpeedDegS; }
  double GetMinShoulderSingularity() const { return this->MinSingularity[0]; }
  double GetMinElbowSingularity() const { return this->MinSingularity[1]; }
  double GetMinWristSingularity() const { return this->MinSingularity[2]; }
  /// Height of the arm's lowest surface (core robot/ArmCapsules.h) over the written path above
  /// the floor the robot stands on (mm; kept at 20 mm or more: a point reached only lower is
  /// unreachable).
  double GetLowestArmHeight() const { return this->LowestArmHeight; }
  /// Height of the part's lowest point (as printed so far, with the plate's footprint: core
  /// robot/PartFloor.h) over the written path above the same floor (mm; kept at 20 mm or more).
  double GetLowestPartHeight() const { return this->LowestPartHeight; }
  /// Least distance of the arm's surfaces (base to wrist 1: core robot/ArmCapsules.h) from the
  /// nozzle's axis over the written path (mm; kept at 35 mm or more, core's
  /// kLinkNozzleSafeDistance: a point reached only nearer is unreachable).
  double GetMinLinkNozzleDistance() const { return this->MinLinkNozzleDistance; }
  /// The tallest part (mm) this cell prints standing up (core robot/RobotPathSolver.h
  /// tallestPart: the arm keeps the floor and the nozzle's clearance, with the printhead used,
  /// while it holds the plate that far below the tip); 0 when it cannot tell (the cell's
  /// parameters or the printhead file are bad: the writer's own run reports why).
  double TallestPart();
  /// Least distance of the arm's surfaces (base to wrist 2) from the part the robot holds, as
  /// printed so far, and its plate, over the written path (mm, measured up to 1000, to 1 mm;
  /// kept at 15 mm or more, core's kLinkPartSafeDistance: core/robot/PartArmClearance.h).
  double GetMinLinkPartDistance() const { return this->MinLinkPartDistance; }
  double GetDuration() const { return this->Duration; }
  vtkIdType GetMaxLineLength() const { return this->MaxLineLength; }
  int GetIKBranch() const { return this->IKBranch; }
  /// The reconfigurations of the last Write() (Reconfigure), in path order: the toolpath point
  /// (an air move, or a seam inside a print stretch) where each is made, whether it is a seam,
  /// the IK branches before and after, how far the part moves away from the nozzle (mm) and the
  /// clearance of its bounding sphere during the joint move (mm).
  int GetNumberOfReconfigurations() const {
    return static_cast<int>(this->Reconfigurations.size());
  }
  vtkIdType GetReconfigurationPoint(int k) const { return this->ReconfigurationAt(k).Point; }
  bool GetReconfigurationAtSeam(int k) const { return this->ReconfigurationAt(k).AtSeam; }
  int GetReconfigurationFromBranch(int k) const { return this->ReconfigurationAt(k).FromBranch; }
  int GetReconfigurationToBranch(int k) const { return this->ReconfigurationAt(k).ToBranch; }
  double GetReconfigurationRetreat(int k) const { return this->ReconfigurationAt(k).Retreat; }
  double GetReconfigurationClearance(int k) const { return this->ReconfigurationAt(k).Clearance; }
  double GetSolveSeconds() const { return this->SolveSeconds; }
  ///@}

protected:
  vtkGLURScriptWriter();
  ~vtkGLURScriptWriter() override;

  void CheckParameters() override;
  void WriteData() override;

  char* Robot = nullptr;
  double NozzleTip[3];
  double NozzleAxis[3];
  double PrintheadRadius;
  double PartOnFlangePosition[3];
  double PartOnFlangeRotation[3];
  vtkIdType MaxFileBytes;
  double SpeedFactor;
  double MaxFilamentRate;
  double MaxBlend;
  double MaxJointStep;
  vtkTypeBool AllowUnreachable;
  vtkTypeBool SearchCellLayout;
  vtkTypeBool Reconfigure;

private:
  vtkGLURScriptWriter(const vtkGLURScriptWriter&) = delete;
  void operator=(const vtkGLURScriptWriter&) = delete;

  void ResetResults();
  /// The cell of the parameters (m and rad).
  geolattice::RobotCell MakeCell() const;
  /// The printhead the arm keeps off: the nozzle's printhead file when it has one (its largest
  /// radius, and its profile in sections: the slim part near the tip is kept less far off), else
  /// a cylinder of PrintheadRadius. Sets PrintheadRadiusUsed and NozzleSectionsUsed.
  void UsePrinthead();
  /// The path solver's options of the parameters and the printhead used.
  geolattice::RobotPathOptions PathOptions() const;
  vtkSmartPointer<vtkGLNozzle> Nozzle;
  double PrintheadRadiusUsed = 0;
  std::vector<geolattice::NozzleSection> NozzleSectionsUsed;
  /// The solution of `path` (input `input`) with the current parameters: the one kept if it
  /// is still valid, else solved now and kept; sets the results. Throws for an unreachable
  /// cell set-up (after marking every point unreachable).
  const geolattice::CellLayoutResult& Solve(vtkPolyData* input,
                                            const geolattice::ToolpathArrays& path);
  struct Solution;
  std::unique_ptr<Solution> Solved;
  bool SolveOnly = false;  ///< inside SolveRobotPath(): WriteData stops after the solve

  struct ReconfigurationResult {
    vtkIdType Point = -1;
    bool AtSeam = false;
    int FromBranch = -1, ToBranch = -1;
    double Retreat = 0, Clearance = 0;  // mm
  };
  const ReconfigurationResult& ReconfigurationAt(int k) const;
  std::vector<ReconfigurationResult> Reconfigurations;

  std::vector<std::string> FilesWritten;
  std::vector<vtkIdType> Unreachable;
  vtkIdType NumberOfWaypoints = 0;
  vtkIdType NumberOfMoves = 0;
  double MaxJointStepDeg = 0;
  vtkIdType LargeJointSteps = 0;
  vtkIdType ViaSegments = 0;
  vtkIdType ViaWaypoints = 0;
  bool LayoutChanged = false;
  double LayoutRotationDeg = 0;
  double LayoutOffsetAdded = 0;
  int LayoutsTried = 0;
  double UsedPartOnFlange[6] = {0, 0, 0, 0, 0, 0};
  double MaxTipError = 0;
  double MaxAxisErrorDeg = 0;
  double MaxJointSpeedDegS = 0;
  double MinSingularity[3] = {0, 0, 0};
  double LowestArmHeight = 0;
  double LowestPartHeight = 0;
  double MinLinkNozzleDistance = 0;
  double MinLinkPartDistance = 0;
  double Duration = 0;
  vtkIdType MaxLineLength = 0;
  int IKBranch = -1;
  double SolveSeconds = 0;
};

#endif
