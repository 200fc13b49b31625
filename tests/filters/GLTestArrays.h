#ifndef GLTestArrays_h
#define GLTestArrays_h
/**
 * @file GLTestArrays.h
 * @brief Test helpers for the filters' arrays: a field-data value, a named int array.
 */
#include <gtest/gtest.h>
#include <vtkDataArray.h>
#include <vtkDataObject.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkSmartPointer.h>

#include <cmath>

/// Component i (over all tuples) of field array `name`; NaN and a test failure if it is missing.
inline double fieldValue(vtkDataObject* d, const char* name, int i = 0) {
  vtkDataArray* a = d ? d->GetFieldData()->GetArray(name) : nullptr;
  EXPECT_NE(a, nullptr) << name;
  return a ? a->GetComponent(i / a->GetNumberOfComponents(), i % a->GetNumberOfComponents())
           : std::nan("");
}

inline vtkSmartPointer<vtkIntArray> namedIntArray(const char* name) {
  auto a = vtkSmartPointer<vtkIntArray>::New();
  a->SetName(name);
  return a;
}

#endif
