#include "io/MeshReader.h"

#include "common/AtomicFile.h"

#include "common/Error.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string_view>
#include <system_error>
#include <vector>

namespace geolattice {

namespace {

namespace fs = std::filesystem;

/// Whole file in memory; throws with the file name when it is missing or unreadable.
std::string loadFile(const std::string& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) {
    throw GeoLatticeError("file not found: " + path);
  }
  if (fs::is_directory(path, ec)) {
    throw GeoLatticeError("cannot read " + path + ": it is a directory");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw GeoLatticeError("cannot open " + path + ": " + std::strerror(errno));
  }
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) {
    throw GeoLatticeError("cannot read " + path + ": I/O error");
  }
  return text.str();
}

/// Splits a text into whitespace-separated tokens line by line, skipping blank lines and
/// '#' comments, and keeps the 1-based number of the current line for error messages.
class LineTokenizer {
public:
  LineTokenizer(std::string path, std::string text)
      : path_(std::move(path)), text_(std::move(text)) {}

  /// Tokens of the next line that has any; false at end of file.
  bool next(std::vector<std::string_view>& tokens) {
    tokens.clear();
    while (pos_ < text_.size()) {
      const size_t end = std::min(text_.find('\n', pos_), text_.size());
      std::string_view line(text_.data() + pos_, end - pos_);
      pos_ = end + 1;
      ++line_;
      line = line.substr(0, line.find('#'));
      size_t i = 0;
      while (i < line.size()) {
        while (i < line.size() && isSpace(line[i])) {
          ++i;
        }
        const size_t start = i;
        while (i < line.size() && !isSpace(line[i])) {
          ++i;
        }
        if (i > start) {
          tokens.push_back(line.substr(start, i - start));
        }
      }
      if (!tokens.empty()) {
        return true;
      }
    }
    return false;
  }

  /// Reads the header line into `tokens`: it must exist and hold minTokens..maxTokens tokens
  /// (else "expected " + layout).
  void header(std::vector<std::string_view>& tokens, size_t minTokens, size_t maxTokens,
              const char* layout) {
    if (!next(tokens)) {
      throw GeoLatticeError("empty mesh: " + path_ + " has no header line");
    }
    if (tokens.size() < minTokens || tokens.size() > maxTokens) {
      fail(std::string("expected '") + layout + "'");
    }
  }

  /// Throws "path:line: message" for the line last returned by next().
  [[noreturn]] void fail(const std::string& message) const {
    throw GeoLatticeError(path_ + ":" + std::to_string(line_) + ": " + message);
  }

  /// Throws when the file ends before `what` (e.g. "vertex 12 of 100") was read.
  [[noreturn]] void failEof(const std::string& what) const {
    throw GeoLatticeError(path_ + ": unexpected end of file: expected " + what +
                          " (counts in the header do not match the data)");
  }

  /// Reads the line of element i of n (e.g. "vertex", "face") into tok; throws failEof naming it
  /// when the file ends first.
  void nextElement(std::vector<std::string_view>& tok, const char* element, int i, int n) {
    if (!next(tok)) {
      failEof(std::string(element) + " " + std::to_string(i) + " of " + std::to_string(n));
    }
  }

  double number(std::string_view token, const char* what) const {
    if (!token.empty() && token.front() == '+') {
      token.remove_prefix(1);  // from_chars does not take a leading '+'
    }
    double value = 0.0;
    const auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (ec != std::errc() || ptr != token.data() + token.size()) {
      fail(std::string("expected a number for ") + what + ", got '" + std::string(token) + "'");
    }
    if (!std::isfinite(value)) {
      fail(std::string("non-finite value for ") + what + ": '" + std::string(token) + "'");
    }
    return value;
  }

  long long integer(std::string_view token, const char* what) const {
    if (!token.empty() && token.front() == '+') {
      token.remove_prefix(1);
    }
    long long value = 0;
    const auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (ec != std::errc() || ptr != token.data() + token.size()) {
      fail(std::string("expected an integer for ") + what + ", got '" + std::string(token) + "'");
    }
    return value;
  }

  /// A non-negative count that fits an int (vertex/cell counts of the header).
  int count(std::string_view token, const char* what) const {
    const long long value = integer(token, what);
    if (value < 0 || value > std::numeric_limits<int>::max()) {
      fail(std::string("invalid ") + what + " " + std::to_string(value));
    }
    return static_cast<int>(value);
  }

  /// A vertex index shifted by -base, checked against [0, numPoints).
  int index(std::string_view token, long long base, int numPoints, long long cell,
            const char* cellName) const {
    const long long raw = integer(token, "a vertex index");
    const long long value = raw - base;
    if (value < 0 || value >= numPoints) {
      fail(std::string(cellName) + " " + std::to_string(cell) + ": vertex index " +
           std::to_string(raw) + " out of range [" + std::to_string(base) + ", " +
           std::to_string(base + numPoints - 1) + "]");
    }
    return static_cast<int>(value);
  }

  Vec3 point(const std::vector<std::string_view>& tokens, size_t first) const {
    return Vec3(number(tokens[first], "x"), number(tokens[first + 1], "y"),
                number(tokens[first + 2], "z"));
  }

  /// Throws if any non-comment line follows the data the header announced.
  void expectEnd(const std::string& announced) {
    std::vector<std::string_view> tokens;
    if (next(tokens)) {
      fail("extra data after " + announced + " (counts in the header do not match the data)");
    }
  }

  const std::string& path() const { return path_; }
  /// 1-based number of the line last returned by next().
  int lineNumber() const { return line_; }

private:
  static bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
  }

  std::string path_;
  std::string text_;
  size_t pos_ = 0;
  int line_ = 0;
};

std::string toLower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

/// True for OFF header keywords whose vertex lines start with x y z: OFF with any of the
/// prefixes S/T (texture), C (colour), N (normal). 4OFF (4-D) and nOFF (n-D) are not.
bool isOffKeyword(std::string_view token) {
  if (token.size() < 3 || token.substr(token.size() - 3) != "OFF") {
    return false;
  }
  const std::string_view prefix = token.substr(0, token.size() - 3);
  return prefix.find_first_not_of("STCN") == std::string_view::npos;
}

void checkNotEmpty(const std::string& path, size_t numPoints, size_t numCells,
                   const char* cellName) {
  if (numPoints == 0 || numCells == 0) {
    throw GeoLatticeError("empty mesh: " + path + " has " + std::to_string(numPoints) +
                          " vertices and " + std::to_string(numCells) + " " + cellName);
  }
}

/// The next n lines as vertices 'x y z' (extra values ignored), as OFF and .tet files list them.
std::vector<Vec3> readVertexLines(LineTokenizer& lines, int n) {
  std::vector<Vec3> points(n);
  std::vector<std::string_view> tok;
  for (int i = 0; i < n; ++i) {
    lines.nextElement(tok, "vertex", i, n);
    if (tok.size() < 3) {
      lines.fail("vertex " + std::to_string(i) + ": expected 'x y z', got " +
                 std::to_string(tok.size()) + " values");
    }
    points[i] = lines.point(tok, 0);
  }
  return points;
}

/// Before writing: a non-empty mesh whose cells index existing vertices, all finite.
/// cellName: "triangle" / "tet" (singular, for the message).
template <class Cells>
void checkWritable(const std::string& path, const std::vector<Vec3>& points, const Cells& cells,
                   const char* cellName) {
  checkNotEmpty(path, points.size(), cells.size(), (std::string(cellName) + "s").c_str());
  const long long numPoints = static_cast<long long>(points.size());
  for (size_t t = 0; t < cells.size(); ++t) {
    for (int id : cells[t]) {
      if (id < 0 || id >= numPoints) {
        throw GeoLatticeError("cannot write " + path + ": " + cellName + " " + std::to_string(t) +
                              " has vertex index " + std::to_string(id) + " out of range [0, " +
                              std::to_string(numPoints - 1) + "]");
      }
    }
  }
  for (size_t i = 0; i < points.size(); ++i) {
    if (!points[i].allFinite()) {
      throw GeoLatticeError("cannot write " + path + ": vertex " + std::to_string(i) +
                            " is not finite");
    }
  }
}

/// Writes "x y z\n", each the shortest representation that parses back to the same double
/// (std::to_chars), so a written mesh reads back exactly.
void writeCoordinates(std::ostream& out, const Vec3& p) {
  char buf[64];
  for (int k = 0; k < 3; ++k) {
    const auto [end, ec] = std::to_chars(buf, buf + sizeof(buf), p[k]);
    out.write(buf, end - buf);
    out.put(k < 2 ? ' ' : '\n');
  }
}

}  // namespace

TriangleSurface readOff(const std::string& path) {
  LineTokenizer lines(path, loadFile(path));
  std::vector<std::string_view> tok;
  if (!lines.next(tok)) {
    throw GeoLatticeError("empty mesh: " + path + " has no data");
  }
  // Header keyword (optional in Geomview's OFF), then the counts on the same or next line.
  if (toLower(std::string(tok[0])).find("off") != std::string::npos) {
    if (!isOffKeyword(tok[0]) && tok[0] != "off") {
      lines.fail("unsupported OFF variant '" + std::string(tok[0]) +
                 "' (supported: OFF, COFF, NOFF, CNOFF, STOFF)");
    }
    tok.erase(tok.begin());
    if (tok.empty() && !lines.next(tok)) {
      lines.failEof("the counts line '#vertices #faces #edges'");
    }
  }
  if (tok.size() < 2 || tok.size() > 3) {
    lines.fail("expected the counts '#vertices #faces [#edges]'");
  }
  const int numPoints = lines.count(tok[0], "vertex count");
  const int numFaces = lines.count(tok[1], "face count");
  checkNotEmpty(path, static_cast<size_t>(numPoints), static_cast<size_t>(numFaces), "faces");

  TriangleSurface surface;
  surface.points = readVertexLines(lines, numPoints);
  surface.triangles.reserve(numFaces);
  for (int f = 0; f < numFaces; ++f) {
    lines.nextElement(tok, "face", f, numFaces);
    const long long n = lines.integer(tok[0], "the face's vertex count");
    if (n < 3) {
      lines.fail("face " + std::to_string(f) + " has " + std::to_string(n) +
                 " vertices; at least 3 needed");
    }
    if (static_cast<long long>(tok.size()) < n + 1) {
      lines.fail("face " + std::to_string(f) + ": expected " + std::to_string(n) +
                 " vertex indices, got " + std::to_string(tok.size() - 1));
    }
    std::vector<int> ids(static_cast<size_t>(n));
    for (long long k = 0; k < n; ++k) {
      ids[k] = lines.index(tok[k + 1], 0, numPoints, f, "face");
    }
    // Fan triangulation keeps the polygon's orientation; exact for convex polygons.
    for (long long k = 1; k + 1 < n; ++k) {
      surface.triangles.push_back({ids[0], ids[k], ids[k + 1]});
    }
  }
  lines.expectEnd(std::to_string(numPoints) + " vertices and " + std::to_string(numFaces) +
                  " faces");
  return surface;
}

TriangleSurface readObj(const std::string& path) {
  LineTokenizer lines(path, loadFile(path));
  std::vector<std::string_view> tok;
  TriangleSurface surface;
  // Raw 1-based (resolved) indices with the line they came from; positive indices are checked
  // against the vertex count once the whole file is read (forward references are legal).
  struct PendingFace {
    std::vector<long long> ids;
    int line;
  };
  std::vector<PendingFace> faces;
  while (lines.next(tok)) {
    if (tok[0] == "v") {
      if (tok.size() < 4) {
        lines.fail("vertex " + std::to_string(surface.points.size() + 1) +
                   ": expected 'v x y z', got " + std::to_string(tok.size() - 1) + " values");
      }
      surface.points.push_back(lines.point(tok, 1));
    } else if (tok[0] == "f") {
      if (tok.size() < 4) {
        lines.fail("face with " + std::to_string(tok.size() - 1) + " vertices; at least 3 needed");
      }
      PendingFace face{{}, lines.lineNumber()};
      face.ids.reserve(tok.size() - 1);
      const long long numRead = static_cast<long long>(surface.points.size());
      for (size_t k = 1; k < tok.size(); ++k) {
        // "v", "v/vt", "v/vt/vn" or "v//vn": the vertex index is the part before the first '/'.
        const std::string_view ref = tok[k];
        const size_t slash = ref.find('/');
        if (slash != std::string_view::npos && std::count(ref.begin(), ref.end(), '/') > 2) {
          lines.fail("malformed vertex reference '" + std::string(ref) +
                     "' (expected v, v/vt, v/vt/vn or v//vn)");
        }
        const long long raw = lines.integer(ref.substr(0, slash), "a vertex index");
        if (raw == 0) {
          lines.fail("vertex index 0 in '" + std::string(ref) +
                     "' (OBJ indices start at 1; negative = relative)");
        }
        long long id = raw;
        if (raw < 0) {
          id = numRead + 1 + raw;  // -1 = the last vertex read so far
          if (id < 1) {
            lines.fail("relative vertex index " + std::to_string(raw) +
                       " reaches before the first vertex (" + std::to_string(numRead) +
                       " vertices read so far)");
          }
        }
        face.ids.push_back(id);
      }
      faces.push_back(std::move(face));
    }
    // Every other statement (vt, vn, vp, g, o, s, usemtl, mtllib, l, p, ...) is ignored.
  }
  checkNotEmpty(path, surface.points.size(), faces.size(), "faces");
  const long long numPoints = static_cast<long long>(surface.points.size());
  if (numPoints > std::numeric_limits<int>::max()) {
    throw GeoLatticeError(path + ": too many vertices (" + std::to_string(numPoints) + ")");
  }
  surface.triangles.reserve(faces.size());
  for (const PendingFace& face : faces) {
    for (long long id : face.ids) {
      if (id > numPoints) {
        throw GeoLatticeError(path + ":" + std::to_string(face.line) + ": vertex index " +
                              std::to_string(id) + " out of range [1, " +
                              std::to_string(numPoints) + "]");
      }
    }
    // Fan triangulation keeps the polygon's orientation; exact for convex polygons.
    for (size_t k = 1; k + 1 < face.ids.size(); ++k) {
      surface.triangles.push_back({static_cast<int>(face.ids[0] - 1),
                                   static_cast<int>(face.ids[k] - 1),
                                   static_cast<int>(face.ids[k + 1] - 1)});
    }
  }
  return surface;
}

void writeObj(const std::string& path, const TriangleSurface& surface, const std::string& comment) {
  checkWritable(path, surface.points, surface.triangles, "triangle");
  AtomicFileSet files;
  {
    std::ostream& out = files.open(path);
    std::istringstream lines(comment);
    for (std::string line; std::getline(lines, line);) {
      out << "# " << line << '\n';
    }
    for (const Vec3& p : surface.points) {
      out << "v ";
      writeCoordinates(out, p);
    }
    for (const auto& t : surface.triangles) {
      out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
    }
  }
  files.commit();
}

TetMesh readTetFile(const std::string& path) {
  LineTokenizer lines(path, loadFile(path));
  std::vector<std::string_view> tok;
  // "N vertices" / "M tets": a count optionally followed by one word.
  auto header = [&](const char* what, const char* example, bool first) {
    if (!lines.next(tok)) {
      if (first) {
        throw GeoLatticeError("empty mesh: " + path + " has no data");
      }
      lines.failEof(std::string("the header line '") + example + "'");
    }
    if (tok.size() > 2) {
      lines.fail(std::string("expected '") + example + "'");
    }
    return lines.count(tok[0], what);
  };
  const int numPoints = header("vertex count", "N vertices", true);
  const int numTets = header("tet count", "M tets", false);
  checkNotEmpty(path, static_cast<size_t>(numPoints), static_cast<size_t>(numTets), "tets");

  TetMesh mesh;
  mesh.points = readVertexLines(lines, numPoints);
  mesh.tets.resize(numTets);
  for (int t = 0; t < numTets; ++t) {
    lines.nextElement(tok, "tet", t, numTets);
    if (tok.size() < 5 || tok[0] != "4") {
      lines.fail("tet " + std::to_string(t) + ": expected '4 a b c d'");
    }
    for (int k = 0; k < 4; ++k) {
      mesh.tets[t][k] = lines.index(tok[k + 1], 0, numPoints, t, "tet");
    }
  }
  lines.expectEnd(std::to_string(numPoints) + " vertices and " + std::to_string(numTets) + " tets");
  return mesh;
}

TetMesh readTetGenMesh(const std::string& path) {
  const fs::path given(path);
  const std::string ext = given.extension().string();
  const std::string lowerExt = toLower(ext);
  if (lowerExt != ".node" && lowerExt != ".ele") {
    throw GeoLatticeError("not a TetGen mesh path (expected a .node or .ele file): " + path);
  }
  // Keep the letter case of the given extension for the partner file (mesh.NODE -> mesh.ELE).
  const bool upper = ext.size() > 1 && std::isupper(static_cast<unsigned char>(ext[1]));
  fs::path nodePath = given;
  fs::path elePath = given;
  nodePath.replace_extension(upper ? ".NODE" : ".node");
  elePath.replace_extension(upper ? ".ELE" : ".ele");

  TetMesh mesh;
  std::vector<std::string_view> tok;
  long long base = 0;
  {
    // .node: "<#points> <dimension> [<#attributes> [<#boundary markers>]]", then
    // "<point #> <x> <y> <z> [attributes] [marker]".
    LineTokenizer lines(nodePath.string(), loadFile(nodePath.string()));
    lines.header(tok, 2, 4, "<#points> <dimension> <#attributes> <#boundary markers>");
    const int numPoints = lines.count(tok[0], "point count");
    const long long dim = lines.integer(tok[1], "dimension");
    if (dim != 3) {
      lines.fail("dimension " + std::to_string(dim) + " is not supported (only 3)");
    }
    const int numAttributes = tok.size() > 2 ? lines.count(tok[2], "attribute count") : 0;
    const int numMarkers = tok.size() > 3 ? lines.count(tok[3], "boundary marker count") : 0;
    if (numMarkers > 1) {
      lines.fail("boundary marker count must be 0 or 1, got " + std::to_string(numMarkers));
    }
    if (numPoints == 0) {
      throw GeoLatticeError("empty mesh: " + nodePath.string() + " has 0 points");
    }
    mesh.points.resize(numPoints);
    const size_t minTokens =
        4 + static_cast<size_t>(numAttributes) + static_cast<size_t>(numMarkers);
    for (int i = 0; i < numPoints; ++i) {
      lines.nextElement(tok, "point", i, numPoints);
      if (tok.size() < minTokens) {
        lines.fail("point line: expected " + std::to_string(minTokens) +
                   " values ('<point #> x y z' + " + std::to_string(numAttributes) +
                   " attributes + " + std::to_string(numMarkers) + " markers), got " +
                   std::to_string(tok.size()));
      }
      const long long number = lines.integer(tok[0], "the point number");
      if (i == 0) {
        if (number != 0 && number != 1) {
          lines.fail("first point number must be 0 or 1, got " + std::to_string(number));
        }
        base = number;
      } else if (number != base + i) {
        lines.fail("point numbers must be consecutive: expected " + std::to_string(base + i) +
                   ", got " + std::to_string(number));
      }
      mesh.points[i] = lines.point(tok, 1);
    }
    lines.expectEnd(std::to_string(numPoints) + " points");
  }
  {
    // .ele: "<#tets> <nodes per tet (4 or 10)> [<#attributes>]", then
    // "<tet #> <n1> ... <nk> [attributes]" with point numbers of the .node file.
    LineTokenizer lines(elePath.string(), loadFile(elePath.string()));
    lines.header(tok, 2, 3, "<#tetrahedra> <nodes per tetrahedron> <#attributes>");
    const int numTets = lines.count(tok[0], "tet count");
    const long long nodesPerTet = lines.integer(tok[1], "nodes per tetrahedron");
    if (nodesPerTet != 4 && nodesPerTet != 10) {
      lines.fail("nodes per tetrahedron must be 4 or 10, got " + std::to_string(nodesPerTet));
    }
    const int numAttributes = tok.size() > 2 ? lines.count(tok[2], "attribute count") : 0;
    if (numTets == 0) {
      throw GeoLatticeError("empty mesh: " + elePath.string() + " has 0 tetrahedra");
    }
    const int numPoints = static_cast<int>(mesh.points.size());
    const size_t minTokens =
        1 + static_cast<size_t>(nodesPerTet) + static_cast<size_t>(numAttributes);
    mesh.tets.resize(numTets);
    for (int t = 0; t < numTets; ++t) {
      lines.nextElement(tok, "tetrahedron", t, numTets);
      if (tok.size() < minTokens) {
        lines.fail("tetrahedron line: expected " + std::to_string(minTokens) + " values, got " +
                   std::to_string(tok.size()));
      }
      lines.integer(tok[0], "the tetrahedron number");
      for (int k = 0; k < 4; ++k) {
        mesh.tets[t][k] = lines.index(tok[k + 1], base, numPoints, t, "tetrahedron");
      }
    }
    lines.expectEnd(std::to_string(numTets) + " tetrahedra");
  }
  return mesh;
}

void writeTetFile(const std::string& path, const TetMesh& mesh) {
  checkWritable(path, mesh.points, mesh.tets, "tet");

  AtomicFileSet files;
  {
    std::ostream& out = files.open(path);
    out << mesh.points.size() << " vertices\n" << mesh.tets.size() << " tets\n";
    for (const Vec3& p : mesh.points) {
      writeCoordinates(out, p);
    }
    for (const auto& t : mesh.tets) {
      out << "4 " << t[0] << ' ' << t[1] << ' ' << t[2] << ' ' << t[3] << '\n';
    }
  }
  files.commit();
}

}  // namespace geolattice
