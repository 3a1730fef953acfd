/// @file mass_properties.cpp
/// @brief Closed forms for capsules and cylinders, polyhedra by the divergence theorem, compounds, Jacobi.
#include "objects/mass_properties.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "objects/inertia.hpp"

namespace stepwise {

namespace {

/// A ball's volume is 4/3·π·r³.
constexpr Real kBallVolumeFactor = Real(4) / Real(3) * kPi;
/// A solid ball's moment is ⅖·m·r² about any diameter; a hemisphere's, about a
/// diameter of its flat face, is the same fraction of its own mass.
constexpr Real kBallMomentFactor = Real(2) / Real(5);
/// A hemisphere's centre of mass lies 3r/8 from its flat face.
constexpr Real kHemisphereCentroid = Real(3) / Real(8);
/// A solid cylinder's moment about its axis is ½·m·r².
constexpr Real kCylinderAxialFactor = Real(1) / Real(2);
/// About a diameter through its centre: m·(3r² + h²)/12.
constexpr Real kCylinderTransverseFactor = Real(1) / Real(12);

// The parameter triangle's integrals (Eberly 2002, §3): for x linear over the triangle,
// ∫x = f₁/6, ∫x² = f₂/12, ∫x³ = f₃/20, ∫x²y = Σ yᵢgᵢ/60, with fₖ the complete symmetric
// sums of degree k of the corner values. Divided by the 1, 2, 3 and 2 of the divergence
// theorem's antiderivatives (x, x²/2, x³/3, x²y/2) they become these weights.
constexpr Real kVolumeWeight = Real(1) / Real(6);
constexpr Real kFirstMomentWeight = Real(1) / Real(24);
constexpr Real kSecondMomentWeight = Real(1) / Real(60);
constexpr Real kProductWeight = Real(1) / Real(120);

/// An off-diagonal entry smaller than this fraction of its two diagonal entries is round-off:
/// a Jacobi rotation would turn the axes by an arbitrary angle for nothing (a cube's three
/// equal moments leave the angle undetermined), so it is left alone.
constexpr Real kJacobiNegligible = Real(1e-12);
/// Sweeps over the three planes; Jacobi converges quadratically, so a 3×3 tensor needs
/// about five, and this bound is only a guard against a NaN never converging.
constexpr int kJacobiMaxSweeps = 50;

/// The sums of one coordinate over a triangle's corners w₀, w₁, w₂ that the integrals need.
struct CornerSums {
    Real f1 = 0;                    ///< w₀ + w₁ + w₂.
    Real f2 = 0;                    ///< Every product of two corners: w₀² + w₀w₁ + w₁² + w₀w₂ + w₁w₂ + w₂².
    Real f3 = 0;                    ///< Every product of three (the complete symmetric sum of degree 3).
    std::array<Real, 3> g{};        ///< gᵢ = wᵢ² + wᵢ·f₁ + f₂: ∫w²·y = Σ yᵢ·gᵢ / 60.
};

CornerSums cornerSums(Real w0, Real w1, Real w2) {
    CornerSums s;
    s.f1 = w0 + w1 + w2;
    const Real twoOfFirst = w0 * w0 + w0 * w1 + w1 * w1;  // the degree-2 sum of w₀, w₁ alone
    s.f2 = twoOfFirst + w2 * s.f1;
    s.f3 = w0 * w0 * w0 + w1 * twoOfFirst + w2 * s.f2;
    const std::array<Real, 3> w{w0, w1, w2};
    for (std::size_t i = 0; i < 3; ++i) s.g[i] = w[i] * w[i] + w[i] * s.f1 + s.f2;
    return s;
}

/// The ten volume integrals of density 1 that mass properties need.
struct VolumeIntegrals {
    Real one = 0;                   ///< ∫1 = V.
    Vec3 first{0, 0, 0};            ///< ∫x, ∫y, ∫z.
    Vec3 second{0, 0, 0};           ///< ∫x², ∫y², ∫z².
    Vec3 products{0, 0, 0};         ///< ∫xy, ∫yz, ∫zx.
};

void addTriangle(VolumeIntegrals& sum, const Vec3& p0, const Vec3& p1, const Vec3& p2) {
    const Vec3 d = glm::cross(p1 - p0, p2 - p0);  // outward normal × twice the area
    const CornerSums x = cornerSums(p0.x, p1.x, p2.x);
    const CornerSums y = cornerSums(p0.y, p1.y, p2.y);
    const CornerSums z = cornerSums(p0.z, p1.z, p2.z);
    sum.one += kVolumeWeight * d.x * x.f1;
    sum.first += kFirstMomentWeight * Vec3(d.x * x.f2, d.y * y.f2, d.z * z.f2);
    sum.second += kSecondMomentWeight * Vec3(d.x * x.f3, d.y * y.f3, d.z * z.f3);
    // ∫xy from x²y/2 through n_x, ∫yz from y²z/2 through n_y, ∫zx from z²x/2 through n_z.
    sum.products.x += kProductWeight * d.x * (p0.y * x.g[0] + p1.y * x.g[1] + p2.y * x.g[2]);
    sum.products.y += kProductWeight * d.y * (p0.z * y.g[0] + p1.z * y.g[1] + p2.z * y.g[2]);
    sum.products.z += kProductWeight * d.z * (p0.x * z.g[0] + p1.x * z.g[1] + p2.x * z.g[2]);
}

/// Volume, centroid and tensor about the centroid from the integrals.
PolyhedronMass fromIntegrals(const VolumeIntegrals& sum) {
    PolyhedronMass result;
    result.volume = sum.one;
    if (!(sum.one > 0)) return result;  // not a closed, outward-wound surface: no mass to speak of
    result.centroid = sum.first / sum.one;
    // About the origin: I_xx = ∫(y² + z²), I_xy = −∫xy, … (GLM is column-major; the tensor is symmetric).
    const Vec3& s = sum.second;
    const Vec3& p = sum.products;
    Mat3 aboutOrigin(0);
    aboutOrigin[0][0] = s.y + s.z;
    aboutOrigin[1][1] = s.z + s.x;
    aboutOrigin[2][2] = s.x + s.y;
    aboutOrigin[0][1] = aboutOrigin[1][0] = -p.x;
    aboutOrigin[1][2] = aboutOrigin[2][1] = -p.y;
    aboutOrigin[0][2] = aboutOrigin[2][0] = -p.z;
    // The parallel-axis theorem read backwards: I_origin = I_centroid + V(|c|²E − c cᵀ).
    result.inertia = parallelAxis(aboutOrigin, -sum.one, result.centroid);
    return result;
}

/// R·diag(moments)·Rᵀ as a full matrix.
Mat3 rotatedDiagonal(const Quat& rotation, const Vec3& moments) {
    const Mat3 r = glm::mat3_cast(rotation);
    Mat3 d(0);
    d[0][0] = moments.x;
    d[1][1] = moments.y;
    d[2][2] = moments.z;
    return r * d * glm::transpose(r);
}

/// A part's principal moments in its own frame (a hull part's tensor may be full: see partInertia()).
Mat3 partOwnInertia(const CompoundPart& part) {
    switch (part.shape) {
        case Shape::Sphere: return rotatedDiagonal(Quat(1, 0, 0, 0), solidSphereInertia(part.mass, part.radius));
        case Shape::Box: return rotatedDiagonal(Quat(1, 0, 0, 0), solidBoxInertia(part.mass, part.scale));
        case Shape::Capsule:
            return rotatedDiagonal(Quat(1, 0, 0, 0), solidCapsuleInertia(part.mass, part.radius, part.height));
        case Shape::Cylinder:
            return rotatedDiagonal(Quat(1, 0, 0, 0), solidCylinderInertia(part.mass, part.radius, part.height));
        case Shape::Hull: {
            if (!part.hull) throw std::invalid_argument("a compound's Hull part has no hull");
            const PolyhedronMass unit = polyhedronMassProperties(*part.hull);
            // Moved to the part's own centroid; ρ = m / V turns the unit-density tensor into kg·m².
            return (part.mass / unit.volume) * unit.inertia;
        }
        case Shape::Compound:
        case Shape::Mesh: break;
    }
    throw std::invalid_argument(std::string("a compound's part cannot be a ") + toString(part.shape));
}

/// Centre of a hull part relative to its own origin (0 for every other shape, which are centred by definition).
Vec3 partOwnCentroid(const CompoundPart& part) {
    if (part.shape != Shape::Hull || !part.hull) return Vec3(0);
    return polyhedronMassProperties(*part.hull).centroid;
}

}  // namespace

Real sphereVolume(Real radius) { return kBallVolumeFactor * radius * radius * radius; }

Real boxVolume(const Vec3& size) { return size.x * size.y * size.z; }

Real capsuleVolume(Real radius, Real height) { return cylinderVolume(radius, height) + sphereVolume(radius); }

Real cylinderVolume(Real radius, Real height) { return kPi * radius * radius * height; }

Vec3 solidCapsuleInertia(Real mass, Real radius, Real height) {
    const Real density = mass / capsuleVolume(radius, height);
    const Real cylinderMass = density * cylinderVolume(radius, height);
    const Real hemisphereMass = density * sphereVolume(radius) / 2;
    const Real r2 = radius * radius;
    const Real axial = kCylinderAxialFactor * cylinderMass * r2 + 2 * kBallMomentFactor * hemisphereMass * r2;
    const Real toOwnCentre = kHemisphereCentroid * radius;          // flat face → hemisphere's centre of mass
    const Real toCapsuleCentre = height / 2 + toOwnCentre;          // capsule's centre → hemisphere's
    const Real hemisphere = kBallMomentFactor * r2 - toOwnCentre * toOwnCentre + toCapsuleCentre * toCapsuleCentre;
    const Real transverse = cylinderMass * kCylinderTransverseFactor * (3 * r2 + height * height) +
                            2 * hemisphereMass * hemisphere;
    return Vec3(transverse, axial, transverse);
}

Vec3 solidCylinderInertia(Real mass, Real radius, Real height) {
    const Real axial = kCylinderAxialFactor * mass * radius * radius;
    const Real transverse = kCylinderTransverseFactor * mass * (3 * radius * radius + height * height);
    return Vec3(transverse, axial, transverse);
}

PolyhedronMass polyhedronMassProperties(std::span<const Vec3> vertices,
                                        std::span<const std::array<std::uint32_t, 3>> triangles) {
    VolumeIntegrals sum;
    for (const auto& t : triangles) addTriangle(sum, vertices[t[0]], vertices[t[1]], vertices[t[2]]);
    return fromIntegrals(sum);
}

PolyhedronMass polyhedronMassProperties(const ConvexHull& hull) {
    VolumeIntegrals sum;
    for (const HullFace& face : hull.faces) {
        // A convex polygon is the fan (v₀, vₖ, vₖ₊₁): same winding, same outward normal.
        const Vec3& v0 = hull.vertices[hull.faceIndices[face.firstIndex]];
        for (std::uint32_t k = 1; k + 1 < face.indexCount; ++k) {
            addTriangle(sum, v0, hull.vertices[hull.faceIndices[face.firstIndex + k]],
                        hull.vertices[hull.faceIndices[face.firstIndex + k + 1]]);
        }
    }
    return fromIntegrals(sum);
}

PrincipalAxes principalAxes(const Mat3& tensor) {
    // a is the tensor in the current axes, v the axes so far (its columns): a = vᵀ·I·v throughout.
    Mat3 a = tensor;
    Mat3 v(1);
    constexpr int kPlanes[3][2] = {{0, 1}, {0, 2}, {1, 2}};
    for (int sweep = 0; sweep < kJacobiMaxSweeps; ++sweep) {
        bool rotated = false;
        for (const auto& plane : kPlanes) {
            const int p = plane[0];
            const int q = plane[1];
            const Real apq = a[q][p];
            if (!(std::abs(apq) > kJacobiNegligible * (std::abs(a[p][p]) + std::abs(a[q][q])))) continue;
            // tan 2θ = 2·a_pq / (a_qq − a_pp); t = tan θ, the smaller root, keeps the turn under 45°.
            const Real tau = (a[q][q] - a[p][p]) / (2 * apq);
            const Real t = (tau >= 0 ? Real(1) : Real(-1)) / (std::abs(tau) + std::sqrt(1 + tau * tau));
            const Real c = 1 / std::sqrt(1 + t * t);
            const Real s = t * c;
            Mat3 j(1);  // the rotation in the (p, q) plane: column p is (c, −s), column q is (s, c)
            j[p][p] = c;
            j[q][q] = c;
            j[p][q] = -s;
            j[q][p] = s;
            a = glm::transpose(j) * a * j;
            v = v * j;
            rotated = true;
        }
        if (!rotated) break;
    }
    if (glm::determinant(v) < 0) v[2] = -v[2];  // a reflection is not a pose: flip the third axis
    PrincipalAxes result;
    result.moments = Vec3(a[0][0], a[1][1], a[2][2]);
    result.rotation = glm::normalize(glm::quat_cast(v));
    return result;
}

BodyFrame moveToPrincipalFrame(ConvexHull& hull) {
    const PolyhedronMass unit = polyhedronMassProperties(hull);
    BodyFrame frame;
    frame.centre = unit.centroid;
    frame.axes = principalAxes(unit.inertia).rotation;
    const Quat toPrincipal = glm::conjugate(frame.axes);
    hull.boundingRadius = 0;
    for (Vec3& vertex : hull.vertices) {
        vertex = toPrincipal * (vertex - frame.centre);
        hull.boundingRadius = std::max(hull.boundingRadius, glm::length(vertex));
    }
    for (HullFace& face : hull.faces) {
        // dot(n, v) ≤ d with v = c + R·v' gives dot(Rᵀn, v') ≤ d − dot(n, c).
        face.offset -= glm::dot(face.normal, frame.centre);
        face.normal = toPrincipal * face.normal;
    }
    hull.volume = unit.volume;
    return frame;
}

Real partVolume(const CompoundPart& part) {
    switch (part.shape) {
        case Shape::Sphere: return sphereVolume(part.radius);
        case Shape::Box: return boxVolume(part.scale);
        case Shape::Capsule: return capsuleVolume(part.radius, part.height);
        case Shape::Cylinder: return cylinderVolume(part.radius, part.height);
        case Shape::Hull: return part.hull ? part.hull->volume : 0;
        case Shape::Compound:
        case Shape::Mesh: break;
    }
    throw std::invalid_argument(std::string("a compound's part cannot be a ") + toString(part.shape));
}

Mat3 partInertia(const CompoundPart& part) {
    const Mat3 r = glm::mat3_cast(part.orientation);
    return r * partOwnInertia(part) * glm::transpose(r);
}

CompoundMass compoundMassProperties(const CompoundShape& compound) {
    CompoundMass result;
    std::vector<Vec3> centres;  // each part's centre of mass, body frame (a hull's centroid may be off its origin)
    centres.reserve(compound.parts.size());
    for (const CompoundPart& part : compound.parts) {
        centres.push_back(part.position + part.orientation * partOwnCentroid(part));
        result.mass += part.mass;
        result.centre += part.mass * centres.back();
    }
    if (!(result.mass > 0)) return result;
    result.centre /= result.mass;
    for (std::size_t i = 0; i < compound.parts.size(); ++i) {
        const CompoundPart& part = compound.parts[i];
        result.inertia += parallelAxis(partInertia(part), part.mass, centres[i] - result.centre);
    }
    return result;
}

BodyFrame moveToPrincipalFrame(CompoundShape& compound) {
    const CompoundMass mass = compoundMassProperties(compound);
    BodyFrame frame;
    frame.centre = mass.centre;
    frame.axes = principalAxes(mass.inertia).rotation;
    const Quat toPrincipal = glm::conjugate(frame.axes);
    compound.boundingRadius = 0;
    for (CompoundPart& part : compound.parts) {
        part.position = toPrincipal * (part.position - frame.centre);
        part.orientation = glm::normalize(toPrincipal * part.orientation);
        compound.boundingRadius = std::max(compound.boundingRadius, partReach(part));
    }
    return frame;
}

Real partReach(const CompoundPart& part) {
    const Real centre = glm::length(part.position);
    switch (part.shape) {
        case Shape::Sphere: return centre + part.radius;
        case Shape::Box: return centre + glm::length(part.scale) / 2;
        case Shape::Capsule: return centre + part.height / 2 + part.radius;
        case Shape::Cylinder: return centre + std::hypot(part.radius, part.height / 2);
        case Shape::Hull: {
            if (!part.hull) return centre;
            // The part's own origin need not be its centroid: measure every vertex.
            Real reach = 0;
            for (const Vec3& v : part.hull->vertices) {
                reach = std::max(reach, glm::length(part.position + part.orientation * v));
            }
            return reach;
        }
        case Shape::Compound:
        case Shape::Mesh: break;
    }
    return centre;
}

Real shapeVolume(const DynamicObject& body) {
    switch (body.shape) {
        case Shape::Sphere: return sphereVolume(body.radius);
        case Shape::Box: return boxVolume(body.scale);
        case Shape::Capsule: return capsuleVolume(body.radius, body.height);
        case Shape::Cylinder: return cylinderVolume(body.radius, body.height);
        case Shape::Hull:
            if (!body.hull) throw std::invalid_argument("DynamicObject '" + body.name + "' is a Hull without a hull");
            return body.hull->volume;
        case Shape::Compound: {
            if (!body.compound) throw std::invalid_argument("DynamicObject '" + body.name + "' is a Compound without parts");
            Real volume = 0;
            for (const CompoundPart& part : body.compound->parts) volume += partVolume(part);
            return volume;
        }
        case Shape::Mesh: break;
    }
    throw std::invalid_argument("DynamicObject '" + body.name + "' is a Mesh: a triangle mesh has no volume");
}

Vec3 shapeInertia(const DynamicObject& body) {
    switch (body.shape) {
        case Shape::Sphere:
            return body.hollow ? hollowSphereInertia(body.mass, body.radius) : solidSphereInertia(body.mass, body.radius);
        case Shape::Box: return solidBoxInertia(body.mass, body.scale);
        case Shape::Capsule: return solidCapsuleInertia(body.mass, body.radius, body.height);
        case Shape::Cylinder: return solidCylinderInertia(body.mass, body.radius, body.height);
        case Shape::Hull: {
            if (!body.hull) throw std::invalid_argument("DynamicObject '" + body.name + "' is a Hull without a hull");
            const PolyhedronMass unit = polyhedronMassProperties(*body.hull);
            // In the principal frame the tensor is diagonal up to round-off: its diagonal is the moments.
            const Real density = body.mass / unit.volume;
            return density * Vec3(unit.inertia[0][0], unit.inertia[1][1], unit.inertia[2][2]);
        }
        case Shape::Compound: {
            if (!body.compound || body.compound->parts.empty()) {
                throw std::invalid_argument("DynamicObject '" + body.name + "' is a Compound without parts");
            }
            const CompoundMass sum = compoundMassProperties(*body.compound);
            // The parts' masses are the body's, shared out; should the body's mass be changed
            // afterwards, every part's share scales with it.
            const Real scale = body.mass / sum.mass;
            return scale * Vec3(sum.inertia[0][0], sum.inertia[1][1], sum.inertia[2][2]);
        }
        case Shape::Mesh: break;
    }
    throw std::invalid_argument("DynamicObject '" + body.name +
                                "' is a Mesh: a triangle mesh has no inside, so no mass; meshes are for "
                                "KinematicsObjects");
}

}  // namespace stepwise
