// The XML file writer with buffered base64: the same bytes as VTK's own writer (arrays of odd
// byte counts, so the encoding's leftover bytes cross array and block boundaries), files that
// read back, and its failures.
#include "GLTestFiles.h"
#include "GLXMLFileWriter.h"
#include "common/Error.h"

#include <gtest/gtest.h>

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <csignal>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <sys/resource.h>
#include <unistd.h>

using geolattice::writeXmlDataFile;

namespace {

/// n points on a curve, one polyline through them, and arrays of 1, 3 and 8 bytes per value
/// (n odd: every array's byte count leaves 1 or 2 bytes for the next write).
vtkNew<vtkPolyData> polyline(int n) {
  vtkNew<vtkPolyData> poly;
  vtkNew<vtkPoints> points;
  vtkNew<vtkDoubleArray> axis;
  axis->SetName("NozzleAxis");
  axis->SetNumberOfComponents(3);
  vtkNew<vtkIntArray> index;
  index->SetName("PointIndex");
  vtkNew<vtkUnsignedCharArray> kind;
  kind->SetName("MoveKind");
  vtkNew<vtkDoubleArray> tilt;  // negative values and a NaN (left out of the range)
  tilt->SetName("AxisTilt");
  vtkNew<vtkIntArray> layer;
  layer->SetName("LayerId");
  vtkNew<vtkDoubleArray> wrench;  // a vector with a NaN component in one tuple
  wrench->SetName("Wrench");
  wrench->SetNumberOfComponents(2);
  vtkNew<vtkCellArray> lines;
  lines->InsertNextCell(n);
  for (int i = 0; i < n; ++i) {
    const double t = 0.01 * i;
    points->InsertNextPoint(std::cos(t) * (50 + t), std::sin(t) * 40, 0.3 * t);
    axis->InsertNextTuple3(std::sin(3 * t), 0.1 * t, 1.0);
    index->InsertNextValue(i * 7919 % 1000003);
    kind->InsertNextValue(static_cast<unsigned char>(i % 3));
    tilt->InsertNextValue(i == n / 2 ? std::nan("") : std::sin(0.37 * i) * 30);
    layer->InsertNextValue(i % 5 - 1);
    wrench->InsertNextTuple2(i == n - 1 ? std::nan("") : -0.5 * i, 2.0);
    lines->InsertCellPoint(i);
  }
  poly->SetPoints(points);
  poly->SetLines(lines);
  poly->GetPointData()->AddArray(axis);
  poly->GetPointData()->AddArray(index);
  poly->GetPointData()->AddArray(kind);
  poly->GetPointData()->AddArray(tilt);
  poly->GetPointData()->AddArray(layer);
  poly->GetPointData()->AddArray(wrench);
  vtkNew<vtkDoubleArray> length;
  length->SetName("ToolpathPrintLength");
  length->InsertNextValue(0.1 * n);
  poly->GetFieldData()->AddArray(length);
  return poly;
}

}  // namespace

TEST(GLXMLFileWriter, SameBytesAsVtksWriter) {
  const auto dir = glFreshDirectory("xmlwriter");
  // Small (one block, leftovers), large (many 48 KiB blocks, LZ4's 32 KiB blocks) and empty.
  for (const int n : {1, 2, 3, 101, 200001}) {
    // Ours stores the arrays' ranges in their information; VTK's writer gets data without them.
    vtkNew<vtkPolyData> poly = polyline(n);
    vtkNew<vtkPolyData> same = polyline(n);
    const std::string ours = (dir / "ours.vtp").string(), vtk = (dir / "vtk.vtp").string();
    ASSERT_TRUE(writeXmlDataFile(poly, ours));
    ASSERT_TRUE(writeXmlDataFile(same, vtk, false));
    const std::string bytes = glReadFile(ours);
    EXPECT_GT(bytes.size(), 500u);
    EXPECT_EQ(bytes, glReadFile(vtk)) << n << " points";

    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName(ours.c_str());
    reader->Update();
    vtkPolyData* back = reader->GetOutput();
    ASSERT_EQ(back->GetNumberOfPoints(), n);
    double p[3], q[3];
    back->GetPoint(n - 1, p);
    poly->GetPoint(n - 1, q);
    EXPECT_EQ(p[0], q[0]);
    EXPECT_EQ(p[2], q[2]);
    EXPECT_EQ(back->GetPointData()->GetArray("PointIndex")->GetTuple1(n - 1),
              poly->GetPointData()->GetArray("PointIndex")->GetTuple1(n - 1));
  }
  // An unstructured grid: one tet.
  auto oneTet = [] {
    vtkNew<vtkUnstructuredGrid> grid;
    vtkNew<vtkPoints> points;
    points->InsertNextPoint(0, 0, 0);
    points->InsertNextPoint(1, 0, 0);
    points->InsertNextPoint(0, 1, 0);
    points->InsertNextPoint(0, 0, 1);
    grid->SetPoints(points);
    const vtkIdType tet[4] = {0, 1, 2, 3};
    grid->InsertNextCell(VTK_TETRA, 4, tet);
    return grid;
  };
  vtkNew<vtkUnstructuredGrid> grid = oneTet();
  vtkNew<vtkUnstructuredGrid> same = oneTet();
  const std::string ours = (dir / "ours.vtu").string(), vtk = (dir / "vtk.vtu").string();
  ASSERT_TRUE(writeXmlDataFile(grid, ours));
  ASSERT_TRUE(writeXmlDataFile(same, vtk, false));
  EXPECT_EQ(glReadFile(ours), glReadFile(vtk));
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(ours.c_str());
  reader->Update();
  EXPECT_EQ(reader->GetOutput()->GetNumberOfCells(), 1);
  std::filesystem::remove_all(dir);
}

TEST(GLXMLFileWriter, Failures) {
  vtkNew<vtkPolyData> poly = polyline(10);
  EXPECT_FALSE(writeXmlDataFile(poly, "/nonexistent-directory/toolpath.vtp"));
  vtkNew<vtkImageData> image;
  EXPECT_THROW(writeXmlDataFile(image, "/tmp/image.vti"), geolattice::GeoLatticeError);
  EXPECT_THROW(writeXmlDataFile(nullptr, "/tmp/none.vtp"), geolattice::GeoLatticeError);
}

// A write that runs out of space (here: past the process's file size limit, RLIMIT_FSIZE, so the
// stream fails as on a full disk) is a failure (false), not a crash: VTK 9.2's writers free
// position arrays on that path that binary inline mode never allocated, and the process aborted
// ("munmap_chunk(): invalid pointer"). Each write runs in a child process with the limit.
TEST(GLXMLFileWriterDeathTest, RunningOutOfSpaceIsAFailureNotACrash) {
  testing::FLAGS_gtest_death_test_style = "threadsafe";
  const std::string file = (std::filesystem::temp_directory_path() /
                            ("geolattice-full-" + std::to_string(::getpid()) + ".vtp"))
                               .string();
  auto fullWrite = [&file](vtkDataObject* data, bool buffered) {
    rlimit limit{};
    limit.rlim_cur = limit.rlim_max = 65536;  // bytes: far less than the data
    setrlimit(RLIMIT_FSIZE, &limit);
    std::signal(SIGXFSZ, SIG_IGN);  // the write fails instead of ending the process
    const bool written = writeXmlDataFile(data, file, buffered);
    // The threadsafe death-test child re-runs this test under its own pid, so its file is not
    // the parent's: it removes what it wrote.
    std::filesystem::remove(file);
    std::exit(written ? 1 : 0);
  };
  vtkNew<vtkPolyData> poly = polyline(200001);
  vtkNew<vtkUnstructuredGrid> grid;  // 20,000 tets over 80,000 points
  vtkNew<vtkPoints> points;
  for (vtkIdType i = 0; i < 80000; ++i) {
    points->InsertNextPoint(std::sin(0.1 * i), std::cos(0.37 * i), 1e-3 * i);
  }
  grid->SetPoints(points);
  for (vtkIdType t = 0; t < 20000; ++t) {
    const vtkIdType tet[4] = {4 * t, 4 * t + 1, 4 * t + 2, 4 * t + 3};
    grid->InsertNextCell(VTK_TETRA, 4, tet);
  }
  for (const bool buffered : {true, false}) {
    EXPECT_EXIT(fullWrite(poly, buffered), testing::ExitedWithCode(0), "") << buffered;
    EXPECT_EXIT(fullWrite(grid, buffered), testing::ExitedWithCode(0), "") << buffered;
  }
  std::filesystem::remove(file);
}
