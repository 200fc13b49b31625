#include "io/MeshReader.h"

#include "common/Error.h"

#include "../common/ErrorOf.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

using namespace geolattice;
namespace fs = std::filesystem;

namespace {

const std::string kData = GEOLATTICE_TESTDATA;

/// A fresh directory per test under the system temp dir, removed afterwards.
class MeshReaderTest : public ::testing::Test {
protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("geolattice_io_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& text) const {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  fs::path dir_;
};

#define EXPECT_CONTAINS(text, part) \
  EXPECT_NE(std::string(text).find(part), std::string::npos) << "message: " << (text)

double totalVolume(const TetMesh& m) {
  double v = 0.0;
  for (const auto& t : m.tets) {
    v += signedTetVolume(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]);
  }
  return v;
}

const char* kTinyTet =
    "5 vertices\n2 tets\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n4 0 1 2 3\n4 4 1 3 2\n";

}  // namespace

// ---------------------------------------------------------------- OFF

TEST_F(MeshReaderTest, OffFanTriangulatesAndSkipsComments) {
  // Counts on the header line, comments, blank lines, CRLF, a quad and a pentagon.
  const std::string p = write("poly.off",
                              "OFF 6 3 0   # header with counts\r\n"
                              "\n"
                              "# vertices\n"
                              "0 0 0\n1 0 0\n1 1 0\r\n0 1 0\n  -1 0.5 0   \n +2e0 0.5 0\n"
                              "3 0 1 2\n"
                              "\n"
                              "4 0 1 2 3 # quad\n"
                              "5 0 5 1 2 4 255 0 0\n");  // pentagon with a trailing colour
  const TriangleSurface s = readOff(p);
  ASSERT_EQ(s.points.size(), 6u);
  EXPECT_DOUBLE_EQ(s.points[4].x(), -1.0);
  EXPECT_DOUBLE_EQ(s.points[5].x(), 2.0);
  ASSERT_EQ(s.triangles.size(), 1u + 2u + 3u);
  EXPECT_EQ(s.triangles[0], (std::array<int, 3>{0, 1, 2}));
  EXPECT_EQ(s.triangles[1], (std::array<int, 3>{0, 1, 2}));
  EXPECT_EQ(s.triangles[2], (std::array<int, 3>{0, 2, 3}));
  EXPECT_EQ(s.triangles[3], (std::array<int, 3>{0, 5, 1}));
  EXPECT_EQ(s.triangles[5], (std::array<int, 3>{0, 2, 4}));
}

TEST_F(MeshReaderTest, OffHeaderVariants) {
  // COFF: colour after xyz; NOFF: normal after xyz; counts on the next line.
  const TriangleSurface c = readOff(write("c.off",
                                          "COFF\n3 1 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n"
                                          "0 1 0 0 0 255 255\n3 0 1 2\n"));
  ASSERT_EQ(c.points.size(), 3u);
  EXPECT_DOUBLE_EQ(c.points[1].x(), 1.0);
  EXPECT_DOUBLE_EQ(c.points[1].y(), 0.0);
  const TriangleSurface n =
      readOff(write("n.off", "NOFF\n3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 2 0 0 0 1\n3 2 0 1\n"));
  EXPECT_DOUBLE_EQ(n.points[2].y(), 2.0);
  EXPECT_EQ(n.triangles.at(0), (std::array<int, 3>{2, 0, 1}));
  // Header keyword left out (optional in Geomview's OFF).
  EXPECT_EQ(readOff(write("bare.off", "3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")).triangles.size(), 1u);
  // 4-D and n-D variants are refused by name.
  EXPECT_CONTAINS(expectedErrorOf([&] {
                    readOff(write("4.off", "4OFF\n3 1 0\n0 0 0 1\n1 0 0 1\n0 1 0 1\n3 0 1 2\n"));
                  }),
                  "unsupported OFF variant '4OFF'");
}

TEST_F(MeshReaderTest, OffKnight) {
  const TriangleSurface s = readOff(kData + "/decimated-knight.off");
  EXPECT_EQ(s.points.size(), 502u);
  EXPECT_EQ(s.triangles.size(), 1000u);
}

TEST_F(MeshReaderTest, OffMalformedNumberNamesFileAndLine) {
  const std::string p = write("bad.off", "OFF\n3 1 0\n0 0 0\n1 x 0\n0 1 0\n3 0 1 2\n");
  const std::string msg = expectedErrorOf([&] { readOff(p); });
  EXPECT_CONTAINS(msg, p + ":4:");
  EXPECT_CONTAINS(msg, "'x'");
}

TEST_F(MeshReaderTest, OffTooFewCoordinates) {
  EXPECT_CONTAINS(
      expectedErrorOf([&] { readOff(write("b.off", "OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n")); }),
      "b.off:4: vertex 1: expected 'x y z'");
}

TEST_F(MeshReaderTest, OffNonFiniteCoordinate) {
  EXPECT_CONTAINS(expectedErrorOf([&] {
                    readOff(write("b.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 nan 0\n3 0 1 2\n"));
                  }),
                  "b.off:5: non-finite");
}

TEST_F(MeshReaderTest, OffIndexOutOfRange) {
  EXPECT_CONTAINS(expectedErrorOf([&] {
                    readOff(write("b.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"));
                  }),
                  "b.off:6: face 0: vertex index 3 out of range [0, 2]");
  EXPECT_CONTAINS(expectedErrorOf([&] {
                    readOff(write("n.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n"));
                  }),
                  "vertex index -1 out of range");
}

TEST_F(MeshReaderTest, OffFaceWithTooFewVertices) {
  EXPECT_CONTAINS(
      expectedErrorOf([&] { readOff(write("b.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n")); }),
      "b.off:6: face 0 has 2 vertices");
  EXPECT_CONTAINS(expectedErrorOf([&] {
                    readOff(write("s.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n"));
                  }),
                  "s.off:6: face 0: expected 4 vertex indices, got 3");
}

TEST_F(MeshReaderTest, OffCountsDoNotMatch) {
  // Fewer faces than announced.
  EXPECT_CONTAINS(expectedErrorOf([&] {
                    readOff(write("few.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"));
                  }),
                  "unexpected end of file: expected face 1 of 2");
  // More data than announced.
  EXPECT_CONTAINS(
      expectedErrorOf([&] {
        readOff(write("many.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 2 1 0\n"));
      }),
      "many.off:7: extra data after 3 vertices and 1 faces");
  // Bad counts line.
  EXPECT_CONTAINS(expectedErrorOf([&] { readOff(write("hdr.off", "OFF\n3\n0 0 0\n")); }),
                  "hdr.off:2: expected the counts");
}

TEST_F(MeshReaderTest, OffEmpty) {
  EXPECT_EQ(expectedErrorOf([&] { readOff(write("e.off", "")); }),
            "empty mesh: " + path("e.off") + " has no data");
  EXPECT_CONTAINS(expectedErrorOf([&] { readOff(write("c.off", "# only a comment\n\n")); }),
                  "empty mesh");
  EXPECT_CONTAINS(
      expectedErrorOf([&] { readOff(write("z.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n")); }),
      "empty mesh: " + path("z.off") + " has 3 vertices and 0 faces");
}

TEST_F(MeshReaderTest, MissingAndUnreadableFiles) {
  const std::string missing = path("nope.off");
  EXPECT_EQ(expectedErrorOf([&] { readOff(missing); }), "file not found: " + missing);
  EXPECT_EQ(expectedErrorOf([&] { readTetFile(path("nope.tet")); }),
            "file not found: " + path("nope.tet"));
  fs::create_directories(dir_ / "folder.tet");
  EXPECT_CONTAINS(expectedErrorOf([&] { readTetFile(path("folder.tet")); }), "is a directory");
}

// ---------------------------------------------------------------- .tet

TEST_F(MeshReaderTest, TetSmallFile) {
  const TetMesh m = readTetFile(write("two.tet", kTinyTet));
  ASSERT_EQ(m.points.size(), 5u);
  ASSERT_EQ(m.tets.size(), 2u);
  EXPECT_EQ(m.tets[1], (std::array<int, 4>{4, 1, 3, 2}));
  EXPECT_DOUBLE_EQ(m.points[4].z(), 1.0);
  EXPECT_NEAR(totalVolume(m), 1.0 / 6.0 + 1.0 / 3.0, 1e-12);
  // Counts without the words and with trailing blanks are accepted too.
  EXPECT_EQ(readTetFile(write("bare.tet", "4\n1\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n4 0 1 2 3 \n\n"))
                .tets.size(),
            1u);
}

TEST_F(MeshReaderTest, TetRing) {
  const TetMesh m = readTetFile(kData + "/ring.tet");
  EXPECT_EQ(m.points.size(), 8150u);
  EXPECT_EQ(m.tets.size(), 40064u);
  EXPECT_DOUBLE_EQ(m.points[0].x(), -33.487572);
  EXPECT_EQ(m.tets[0], (std::array<int, 4>{867, 1407, 164, 4246}));
  EXPECT_EQ(m.tets.back(), (std::array<int, 4>{7524, 8123, 8138, 8148}));
}

TEST_F(MeshReaderTest, TetMalformedLines) {
  EXPECT_CONTAINS(expectedErrorOf([&] { readTetFile(write("h.tet", "five vertices\n1 tets\n")); }),
                  "h.tet:1: expected an integer for vertex count, got 'five'");
  EXPECT_CONTAINS(
      expectedErrorOf([&] { readTetFile(write("h2.tet", "4 vertices\n1 tets extra\n")); }),
      "h2.tet:2: expected 'M tets'");
  EXPECT_CONTAINS(
      expectedErrorOf([&] {
        readTetFile(write("n.tet", "4 vertices\n1 tets\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n"));
      }),
      "n.tet:7: tet 0: expected '4 a b c d'");
  EXPECT_CONTAINS(
      expectedErrorOf([&] {
        readTetFile(write("s.tet", "4 vertices\n1 tets\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n4 0 1 2\n"));
      }),
      "s.tet:7: tet 0: expected '4 a b c d'");
  EXPECT_CONTAINS(
      expectedErrorOf([&] {
        readTetFile(write("c.tet", "4 vertices\n1 tets\n0 0 0\n1 0 0\n0 1 0\n0 0 1e\n4 0 1 2 3\n"));
      }),
      "c.tet:6: expected a number for z, got '1e'");
}

TEST_F(MeshReaderTest, TetIndexOutOfRange) {
  EXPECT_CONTAINS(
      expectedErrorOf([&] {
        readTetFile(write("r.tet", "4 vertices\n1 tets\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n4 0 1 2 4\n"));
      }),
      "r.tet:7: tet 0: vertex index 4 out of range [0, 3]");
}

TEST_F(MeshReaderTest, TetCountsDoNotMatch) {
  // 3 vertex lines where 4 are announced: the tet line is read as the 4th vertex, then EOF.
  EXPECT_CONTAINS(
      expectedErrorOf([&] {
        readTetFile(write("f.tet", "4 vertices\n1 tets\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2 3\n"));
      }),
      "unexpected end of file: expected tet 0 of 1");
  // 5 vertex lines where 4 are announced: the 5th vertex is not a tet line.
  EXPECT_CONTAINS(
      expectedErrorOf([&] {
        readTetFile(
            write("m.tet", "4 vertices\n1 tets\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n4 0 1 2 3\n"));
      }),
      "m.tet:7: tet 0: expected '4 a b c d'");
  // A tet more than announced.
  EXPECT_CONTAINS(
      expectedErrorOf([&] {
        readTetFile(write(
            "x.tet", "4 vertices\n1 tets\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n4 0 1 2 3\n4 0 1 3 2\n"));
      }),
      "x.tet:8: extra data after 4 vertices and 1 tets");
}

TEST_F(MeshReaderTest, TetEmpty) {
  EXPECT_EQ(expectedErrorOf([&] { readTetFile(write("e.tet", "")); }),
            "empty mesh: " + path("e.tet") + " has no data");
  EXPECT_CONTAINS(expectedErrorOf([&] { readTetFile(write("h.tet", "4 vertices\n")); }),
                  "h.tet: unexpected end of file");
  EXPECT_CONTAINS(expectedErrorOf([&] { readTetFile(write("z.tet", "0 vertices\n0 tets\n")); }),
                  "empty mesh: " + path("z.tet") + " has 0 vertices and 0 tets");
}

// ---------------------------------------------------------------- TetGen

TEST_F(MeshReaderTest, TetGenTinyFromEitherFile) {
  for (const char* name : {"/tiny.node", "/tiny.ele"}) {
    const TetMesh m = readTetGenMesh(kData + name);
    ASSERT_EQ(m.points.size(), 8u) << name;
    ASSERT_EQ(m.tets.size(), 5u) << name;
    // Numbered from 1 in the files: point 1 is index 0, the first tet "1 2 4 5" is {0, 1, 3, 4}.
    EXPECT_EQ(m.tets[0], (std::array<int, 4>{0, 1, 3, 4}));
    EXPECT_DOUBLE_EQ(m.points[6].x(), 1.0);
    EXPECT_DOUBLE_EQ(m.points[6].z(), 1.0);
    for (const auto& t : m.tets) {
      EXPECT_GT(signedTetVolume(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]),
                0.0);
    }
    EXPECT_NEAR(totalVolume(m), 1.0, 1e-12);
  }
}

TEST_F(MeshReaderTest, TetGenZeroBasedAndQuadratic) {
  // 0-based numbering, no attributes/markers in the header, 10-node tets (corner nodes kept).
  write("q.node", "5 3\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n4 0.5 0 0\n");
  const std::string ele = write("q.ele", "1 10 0\n0 0 1 2 3 4 4 4 4 4 4\n");
  const TetMesh m = readTetGenMesh(ele);
  ASSERT_EQ(m.points.size(), 5u);
  ASSERT_EQ(m.tets.size(), 1u);
  EXPECT_EQ(m.tets[0], (std::array<int, 4>{0, 1, 2, 3}));
  // Upper-case extensions pair with upper-case partners.
  write("U.NODE", "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n");
  write("U.ELE", "1 4 0\n1 1 2 3 4\n");
  EXPECT_EQ(readTetGenMesh(path("U.NODE")).tets.size(), 1u);
}

TEST_F(MeshReaderTest, TetGenMissingPartner) {
  const std::string node = write("alone.node", "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n");
  EXPECT_EQ(expectedErrorOf([&] { readTetGenMesh(node); }), "file not found: " + path("alone.ele"));
  EXPECT_EQ(expectedErrorOf([&] { readTetGenMesh(path("none.ele")); }),
            "file not found: " + path("none.node"));
}

TEST_F(MeshReaderTest, TetGenBadInput) {
  EXPECT_CONTAINS(expectedErrorOf([&] { readTetGenMesh(path("mesh.tet")); }),
                  "expected a .node or .ele file");
  struct BadPair {
    const char* name;  // files name.node and name.ele
    const char* node;  // their contents
    const char* ele;
    const char* given;  // the extension passed to readTetGenMesh
    const char* error;  // a part of the message
  };
  const BadPair cases[] = {
      // 1-based .node, but the .ele uses point number 0.
      {"a", "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n", "1 4 0\n1 0 1 2 3\n", ".node",
       "a.ele:2: tetrahedron 0: vertex index 0 out of range [1, 4]"},
      {"b", "4 3 0 0\n0 0 0 0\n1 1 0 0\n3 0 1 0\n4 0 0 1\n", "1 4 0\n0 0 1 2 3\n", ".ele",
       "b.node:4: point numbers must be consecutive: expected 2, got 3"},
      {"c", "4 2 0 0\n", "1 4 0\n0 0 1 2 3\n", ".node", "c.node:1: dimension 2 is not supported"},
      {"d", "4 3 0 0\n2 0 0 0\n3 1 0 0\n4 0 1 0\n5 0 0 1\n", "1 4 0\n1 2 3 4 5\n", ".node",
       "d.node:2: first point number must be 0 or 1"},
      // Attribute announced in the header but missing on a point line.
      {"e", "2 3 1 0\n0 0 0 0 7\n1 1 0 0\n", "1 4 0\n0 0 1 0 1\n", ".node",
       "e.node:3: point line: expected 5 values"},
      {"f", "4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n", "2 4 0\n0 0 1 2 3\n", ".node",
       "expected tetrahedron 1 of 2"},
      {"g", "4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n", "1 6 0\n0 0 1 2 3 4 5\n", ".node",
       "nodes per tetrahedron must be 4 or 10, got 6"},
      {"h", "0 3 0 0\n", "0 4 0\n", ".node", "empty mesh"},
  };
  for (const BadPair& c : cases) {
    SCOPED_TRACE(c.name);
    write(std::string(c.name) + ".node", c.node);
    write(std::string(c.name) + ".ele", c.ele);
    EXPECT_CONTAINS(expectedErrorOf([&] { readTetGenMesh(path(std::string(c.name) + c.given)); }),
                    c.error);
  }
}

// ---------------------------------------------------------------- writer

TEST_F(MeshReaderTest, WriteReadRoundTripIsExact) {
  const TetMesh ring = readTetFile(kData + "/ring.tet");
  TetMesh m = ring;
  m.points[0] = Vec3(0.1, 1.0 / 3.0, -2.5e-17);  // values that a fixed "%f" would lose
  const std::string p = path("out.tet");
  writeTetFile(p, m);
  EXPECT_FALSE(fs::exists(p + ".tmp"));
  const TetMesh back = readTetFile(p);
  ASSERT_EQ(back.points.size(), m.points.size());
  ASSERT_EQ(back.tets.size(), m.tets.size());
  for (size_t i = 0; i < m.points.size(); ++i) {
    ASSERT_EQ(back.points[i], m.points[i]) << "vertex " << i;
  }
  EXPECT_EQ(back.tets, m.tets);
  // Overwriting an existing file replaces it.
  writeTetFile(p, readTetFile(write("two.tet", kTinyTet)));
  EXPECT_EQ(readTetFile(p).tets.size(), 2u);
}

TEST_F(MeshReaderTest, WriteRefusesBadMeshesAndLeavesNothing) {
  TetMesh empty;
  const std::string p = path("bad.tet");
  EXPECT_CONTAINS(expectedErrorOf([&] { writeTetFile(p, empty); }), "empty mesh");
  TetMesh m = readTetFile(write("two.tet", kTinyTet));
  m.tets[1][2] = 5;
  EXPECT_CONTAINS(expectedErrorOf([&] { writeTetFile(p, m); }),
                  "tet 1 has vertex index 5 out of range [0, 4]");
  EXPECT_FALSE(fs::exists(p));
  EXPECT_FALSE(fs::exists(p + ".tmp"));
  // Unwritable location: the error names the temporary file; nothing is created.
  const std::string q = path("no_such_dir/out.tet");
  EXPECT_CONTAINS(expectedErrorOf([&] { writeTetFile(q, readTetFile(path("two.tet"))); }),
                  "cannot create " + q);
  EXPECT_FALSE(fs::exists(q));
}

// ---------------------------------------------------------------- OBJ

TEST_F(MeshReaderTest, ObjFaceFormsNegativeIndicesAndPolygons) {
  // All four vertex reference forms, relative indices, a quad, a pentagon, ignored statements,
  // comments, CRLF and a forward reference (face before its last vertex).
  const std::string p = write("forms.obj",
                              "# comment\r\n"
                              "mtllib none.mtl\n"
                              "o part\n"
                              "v 0 0 0\nv 1 0 0\nv 1 1 0 1.0\n"  // optional w
                              "vt 0 0\nvt 1 0\nvn 0 0 1\n"
                              "g group\ns off\nusemtl red\n"
                              "f 1 2 3\n"
                              "f 1/1 2/2 3/1\n"
                              "f 1/1/1 2/2/1 3/1/1   # trailing comment\n"
                              "f 1//1 2//1 3//1\n"
                              "f -3 -2 -1\n"           // = 1 2 3
                              "v 0 1 0 0.5 0.5 0.5\n"  // vertex 4 with a colour
                              "f 1 2 3 -1\n"           // quad 1 2 3 4
                              "f 1 2 5 3 4\n"          // pentagon, vertex 5 defined below
                              "l 1 2\n"
                              "v -1 0.5 +2e0\n");
  const TriangleSurface s = readObj(p);
  ASSERT_EQ(s.points.size(), 5u);
  EXPECT_EQ(s.points[4], Vec3(-1, 0.5, 2));
  EXPECT_EQ(s.points[3], Vec3(0, 1, 0));
  const std::vector<std::array<int, 3>> expected = {{0, 1, 2}, {0, 1, 2}, {0, 1, 2}, {0, 1, 2},
                                                    {0, 1, 2}, {0, 1, 2}, {0, 2, 3}, {0, 1, 4},
                                                    {0, 4, 2}, {0, 2, 3}};
  EXPECT_EQ(s.triangles, expected);
}

TEST_F(MeshReaderTest, ObjBunny) {
  const TriangleSurface s = readObj(kData + "/bunny.obj");
  EXPECT_EQ(s.triangles.size(), 3674u);
  EXPECT_EQ(s.points.size(), 1839u);  // closed genus-0 surface: V = F/2 + 2
  for (const auto& t : s.triangles) {
    for (int id : t) {
      ASSERT_TRUE(id >= 0 && id < static_cast<int>(s.points.size()));
    }
  }
}

TEST_F(MeshReaderTest, ObjMalformedLinesNameFileAndLine) {
  const std::string v = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  const std::string a = write("a.obj", v + "v 1 2\nf 1 2 3\n");
  EXPECT_CONTAINS(expectedErrorOf([&] { readObj(a); }),
                  a + ":4: vertex 4: expected 'v x y z', got 2 values");
  const std::string b = write("b.obj", v + "v 1 x 2\n");
  EXPECT_CONTAINS(expectedErrorOf([&] { readObj(b); }), b + ":4: expected a number for y, got 'x'");
  const std::string c = write("c.obj", v + "f 1 2\n");
  EXPECT_CONTAINS(expectedErrorOf([&] { readObj(c); }),
                  c + ":4: face with 2 vertices; at least 3 needed");
  const std::string d = write("d.obj", v + "\nf 1 2 0\n");
  EXPECT_CONTAINS(expectedErrorOf([&] { readObj(d); }), d + ":5: vertex index 0");
  const std::string e = write("e.obj", v + "f 1 2 three\n");
  EXPECT_CONTAINS(expectedErrorOf([&] { readObj(e); }),
                  e + ":4: expected an integer for a vertex index, got 'three'");
  const std::string f = write("f.obj", v + "f 1/1/1/1 2 3\n");
  EXPECT_CONTAINS(expectedErrorOf([&] { readObj(f); }),
                  f + ":4: malformed vertex reference '1/1/1/1'");
  const std::string g = write("g.obj", v + "f /1 2 3\n");
  EXPECT_CONTAINS(expectedErrorOf([&] { readObj(g); }),
                  g + ":4: expected an integer for a vertex index, got ''");
  const std::string h = write("h.obj", "v inf 0 0\n");
  EXPECT_CONTAINS(expectedErrorOf([&] { readObj(h); }), h + ":1: non-finite value for x");
}

TEST_F(MeshReaderTest, ObjIndexOutOfRange) {
  const std::string v = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  const std::string a = write("a.obj", v + "f 1 2 3\nf 1 2 4\n");
  EXPECT_CONTAINS(expectedErrorOf([&] { readObj(a); }),
                  a + ":5: vertex index 4 out of range [1, 3]");
  const std::string b = write("b.obj", v + "f -1 -2 -4\n");
  EXPECT_CONTAINS(expectedErrorOf([&] { readObj(b); }),
                  b + ":4: relative vertex index -4 reaches before the first vertex");
  // A relative index counts only the vertices read before the face.
  const std::string c = write("c.obj", "v 0 0 0\nf -1 -2 -3\nv 1 0 0\nv 0 1 0\n");
  EXPECT_CONTAINS(expectedErrorOf([&] { readObj(c); }), c + ":2: relative vertex index -2");
}

TEST_F(MeshReaderTest, ObjEmptyAndMissing) {
  const std::string a = write("a.obj", "# nothing\n");
  EXPECT_CONTAINS(expectedErrorOf([&] { readObj(a); }),
                  "empty mesh: " + a + " has 0 vertices and 0 faces");
  const std::string b = write("b.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\n");
  EXPECT_CONTAINS(expectedErrorOf([&] { readObj(b); }),
                  "empty mesh: " + b + " has 3 vertices and 0 faces");
  EXPECT_CONTAINS(expectedErrorOf([&] { readObj(path("missing.obj")); }),
                  "file not found: " + path("missing.obj"));
}

TEST_F(MeshReaderTest, ObjWriteReadRoundTripIsExact) {
  TriangleSurface s = readObj(kData + "/bunny.obj");
  s.points[0] = Vec3(0.1, 1.0 / 3.0, -2.5e-17);
  const std::string p = path("out.obj");
  writeObj(p, s, "generated by a test\nsecond line");
  EXPECT_FALSE(fs::exists(p + ".tmp"));
  std::ifstream in(p);
  std::string first;
  std::getline(in, first);
  EXPECT_EQ(first, "# generated by a test");
  const TriangleSurface back = readObj(p);
  ASSERT_EQ(back.points.size(), s.points.size());
  for (size_t i = 0; i < s.points.size(); ++i) {
    ASSERT_EQ(back.points[i], s.points[i]) << "vertex " << i;
  }
  EXPECT_EQ(back.triangles, s.triangles);
}

TEST_F(MeshReaderTest, ObjWriteRefusesBadSurfacesAndLeavesNothing) {
  const std::string p = path("bad.obj");
  EXPECT_CONTAINS(expectedErrorOf([&] { writeObj(p, TriangleSurface{}); }), "empty mesh");
  TriangleSurface s;
  s.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  s.triangles = {{0, 1, 3}};
  EXPECT_CONTAINS(expectedErrorOf([&] { writeObj(p, s); }),
                  "triangle 0 has vertex index 3 out of range [0, 2]");
  s.triangles = {{0, 1, 2}};
  s.points[1].y() = std::nan("");
  EXPECT_CONTAINS(expectedErrorOf([&] { writeObj(p, s); }), "vertex 1 is not finite");
  EXPECT_FALSE(fs::exists(p));
  EXPECT_FALSE(fs::exists(p + ".tmp"));
  s.points[1].y() = 0.0;
  const std::string q = path("no_such_dir/out.obj");
  EXPECT_CONTAINS(expectedErrorOf([&] { writeObj(q, s); }), "cannot create " + q);
  EXPECT_FALSE(fs::exists(q));
}
