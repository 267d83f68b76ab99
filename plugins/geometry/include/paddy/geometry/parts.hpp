// Parameterised parts for the reference experiments. Body coordinates: metres, axis of symmetry
// = +z through the origin, the part's base at z = 0. Meshes are oriented "towards the material":
// open surfaces have their normals on the side the mud is (inside of cone and cup, +z of the
// plate); closed parts (cone/cup with wall thickness, vane) are solids with outward normals.
// Contacts with MeshWall are two-sided for open surfaces, so orientation only matters for solids.
#pragma once

#include <paddy/geometry.hpp>

#include <vector>

namespace paddy::geometry {

// Slump cone after GB/T 50080-2016 (standard for test methods of performance of ordinary fresh
// concrete): frustum with inner diameters 100 mm (top) and 200 mm (bottom), height 300 mm, open
// at both ends. thickness = 0: a single surface at the inner diameters; thickness > 0: a solid
// wall, the outer surface offset by `thickness` along the surface normal (radii + t/cos β,
// tan β = (R_bottom − R_top)/height), flat rims. handles: two closed boxes (bars) on ±x at 2/3 of
// the height, as on the standard's cone (not in contact with the mud; off by default).
struct SlumpConeParams {
  double top_diameter = 0.100;
  double bottom_diameter = 0.200;
  double height = 0.300;
  int segments = 96;        // facet chord error R(1−cos(π/n)) = 0.054 mm at R = 0.1 m
  double thickness = 0.0;
  bool handles = false;
};

// Square plate of side `side` in the plane z = 0, centred at the origin, normal +z; each side
// cut in `divisions` and every square split along the same diagonal (interior vertices are
// shared by 6 triangles).
struct PlateParams {
  double side = 1.0;
  int divisions = 8;
};

// Rheometer cup: cylinder of inner diameter `diameter`, inner depth `height`, with a flat bottom
// at z = 0 and open top. Defaults (0.1 m × 0.12 m) hold the default vane (0.05 m) with a
// 25 mm = 12.5 particle-diameter gap to the wall for the reference's 2 mm particles, and the vane
// 0.03 m above the bottom and 0.03 m below the fill level. thickness > 0: solid wall and bottom.
struct CupParams {
  double diameter = 0.100;
  double height = 0.120;
  int segments = 96;
  double thickness = 0.0;
};

// Vane rotor: `blades` flat blades of thickness `blade_thickness` on a shaft of diameter
// `shaft_diameter`; blade outer corners on the circle of diameter `diameter`; blades span
// z ∈ [0, height]; the shaft continues to z = height + shaft_length. One closed solid.
// Torque → shear stress (cylinder swept by the blade tips, uniform stress τ on its side and both
// ends): T = τ · (π D²/2) · (H + D/3).
struct VaneParams {
  int blades = 4;
  double diameter = 0.050;
  double height = 0.060;
  double blade_thickness = 0.002;
  double shaft_diameter = 0.008;
  double shaft_length = 0.060;
  int segments = 32;  // shaft facets (at least 2 per blade gap)
};

TriangleMesh buildSlumpCone(const SlumpConeParams& p = {});
TriangleMesh buildPlate(const PlateParams& p = {});
TriangleMesh buildCup(const CupParams& p = {});
TriangleMesh buildVane(const VaneParams& p = {});

// τ from the vane torque (see VaneParams).
double vaneShearStress(double torque, double diameter, double height);

// The parts as GeometryInfo (names slump_cone, plate, cup, vane), registered by the plugin.
std::vector<GeometryInfo> partCatalogue();

}  // namespace paddy::geometry
