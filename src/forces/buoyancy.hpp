/// @file buoyancy.hpp
/// @brief Buoyancy: Archimedes' push on the part of a body under a fluid's surface (Effect=Buoyancy).
///
/// A body in a fluid at rest is pushed up by the weight of the fluid it
/// displaces (Archimedes): F = −ρ_f·V_sub·g, where V_sub is the volume under
/// the surface and g the gravitational acceleration (pointing down, so F
/// points up). The push acts at the centre of buoyancy B, the centroid of the
/// submerged volume, so about the centre of mass G it has the torque
/// τ = (B − G) × F.
///
/// That torque is what makes a boat right itself, or capsize. Tilt a floating
/// body by a small angle θ: B moves sideways, and the vertical through it
/// meets the body's centre line at the metacentre M, a height
/// BM = I_wl / V_sub above B, where I_wl is the second moment of area of the
/// waterline section about the tilt axis (for a box of width W and length L,
/// I_wl = L·W³/12). The weight at G and the push at B form a couple
/// m·g·GM·sin θ that turns the body back upright when the metacentric height
/// GM = BM − BG is positive, and over when it is negative. (Biran &
/// López-Pulido, *Ship Hydrostatics and Stability*, ch. 2; Tipler, §13.)
///
/// A flat box of density ½ρ_f floats with half its height H under water, and
/// BG = H/4; BM = W²/(6H). So it floats upright when W > √1.5·H and capsizes
/// otherwise: a cube of half the water's density does not float flat.
///
/// The fluid also resists motion through it: the region's drag law
/// (drag.hpp) acts with the submerged fraction V_sub/V of its coefficient,
/// relative to the fluid's velocity (a current). Without it a floating body
/// bobs for ever; with it the bobbing dies away as a damped oscillator's.
///
/// The surface is the plane of a HalfSpace region, or the top face of a Box
/// region (the face most opposed to gravity); the fluid is taken to fill the
/// half-space below it, so a body sticking out of a tank's side is buoyed as
/// if the water went on. Spheres and boxes have exact submerged volumes here
/// (submergedSphere(), submergedBox()); the scene loader refuses a buoyancy
/// region in a scene with other dynamic shapes.
#pragma once

#include "forces/region.hpp"

namespace stepwise {

/// @brief The part of a body below a plane: its volume and centroid.
struct SubmergedPart {
    Real volume = 0;          ///< V_sub, m³.
    Vec3 centroid{0, 0, 0};   ///< The centre of buoyancy B, world space, m (the body's centre when volume = 0).
};

/// @brief The fluid's surface: a point on it and its unit normal pointing up, out of the fluid.
struct FluidSurface {
    Vec3 point{0, 0, 0};   ///< m.
    Vec3 normal{0, 1, 0};  ///< Unit; the fluid is where (p − point)·normal ≤ 0.
};

/// @brief The surface of a Buoyancy region (HalfSpace: its plane; Box: its face most opposed to @p gravity).
FluidSurface fluidSurface(const Region& region, const Vec3& gravity);

/// @brief The cap of a ball of radius @p radius at @p centre below the surface.
///
/// With the ball's lowest point a depth d below the surface, clamped to
/// 0 ≤ d ≤ 2r: V = π·d²·(3r − d)/3, and the cap's centroid lies
/// 3·(2r − d)²/(4·(3r − d)) from the centre, on the submerged side
/// (the spherical cap of any table of volumes and centroids, e.g. Beyer,
/// *CRC Standard Mathematical Tables*, "spherical segment").
SubmergedPart submergedSphere(const Vec3& centre, Real radius, const FluidSurface& surface);

/// @brief The part of a box (centre, orientation, half edges) below the surface.
///
/// Each of the box's six faces is clipped to the fluid's side of the plane
/// (Sutherland–Hodgman against one plane), and the clipped polyhedron's volume
/// and centroid are summed from tetrahedra that join each clipped face's
/// triangles to a point O on the surface: V = Σ (a−O)·((b−O)×(c−O))/6, and
/// the centroid Σ V_t·(O+a+b+c)/4 / V (the divergence theorem). The lid the
/// cut leaves lies in the surface, so its tetrahedra with O are flat: it
/// needs no polygon of its own.
SubmergedPart submergedBox(const Vec3& centre, const Quat& orientation, const Vec3& halfExtents,
                           const FluidSurface& surface);

/// @brief The submerged part of a dynamic sphere or box (volume 0 for other shapes).
SubmergedPart submergedPart(const DynamicObject& body, const FluidSurface& surface);

/// @brief The whole volume of a sphere or box body, m³ (0 for other shapes).
Real bodyVolume(const DynamicObject& body);

/// @brief Adds Archimedes' push and torque, and the fluid's drag on the submerged fraction, to @p body.
void addBuoyancy(DynamicObject& body, const Region& region, const Vec3& gravity, Real substepTime);

}  // namespace stepwise
