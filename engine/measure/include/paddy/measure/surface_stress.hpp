// Stress carried across a surface inside a packing, from its contact forces: the method of planes
// (Todd, Evans & Daivis 1995, Phys. Rev. E 52:1627), the static form used for granular packings
// (e.g. Weber 1966; Goldhirsch 2010, Granular Matter 12:239, "the force across a surface").
//
// A contact between particles i and j transmits its force across a surface when the segment
// between their centres (the branch vector) crosses it. The traction the material on the far side
// of a surface exerts on the near side is the sum, over the crossing contacts, of the force the
// far particle exerts on the near one, divided by the area:
//
//   t = (1/A) Σ_{c crosses S} F_{far→near},  σ_n = −t·n̂  (compression positive),  τ = t·ê
//
// with n̂ the surface normal pointing from the near to the far side and ê a tangent. At rest the
// kinetic (momentum flux) part vanishes, and the sum is the exact force the surface carries: for a
// horizontal plane under gravity it is the weight above it that the packing, not a wall, holds up.
//
// Two surfaces, both about a vertical axis through (axis.x, axis.y):
// - disc: the horizontal plane z = z0 over r_min ≤ r < r_max (near side below, n̂ = +z;
//   tangent ê = the azimuthal direction θ̂ at the crossing point): σ_zz, τ_zθ;
// - cylinder: r = R over z_min ≤ z < z_max (near side inside, n̂ = +r̂ at the crossing point;
//   ê = θ̂): σ_rr, τ_rθ — the latter is the shear stress a vane of radius R turns against.
// A branch segment with both ends on one side crosses a cylinder twice or not at all; its two
// crossings carry the force each way and cancel, so only segments with one end inside count
// (one crossing, found by solving |x_j + t(x_i − x_j)|_xy = R for t in [0, 1]).
// Wall contacts are not counted: put the surface where only particles touch each other.
#pragma once

#include <paddy/measure/common.hpp>

#include <cstddef>
#include <vector>

namespace paddy::measure {

// One particle–particle contact: both centres and the force particle j exerts on particle i
// (the force on j is its negative).
struct ContactForce {
  Vec3 x_i = Vec3::Zero(), x_j = Vec3::Zero();
  Vec3 force_on_i = Vec3::Zero();
};

struct DiscSurface {
  Vec2 axis = Vec2::Zero();  // (x, y) of the vertical axis [m]
  double z = 0.0;            // height of the plane [m]
  double r_min = 0.0;        // inner radius [m] (0: a full disc)
  double r_max = 0.0;        // outer radius [m], > r_min
};

struct CylinderSurface {
  Vec2 axis = Vec2::Zero();
  double radius = 0.0;       // R [m], > 0
  double z_min = 0.0, z_max = 0.0;  // height range [m], z_max > z_min
};

struct SurfaceStress {
  double normal = 0.0;      // σ_n [Pa], compression positive
  double shear = 0.0;       // τ along the azimuthal direction θ̂ [Pa] (traction on the near side)
  double area = 0.0;        // [m²]
  std::size_t crossings = 0;  // contacts whose branch segment crosses the surface
};

// Throw paddy::InputError naming the bad value (non-finite, r_max <= r_min, radius <= 0, ...).
SurfaceStress discStress(const std::vector<ContactForce>& contacts, const DiscSurface& disc);
SurfaceStress cylinderStress(const std::vector<ContactForce>& contacts, const CylinderSurface& cylinder);

}  // namespace paddy::measure
