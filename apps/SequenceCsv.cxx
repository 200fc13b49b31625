#include "SequenceCsv.h"

#include "OutputFiles.h"
#include "common/Error.h"
#include "vtkGLArrayNames.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkPolyData.h>

#include <fstream>
#include <iomanip>

namespace geolattice {

namespace {

vtkDataArray* fieldArray(vtkDataObject* data, const char* name) {
  vtkDataArray* a =
      data ? vtkDataArray::SafeDownCast(data->GetFieldData()->GetAbstractArray(name)) : nullptr;
  if (!a) {
    throw GeoLatticeError(std::string("sequence output has no field array ") + name);
  }
  return a;
}

}  // namespace

void writeSequenceCsv(vtkPolyData* lattice, vtkPolyData* printOrder, const std::string& path) {
  vtkDataArray* order = fieldArray(lattice, arrays::SequenceOrder);
  vtkDataArray* start = fieldArray(lattice, arrays::SequenceStart);
  vtkDataArray* end = fieldArray(lattice, arrays::SequenceEnd);
  vtkDataArray* layer = fieldArray(lattice, arrays::SubgraphLayer);
  vtkDataArray* retraction =
      printOrder ? printOrder->GetCellData()->GetArray(arrays::Retraction) : nullptr;
  const vtkIdType n = order->GetNumberOfTuples();
  if (start->GetNumberOfTuples() != n || end->GetNumberOfTuples() != n ||
      (retraction && retraction->GetNumberOfTuples() != std::max<vtkIdType>(n - 1, 0))) {
    throw GeoLatticeError("sequence output arrays do not match the number of sub-graphs");
  }
  writeAtomically(path, [&](const std::string& tmp) {
    std::ofstream out(tmp);
    out << "order,subgraph,layer,start_x,start_y,start_z,end_x,end_y,end_z,retraction\n";
    out << std::setprecision(9);
    for (vtkIdType i = 0; i < n; ++i) {
      const auto s = static_cast<vtkIdType>(order->GetTuple1(i));
      const double* a = start->GetTuple3(i);
      out << i << ',' << s << ','
          << (s >= 0 && s < layer->GetNumberOfTuples() ? layer->GetTuple1(s) : -1);
      out << ',' << a[0] << ',' << a[1] << ',' << a[2];
      const double* b = end->GetTuple3(i);
      out << ',' << b[0] << ',' << b[1] << ',' << b[2];
      out << ',' << (i > 0 && retraction ? static_cast<int>(retraction->GetTuple1(i - 1)) : 0)
          << '\n';
    }
    return static_cast<bool>(out);
  });
}

}  // namespace geolattice
