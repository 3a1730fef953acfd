/// @file inertia.cpp
/// @brief YOUR inertia tensors (lecture 4): a student template (lectures/student-template/README.md).
///
/// Copied to student/objects/inertia.cpp, it replaces src/objects/inertia.cpp
/// in the student preset's build. It defines the functions
/// src/objects/inertia.hpp declares; you write three parts (lecture 4,
/// "Inertia: mass, spread out"):
///
///     solidSphereInertia    (2/5) m r^2 about every axis
///     hollowSphereInertia   (2/3) m r^2 about every axis
///     solidBoxInertia       edges (a, b, c) = size: m (b^2 + c^2)/12, m (a^2 + c^2)/12, m (a^2 + b^2)/12
///     parallelAxis          I_P = I_C + m (|d|^2 E - d d^T)     (glm::outerProduct(d, d) is d d^T)
///     rotateDiagonal        R diag(x, y, z) R^T, with R = glm::mat3_cast(orientation)
///
/// The rest (the world tensors built on rotateDiagonal, omega = I_world^-1 L,
/// impulses) is given. Until you write them, the first body that needs one
/// stops with "student stage not written yet: stepwise::solidSphereInertia"
/// (or the function it reached).
/// Test it: ctest --preset student -L inertia
#include "core/student_todo.hpp"
#include "objects/inertia.hpp"
#include "objects/mass_properties.hpp"

namespace stepwise {

// ==== YOUR CODE BEGINS: lecture 4, "Inertia: mass, spread out" (the table of shapes) ====
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
// ==== YOUR CODE ENDS ====

Mat3 parallelAxis(const Mat3& inertiaAboutCentre, Real mass, const Vec3& offset) {
    // ==== YOUR CODE BEGINS: lecture 4, "Inertia: mass, spread out" (parallel-axis theorem) ====
    // |d|²E − d dᵀ: the inertia of a point mass at d (GLM matrices are column-major,
    // outerProduct(d, d)[j][i] = d_i d_j, symmetric either way).
    return inertiaAboutCentre + mass * (glm::dot(offset, offset) * Mat3(1) - glm::outerProduct(offset, offset));
    // ==== YOUR CODE ENDS ====
}

bool equalMoments(const Vec3& diagonal) { return diagonal.x == diagonal.y && diagonal.y == diagonal.z; }

namespace {

/// R diag(d) R^T: a diagonal body-frame tensor seen in the world.
Mat3 rotateDiagonal(const Quat& orientation, const Vec3& diagonal) {
    // The same in every orientation: the rotation (two 3x3 products) is skipped.
    if (equalMoments(diagonal)) return Mat3(diagonal.x);
    // ==== YOUR CODE BEGINS: lecture 4, "Inertia: mass, spread out" (world frame) ====
    const Mat3 r = glm::mat3_cast(orientation);
    Mat3 d(0);
    d[0][0] = diagonal.x;
    d[1][1] = diagonal.y;
    d[2][2] = diagonal.z;
    return r * d * glm::transpose(r);
    // ==== YOUR CODE ENDS ====
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
    // Three equal moments: omega = s L in every orientation, the same numbers the tensor
    // product gives (rotateDiagonal() returns s E), without building it every substep.
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
