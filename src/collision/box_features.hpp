/// @file box_features.hpp
/// @brief A box's corners, edges and faces by number, and the feature ids the box tests pack from them.
///
/// The box tests (box_plane.cpp, box_box.cpp) name every point they report
/// by the features of the two boxes that produced it. The numbering is fixed
/// here once, in the box's own frame, so that the same physical corner gets
/// the same number every step.
///
/// **Corners (0–7).** Bit i of the index set ⇒ +halfExtent on body axis i,
/// clear ⇒ −halfExtent:
///
///     index  bits(zyx)  corner            index  bits(zyx)  corner
///       0      000      (−x, −y, −z)        4      100      (−x, −y, +z)
///       1      001      (+x, −y, −z)        5      101      (+x, −y, +z)
///       2      010      (−x, +y, −z)        6      110      (−x, +y, +z)
///       3      011      (+x, +y, −z)        7      111      (+x, +y, +z)
///
/// So the bottom face (−y) holds corners 0, 1, 4, 5.
///
/// **Faces (0–5).** face = 2·axis + (1 if the outward normal is −axis):
/// 0 = +x, 1 = −x, 2 = +y, 3 = −y, 4 = +z, 5 = −z.
///
/// **Edges (0–11).** Edge e runs along body axis i = e / 4. Its other two
/// axes are j = (i + 1) mod 3 and k = (i + 2) mod 3; bit 0 of e set ⇒ the
/// edge lies at +halfExtent on j, bit 1 set ⇒ at +halfExtent on k. Example:
/// edge 6 = 4·1 + 2 runs along y (i = 1, so j = z and k = x) at z = −e_z
/// (bit 0 clear) and x = +eₓ (bit 1 set).
#pragma once

#include <cstdint>

#include "collision/narrowphase.hpp"

namespace stepwise {

/// @brief A box in world space, ready for feature queries: centre, axes, half extents.
struct OrientedBox {
    Vec3 centre{0, 0, 0};       ///< Centre, m.
    Mat3 axes{1};               ///< Column i is body axis i in world space (unit).
    Vec3 halfExtents{0, 0, 0};  ///< Half edge lengths along the body axes, m.
};

/// @brief The OrientedBox of a box Geometry (its rotation matrix computed once).
inline OrientedBox orientedBoxOf(const Geometry& box) {
    return {box.centre, glm::mat3_cast(box.orientation), box.halfExtents};
}

/// @brief ±1 for bit @p axis of a corner index: +1 when set.
inline Real cornerSign(int corner, int axis) { return ((corner >> axis) & 1) != 0 ? Real(1) : Real(-1); }

/// @brief World position of corner @p index (0–7, see the file comment).
inline Vec3 cornerOf(const OrientedBox& box, int index) {
    Vec3 p = box.centre;
    for (int i = 0; i < 3; ++i) p += box.axes[i] * (cornerSign(index, i) * box.halfExtents[i]);
    return p;
}

/// @brief Face number (0–5) of the face whose outward normal is @p sign (±1) times body axis @p axis.
inline int faceIndex(int axis, Real sign) { return 2 * axis + (sign < 0 ? 1 : 0); }

/// @brief Edge number (0–11) of the edge along body axis @p axis whose other
/// two coordinates have the signs of @p signJ and @p signK (axes (axis+1)%3 and (axis+2)%3).
inline int edgeIndex(int axis, Real signJ, Real signK) {
    return 4 * axis + (signJ > 0 ? 1 : 0) + (signK > 0 ? 2 : 0);
}

// ------------------------------------------------------------------ feature ids

/// @brief What kind of contact a box-box feature id describes (its top bits).
enum class BoxContactKind : std::uint32_t {
    FaceOfA = 1,  ///< A face of A is the reference face; B's face is clipped against it.
    FaceOfB = 2,  ///< A face of B is the reference face; A's face is clipped against it.
    EdgeEdge = 3, ///< An edge of A crosses an edge of B.
};

/// Bit position of the BoxContactKind in a box-box feature id (bits 12–13).
inline constexpr int kFeatureKindShift = 12;

/// @brief Feature id of a face contact point.
///
/// Layout (bit 0 is the lowest):
///
///     bits 0–2   reference face (0–5)
///     bits 3–5   incident face (0–5)
///     bits 6–8   label of the polygon edge arriving at the point
///     bits 9–11  label of the polygon edge leaving the point
///     bits 12–13 BoxContactKind (FaceOfA or FaceOfB)
///
/// Edge labels 0–3 are the incident face's own edges (edge m runs from its
/// vertex m to vertex m + 1); 4–7 are the reference face's side planes
/// (+u, −u, +v, −v). A point that is an incident corner has two incident
/// labels; a point made by clipping has one side label (two at a corner of
/// the reference face). The pair does not change while the boxes rest on
/// each other, so neither does the id.
inline std::uint32_t faceFeatureId(BoxContactKind kind, int referenceFace, int incidentFace, int inEdge,
                                   int outEdge) {
    return (static_cast<std::uint32_t>(kind) << kFeatureKindShift) | static_cast<std::uint32_t>(referenceFace) |
           (static_cast<std::uint32_t>(incidentFace) << 3) | (static_cast<std::uint32_t>(inEdge) << 6) |
           (static_cast<std::uint32_t>(outEdge) << 9);
}

/// @brief Feature id of an edge–edge contact point.
///
///     bits 0–3   edge of A (0–11)
///     bits 4–7   edge of B (0–11)
///     bits 12–13 BoxContactKind::EdgeEdge
inline std::uint32_t edgeFeatureId(int edgeOfA, int edgeOfB) {
    return (static_cast<std::uint32_t>(BoxContactKind::EdgeEdge) << kFeatureKindShift) |
           static_cast<std::uint32_t>(edgeOfA) | (static_cast<std::uint32_t>(edgeOfB) << 4);
}

/// @brief The BoxContactKind stored in a box-box feature id.
inline BoxContactKind featureKind(std::uint32_t featureId) {
    return static_cast<BoxContactKind>((featureId >> kFeatureKindShift) & 3u);
}

}  // namespace stepwise
