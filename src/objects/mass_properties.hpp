/// @file mass_properties.hpp
/// @brief Mass, centre of mass and inertia of the larger shapes: capsules, cylinders, polyhedra, compounds.
///
/// src/objects/inertia.hpp has the sphere and the box, whose tensors every
/// course derives first. This file adds what lecture 12 ("bodies from
/// parts") builds on them:
///
/// - closed forms for a solid capsule and a solid cylinder;
/// - the volume, centre of mass and inertia tensor of any closed polyhedron,
///   by the divergence theorem (Eberly, "Polyhedral Mass Properties
///   (Revisited)", 2002; Mirtich, "Fast and Accurate Computation of
///   Polyhedral Mass Properties", 1996): three volume integrals become sums
///   over the surface's triangles;
/// - a compound body's mass, centre and tensor from its parts (each part's
///   tensor rotated into the body frame, then moved by the parallel-axis theorem);
/// - the principal axes of a symmetric tensor, by Jacobi rotations.
///
/// **Why the frame moves.** A DynamicObject stores its inertia as three
/// principal moments (`inertiaBody` is a Vec3), which is only true in a frame
/// whose origin is the centre of mass and whose axes are the principal axes.
/// A box or a cylinder is built that way; a hull's points or a compound's
/// parts, as a scene writes them, usually are not. So at load time the shape
/// is re-expressed in that frame (moveToPrincipalFrame()), and the body's pose
/// becomes the scene's pose composed with the returned BodyFrame:
/// \f[ x_\text{body} = x_\text{scene} + R_\text{scene}\,c, \qquad
///     q_\text{body} = q_\text{scene}\,q_\text{axes}. \f]
/// Every point of the body stays where the scene put it.
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "objects/game_object.hpp"

namespace stepwise {

/// @brief Volume of a ball of radius @p radius: 4/3·π·r³, m³.
Real sphereVolume(Real radius);
/// @brief Volume of a box with full edge lengths @p size: a·b·c, m³.
Real boxVolume(const Vec3& size);
/// @brief Volume of a capsule: a cylinder π·r²·h plus a ball 4/3·π·r³, m³.
Real capsuleVolume(Real radius, Real height);
/// @brief Volume of a cylinder of full length @p height: π·r²·h, m³.
Real cylinderVolume(Real radius, Real height);

/// @brief Principal moments of a solid capsule whose segment of length @p height runs along y, kg·m².
///
/// Uniform density ρ = m / (π r² h + 4/3 π r³). The cylinder (mass m_c) and the
/// two hemispheres (mass m_h each) add up:
/// \f[ I_y = \tfrac12 m_c r^2 + 2\cdot\tfrac25 m_h r^2, \f]
/// \f[ I_x = I_z = m_c\,\frac{3r^2 + h^2}{12}
///     + 2\,m_h\Big(\tfrac25 r^2 - \big(\tfrac38 r\big)^2 + \big(\tfrac h2 + \tfrac38 r\big)^2\Big). \f]
/// A hemisphere's moment about a diameter of its flat face is half a ball's,
/// ⅖·m_h·r²; its centre of mass is 3r/8 from that face, so the parallel-axis
/// theorem takes m_h·(3r/8)² off to reach its own centre and adds
/// m_h·(h/2 + 3r/8)² to reach the capsule's. With h = 0 it is a ball: ⅖·m·r².
Vec3 solidCapsuleInertia(Real mass, Real radius, Real height);

/// @brief Principal moments of a solid cylinder of full length @p height along y, kg·m²:
/// I_y = ½·m·r², I_x = I_z = m·(3r² + h²)/12.
Vec3 solidCylinderInertia(Real mass, Real radius, Real height);

/// @brief Volume, centre and inertia of a solid of density 1.
///
/// Multiply `inertia` by the density ρ = m / volume for a body of mass m.
struct PolyhedronMass {
    Real volume = 0;            ///< m³.
    Vec3 centroid{0, 0, 0};     ///< Centre of mass (of volume), m, in the frame of the vertices.
    Mat3 inertia{0};            ///< Tensor about the centroid per unit density, m⁵, in the frame of the vertices.
};

/// @brief Mass properties of the closed polyhedron bounded by @p triangles (indices into
/// @p vertices, counter-clockwise seen from outside), by the divergence theorem.
///
/// Each triangle (p₀, p₁, p₂) is parametrised p(u, v) = p₀ + u(p₁ − p₀) + v(p₂ − p₀),
/// so its outward area element is d·du·dv with d = (p₁ − p₀) × (p₂ − p₀). The
/// divergence theorem turns each volume integral into a surface integral,
/// \f[ \int_V 1\,dV = \oint x\,n_x\,dA,\quad \int_V x\,dV = \oint \tfrac{x^2}{2}\,n_x\,dA,\quad
///     \int_V x^2\,dV = \oint \tfrac{x^3}{3}\,n_x\,dA,\quad \int_V xy\,dV = \oint \tfrac{x^2 y}{2}\,n_x\,dA, \f]
/// (and the same with the axes renamed), and over the parameter triangle the
/// integral of a product of linear functions is a symmetric sum of the corner
/// values, e.g. ∫x du dv = (x₀ + x₁ + x₂)/6. Exact for any closed, consistently
/// wound triangle surface, convex or not (Eberly 2002, §2–3).
PolyhedronMass polyhedronMassProperties(std::span<const Vec3> vertices,
                                        std::span<const std::array<std::uint32_t, 3>> triangles);

/// @brief Mass properties of a hull; each face's loop is split into a fan of triangles.
PolyhedronMass polyhedronMassProperties(const ConvexHull& hull);

/// @brief A symmetric tensor's principal moments and axes: I = R·diag(moments)·Rᵀ.
struct PrincipalAxes {
    Vec3 moments{0, 0, 0};        ///< The eigenvalues, kg·m² (or m⁵ per unit density).
    Quat rotation{1, 0, 0, 0};    ///< R: its columns are the principal axes; right-handed.
};

/// @brief Diagonalises the symmetric tensor @p tensor by cyclic Jacobi rotations.
///
/// Each rotation, in the plane of two axes p and q, turns by the angle θ with
/// tan 2θ = 2·I_pq / (I_qq − I_pp), which makes I_pq zero; the sweeps over the
/// three planes repeat until every off-diagonal entry is negligible next to the
/// diagonal (Golub and Van Loan, *Matrix Computations*, §8.5). Off-diagonal entries
/// already at round-off level are left alone, so a tensor that is diagonal (a box,
/// a cube hull) keeps the identity rotation. The axes are returned right-handed
/// (det R = +1), so R is a rotation, as a body's orientation must be.
PrincipalAxes principalAxes(const Mat3& tensor);

/// @brief Where the principal frame lies in the frame a shape was written in.
struct BodyFrame {
    Vec3 centre{0, 0, 0};       ///< Centre of mass, m, in the written frame.
    Quat axes{1, 0, 0, 0};      ///< Rotation from the principal frame to the written frame.
};

/// @brief Moves @p hull to its centre of mass and principal axes (uniform density):
/// every vertex v becomes Rᵀ·(v − c), every face plane follows, and the bounding
/// radius is measured again. @returns the frame it was moved to.
BodyFrame moveToPrincipalFrame(ConvexHull& hull);

/// @brief Volume of one part of a compound (Sphere, Box, Capsule, Cylinder or Hull), m³.
Real partVolume(const CompoundPart& part);

/// @brief Inertia tensor of one part about its own centre, in the body frame, with mass `part.mass`:
/// R_part·I_part·R_partᵀ, kg·m².
Mat3 partInertia(const CompoundPart& part);

/// @brief Mass, centre of mass and tensor of a whole compound.
struct CompoundMass {
    Real mass = 0;              ///< Σ m_i, kg.
    Vec3 centre{0, 0, 0};       ///< Σ m_i·p_i / Σ m_i, m, body frame.
    Mat3 inertia{0};            ///< About `centre`, body frame, kg·m².
};

/// @brief Sums the parts: each part's tensor rotated into the body frame and moved by the
/// parallel-axis theorem from its own centre to the compound's,
/// \f[ I = \sum_i \Big( R_i I_i R_i^\mathsf{T} + m_i\,(|d_i|^2 E - d_i d_i^\mathsf{T}) \Big),
///     \qquad d_i = p_i - c. \f]
CompoundMass compoundMassProperties(const CompoundShape& compound);

/// @brief Moves @p compound to its centre of mass and principal axes: each part's
/// position p becomes Rᵀ·(p − c), its orientation q_axes⁻¹·q, and the bounding
/// radius is measured again. @returns the frame it was moved to.
BodyFrame moveToPrincipalFrame(CompoundShape& compound);

/// @brief The farthest any point of @p part reaches from the body's origin, m.
Real partReach(const CompoundPart& part);

/// @brief Volume of a solid body's shape, m³: what a density multiplies into its mass.
///
/// A sphere is the solid ball (its `hollow` flag is not read: a thin shell has no volume,
/// so the loader refuses a density for one); a hull's is its polyhedron's; a compound's is
/// the sum of its parts' (they are taken not to overlap).
/// @throws std::invalid_argument for a Mesh, or a Hull or Compound body without its data.
Real shapeVolume(const DynamicObject& body);

/// @brief Principal moments of a Capsule, Cylinder, Hull or Compound body, kg·m².
///
/// A hull and a compound must already be in their principal frames (as the
/// scene loader leaves them); a compound's part masses are scaled to the body's `mass`.
/// @throws std::invalid_argument for a Mesh (meshes belong to kinematic objects
///         only), or a Hull or Compound body without its data.
Vec3 shapeInertia(const DynamicObject& body);

}  // namespace stepwise
