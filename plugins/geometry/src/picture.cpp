// Part pictures through gnuplot: triangles as `with polygons` (gnuplot ≥ 5.4), pm3d depth
// ordering, facets shaded by pm3d lighting. Equal axis scales (`set view equal xyz`).
#include <paddy/geometry/mesh_check.hpp>
#include <paddy/geometry/picture.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace paddy::geometry {

namespace {
// A gnuplot string constant: single quotes (gnuplot runs `commands` only in double-quoted
// strings), a quote doubled; a line break (which would start a new gnuplot command) becomes a blank.
std::string gnuplotText(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("''") : (c == '\n' || c == '\r') ? std::string(" ") : std::string(1, c);
  return out + "'";
}
// One shell word.
std::string shellWord(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}
}  // namespace

bool writePicture(const TriangleMesh& mesh, const std::string& png, const PictureOptions& o) {
  namespace fs = std::filesystem;
  const std::string base = png + ".gp";
  const std::string dat = png + ".dat";
  {
    std::ofstream d(dat);
    if (!d) return false;
    d.precision(7);
    for (const auto& t : mesh.triangles) {
      for (int c = 0; c < 3; ++c) {
        const Vec3& v = mesh.vertices[t[c]];
        d << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
      }
      d << '\n';
    }
  }
  const Bounds b = bounds(mesh);
  const Vec3 mid = 0.5 * (b.lo + b.hi);
  const double half = 0.5 * b.size().maxCoeff() * 1.05;
  {
    std::ofstream g(base);
    g << "set terminal pngcairo size " << o.width << "," << o.height << " enhanced font 'sans,10'\n"
      << "set output " << gnuplotText(png + ".tmp") << "\n"
      << "set title " << gnuplotText(o.title) << "\n"
      << "set view " << o.view_rot_x << "," << o.view_rot_z << "\n"
      << "set view equal xyz\n"
      << "set xrange [" << mid.x() - half << ":" << mid.x() + half << "]\n"
      << "set yrange [" << mid.y() - half << ":" << mid.y() + half << "]\n"
      << "set zrange [" << mid.z() - half << ":" << mid.z() + half << "]\n"
      << "set xyplane at " << mid.z() - half << "\n"
      << "set format '%.3g'\n"
      << "set xlabel 'x [m]'\nset ylabel 'y [m]'\nset zlabel 'z [m]' rotate parallel\n"
      << "set xtics " << half / 2 << "\nset ytics " << half / 2 << "\nset ztics " << half / 2 << "\n"
      << "set pm3d depthorder border lc rgb '#404040' lw 0.3\n"
      << "set pm3d lighting primary 0.6 specular 0.1\n"
      << "unset colorbox\n"
      << "splot " << gnuplotText(dat) << " with polygons fc rgb '#a0b4d0' notitle\n";
  }
  const std::string cmd = "gnuplot " + shellWord(base) + " > /dev/null 2>&1";
  const int rc = std::system(cmd.c_str());
  std::error_code ec;
  fs::remove(base, ec);
  fs::remove(dat, ec);
  if (rc != 0 || !fs::exists(png + ".tmp")) {
    fs::remove(png + ".tmp", ec);
    return false;
  }
  fs::rename(png + ".tmp", png, ec);
  return !ec;
}

}  // namespace paddy::geometry
