// Mesh import/export (see mesh_io.hpp). Parsing is CGAL's (CGAL::IO::read_polygon_soup); this file
// adds a light scan of the raw file that finds non-finite coordinates with their vertex index
// and line (CGAL's text readers reject "nan"/"inf" without saying where; its binary STL reader
// would merge a NaN point with another point), and the writers.
#include <paddy/io/atomic_file.hpp>
#include <paddy/errors.hpp>
#include <paddy/geometry/cgal_ops.hpp>
#include <paddy/geometry/mesh_io.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace paddy::geometry {
namespace fs = std::filesystem;
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

[[noreturn]] void nonFinite(const std::string& path, const std::string& where, const double xyz[3]) {
  std::ostringstream m;
  m << path << ": " << where << " has a non-finite coordinate (" << xyz[0] << ", " << xyz[1] << ", " << xyz[2] << ")";
  throw InputError(m.str());
}

bool isBinaryStl(const std::string& bytes) {
  if (bytes.size() < 84) return false;
  std::uint32_t n = 0;
  std::memcpy(&n, bytes.data() + 80, 4);
  return bytes.size() == 84 + 50ull * n;
}

// Parses up to 3 numbers after position `pos` of `line`; returns how many were numbers.
int parse3(const std::string& line, std::size_t pos, double xyz[3]) {
  const char* p = line.c_str() + pos;
  for (int k = 0; k < 3; ++k) {
    char* end = nullptr;
    xyz[k] = std::strtod(p, &end);
    if (end == p) return k;
    p = end;
  }
  return 3;
}

void scanNonFinite(const std::string& path, const std::string& ext, const std::string& bytes) {
  if (ext == ".stl" && isBinaryStl(bytes)) {
    std::uint32_t n = 0;
    std::memcpy(&n, bytes.data() + 80, 4);
    for (std::uint32_t t = 0; t < n; ++t)
      for (int c = 0; c < 3; ++c) {
        float f[3];
        std::memcpy(f, bytes.data() + 84 + 50ull * t + 12 + 12ull * c, 12);
        const double xyz[3] = {f[0], f[1], f[2]};
        if (!std::isfinite(xyz[0]) || !std::isfinite(xyz[1]) || !std::isfinite(xyz[2]))
          nonFinite(path, "triangle " + std::to_string(t) + ", corner " + std::to_string(c) + " (vertex " +
                              std::to_string(3ull * t + c) + ")", xyz);
      }
    return;
  }
  std::istringstream in(bytes);
  std::string line;
  std::size_t lineno = 0, vertex = 0;
  // OFF: vertices follow the header line "OFF" and the counts line.
  long off_vertices = -1;
  bool off_header = false;
  while (std::getline(in, line)) {
    ++lineno;
    std::size_t p = line.find_first_not_of(" \t\r");
    if (p == std::string::npos || line[p] == '#') continue;
    double xyz[3];
    if (ext == ".stl") {
      if (line.compare(p, 6, "vertex") != 0) continue;
      if (parse3(line, p + 6, xyz) == 3 &&
          !(std::isfinite(xyz[0]) && std::isfinite(xyz[1]) && std::isfinite(xyz[2])))
        nonFinite(path, "line " + std::to_string(lineno) + ": vertex " + std::to_string(vertex), xyz);
      ++vertex;
    } else if (ext == ".obj") {
      if (line.compare(p, 2, "v ") != 0 && line.compare(p, 2, "v\t") != 0) continue;
      if (parse3(line, p + 2, xyz) == 3 &&
          !(std::isfinite(xyz[0]) && std::isfinite(xyz[1]) && std::isfinite(xyz[2])))
        nonFinite(path, "line " + std::to_string(lineno) + ": vertex " + std::to_string(vertex), xyz);
      ++vertex;
    } else if (ext == ".off") {
      if (!off_header) {
        off_header = true;
        std::size_t q = line.find("OFF", p);
        if (q == std::string::npos) return;  // not an OFF header; let CGAL report
        std::istringstream rest(line.substr(q + 3));
        long nv;
        if (rest >> nv) off_vertices = nv;
        continue;
      }
      if (off_vertices < 0) {
        std::istringstream counts(line);
        if (!(counts >> off_vertices)) return;
        continue;
      }
      if (static_cast<long>(vertex) >= off_vertices) return;
      if (parse3(line, p, xyz) == 3 && !(std::isfinite(xyz[0]) && std::isfinite(xyz[1]) && std::isfinite(xyz[2])))
        nonFinite(path, "line " + std::to_string(lineno) + ": vertex " + std::to_string(vertex), xyz);
      ++vertex;
    }
  }
}

// ASCII OFF facets, read the way CGAL reads them (File_header_OFF, File_scanner_OFF): the
// keyword and the counts "V F E" are tokens (blanks and '#' comments between them skipped), then
// each vertex and each facet is the rest of a line starting at the next character that is neither
// blank nor in a comment. CGAL converts a facet's corner count and its vertex indices from double
// to std::size_t, which is undefined behaviour for a negative, huge or non-finite value: such a
// facet is refused here, naming it (a fractional index is refused too: it names no vertex).
void checkOffFacets(const std::string& path, const std::string& bytes) {
  const std::size_t n = bytes.size();
  std::size_t pos = 0;
  const auto skip = [&] {
    while (pos < n) {
      if (std::isspace(static_cast<unsigned char>(bytes[pos]))) {
        ++pos;
      } else if (bytes[pos] == '#') {
        pos = bytes.find('\n', pos);
        if (pos == std::string::npos) pos = n;
      } else {
        break;
      }
    }
  };
  // The keyword, as CGAL reads it: its first character, then letters and digits; the character
  // that ends it is consumed.
  skip();
  if (pos >= n) return;
  std::string magic(1, bytes[pos++]);
  while (magic.size() < 41 && pos < n) {
    const char c = bytes[pos++];
    if (!std::isalnum(static_cast<unsigned char>(c))) break;
    magic += c;
  }
  std::size_t j = 0;
  if (magic.compare(0, 2, "ST") == 0) j += 2;
  if (j < magic.size() && magic[j] == 'C') ++j;
  if (j < magic.size() && magic[j] == 'N') ++j;
  // nOFF and 4OFF carry other entries, SKEL is not a surface; a binary OFF is left to CGAL too
  // (its indices are int32, no conversion from double).
  if (magic.compare(j, std::string::npos, "OFF") != 0) return;
  // CGAL 5.5 reads a vertex's texture coordinates without checking the line holds them (a read
  // past the end of its entries, found by fuzzing); a wall needs no texture.
  if (magic.compare(0, 2, "ST") == 0)
    throw InputError(path + ": textured OFF ('" + magic + "') is not supported: write it as plain OFF");
  skip();
  if (pos >= n || !std::isdigit(static_cast<unsigned char>(bytes[pos]))) return;  // BINARY, or refused
  long counts[3];
  for (long& c : counts) {  // `in >> int`: blanks, then an optional sign and digits
    while (pos < n && std::isspace(static_cast<unsigned char>(bytes[pos]))) ++pos;
    const std::size_t start = pos;
    if (pos < n && (bytes[pos] == '+' || bytes[pos] == '-')) ++pos;
    while (pos < n && std::isdigit(static_cast<unsigned char>(bytes[pos]))) ++pos;
    const std::string t = bytes.substr(start, pos - start);
    char* end = nullptr;
    c = std::strtol(t.c_str(), &end, 10);
    if (t.empty() || *end != '\0' || c < 0 || c > 100000000) return;  // CGAL refuses the header
  }
  const auto record = [&] {
    skip();
    std::size_t end = bytes.find('\n', pos);
    if (end == std::string::npos) end = n;
    std::string line = bytes.substr(pos, end - pos);
    pos = end < n ? end + 1 : n;
    return line.substr(0, line.find('#'));
  };
  for (long v = 0; v < counts[0] && pos < n; ++v) record();
  const auto index = [](double d) { return std::isfinite(d) && d >= 0 && d < 9.0e15 && d == std::floor(d); };
  for (long f = 0; f < counts[1] && pos < n; ++f) {
    const std::string line = record();
    std::istringstream in(line);
    std::vector<double> e;
    for (double d; in >> d;) e.push_back(d);
    if (e.empty()) return;  // CGAL refuses it
    const std::string where = path + ": facet " + std::to_string(f) + " ('" + line + "')";
    if (!index(e[0])) throw InputError(where + ": the corner count is not a whole number >= 0");
    const double k = e[0];
    for (std::size_t j = 1; j <= e.size() - 1 && static_cast<double>(j) <= k; ++j)
      if (!index(e[j]))
        throw InputError(where + ": corner " + std::to_string(j - 1) + " is not a vertex index (a whole number >= 0)");
  }
}

std::string formatName(const std::string& ext) {
  if (ext == ".stl") return "STL";
  if (ext == ".off") return "OFF";
  return "OBJ";
}

void atomicWrite(const std::string& path, const std::string& bytes) {
  io::writeFileAtomic(path, bytes);  // temporary + rename; errors name the file and the cause
}

}  // namespace

TriangleMesh readMesh(const std::string& path, const ImportOptions& o) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) throw InputError(path + ": mesh file not found");
  const std::string ext = lower(fs::path(path).extension().string());
  if (ext != ".stl" && ext != ".off" && ext != ".obj")
    throw InputError(path + ": unknown mesh format '" + ext + "' (choices: .stl (ASCII or binary), .off, .obj)");
  std::string bytes;
  {
    std::ifstream f(path, std::ios::binary);
    if (!f) throw InputError(path + ": cannot open the mesh file");
    std::ostringstream ss;
    ss << f.rdbuf();
    bytes = ss.str();
  }
  if (bytes.find_first_not_of(" \t\r\n") == std::string::npos) throw InputError(path + ": empty file");
  scanNonFinite(path, ext, bytes);
  if (ext == ".off") checkOffFacets(path, bytes);

  PolygonSoup soup;
  if (!cgal::readPolygonSoup(path, soup))
    throw InputError(path + ": not a valid " + formatName(ext) + " file (CGAL could not parse it: malformed or truncated)");
  if (soup.polygons.empty() || soup.points.empty()) throw InputError(path + ": empty mesh (no triangles)");
  for (std::size_t v = 0; v < soup.points.size(); ++v)
    if (!soup.points[v].allFinite()) {
      const double xyz[3] = {soup.points[v].x(), soup.points[v].y(), soup.points[v].z()};
      nonFinite(path, "vertex " + std::to_string(v), xyz);
    }
  for (std::size_t k = 0; k < soup.polygons.size(); ++k) {
    if (soup.polygons[k].size() < 3)
      throw InputError(path + ": polygon " + std::to_string(k) + " has fewer than 3 corners");
    for (auto v : soup.polygons[k])
      if (v >= soup.points.size())
        throw InputError(path + ": polygon " + std::to_string(k) + " refers to vertex " + std::to_string(v) +
                         ", but there are only " + std::to_string(soup.points.size()) + " vertices");
  }

  const Eigen::Matrix3d R = axisRotation(o.rotation_axis, o.rotation_angle);
  checkRange("scale", o.scale, 1e-12, 1e12);
  if (!o.translation.allFinite()) throw InputError(path + ": the translation must be finite");
  for (Vec3& p : soup.points) p = R * (o.scale * p) + o.translation;
  cgal::mergeDuplicatePoints(soup);

  TriangleMesh mesh;
  mesh.vertices = soup.points;
  for (std::size_t k = 0; k < soup.polygons.size(); ++k) {
    const auto& poly = soup.polygons[k];
    if (poly.size() == 3) {
      mesh.triangles.push_back({poly[0], poly[1], poly[2]});
      continue;
    }
    std::vector<Vec3> corners;
    for (auto v : poly) corners.push_back(soup.points[v]);
    std::vector<std::array<std::uint32_t, 3>> tris;
    if (!cgal::triangulatePolygon(corners, tris))
      throw InputError(path + ": polygon " + std::to_string(k) + " (" + std::to_string(poly.size()) +
                       " corners) cannot be triangulated (degenerate or self-intersecting)");
    for (const auto& t : tris) mesh.triangles.push_back({poly[t[0]], poly[t[1]], poly[t[2]]});
  }
  MeshCheckOptions check;
  check.source = path;
  check.closure = o.closure;
  validateMesh(mesh, check);
  if (o.orient) cgal::orientComponents(mesh, path);
  return mesh;
}

void writeStl(const std::string& path, const TriangleMesh& m, bool binary, const std::string& solid_name) {
  std::string out;
  if (binary) {
    out.assign(80, '\0');
    const std::string head = "binary STL written by Paddy: " + solid_name;
    std::memcpy(out.data(), head.data(), std::min<std::size_t>(79, head.size()));
    const auto n = static_cast<std::uint32_t>(m.triangles.size());
    out.append(reinterpret_cast<const char*>(&n), 4);
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
      const Vec3 nrm = triangleNormal(m, t);
      float rec[12];
      for (int k = 0; k < 3; ++k) rec[k] = static_cast<float>(nrm[k]);
      for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k) rec[3 + 3 * c + k] = static_cast<float>(m.vertices[m.triangles[t][c]][k]);
      out.append(reinterpret_cast<const char*>(rec), sizeof rec);
      out.append(2, '\0');
    }
  } else {
    std::ostringstream s;
    s.precision(9);
    s << "solid " << solid_name << "\n";
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
      const Vec3 nrm = triangleNormal(m, t);
      s << "  facet normal " << nrm.x() << " " << nrm.y() << " " << nrm.z() << "\n    outer loop\n";
      for (int c = 0; c < 3; ++c) {
        const Vec3& v = m.vertices[m.triangles[t][c]];
        s << "      vertex " << v.x() << " " << v.y() << " " << v.z() << "\n";
      }
      s << "    endloop\n  endfacet\n";
    }
    s << "endsolid " << solid_name << "\n";
    out = s.str();
  }
  atomicWrite(path, out);
}

void writeOff(const std::string& path, const TriangleMesh& m) {
  std::ostringstream s;
  s.precision(17);
  s << "OFF\n" << m.vertices.size() << " " << m.triangles.size() << " 0\n";
  for (const Vec3& v : m.vertices) s << v.x() << " " << v.y() << " " << v.z() << "\n";
  for (const auto& t : m.triangles) s << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
  atomicWrite(path, s.str());
}

}  // namespace paddy::geometry
