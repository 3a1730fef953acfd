/// @file scenario_metrics.cpp
/// @brief The meters of scenario_metrics.hpp.
#include "scenario_metrics.hpp"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <numeric>
#include <cmath>
#include <limits>

namespace stepwise::bench {

namespace {

/// The grid never has more cells than this along an axis: a sphere thrown far
/// away makes the cells coarser (slower), never the grid huge.
constexpr std::int64_t kMaxCellsPerAxis = 512;

glm::dvec3 d(const Vec3& v) { return {double(v.x), double(v.y), double(v.z)}; }

}  // namespace

Scene onOneThread(Scene scene) {
    scene.settings.threads = 1;
    return scene;
}

void statesOf(const World& world, std::vector<BodyState>& out) {
    out.resize(world.dynamics().size());
    for (std::size_t n = 0; n < out.size(); ++n) {
        const DynamicObject& body = world.dynamics()[n];
        out[n] = {body.position, body.orientation, body.velocity, body.angularVelocity, body.angularMomentum};
    }
}

RainMeter::RainMeter(std::vector<CollisionPlane> planes, Real radius, std::vector<OrientedBox> walls)
    : planes_(std::move(planes)), walls_(std::move(walls)), radius_(radius) {}

void RainMeter::observe(std::span<const BodyState> bodies) {
    if (bodies.empty()) return;
    for (const BodyState& b : bodies) {
        for (const CollisionPlane& plane : planes_) {
            worstOverlap_ = std::max(worstOverlap_, radius_ - plane.signedDistance(b.position));
        }
        for (const OrientedBox& wall : walls_) {
            worstOverlap_ = std::max(worstOverlap_, sphereBoxOverlap(b.position, radius_, wall));
        }
    }
    // Counting sort of the bodies into cells of at least 2r: two overlapping
    // spheres are then in the same or neighbouring cells.
    Vec3 lo = bodies[0].position, hi = bodies[0].position;
    for (const BodyState& b : bodies) {
        lo = glm::min(lo, b.position);
        hi = glm::max(hi, b.position);
    }
    const Vec3 extent = hi - lo;
    const Real largest = std::max({extent.x, extent.y, extent.z});
    const Real cell = std::max(2 * radius_, largest / Real(kMaxCellsPerAxis - 1));
    const auto cellsAlong = [&](Real length) { return std::int64_t(length / cell) + 1; };
    const std::int64_t nx = cellsAlong(extent.x), ny = cellsAlong(extent.y), nz = cellsAlong(extent.z);
    const auto index = [&](std::int64_t i, std::int64_t j, std::int64_t k) {
        return static_cast<std::uint32_t>((i * ny + j) * nz + k);
    };
    const auto cellCoords = [&](const Vec3& p) {
        return glm::i64vec3(std::int64_t((p.x - lo.x) / cell), std::int64_t((p.y - lo.y) / cell),
                            std::int64_t((p.z - lo.z) / cell));
    };
    cellOf_.resize(bodies.size());
    cellStart_.assign(static_cast<std::size_t>(nx * ny * nz) + 1, 0);
    for (std::size_t n = 0; n < bodies.size(); ++n) {
        const glm::i64vec3 c = cellCoords(bodies[n].position);
        cellOf_[n] = index(c.x, c.y, c.z);
        ++cellStart_[cellOf_[n] + 1];
    }
    for (std::size_t c = 1; c < cellStart_.size(); ++c) cellStart_[c] += cellStart_[c - 1];
    order_.resize(bodies.size());
    fill_.assign(cellStart_.begin(), cellStart_.end() - 1);
    for (std::size_t n = 0; n < bodies.size(); ++n) order_[fill_[cellOf_[n]]++] = static_cast<std::uint32_t>(n);
    const Real touching = 2 * radius_;
    for (std::size_t n = 0; n < bodies.size(); ++n) {
        const Vec3& p = bodies[n].position;
        const glm::i64vec3 c = cellCoords(p);
        for (std::int64_t i = std::max<std::int64_t>(c.x - 1, 0); i <= std::min(c.x + 1, nx - 1); ++i) {
            for (std::int64_t j = std::max<std::int64_t>(c.y - 1, 0); j <= std::min(c.y + 1, ny - 1); ++j) {
                for (std::int64_t k = std::max<std::int64_t>(c.z - 1, 0); k <= std::min(c.z + 1, nz - 1); ++k) {
                    const std::uint32_t cellIndex = index(i, j, k);
                    for (std::uint32_t e = cellStart_[cellIndex]; e < cellStart_[cellIndex + 1]; ++e) {
                        const std::uint32_t other = order_[e];
                        if (other <= n) continue;  // each pair once
                        const Real distance = glm::length(bodies[other].position - p);
                        worstOverlap_ = std::max(worstOverlap_, touching - distance);
                    }
                }
            }
        }
    }
}

std::size_t RainMeter::escaped(std::span<const BodyState> bodies) const {
    return static_cast<std::size_t>(std::count_if(bodies.begin(), bodies.end(), [&](const BodyState& b) {
        return std::any_of(planes_.begin(), planes_.end(),
                           [&](const CollisionPlane& plane) { return plane.signedDistance(b.position) < 0; }) ||
               outsideLevel(b.position, walls_);
    }));
}

StackMeter::StackMeter(std::span<const BodyState> initial) {
    start_.reserve(initial.size());
    for (const BodyState& b : initial) start_.push_back(b.position);
}

void StackMeter::observe(std::span<const BodyState> bodies, Real time) {
    for (std::size_t n = 0; n < bodies.size() && n < start_.size(); ++n) {
        const Real moved = glm::length(bodies[n].position - start_[n]);
        worstDrift_ = std::max(worstDrift_, moved);
        if (!fallTime_ && moved > kFallenDistance) fallTime_ = time;
    }
}

FreeBodyMeter::FreeBodyMeter(const BodyState& initial)
    : l0_(d(initial.angularMomentum)), e0_(0.5 * glm::dot(d(initial.angularVelocity), d(initial.angularMomentum))) {}

void FreeBodyMeter::observe(const BodyState& body) {
    const glm::dvec3 l = d(body.angularMomentum);
    const double e = 0.5 * glm::dot(d(body.angularVelocity), l);
    lastMomentum_ = glm::length(l - l0_) / glm::length(l0_);
    lastEnergy_ = (e - e0_) / e0_;
    worstMomentum_ = std::max(worstMomentum_, lastMomentum_);
    worstEnergy_ = std::max(worstEnergy_, std::abs(lastEnergy_));
}

BounceMeter::BounceMeter(Real floorHeight, Real radius) : floor_(floorHeight), radius_(radius) {}

void BounceMeter::observe(const BodyState& ball) {
    const Real vy = ball.velocity.y;
    const Real height = ball.position.y - radius_ - floor_;
    if (previousVy_ < 0 && vy > 0) {  // a bounce: the flight up starts
        rising_ = true;
        highest_ = height;
    }
    if (rising_) highest_ = std::max(highest_, height);
    if (rising_ && vy <= 0) {  // past the top
        rising_ = false;
        if (highest_ >= kSmallestApex) apexes_.push_back(highest_);
    }
    previousVy_ = vy;
}

Vec3 downSlope(const CollisionPlane& slope, const Vec3& gravity) {
    const Vec3 along = gravity - glm::dot(gravity, slope.normal) * slope.normal;
    return glm::normalize(along);
}

Real inclineAcceleration(const DynamicObject& body, const CollisionPlane& slope, const Vec3& gravity) {
    const Real g = glm::length(gravity);
    const Real cosTheta = -glm::dot(gravity, slope.normal) / g;
    const Real sinTheta = std::sqrt(std::max(Real(0), 1 - cosTheta * cosTheta));
    const Real mu = body.friction * slope.friction;  // the product rule, docs/config-format.md
    const Real sliding = g * (sinTheta - mu * cosTheta);
    if (body.shape == Shape::Sphere) {
        // k = I/(m·r²): 2/5 for a solid ball, 2/3 for a thin shell.
        const Real k = body.hollow ? Real(2) / Real(3) : Real(2) / Real(5);
        if (mu * cosTheta >= k / (1 + k) * sinTheta) return g * sinTheta / (1 + k);
        return sliding;
    }
    return std::max(Real(0), sliding);
}

double median(std::vector<double>& values) {
    if (values.empty()) return 0;
    const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

namespace {

double cpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

double wallSeconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

StepTimer::StepTimer(std::size_t steps) {
    cpu_.reserve(steps);
    wall_.reserve(steps);
}

void StepTimer::start() {
    wallStart_ = wallSeconds();
    cpuStart_ = cpuSeconds();
}

void StepTimer::stop() {
    cpu_.push_back(cpuSeconds() - cpuStart_);
    wall_.push_back(wallSeconds() - wallStart_);
}

double StepTimer::medianCpu() { return median(cpu_); }
double StepTimer::medianWall() { return median(wall_); }
double StepTimer::meanCpu() const {
    return cpu_.empty() ? 0 : std::accumulate(cpu_.begin(), cpu_.end(), 0.0) / double(cpu_.size());
}

}  // namespace stepwise::bench
