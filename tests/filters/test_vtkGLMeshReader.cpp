#include "vtkGLMeshReader.h"

#include "GLTestErrorObserver.h"
#include "GLTestProgress.h"

#include <gtest/gtest.h>

#include <vtkCellArray.h>
#include <vtkCellType.h>
#include <vtkFeatureEdges.h>
#include <vtkNew.h>
#include <vtkPLYWriter.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSTLWriter.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {
const std::string kData = GEOLATTICE_TESTDATA;

/// Output of a fresh reader on `path`, with the errors it reported.
struct ReadResult {
  vtkSmartPointer<vtkDataObject> Output;
  vtkSmartPointer<GLTestErrorObserver> Errors;
  /// The output as a T after a read that reported no error (a failure otherwise; nullptr if the
  /// output is not a T).
  template <class T>
  T* Get() const {
    EXPECT_FALSE(Errors->HasError()) << Errors->Errors();
    return T::SafeDownCast(Output);
  }
};

ReadResult read(const std::string& path, bool setName = true) {
  vtkNew<vtkGLMeshReader> reader;
  ReadResult r;
  r.Errors = vtkSmartPointer<GLTestErrorObserver>::New();
  r.Errors->Observe(reader);
  if (setName) {
    reader->SetFileName(path.c_str());
  }
  reader->Update();
  r.Output = reader->GetOutputDataObject(0);
  return r;
}

/// Edges used by one triangle only (boundary; 0 for a closed surface), or by more than two
/// (non-manifold).
vtkIdType featureEdges(vtkPolyData* poly, bool boundary) {
  vtkNew<vtkFeatureEdges> edges;
  edges->SetInputData(poly);
  edges->SetBoundaryEdges(boundary);
  edges->FeatureEdgesOff();
  edges->SetNonManifoldEdges(!boundary);
  edges->ManifoldEdgesOff();
  edges->Update();
  return edges->GetOutput()->GetNumberOfLines();
}

vtkIdType boundaryEdges(vtkPolyData* poly) {
  return featureEdges(poly, true);
}

vtkIdType nonManifoldEdges(vtkPolyData* poly) {
  return featureEdges(poly, false);
}

/// Polydata with triangles only, no verts/lines/strips, every polygon a triangle.
void expectTrianglesOnly(vtkPolyData* poly) {
  EXPECT_EQ(poly->GetNumberOfVerts(), 0);
  EXPECT_EQ(poly->GetNumberOfLines(), 0);
  EXPECT_EQ(poly->GetNumberOfStrips(), 0);
  EXPECT_TRUE(poly->GetPolys()->IsHomogeneous() == 3) << "not all polygons are triangles";
}

class MeshReaderTest : public ::testing::Test {
protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    this->Dir = fs::temp_directory_path() /
                ("geolattice_reader_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(this->Dir);
    fs::create_directories(this->Dir);
  }
  void TearDown() override { fs::remove_all(this->Dir); }

  std::string Write(const std::string& name, const std::string& text) const {
    const fs::path p = this->Dir / name;
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
  }
  std::string Path(const std::string& name) const { return (this->Dir / name).string(); }

  fs::path Dir;
};

struct SurfaceCase {
  const char* File;
  vtkIdType Points;
  vtkIdType Triangles;
};
}  // namespace

TEST_F(MeshReaderTest, ReadsEverySurfaceModelAsClosedTriangles) {
  const SurfaceCase cases[] = {
      {"bunny.obj", 1839, 3674},     {"spot.obj", 2930, 5856},
      {"cube.obj", 8, 12},           {"decimated-knight.off", 502, 1000},
      {"ring_surf.obj", 3459, 6918}, {"topopt_new4_surf.obj", 6735, 13490}};
  for (const SurfaceCase& c : cases) {
    SCOPED_TRACE(c.File);
    const std::string path = kData + "/" + c.File;
    EXPECT_FALSE(vtkGLMeshReader::IsTetMeshFile(path.c_str()));
    ReadResult r = read(path);
    vtkPolyData* poly = r.Get<vtkPolyData>();
    ASSERT_NE(poly, nullptr);
    EXPECT_EQ(poly->GetNumberOfPoints(), c.Points);
    EXPECT_EQ(poly->GetNumberOfPolys(), c.Triangles);
    expectTrianglesOnly(poly);
    // Texture coordinates split spot's and cube's OBJ vertices; merged again, no tcoords left.
    EXPECT_EQ(poly->GetPointData()->GetTCoords(), nullptr);
    EXPECT_EQ(poly->GetPointData()->GetNormals(), nullptr);
    EXPECT_EQ(boundaryEdges(poly), 0);
    EXPECT_EQ(nonManifoldEdges(poly), 0);
  }
}

TEST_F(MeshReaderTest, ReadsTetMeshes) {
  struct TetCase {
    std::string File;
    vtkIdType Points;
    vtkIdType Tets;
  };
  const TetCase cases[] = {{kData + "/ring.tet", 8150, 40064},
                           {kData + "/tiny.node", 8, 5},
                           {kData + "/tiny.ele", 8, 5}};
  for (const TetCase& c : cases) {
    SCOPED_TRACE(c.File);
    EXPECT_TRUE(vtkGLMeshReader::IsTetMeshFile(c.File.c_str()));
    ReadResult r = read(c.File);
    vtkUnstructuredGrid* grid = r.Get<vtkUnstructuredGrid>();
    ASSERT_NE(grid, nullptr);
    EXPECT_EQ(grid->GetNumberOfPoints(), c.Points);
    ASSERT_EQ(grid->GetNumberOfCells(), c.Tets);
    for (vtkIdType i = 0; i < grid->GetNumberOfCells(); ++i) {
      ASSERT_EQ(grid->GetCellType(i), VTK_TETRA) << "cell " << i;
    }
  }
}

TEST_F(MeshReaderTest, StlSoupBecomesConnectedSurface) {
  vtkSmartPointer<vtkPolyData> bunny = vtkPolyData::SafeDownCast(read(kData + "/bunny.obj").Output);
  ASSERT_NE(bunny, nullptr);
  for (const bool binary : {true, false}) {
    SCOPED_TRACE(binary ? "binary STL" : "ASCII STL");
    // An STL stores every triangle with its own 3 corners (a soup).
    const std::string path = this->Path(binary ? "bunny.stl" : "bunny_ascii.STL");
    vtkNew<vtkSTLWriter> writer;
    writer->SetInputData(bunny);
    writer->SetFileName(path.c_str());
    binary ? writer->SetFileTypeToBinary() : writer->SetFileTypeToASCII();
    ASSERT_EQ(writer->Write(), 1);
    ReadResult r = read(path);
    vtkPolyData* poly = r.Get<vtkPolyData>();
    ASSERT_NE(poly, nullptr);
    EXPECT_EQ(poly->GetNumberOfPoints(), 1839);
    EXPECT_EQ(poly->GetNumberOfPolys(), 3674);
    EXPECT_EQ(boundaryEdges(poly), 0);
  }
}

TEST_F(MeshReaderTest, PlyAndVtpAndVtuRoundTrips) {
  vtkSmartPointer<vtkPolyData> bunny = vtkPolyData::SafeDownCast(read(kData + "/bunny.obj").Output);
  ASSERT_NE(bunny, nullptr);
  {
    vtkNew<vtkPLYWriter> writer;
    writer->SetInputData(bunny);
    writer->SetFileName(this->Path("bunny.ply").c_str());
    ASSERT_EQ(writer->Write(), 1);
  }
  {
    vtkNew<vtkXMLPolyDataWriter> writer;  // binary: appended files do not read back (build notes)
    writer->SetInputData(bunny);
    writer->SetDataModeToBinary();
    writer->SetFileName(this->Path("bunny.vtp").c_str());
    ASSERT_EQ(writer->Write(), 1);
  }
  for (const char* name : {"bunny.ply", "bunny.vtp"}) {
    SCOPED_TRACE(name);
    ReadResult r = read(this->Path(name));
    vtkPolyData* poly = r.Get<vtkPolyData>();
    ASSERT_NE(poly, nullptr);
    EXPECT_EQ(poly->GetNumberOfPoints(), 1839);
    EXPECT_EQ(poly->GetNumberOfPolys(), 3674);
    EXPECT_EQ(boundaryEdges(poly), 0);
  }

  vtkSmartPointer<vtkUnstructuredGrid> ring =
      vtkUnstructuredGrid::SafeDownCast(read(kData + "/ring.tet").Output);
  ASSERT_NE(ring, nullptr);
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetInputData(ring);
  writer->SetDataModeToBinary();
  writer->SetFileName(this->Path("ring.vtu").c_str());
  ASSERT_EQ(writer->Write(), 1);
  ReadResult r = read(this->Path("ring.vtu"));
  vtkUnstructuredGrid* grid = r.Get<vtkUnstructuredGrid>();
  ASSERT_NE(grid, nullptr);
  EXPECT_EQ(grid->GetNumberOfPoints(), 8150);
  EXPECT_EQ(grid->GetNumberOfCells(), 40064);
}

TEST_F(MeshReaderTest, ObjQuadsAreTriangulatedAndLinesDropped) {
  // Unit cube of 6 quads plus a polyline and a point element.
  const std::string path =
      this->Write("quads.Obj",
                  "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                  "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n"
                  "l 1 7\np 3\n");
  ReadResult r = read(path);
  vtkPolyData* poly = r.Get<vtkPolyData>();
  ASSERT_NE(poly, nullptr);
  EXPECT_EQ(poly->GetNumberOfPoints(), 8);
  EXPECT_EQ(poly->GetNumberOfPolys(), 12);
  expectTrianglesOnly(poly);
  EXPECT_EQ(boundaryEdges(poly), 0);
}

TEST_F(MeshReaderTest, OutputTypeFollowsTheFileName) {
  vtkNew<vtkGLMeshReader> reader;
  reader->SetFileName((kData + "/tiny.ele").c_str());
  reader->Update();
  EXPECT_TRUE(vtkUnstructuredGrid::SafeDownCast(reader->GetOutputDataObject(0)));
  reader->SetFileName((kData + "/cube.obj").c_str());
  reader->Update();
  vtkPolyData* poly = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
  ASSERT_NE(poly, nullptr);
  EXPECT_EQ(poly->GetNumberOfPolys(), 12);
}

TEST(MeshReaderStatic, ExtensionHelpers) {
  EXPECT_TRUE(vtkGLMeshReader::IsTetMeshFile("a/b.TET"));
  EXPECT_TRUE(vtkGLMeshReader::IsTetMeshFile("m.vtu"));
  EXPECT_TRUE(vtkGLMeshReader::IsTetMeshFile("m.Node"));
  EXPECT_FALSE(vtkGLMeshReader::IsTetMeshFile("m.stl"));
  EXPECT_FALSE(vtkGLMeshReader::IsTetMeshFile("m.xyz"));
  EXPECT_FALSE(vtkGLMeshReader::IsTetMeshFile("tet"));
  EXPECT_FALSE(vtkGLMeshReader::IsTetMeshFile(nullptr));
  EXPECT_TRUE(vtkGLMeshReader::IsSupportedFile("x.PLY"));
  EXPECT_FALSE(vtkGLMeshReader::IsSupportedFile("x.vtk"));

  ASSERT_EQ(vtkGLMeshReader::GetNumberOfSupportedExtensions(), 9);
  std::string joined;
  for (int i = 0; i < vtkGLMeshReader::GetNumberOfSupportedExtensions(); ++i) {
    const std::string ext = vtkGLMeshReader::GetSupportedExtension(i);
    EXPECT_EQ(ext.front(), '.');
    EXPECT_TRUE(vtkGLMeshReader::IsSupportedFile(("f" + ext).c_str())) << ext;
    joined += (i ? " " : "") + ext;
  }
  EXPECT_EQ(joined, vtkGLMeshReader::GetSupportedExtensionsString());
  EXPECT_EQ(vtkGLMeshReader::GetSupportedExtension(9), nullptr);

  EXPECT_EQ(vtkGLMeshReader::CanReadFile((kData + "/bunny.obj").c_str()), 1);
  EXPECT_EQ(vtkGLMeshReader::CanReadFile((kData + "/README.md").c_str()), 0);
  EXPECT_EQ(vtkGLMeshReader::CanReadFile((kData + "/missing.obj").c_str()), 0);
}

// ---------------------------------------------------------------- bad input

TEST_F(MeshReaderTest, NoFileName) {
  ReadResult r = read("", /*setName=*/false);
  EXPECT_TRUE(r.Errors->HasError());
  EXPECT_NE(r.Errors->Errors().find("no file name"), std::string::npos) << r.Errors->Errors();
  ASSERT_NE(r.Output, nullptr);
  EXPECT_EQ(vtkDataSet::SafeDownCast(r.Output)->GetNumberOfPoints(), 0);
}

TEST_F(MeshReaderTest, MissingFile) {
  for (const char* name : {"gone.obj", "gone.tet", "gone.vtu"}) {
    const std::string path = this->Path(name);
    ReadResult r = read(path);
    EXPECT_EQ(r.Errors->GetErrorCount(), 1);
    EXPECT_NE(r.Errors->Errors().find("file not found: " + path), std::string::npos)
        << r.Errors->Errors();
    vtkDataSet* ds = vtkDataSet::SafeDownCast(r.Output);
    ASSERT_NE(ds, nullptr);
    EXPECT_EQ(ds->GetNumberOfPoints(), 0);
  }
}

TEST_F(MeshReaderTest, UnknownExtensionListsSupportedOnes) {
  const std::string path = this->Write("model.xyz", "0 0 0\n");
  ReadResult r = read(path);
  EXPECT_TRUE(r.Errors->HasError());
  EXPECT_NE(r.Errors->Errors().find("unsupported file extension '.xyz'"), std::string::npos)
      << r.Errors->Errors();
  EXPECT_NE(r.Errors->Errors().find(vtkGLMeshReader::GetSupportedExtensionsString()),
            std::string::npos);
  EXPECT_EQ(vtkDataSet::SafeDownCast(r.Output)->GetNumberOfPoints(), 0);
  // No extension at all.
  ReadResult none = read(this->Write("model", "x"));
  EXPECT_NE(none.Errors->Errors().find("unsupported file extension ''"), std::string::npos)
      << none.Errors->Errors();
}

TEST_F(MeshReaderTest, EmptyFilesGiveAnErrorAndEmptyOutput) {
  for (const char* name : {"e.obj", "e.stl", "e.ply", "e.vtp", "e.off", "e.vtu", "e.tet"}) {
    SCOPED_TRACE(name);
    ReadResult r = read(this->Write(name, ""));
    EXPECT_TRUE(r.Errors->HasError());
    vtkDataSet* ds = vtkDataSet::SafeDownCast(r.Output);
    ASSERT_NE(ds, nullptr);
    EXPECT_EQ(ds->GetNumberOfPoints(), 0);
    EXPECT_EQ(ds->GetNumberOfCells(), 0);
    EXPECT_EQ(vtkGLMeshReader::IsTetMeshFile(name),
              vtkUnstructuredGrid::SafeDownCast(ds) != nullptr);
  }
  // The message names the file and says why, without the executive's request dump.
  ReadResult ply = read(this->Write("f.ply", ""));
  EXPECT_NE(ply.Errors->Errors().find("vtkPLYReader cannot read " + this->Path("f.ply") +
                                      ": Could not open PLY file"),
            std::string::npos)
      << ply.Errors->Errors();
  EXPECT_EQ(ply.Errors->Errors().find("returned failure"), std::string::npos);
  // Points but no faces.
  ReadResult r = read(this->Write("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"));
  EXPECT_NE(r.Errors->Errors().find("empty mesh"), std::string::npos) << r.Errors->Errors();
  EXPECT_EQ(vtkDataSet::SafeDownCast(r.Output)->GetNumberOfPoints(), 0);
}

TEST_F(MeshReaderTest, MalformedFileNamesLine) {
  const std::string path = this->Write("bad.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
  ReadResult r = read(path);
  EXPECT_NE(r.Errors->Errors().find(path + ":6: face 0: vertex index 7 out of range"),
            std::string::npos)
      << r.Errors->Errors();
  EXPECT_EQ(vtkDataSet::SafeDownCast(r.Output)->GetNumberOfCells(), 0);
}

TEST_F(MeshReaderTest, ObjIndexOutOfRangeIsRefused) {
  // vtkOBJReader itself accepts this and makes a polygon with point id 8.
  const std::string path =
      this->Write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 3 9\n");
  ReadResult r = read(path);
  EXPECT_NE(r.Errors->Errors().find(path + ":5: vertex index 9 out of range [1, 3]"),
            std::string::npos)
      << r.Errors->Errors();
  EXPECT_EQ(vtkDataSet::SafeDownCast(r.Output)->GetNumberOfCells(), 0);
}

TEST_F(MeshReaderTest, ObjTextureAndNormalReferencesAreIgnored) {
  // A tetrahedron whose faces refer to texture coordinates and normals beyond the ones listed
  // (as vtkOBJWriter can write them): vtkOBJReader wrote past its arrays and the process
  // aborted in realloc(). Only the vertex references matter for the surface.
  const std::string path = this->Write(
      "tcoords.obj",
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvn 0 0 1\nvt 0 0\nvt 1 0\n"
      "f 1/1/1 3/3/3 2/2/2\nf 1/1/1 2/2/2 4/4/4\nf 1/1/1 4/4/4 3/3/3\nf 2/2/2 3/3/3 4/4/4\n");
  ReadResult r = read(path);
  EXPECT_FALSE(r.Errors->HasError()) << r.Errors->Errors();
  vtkPolyData* surface = vtkPolyData::SafeDownCast(r.Output);
  ASSERT_NE(surface, nullptr);
  EXPECT_EQ(surface->GetNumberOfPoints(), 4);
  EXPECT_EQ(surface->GetNumberOfPolys(), 4);
  EXPECT_EQ(surface->GetPointData()->GetTCoords(), nullptr);
}

TEST_F(MeshReaderTest, CorruptVtkFileReportsReaderError) {
  const std::string path = this->Write("bad.vtp", "<VTKFile type=\"PolyData\"><PolyData><Piece");
  ReadResult r = read(path);
  EXPECT_TRUE(r.Errors->HasError());
  EXPECT_NE(r.Errors->Errors().find("vtkXMLPolyDataReader cannot read " + path), std::string::npos)
      << r.Errors->Errors();
  EXPECT_EQ(vtkDataSet::SafeDownCast(r.Output)->GetNumberOfPoints(), 0);
}

TEST_F(MeshReaderTest, VtuWithNonTetCellsIsRefused) {
  vtkNew<vtkUnstructuredGrid> grid;
  vtkNew<vtkPoints> points;
  for (int i = 0; i < 8; ++i) {
    points->InsertNextPoint(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  }
  grid->SetPoints(points);
  const vtkIdType tet[4] = {0, 1, 2, 4};
  const vtkIdType hex[8] = {0, 1, 3, 2, 4, 5, 7, 6};
  grid->InsertNextCell(VTK_TETRA, 4, tet);
  grid->InsertNextCell(VTK_HEXAHEDRON, 8, hex);
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetInputData(grid);
  writer->SetDataModeToBinary();
  writer->SetFileName(this->Path("hex.vtu").c_str());
  ASSERT_EQ(writer->Write(), 1);
  ReadResult r = read(this->Path("hex.vtu"));
  EXPECT_NE(r.Errors->Errors().find("cell 1 of " + this->Path("hex.vtu") +
                                    " is not a linear tetrahedron (VTK cell type 12)"),
            std::string::npos)
      << r.Errors->Errors();
  EXPECT_EQ(vtkDataSet::SafeDownCast(r.Output)->GetNumberOfCells(), 0);
}

TEST(MeshReaderProgress, SurfaceAndTetMeshReportProgressAndStopOnAbort) {
  for (const char* name : {"bunny.obj", "decimated-knight.off", "ring.tet"}) {
    SCOPED_TRACE(name);
    vtkNew<vtkGLMeshReader> reader;
    reader->SetFileName((kData + "/" + name).c_str());
    // The file read (OBJ: vtkOBJReader's own progress forwarded), then merging (surfaces).
    glExpectProgressReport(reader, 2);
    GLAbortRequest afterTheFirstReport;
    glExpectCleanAbort(reader, afterTheFirstReport);
    glExpectCleanAbort(reader, glAbortAt(0.5));
  }
}
