/// @file camera.hpp
/// @brief The viewer's orbit camera: where it looks from, and how a world point lands on a pixel.
///
/// This header is plain maths (GLM, no OpenGL) so that the viewer test can
/// compute, with exactly the matrices the viewer loads into OpenGL, the pixel
/// at which a body must appear in a screenshot. The viewer hands
/// viewMatrix() and projectionMatrix() to `glLoadMatrixd`; project() and
/// rayThroughPixel() do by hand what OpenGL does with them.
#pragma once

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "collision/broadphase.hpp"
#include "core/types.hpp"
#include "world/world.hpp"

/// @brief The freeglut viewer (`stepwise view`): drawing, controls, screenshots. Not part of the engine.
namespace stepwise::viewer {

/// @brief 4×4 matrix of the engine's precision (view and projection matrices).
using Mat4 = glm::mat<4, 4, Real, glm::defaultp>;
/// @brief 4-vector of the engine's precision (homogeneous points).
using Vec4 = glm::vec<4, Real, glm::defaultp>;

/// @brief A ray: the points origin + s·direction for s ≥ 0.
struct Ray {
    Vec3 origin{0, 0, 0};     ///< Start point, m.
    Vec3 direction{0, 0, -1}; ///< Unit direction.
};

/// @brief A camera on a sphere around a target point, always upright (+y up).
///
/// The eye sits at distance `distance` from `target`, in the direction given
/// by two angles: `yaw` about the vertical (0 looks from +z towards −z) and
/// `pitch` above the horizontal plane:
/// \f[ e = t + d\,(\cos p \sin y,\ \sin p,\ \cos p \cos y). \f]
/// Orbiting changes the angles, zooming the distance, panning the target.
struct OrbitCamera {
    Vec3 target{0, 0, 0};     ///< Point looked at, m.
    Real distance = 10;       ///< Eye-to-target distance, m.
    Real yaw = Real(0.6);     ///< Angle about +y, rad.
    Real pitch = Real(0.5);   ///< Angle above the horizontal, rad (kept inside ±1.5).
    Real fovY = Real(0.8);    ///< Vertical field of view, rad (about 46°).

    /// @brief The eye position, m.
    Vec3 eye() const {
        const Vec3 offset(std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw));
        return target + distance * offset;
    }

    /// @brief Near clipping distance, m: small against the distance, so close bodies are not cut.
    Real nearPlane() const { return std::max(Real(0.01), distance * Real(0.01)); }

    /// @brief Far clipping distance, m: far enough for the floor's grid.
    Real farPlane() const { return distance * Real(20) + Real(200); }

    /// @brief World → camera matrix (what `glLoadMatrixd` gets for GL_MODELVIEW).
    Mat4 viewMatrix() const { return glm::lookAt(eye(), target, Vec3(0, 1, 0)); }

    /// @brief Camera → clip matrix for a viewport of aspect ratio @p aspect = width / height.
    Mat4 projectionMatrix(Real aspect) const { return glm::perspective(fovY, aspect, nearPlane(), farPlane()); }

    /// @brief Where world point @p p is drawn in a @p width × @p height image.
    /// @return x from the left edge and y from the *top* edge, in pixels (the
    ///         pixel's centre is at +0.5), and z the depth in 0–1; a point
    ///         behind the eye gives z outside 0–1.
    Vec3 project(const Vec3& p, int width, int height) const {
        const Vec4 clip = projectionMatrix(Real(width) / Real(height)) * viewMatrix() * Vec4(p, 1);
        const Vec3 ndc = Vec3(clip) / clip.w;
        return {(ndc.x + 1) / 2 * Real(width), (1 - ndc.y) / 2 * Real(height), (ndc.z + 1) / 2};
    }

    /// @brief The ray from the eye through pixel (@p x, @p y), y measured from the top, as GLUT reports the mouse.
    Ray rayThroughPixel(Real x, Real y, int width, int height) const {
        const Mat4 inverse = glm::inverse(projectionMatrix(Real(width) / Real(height)) * viewMatrix());
        const Real nx = 2 * x / Real(width) - 1;
        const Real ny = 1 - 2 * y / Real(height);
        const Vec4 nearPoint = inverse * Vec4(nx, ny, -1, 1);
        const Vec4 farPoint = inverse * Vec4(nx, ny, 1, 1);
        const Vec3 a = Vec3(nearPoint) / nearPoint.w;
        const Vec3 b = Vec3(farPoint) / farPoint.w;
        return {a, glm::normalize(b - a)};
    }

    /// @brief Turns the camera about the target by @p dYaw and @p dPitch, rad.
    void orbit(Real dYaw, Real dPitch) {
        yaw += dYaw;
        pitch = std::clamp(pitch + dPitch, Real(-1.5), Real(1.5));
    }

    /// @brief Moves the eye towards the target by the factor @p factor (< 1 zooms in).
    void zoom(Real factor) { distance = std::clamp(distance * factor, Real(0.2), Real(1000)); }

    /// @brief Slides target and eye sideways and up by a fraction of the view's size
    /// (@p right, @p up: 1 = the visible height at the target).
    void pan(Real right, Real up) {
        const Mat4 view = viewMatrix();
        const Vec3 rightAxis(view[0][0], view[1][0], view[2][0]);
        const Vec3 upAxis(view[0][1], view[1][1], view[2][1]);
        const Real visibleHeight = 2 * distance * std::tan(fovY / 2);
        target += visibleHeight * (right * rightAxis + up * upAxis);
    }
};

/// @brief A camera that frames @p box: its centre is the target, and the distance fits the
/// box's bounding sphere (at least 1 m of radius) into the vertical field of view with a margin.
inline OrbitCamera cameraForBox(const Aabb& box) {
    OrbitCamera camera;
    const Real radius = std::max(Real(1), glm::length(box.max - box.min) / 2);
    camera.target = (box.min + box.max) / Real(2);
    camera.distance = Real(1.05) * radius / std::sin(camera.fovY / 2);
    return camera;
}

/// @brief The camera `stepwise view` starts with: it frames every dynamic and
/// kinematic body of @p world as it is now (planes are infinite and left out).
///
/// The target is the centre of the bodies' joint bounding box; the distance
/// fits that box's bounding sphere into the vertical field of view with a
/// margin (cameraForBox()). An empty scene gets
/// a view of the origin from 10 m. (A scene with spaces is framed by
/// cameraForSpaces(), src/viewer/space_layout.hpp: every space, as drawn.)
inline OrbitCamera cameraForScene(const World& world) {
    OrbitCamera camera;
    bool any = false;
    Aabb all;
    auto add = [&](const Aabb& box) {
        if (!any) all = box;
        all.min = glm::min(all.min, box.min);
        all.max = glm::max(all.max, box.max);
        any = true;
    };
    for (const DynamicObject& b : world.dynamics()) add(shapeAabb(b));
    for (const KinematicsObject& b : world.kinematics()) add(shapeAabb(b));
    if (!any) return camera;
    return cameraForBox(all);
}

}  // namespace stepwise::viewer
