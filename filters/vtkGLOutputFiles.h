#ifndef vtkGLOutputFiles_h
#define vtkGLOutputFiles_h
/**
 * @file vtkGLOutputFiles.h
 * @brief The writers' pipeline helper: a time-dependent input is written whole. Files are
 * written all-or-nothing with core/common/AtomicFile.h.
 */
#include "common/AtomicFile.h"  // AtomicFileSet, FileWriteError: the one atomic-write scheme

#include <string>

class vtkInformation;
class vtkInformationVector;

namespace geolattice {

/// For a writer's REQUEST_UPDATE_EXTENT: asks input port 0 for the end of its time range (the
/// last TIME_STEPS value, else the end of TIME_RANGE) if it has one, so a time-dependent
/// toolpath (the planner's print replay) is written whole whatever the pipeline time.
void requestEndOfTimeRange(vtkInformationVector** inputVector);

}  // namespace geolattice
#endif
