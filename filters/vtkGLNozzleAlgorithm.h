/**
 * @class   vtkGLNozzleAlgorithm
 * @brief   Base of the filters that keep the nozzle clear of printed material (GL Print
 *          Sequencer, GL Collision Verifier, GL Toolpath Planner): they share one nozzle
 *          parameter block (vtkGLNozzle) and re-execute when it changes.
 */
#ifndef vtkGLNozzleAlgorithm_h
#define vtkGLNozzleAlgorithm_h

#include "GeoLatticeFiltersModule.h"
#include "vtkGLNozzle.h"
#include "vtkPolyDataAlgorithm.h"
#include "vtkSmartPointer.h"

class GEOLATTICEFILTERS_EXPORT vtkGLNozzleAlgorithm : public vtkPolyDataAlgorithm {
public:
  vtkTypeMacro(vtkGLNozzleAlgorithm, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The nozzle (a default one unless set; null restores a default one). Sharing one object
  /// between filters gives them the same nozzle.
  void SetNozzle(vtkGLNozzle* nozzle);
  vtkGLNozzle* GetNozzle() { return this->Nozzle; }
  ///@}

  /// Includes the nozzle's modification time.
  vtkMTimeType GetMTime() override;

protected:
  vtkGLNozzleAlgorithm();
  ~vtkGLNozzleAlgorithm() override = default;

  /// Checks the nozzle and plate parameters (subclasses that override it call it first).
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkSmartPointer<vtkGLNozzle> Nozzle;

private:
  vtkGLNozzleAlgorithm(const vtkGLNozzleAlgorithm&) = delete;
  void operator=(const vtkGLNozzleAlgorithm&) = delete;
};

#endif
