/// @file inertia.cpp
/// @brief Inertia tensors of the shapes, the parallel-axis theorem, and world-frame conversions.
#include "objects/inertia.hpp"

#include "objects/mass_properties.hpp"

namespace stepwise {

/// Solid ball: I = k·m·r² with k = ⅖, the volume integral of r⊥² (the
/// distance from the axis squared) over the ball, divided by m·r².
constexpr Real kSolidSphereFactor = Real(2) / Real(5);
/// Thin spherical shell: k = ⅔, the same integral over the surface. All the
/// mass is at the radius r, none near the centre, hence more than ⅖.
constexpr Real kHollowSphereFactor = Real(2) / Real(3);
/// A uniform rod or box side of length a contributes m·a²/12 about its centre.
constexpr Real kBoxFactor = Real(1) / Real(12);

Vec3 solidSphereInertia(Real mass, Real radius) { return Vec3(kSolidSphereFactor * mass * radius * radius); }

Vec3 hollowSphereInertia(Real mass, Real radius) { return Vec3(kHollowSphereFactor * mass * radius * radius); }

Vec3 solidBoxInertia(Real mass, const Vec3& size) {
    const Vec3 s2 = size * size;
    return kBoxFactor * mass * Vec3(s2.y + s2.z, s2.x + s2.z, s2.x + s2.y);
}

Mat3 parallelAxis(const Mat3& inertiaAboutCentre, Real mass, const Vec3& offset) {
    // |d|²E − d dᵀ: the inertia of a point mass at d (GLM matrices are column-major,
    // outerProduct(d, d)[j][i] = d_i d_j, symmetric either way).
    return inertiaAboutCentre + mass * (glm::dot(offset, offset) * Mat3(1) - glm::outerProduct(offset, offset));
}

bool equalMoments(const Vec3& diagonal) { return diagonal.x == diagonal.y && diagonal.y == diagonal.z; }

namespace {

Mat3 rotateDiagonal(const Quat& orientation, const Vec3& diagonal) {
    // The same in every orientation: the rotation (two 3×3 products) is skipped.
    if (equalMoments(diagonal)) return Mat3(diagonal.x);
    const Mat3 r = glm::mat3_cast(orientation);
    Mat3 d(0);
    d[0][0] = diagonal.x;
    d[1][1] = diagonal.y;
    d[2][2] = diagonal.z;
    return r * d * glm::transpose(r);
}
}  // namespace

Mat3 worldInverseInertia(const Quat& orientation, const Vec3& inverseInertiaBody) {
    return rotateDiagonal(orientation, inverseInertiaBody);
}

Mat3 worldInertia(const Quat& orientation, const Vec3& inertiaBody) { return rotateDiagonal(orientation, inertiaBody); }

void initialiseMassProperties(DynamicObject& body) {
    if (body.shape == Shape::Box) {
        body.inertiaBody = solidBoxInertia(body.mass, body.scale);
    } else if (body.shape == Shape::Sphere) {
        body.inertiaBody = body.hollow ? hollowSphereInertia(body.mass, body.radius)
                                       : solidSphereInertia(body.mass, body.radius);
    } else {
        // Capsules, cylinders, hulls and compounds (lecture 12): objects/mass_properties.hpp.
        body.inertiaBody = shapeInertia(body);
    }
    body.inverseInertiaBody = Real(1) / body.inertiaBody;
    body.angularMomentum = worldInertia(body.orientation, body.inertiaBody) * body.angularVelocity;
}

void updateAngularVelocity(DynamicObject& body) {
    // Three equal moments: ω = s·L in every orientation, the same numbers the tensor
    // product gives (rotateDiagonal() returns s·E), without building it every substep.
    if (equalMoments(body.inverseInertiaBody)) {
        body.angularVelocity = body.inverseInertiaBody.x * body.angularMomentum;
        return;
    }
    body.angularVelocity = worldInverseInertia(body.orientation, body.inverseInertiaBody) * body.angularMomentum;
}

void applyImpulseAt(DynamicObject& body, const Vec3& impulse, const Vec3& point) {
    body.velocity += impulse * body.inverseMass;
    body.angularMomentum += glm::cross(point - body.position, impulse);
    updateAngularVelocity(body);
}

}  // namespace stepwise
