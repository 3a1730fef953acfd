/// @file buoyancy.cpp
/// @brief Effect=Buoyancy: F = −ρ_f·V_sub·g at the centre of buoyancy, plus drag on the submerged share.
#include "forces/buoyancy.hpp"

#include <algorithm>
#include <array>
#include <numbers>

#include "forces/drag.hpp"

namespace stepwise {

FluidSurface fluidSurface(const Region& region, const Vec3& gravity) {
    if (region.shape == RegionShape::HalfSpace) return {region.position, region.normal};
    // A tank: its top is the face whose outward normal points most against gravity ("up").
    // The loader allows Buoyancy in HalfSpace and Box regions only.
    int axis = 1;
    for (int i = 0; i < 3; ++i) {
        if (std::abs(gravity[i]) > std::abs(gravity[axis])) axis = i;
    }
    Vec3 up(0);
    up[axis] = gravity[axis] > 0 ? Real(-1) : Real(1);
    return {region.position + up * region.halfExtents[axis], up};
}

SubmergedPart submergedSphere(const Vec3& centre, Real radius, const FluidSurface& surface) {
    const Real height = glm::dot(centre - surface.point, surface.normal);  // of the centre above the surface
    const Real depth = std::clamp(radius - height, Real(0), 2 * radius);  // of the lowest point below it
    if (depth == 0) return {0, centre};
    const Real volume = std::numbers::pi_v<Real> * depth * depth * (3 * radius - depth) / 3;
    const Real offset = 3 * (2 * radius - depth) * (2 * radius - depth) / (4 * (3 * radius - depth));
    return {volume, centre - surface.normal * offset};  // the cap's centroid, below the centre
}

namespace {

/// Most vertices a face of the box can have once clipped by one plane: a quad gains at most one.
constexpr std::size_t kClippedFaceMax = 5;

/// Clips the convex polygon @p in to the fluid's side, (p − O)·n ≤ 0 (Sutherland–Hodgman, one plane).
std::size_t clipBelow(const std::array<Vec3, 4>& in, const FluidSurface& s, std::array<Vec3, kClippedFaceMax>& out) {
    std::size_t count = 0;
    for (std::size_t i = 0; i < in.size(); ++i) {
        const Vec3& a = in[i];
        const Vec3& b = in[(i + 1) % in.size()];
        const Real da = glm::dot(a - s.point, s.normal);
        const Real db = glm::dot(b - s.point, s.normal);
        if (da <= 0) out[count++] = a;
        if ((da < 0 && db > 0) || (da > 0 && db < 0)) out[count++] = a + (b - a) * (da / (da - db));
    }
    return count;
}

}  // namespace

SubmergedPart submergedBox(const Vec3& centre, const Quat& orientation, const Vec3& halfExtents,
                           const FluidSurface& surface) {
    const auto axes = glm::mat3_cast(orientation);  // body → world: its columns are the box's axes
    // O: the box's centre dropped onto the surface, a point of the lid.
    const Vec3 origin = centre - surface.normal * glm::dot(centre - surface.point, surface.normal);
    Real volume = 0;
    Vec3 moment(0);  // Σ V_t·(centroid of t), m⁴
    for (int a = 0; a < 3; ++a) {
        const int b = (a + 1) % 3;
        const int c = (a + 2) % 3;
        for (Real side : {Real(-1), Real(1)}) {
            // The face x_a = ±h_a, its corners in the order (−,−), (+,−), (+,+), (−,+) in (x_b, x_c):
            // counter-clockwise seen from outside on the + side (e_b × e_c = e_a), so reversed on the − side.
            std::array<Vec3, 4> face;
            const Real bs[4] = {-1, 1, 1, -1};
            const Real cs[4] = {-1, -1, 1, 1};
            for (int k = 0; k < 4; ++k) {
                Vec3 local(0);
                local[a] = side * halfExtents[a];
                local[b] = bs[k] * halfExtents[b];
                local[c] = cs[k] * halfExtents[c];
                face[side > 0 ? k : 3 - k] = centre + axes * local;
            }
            std::array<Vec3, kClippedFaceMax> clipped;
            const std::size_t n = clipBelow(face, surface, clipped);
            for (std::size_t k = 1; k + 1 < n; ++k) {  // the fan of triangles (0, k, k+1)
                const Vec3 p = clipped[0] - origin;
                const Vec3 q = clipped[k] - origin;
                const Vec3 r = clipped[k + 1] - origin;
                const Real v = glm::dot(p, glm::cross(q, r)) / 6;
                volume += v;
                moment += v * (p + q + r) / Real(4);  // the tetrahedron's centroid, relative to O
            }
        }
    }
    if (volume <= 0) return {0, centre};
    return {volume, origin + moment / volume};
}

SubmergedPart submergedPart(const DynamicObject& body, const FluidSurface& surface) {
    switch (body.shape) {
        case Shape::Sphere: return submergedSphere(body.position, body.radius, surface);
        case Shape::Box: return submergedBox(body.position, body.orientation, body.halfExtents(), surface);
        default: return {0, body.position};
    }
}

Real bodyVolume(const DynamicObject& body) {
    switch (body.shape) {
        case Shape::Sphere: return 4 * std::numbers::pi_v<Real> * body.radius * body.radius * body.radius / 3;
        case Shape::Box: return body.scale.x * body.scale.y * body.scale.z;
        default: return 0;
    }
}

void addBuoyancy(DynamicObject& body, const Region& region, const Vec3& gravity, Real substepTime) {
    const SubmergedPart part = submergedPart(body, fluidSurface(region, gravity));
    if (part.volume <= 0) return;
    const Vec3 push = -region.density * part.volume * gravity;  // Archimedes: the displaced fluid's weight, N
    body.acceleration += push * body.inverseMass;
    body.torque += glm::cross(part.centroid - body.position, push);  // τ = (B − G) × F
    const Real share = std::min(Real(1), part.volume / bodyVolume(body));
    if (region.coefficient > 0 || region.angularCoefficient > 0) addDrag(body, region, region.velocity, share, substepTime);
}

}  // namespace stepwise
