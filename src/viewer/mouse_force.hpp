/// @file mouse_force.hpp
/// @brief The force of a push or pull with the mouse, applied at the picked point so that it also turns the body.
///
/// A held body feels a force F of fixed size along the mouse ray (push) or
/// against it (pull), applied at the point where the ray first hit it. That
/// point is stored in the body's own frame, so it turns with the body. Each
/// step, before World::step(), the force acts as the impulse J = F·h at the
/// point p (Baraff, *Physically Based Modeling: Rigid Body Simulation*, the
/// torque τ = (p − x) × F and the impulse of a collision):
/// \f[ \Delta v = \frac{J}{m}, \qquad \Delta L = (p - x) \times J, \f]
/// so a push through the centre only moves the body, and an off-centre push
/// also turns it, about r × F with r = p − x. Over a frame the impulses add up
/// to F times the frame's simulated time.
///
/// Plain maths (no OpenGL): the viewer test checks it without a window.
#pragma once

#include <cstdint>

#include "objects/inertia.hpp"
#include "objects/game_object.hpp"

namespace stepwise::viewer {

/// @brief Acceleration a grab gives a body without gravity, m/s² (about twice standard gravity).
inline constexpr Real kGrabAccelerationWithoutGravity = Real(20);
/// @brief A grab accelerates a body by this many times the scene's gravity, so a push can lift it.
inline constexpr Real kGrabAccelerationPerGravity = Real(2);

/// @brief A body held with the mouse: pushed (left button) or pulled (right button) at a point.
struct Grab {
    std::uint32_t body = 0;      ///< Index of the dynamic body.
    Vec3 localPoint{0, 0, 0};    ///< The held point in the body's own frame, m (it turns with the body).
    Vec3 direction{0, 0, -1};    ///< Unit direction of the force: along the mouse ray to push, against it to pull.
    bool pull = false;           ///< True for the right button.
};

/// @brief Starts holding @p body (index @p index) at world point @p point, pushed along
/// the unit mouse-ray direction @p rayDirection, or pulled against it when @p pull.
inline Grab grabAt(const DynamicObject& body, std::uint32_t index, const Vec3& point, const Vec3& rayDirection,
                   bool pull) {
    return Grab{index, glm::conjugate(body.orientation) * (point - body.position),
                pull ? -rayDirection : rayDirection, pull};
}

/// @brief Points the force along (push) or against (pull) a new unit mouse-ray direction.
inline void aimGrab(Grab& grab, const Vec3& rayDirection) { grab.direction = grab.pull ? -rayDirection : rayDirection; }

/// @brief World-space position of the held point of @p body now, m: x + R·p_local.
inline Vec3 grabPoint(const DynamicObject& body, const Grab& grab) {
    return body.position + body.orientation * grab.localPoint;
}

/// @brief Size of the acceleration a grab gives a body, m/s²: 2·|g|, or 20 m/s² without gravity.
inline Real grabAcceleration(const Vec3& gravity) {
    const Real g = glm::length(gravity);
    return g > 0 ? kGrabAccelerationPerGravity * g : kGrabAccelerationWithoutGravity;
}

/// @brief The force on the held body, N: F = m · grabAcceleration(g) along the grab's direction.
inline Vec3 grabForce(const DynamicObject& body, const Grab& grab, const Vec3& gravity) {
    return body.mass * grabAcceleration(gravity) * grab.direction;
}

/// @brief Gives @p body one step's worth of the grab's force: the impulse F·h at the held point.
/// @param gravity the scene's gravity, m/s² (sets the force's size)
/// @param h       the time step, s
inline void applyGrab(DynamicObject& body, const Grab& grab, const Vec3& gravity, Real h) {
    applyImpulseAt(body, grabForce(body, grab, gravity) * h, grabPoint(body, grab));
}

}  // namespace stepwise::viewer
