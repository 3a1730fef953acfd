/// @file convex_manifold.hpp
/// @brief Contact manifolds of convex shapes: the features that meet along the normal GJK, EPA or MPR found, clipped.
///
/// GJK+EPA and MPR give one normal n (A → B) and one pair of deepest
/// points. One point does not hold a box flat on a hull: it rocks about it.
/// The manifold is built as SAT's is (box_box.cpp, Catto GDC 2007):
///
/// 1. **Features.** Each shape shows the feature that reaches farthest
///    along the normal (A along n, B along −n):
///    - box: the face whose outward normal is most aligned (4 corners);
///    - hull: the face whose outward normal is most aligned (its loop);
///    - cylinder: a cap (approximated by kCylinderCapVertices rim points)
///      when the axis is within 5° of the normal, the straight line of its
///      side when the axis is within 5° of square to it, else the one rim point;
///    - capsule: its segment; sphere: its centre (both with their radius).
/// 2. **Reference and incident.** Of the two features that are faces, the
///    one that separates the shapes least along its own normal (the
///    separation −n·(s_A(n) − s_B(−n)) from the support points) is the
///    *reference* face, with SAT's bias for A's face (box_box.cpp section 2:
///    B's face must do better by 5 % of the separation plus 1 % of the
///    smaller shape's size, so the choice does not flicker); the other
///    shape's feature is *incident*. The contact is a face contact unless the
///    algorithm's own normal (an edge across an edge) beats that face by the
///    same bias; the manifold normal is then the reference face's normal,
///    as SAT reports it.
/// 3. **Clip** the incident polygon or segment by the side planes of the
///    reference face (clip_polygon.hpp; each side plane is the face edge
///    e extruded along the face normal n_ref, with outward normal e × n_ref).
/// 4. **Keep** each clipped point q with gap d = n_ref·(q − p_ref) − r_incident
///    up to the allowed gap, as depth −d at the middle of the overlap; if
///    more than kMaxManifoldPoints remain, keep the deepest and those that
///    span the widest area (as box_box.cpp's keepSpreadPoints).
///
/// Anything else (edge across edge, a sphere, a rim point) is a single
/// point: the middle of the two deepest points.
///
/// **Feature ids.** A clipped point's id packs the reference face, the
/// incident face and the two clip labels that made it (the incident
/// polygon's edges 0–63, the reference face's side planes 64–127), as
/// box_features.hpp does for boxes: none depends on a position, so a box
/// resting on a hull keeps its ids from step to step.
#pragma once

#include "collision/narrowphase.hpp"
#include "collision/support.hpp"

namespace stepwise {

/// A cylinder shows its cap as a face when its axis is within 5° of the
/// normal (cos 5° = 0.9962); tilted more, it stands on one rim point.
inline constexpr Real kFaceContactCosine = Real(0.9962);

/// A cylinder lies on its side when its axis is within 5° of square to the normal (sin 5°).
inline constexpr Real kSideContactSine = Real(0.0872);

/// Rim points that stand for a cylinder's cap: a regular octagon. Its
/// edges' middles lie 1 − cos(22.5°) = 7.6 % of the radius inside the rim,
/// close enough for where to push, and 4 of its corners survive the
/// reduction to kMaxManifoldPoints, as the corners of a box's face do.
inline constexpr int kCylinderCapVertices = 8;

/// Most vertices a face may have to be clipped; a hull face with more is
/// met at its deepest point only.
inline constexpr int kMaxFeatureVertices = 64;

/// @brief The manifold of A and B around a normal found by GJK, EPA or MPR (see the file comment).
/// @param normal   unit, from A towards B
/// @param onA      the algorithm's deepest (or closest) point of A, m
/// @param onB      the algorithm's deepest (or closest) point of B, m
/// @param depth    the algorithm's depth, m (negative: a gap)
/// @param maxGap   points whose surfaces are farther apart than this are left out, m
/// @param out      the manifold
/// @return true when at least one point was kept
bool convexManifold(const Geometry& a, const Geometry& b, const Vec3& normal, const Vec3& onA, const Vec3& onB,
                    Real depth, Real maxGap, ContactManifold& out);

/// @brief The manifold of A and one triangle of a mesh (as B) around a normal found by GJK, EPA or closest points.
///
/// The triangle shows the face that looks towards A (its front, whose normal
/// is (p₁ − p₀) × (p₂ − p₀), or its back), and the steps of the file comment
/// follow, with the face bias scaled by A alone (a triangle has no thickness).
/// @param triangle its three corners, world (convexShapeOfTriangle())
/// @param normal   unit, from A towards the triangle
/// @param onA      the deepest (or closest) point of A, m
/// @param onB      the deepest (or closest) point of the triangle, m
/// @param depth    the depth along @p normal, m (negative: a gap)
/// @param maxGap   points whose surfaces are farther apart than this are left out, m
/// @param out      the manifold
/// @return true when at least one point was kept
bool triangleManifold(const Geometry& a, const ConvexShape& triangle, const Vec3& normal, const Vec3& onA,
                      const Vec3& onB, Real depth, Real maxGap, ContactManifold& out);

/// Most points triangleFacePoints() gives: a clipped face of kMaxFeatureVertices corners, plus one per side plane.
inline constexpr int kMaxTriangleFacePoints = 2 * kMaxFeatureVertices;

/// @brief The points of A that lie over a triangle's front face, pushed along its normal: steps 3 and 4
/// of the file comment with the triangle's front as the reference face, whatever A shows.
///
/// A's feature towards the triangle (a box's face, a capsule's segment, a
/// sphere's centre) is clipped by the triangle's three side planes, and every
/// point within @p maxGap is kept at the middle of the overlap, with its depth
/// along the face normal; none is dropped for being a fifth (the caller
/// gathers the points of many triangles, then cuts them down). What does not
/// lie over the triangle gives nothing: that is what the mesh test asks of a
/// contact it has turned to the face normal (mesh_contacts.hpp), whose other
/// part lies over the neighbouring triangle.
/// @param triangle its three corners, counter-clockwise seen from the front (convexShapeOfTriangle())
/// @param maxGap   points whose surfaces are farther apart than this are left out, m
/// @param points   room for kMaxTriangleFacePoints points
/// @return how many points were written (their normal, from A, is minus the face normal)
int triangleFacePoints(const Geometry& a, const ConvexShape& triangle, Real maxGap, ContactPoint* points);

/// @brief Keeps the deepest of @p count points and those that span the widest area around it, up to kMaxManifoldPoints.
///
/// Deepest first, then the point farthest from it, then the one farthest
/// from the line through those two, then the farthest on the other side
/// (box_box.cpp's keepSpreadPoints explains why that order keeps a wide base).
/// The kept points stay in their original order.
/// @return how many were kept
int keepSpreadContactPoints(ContactPoint* points, int count, const Vec3& normal);

}  // namespace stepwise
