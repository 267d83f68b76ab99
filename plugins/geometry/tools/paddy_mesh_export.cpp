// paddy_mesh_export: regenerates the shipped part meshes and their pictures.
//   paddy_mesh_export [<meshes dir> [<images dir>]]     (defaults: meshes, docs/images)
// Writes <meshes>/{slump_cone,plate,cup,vane}.stl (binary STL, default parameters) and
// <images>/geometry_<part>.png (gnuplot). tests/geometry checks the STL files match the builders.
#include <paddy/geometry/mesh_check.hpp>
#include <paddy/geometry/mesh_io.hpp>
#include <paddy/geometry/parts.hpp>
#include <paddy/geometry/picture.hpp>

#include <cstdio>
#include <exception>
#include <string>

int main(int argc, char** argv) {
  using namespace paddy::geometry;
  const std::string meshes = argc > 1 ? argv[1] : "meshes";
  const std::string images = argc > 2 ? argv[2] : "docs/images";
  try {
    struct Part { std::string name, title; paddy::TriangleMesh mesh; };
    const Part parts[] = {
        {"slump_cone", "slump cone (GB/T 50080-2016): D 0.1/0.2 m, H 0.3 m, 96 segments", buildSlumpCone()},
        {"plate", "plate 1 m x 1 m, 8 x 8 squares", buildPlate()},
        {"cup", "rheometer cup: D 0.1 m, depth 0.12 m", buildCup()},
        {"vane", "vane: 4 blades, D 0.05 m, H 0.06 m, shaft 8 mm", buildVane()},
    };
    for (const Part& p : parts) {
      const std::string stl = meshes + "/" + p.name + ".stl";
      writeStl(stl, p.mesh, true, p.name);
      const Bounds b = bounds(p.mesh);
      std::printf("%-11s %6zu triangles %6zu vertices  extent %.4f x %.4f x %.4f m  -> %s\n", p.name.c_str(),
                  p.mesh.triangles.size(), p.mesh.vertices.size(), b.size().x(), b.size().y(), b.size().z(), stl.c_str());
      PictureOptions o;
      o.title = p.title;
      if (p.name == "plate") o.view_rot_x = 50.0;
      const std::string png = images + "/geometry_" + p.name + ".png";
      if (!writePicture(p.mesh, png, o)) std::fprintf(stderr, "warning: could not render %s (gnuplot)\n", png.c_str());
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "paddy_mesh_export: %s\n", e.what());
    return 2;
  }
  return 0;
}
