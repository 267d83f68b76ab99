// Pictures of the slump-flow measurement: PGM images and a gnuplot PNG (top view, contour, circle).
#include <paddy/io/atomic_file.hpp>
#include <paddy/measure/slump_flow.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace paddy::measure {

namespace {

// Grey levels with row 0 = southmost row (y up): plate 255, mud 200 (thin) .. 40 (highest).
std::vector<unsigned char> greyImage(const SlumpFlowResult& res, PgmLayer layer) {
  const TopViewImage& g = res.image;
  std::vector<unsigned char> out(g.height.size(), 255);
  float hmax = 0.0f;
  for (std::size_t k = 0; k < g.height.size(); ++k)
    if (g.covered[k]) hmax = std::max(hmax, g.height[k]);
  for (std::size_t k = 0; k < out.size(); ++k) {
    switch (layer) {
      case PgmLayer::Height:
        if (g.covered[k]) {
          const float t = hmax > 0.0f ? std::clamp(g.height[k] / hmax, 0.0f, 1.0f) : 0.0f;
          out[k] = static_cast<unsigned char>(200.0f - 160.0f * t);
        }
        break;
      case PgmLayer::Mask:
        if (!g.mask.empty() && g.mask[k]) out[k] = 0;
        break;
      case PgmLayer::Component:
        if (!res.component.empty() && res.component[k]) out[k] = 0;
        break;
    }
  }
  return out;
}

std::ofstream openFile(const std::filesystem::path& file, std::ios::openmode mode = std::ios::out) {
  std::ofstream f(file, mode);
  if (!f) throw std::runtime_error("cannot write " + file.string());
  return f;
}

}  // namespace

void writePgm(const SlumpFlowResult& res, const std::filesystem::path& file, PgmLayer layer) {
  const TopViewImage& g = res.image;
  const auto grey = greyImage(res, layer);
  std::ostringstream f;
  f << "P5\n# paddy slump-flow top view, pixel " << g.pixel << " m\n" << g.nx << ' ' << g.ny << "\n255\n";
  for (int j = g.ny - 1; j >= 0; --j)  // north up
    f.write(reinterpret_cast<const char*>(grey.data() + static_cast<std::size_t>(j) * g.nx), g.nx);
  io::writeFileAtomic(file, f.str());  // temporary + rename; errors name the file and the cause
}

void plotSlumpFlow(const SlumpFlowResult& res, const std::filesystem::path& png, const std::string& title) {
  const TopViewImage& g = res.image;
  const std::string stem = (png.parent_path() / png.stem()).string();
  for (const std::string& s : {png.string(), stem, title})
    if (s.find('\'') != std::string::npos || s.find('\n') != std::string::npos)
      throw std::runtime_error("plotSlumpFlow: quotes and newlines are not allowed in '" + s + "'");
  const std::string bin = stem + "_top.bin", contour = stem + "_contour.dat", circle = stem + "_circle.dat",
                    script = stem + ".gp", log = stem + ".gp.log";
  {
    const auto grey = greyImage(res, PgmLayer::Height);
    auto f = openFile(bin, std::ios::out | std::ios::binary);
    f.write(reinterpret_cast<const char*>(grey.data()), static_cast<std::streamsize>(grey.size()));
  }
  {
    auto f = openFile(contour);
    f << "# contour points x y [mm]\n";
    for (const auto& p : res.contour) f << 1e3 * p.x() << ' ' << 1e3 * p.y() << '\n';
  }
  {
    auto f = openFile(circle);
    f << "# fitted circle x y [mm]; centre " << 1e3 * res.circle.centre.transpose() << ", diameter "
      << 1e3 * res.diameter_fit << '\n';
    for (const auto& p : circlePoints(res.circle, 360)) f << 1e3 * p.x() << ' ' << 1e3 * p.y() << '\n';
  }
  {
    const double p = 1e3 * g.pixel, cx = 1e3 * res.circle.centre.x(), cy = 1e3 * res.circle.centre.y(),
                 cr = 1e3 * res.circle.radius;
    auto f = openFile(script);
    f << "set terminal pngcairo size 900,900\n"
      << "set output '" << png.string() << "'\n"
      << "set size ratio -1\nset xlabel 'x [mm]'\nset ylabel 'y [mm]'\n"
      << "set title '" << (title.empty() ? std::string("slump-flow") : title) << "'\n"
      << "set palette grey\nunset colorbox\nset cbrange [0:255]\nset key below\n"
      << "set xrange [" << std::min(1e3 * g.x0, cx - cr) - 2 << ':' << std::max(1e3 * g.x0 + g.nx * p, cx + cr) + 2
      << "]\n"
      << "set yrange [" << std::min(1e3 * g.y0, cy - cr) - 2 << ':' << std::max(1e3 * g.y0 + g.ny * p, cy + cr) + 2
      << "]\n"
      << "plot '" << bin << "' binary array=(" << g.nx << ',' << g.ny << ") format='%uchar' dx=" << p
      << " dy=" << p << " origin=(" << 1e3 * g.x0 + 0.5 * p << ',' << 1e3 * g.y0 + 0.5 * p
      << ") with image notitle, \\\n"
      << "  '" << contour << "' with points pt 7 ps 0.25 lc rgb 'red' title 'contour', \\\n"
      << "  '" << circle << "' with lines lw 2 lc rgb 'blue' title sprintf('circle fit D = %.1f mm, ruler D = %.1f mm', "
      << 1e3 * res.diameter_fit << ", " << 1e3 * res.ruler.mean << ")\n";
  }
  const std::string cmd = "gnuplot '" + script + "' > '" + log + "' 2>&1";
  const int rc = std::system(cmd.c_str());
  if (rc != 0)
    throw std::runtime_error("plotSlumpFlow: gnuplot failed (exit status " + std::to_string(rc) + ") on " + script +
                             "; see " + log);
}

}  // namespace paddy::measure
