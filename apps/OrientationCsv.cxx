#include "OrientationCsv.h"

#include "common/AtomicFile.h"
#include "common/Error.h"
#include "vtkGLArrayNames.h"

#include <vtkAbstractArray.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <numeric>
#include <vector>

namespace geolattice {

void writeOrientationCsv(vtkPolyData* candidates, const std::string& path) {
  vtkPointData* pd = candidates ? candidates->GetPointData() : nullptr;
  auto array = [pd](const char* name) {
    vtkDataArray* a = pd ? pd->GetArray(name) : nullptr;
    if (!a) {
      throw GeoLatticeError(std::string("orientation candidates have no array ") + name);
    }
    return a;
  };
  vtkDataArray* rank = array(arrays::OrientRank);
  vtkDataArray* up = array(arrays::OrientUp);
  vtkDataArray* area = array(arrays::BaseArea);
  vtkDataArray* feasible = array(arrays::Feasible);
  vtkDataArray* evaluated = array(arrays::Evaluated);
  vtkDataArray* colliding = array(arrays::CollidingStations);
  vtkDataArray* plate = array(arrays::PlateStations);
  vtkDataArray* stations = array(arrays::CollisionStations);
  vtkDataArray* forced = array(arrays::ForcedSteps);
  vtkDataArray* overhang = array(arrays::OverhangFraction);
  vtkDataArray* layers = array(arrays::LayerCount);
  vtkDataArray* seconds = array(arrays::OrientSeconds);
  vtkDataArray* pedestal = array(arrays::Pedestal);
  vtkDataArray* refined = array(arrays::Refined);
  vtkDataArray* coarse = array(arrays::CoarseCollidingStations);
  auto* source = vtkStringArray::SafeDownCast(pd->GetAbstractArray(arrays::OrientSource));
  const vtkIdType n = candidates->GetNumberOfPoints();
  std::vector<vtkIdType> order(static_cast<size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [rank](vtkIdType a, vtkIdType b) { return rank->GetTuple1(a) < rank->GetTuple1(b); });
  AtomicFileSet files;
  std::ostream& out = files.open(path);
  out << "rank,source,up_x,up_y,up_z,base_area_mm2,feasible,evaluated,colliding_stations,"
         "plate_stations,stations,forced_steps,overhang_fraction,layers,seconds,pedestal_mm,"
         "refined,"
         "coarse_colliding_stations\n"
      << std::setprecision(6);
  for (vtkIdType i : order) {
    std::string s = source ? source->GetValue(i) : "";
    std::replace(s.begin(), s.end(), ',', ';');
    const double* u = up->GetTuple3(i);
    out << rank->GetTuple1(i) << ',' << s << ',' << u[0] << ',' << u[1] << ',' << u[2] << ','
        << area->GetTuple1(i) << ',' << feasible->GetTuple1(i) << ',' << evaluated->GetTuple1(i)
        << ',' << colliding->GetTuple1(i) << ',' << plate->GetTuple1(i) << ','
        << stations->GetTuple1(i) << ',' << forced->GetTuple1(i) << ',' << overhang->GetTuple1(i)
        << ',' << layers->GetTuple1(i) << ',' << seconds->GetTuple1(i) << ','
        << pedestal->GetTuple1(i) << ',' << refined->GetTuple1(i) << ',' << coarse->GetTuple1(i)
        << '\n';
  }
  files.commit();
}

}  // namespace geolattice
