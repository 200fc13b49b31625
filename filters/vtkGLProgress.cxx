#include "vtkGLProgress.h"

namespace geolattice {

std::atomic<bool>& stopRequest() {
  static std::atomic<bool> request{false};
  static_assert(std::atomic<bool>::is_always_lock_free, "set from a signal handler");
  return request;
}

}  // namespace geolattice
