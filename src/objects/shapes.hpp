/// @file shapes.hpp
/// @brief The collision shapes a body can have, and the data the larger ones carry.
///
/// A sphere and a box are described by numbers on the object itself (`radius`,
/// `scale`), and so are a capsule and a cylinder (`radius`, `height`). A convex
/// hull, a compound and a triangle mesh carry lists of points, faces or parts.
/// Those lists are built once, when the scene is loaded, and never change: an
/// object holds them through a `std::shared_ptr<const …>`, so copies of a body
/// (a World built from a Scene, a step-by-step snapshot) share one copy of them.
///
/// Every shape is described in its body's own frame, whose origin is the
/// body's centre of mass and whose axes are its principal axes of inertia
/// (src/objects/mass_properties.hpp says how the scene's frame is moved there).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/types.hpp"

namespace stepwise {

/// @brief Collision shape of a dynamic or kinematic object.
enum class Shape : std::uint8_t {
    Sphere,    ///< Ball of `radius` metres around the object's position.
    Box,       ///< Oriented box whose full edge lengths are the object's `scale`.
    Capsule,   ///< All points within `radius` of a segment of length `height` along the body's y axis.
    Cylinder,  ///< Solid cylinder of `radius` and full length `height` along the body's y axis.
    Hull,      ///< Convex polyhedron: the object's `hull`.
    Compound,  ///< A rigid body made of parts: the object's `compound`.
    Mesh,      ///< Triangles (kinematic objects only): the object's `mesh`.
};

/// @brief Human-readable name of a shape ("Sphere", "Box", "Capsule", …).
const char* toString(Shape shape);

/// @brief Is @p shape one a GJK support function describes (everything but Compound and Mesh)?
constexpr bool isConvex(Shape shape) { return shape != Shape::Compound && shape != Shape::Mesh; }

/// @brief One face of a convex hull: a plane and the loop of vertices that bounds it.
///
/// The loop runs counter-clockwise seen from outside, so (v₁ − v₀) × (v₂ − v₀)
/// points along `normal`. Coplanar triangles are merged into one face: a cube
/// has 6 faces of 4 vertices, not 12 triangles, which is what lets the contact
/// stage clip a face against a face as SAT does for boxes.
struct HullFace {
    Vec3 normal{0, 1, 0};            ///< Unit outward normal, body frame.
    Real offset = 0;                 ///< Plane offset: every vertex v has dot(normal, v) ≤ offset, m.
    std::uint32_t firstIndex = 0;    ///< First of this face's vertex indices in ConvexHull::faceIndices.
    std::uint32_t indexCount = 0;    ///< How many vertices the loop has (≥ 3).
};

/// @brief A convex polyhedron in its body's frame (centre of mass at the origin, principal axes).
struct ConvexHull {
    std::vector<Vec3> vertices;                        ///< Corner points, m, body frame; numbered by z, then y, then x as written.
    std::vector<std::uint32_t> faceIndices;            ///< Each face's loop, one after another.
    std::vector<HullFace> faces;                       ///< Faces, outward normals.
    std::vector<std::array<std::uint32_t, 2>> edges;   ///< Each edge once, as two vertex indices.
    Real volume = 0;                                   ///< m³.
    Real boundingRadius = 0;                           ///< Farthest vertex from the origin, m.
};

/// @brief One part of a compound body: a convex shape placed in the body's frame.
struct CompoundPart {
    Shape shape = Shape::Box;           ///< Sphere, Box, Capsule, Cylinder or Hull.
    Vec3 position{0, 0, 0};             ///< Centre of the part in the body's frame, m.
    Quat orientation{1, 0, 0, 0};       ///< Rotation from the part's frame to the body's.
    Vec3 scale{1, 1, 1};                ///< Box edge lengths, m.
    Real radius = Real(0.5);            ///< Sphere, Capsule, Cylinder radius, m.
    Real height = 1;                    ///< Capsule segment or Cylinder length, m.
    Real mass = 0;                      ///< The part's share of the body's mass, kg.
    std::shared_ptr<const ConvexHull> hull;  ///< Shape=Hull: the part's hull, in the part's frame.
    /// The part's `Material` (index in the scene's list), or 0xFFFFFFFF (kNoMaterial): none, its
    /// contacts use the body's friction and elasticity. With one, they use the two below.
    std::uint32_t material = 0xFFFFFFFFu;
    Real friction = 0;                  ///< With a material: its Friction (the body's when it gives none).
    Real elasticity = 0;                ///< With a material: its Elasticity (the body's when it gives none).
};

/// @brief The parts of a compound body and the sphere that holds them all.
struct CompoundShape {
    std::vector<CompoundPart> parts;    ///< At least one.
    Real boundingRadius = 0;            ///< Farthest point of any part from the body's origin, m.
};

/// @brief One node of a triangle mesh's bounding-volume hierarchy.
///
/// A leaf holds `count` triangles starting at `first` (in TriangleMesh::order);
/// an inner node has `count` 0 and its children at `first` and `first + 1`.
struct MeshNode {
    Vec3 lower{0, 0, 0};          ///< Box corner, body frame, m.
    Vec3 upper{0, 0, 0};          ///< Opposite corner, m.
    std::uint32_t first = 0;      ///< First child (inner) or first triangle (leaf).
    std::uint32_t count = 0;      ///< Triangles in a leaf; 0 for an inner node.
};

/// @brief A static triangle mesh in its body's frame, with a hierarchy of boxes over it.
struct TriangleMesh {
    std::vector<Vec3> vertices;                          ///< m, body frame.
    std::vector<std::array<std::uint32_t, 3>> triangles; ///< Counter-clockwise seen from the solid's outside.
    std::vector<MeshNode> nodes;                         ///< The hierarchy; nodes[0] is the root.
    std::vector<std::uint32_t> order;                    ///< Triangle indices in leaf order.
    /// For each triangle and each of its edges (v0→v1, v1→v2, v2→v0): true when a contact
    /// may push along that edge's outward direction, false when the edge is shared with a
    /// neighbour in a flat or concave fold, where such a push would snag a sliding body.
    std::vector<std::array<bool, 3>> activeEdges;
};

}  // namespace stepwise
