/// @file exact_solutions.cpp
/// @brief Closed-form and Runge–Kutta references for the reference problems.
#include "exact_solutions.hpp"

#include <cmath>
#include <stdexcept>

namespace stepwise::bench {

namespace {

constexpr double kTwoPi = 2 * 3.14159265358979323846;
/// Newton's method on Kepler's equation stops when ΔE changes by less than this, rad.
constexpr double kKeplerTolerance = 1e-15;
/// ... or after this many iterations (it converges in a handful for e < 0.9).
constexpr int kKeplerMaxIterations = 50;
/// The AGM stops when a and b agree to this relative difference (double precision).
constexpr double kAgmTolerance = 1e-15;
/// ... or after this many iterations (quadratic convergence: 5 suffice below k = 0.99).
constexpr int kAgmMaxIterations = 30;

}  // namespace

double completeEllipticK(double k) {
    if (!(k >= 0 && k < 1)) throw std::invalid_argument("completeEllipticK: k must be in [0, 1)");
    double a = 1, b = std::sqrt(1 - k * k);
    for (int i = 0; i < kAgmMaxIterations && std::abs(a - b) > kAgmTolerance * a; ++i) {
        const double mean = 0.5 * (a + b);
        b = std::sqrt(a * b);
        a = mean;
    }
    return 0.5 * kTwoPi / (2 * a);  // π / (2·AGM)
}

double pendulumPeriod(double length, double g, double theta0) {
    return 4 * std::sqrt(length / g) * completeEllipticK(std::sin(0.5 * theta0));
}

PointState projectileAt(const PointState& start, const DVec3& gravity, double t) {
    return {start.position + start.velocity * t + 0.5 * gravity * t * t, start.velocity + gravity * t};
}

std::pair<double, double> oscillatorAt(double u0, double rate0, double omega, double t) {
    const double c = std::cos(omega * t), s = std::sin(omega * t);
    return {u0 * c + rate0 / omega * s, -u0 * omega * s + rate0 * c};
}

KeplerOrbit::KeplerOrbit(const PointState& start, double mu) : start_(start), mu_(mu) {
    const double r0 = glm::length(start.position);
    const double inverseA = 2 / r0 - glm::dot(start.velocity, start.velocity) / mu;  // vis-viva: 1/a = 2/r − v²/μ
    if (!(inverseA > 0)) throw std::invalid_argument("KeplerOrbit: the orbit is not bound (energy >= 0)");
    a_ = 1 / inverseA;
}

double KeplerOrbit::period() const { return kTwoPi * std::sqrt(a_ * a_ * a_ / mu_); }

double KeplerOrbit::specificEnergy() const {
    return 0.5 * glm::dot(start_.velocity, start_.velocity) - mu_ / glm::length(start_.position);
}

double KeplerOrbit::eccentricity() const {
    // e = ((v² − μ/r)·r − (r·v)·v)/μ, the Laplace–Runge–Lenz vector over μ.
    const DVec3& r = start_.position;
    const DVec3& v = start_.velocity;
    const DVec3 e = ((glm::dot(v, v) - mu_ / glm::length(r)) * r - glm::dot(r, v) * v) / mu_;
    return glm::length(e);
}

PointState KeplerOrbit::at(double t) const {
    const DVec3& r0v = start_.position;
    const DVec3& v0v = start_.velocity;
    const double r0 = glm::length(r0v);
    const double sigma0 = glm::dot(r0v, v0v) / std::sqrt(mu_);
    const double sqrtA = std::sqrt(a_);
    const double meanMotion = std::sqrt(mu_ / (a_ * a_ * a_));
    // Whole orbits change nothing: reduce the mean anomaly to [0, 2π) so Newton starts close.
    const double meanAnomaly = std::fmod(meanMotion * t, kTwoPi);

    double dE = meanAnomaly;
    for (int i = 0; i < kKeplerMaxIterations; ++i) {
        const double f = dE - (1 - r0 / a_) * std::sin(dE) + sigma0 / sqrtA * (1 - std::cos(dE)) - meanAnomaly;
        const double df = 1 - (1 - r0 / a_) * std::cos(dE) + sigma0 / sqrtA * std::sin(dE);  // = r/a > 0
        const double step = f / df;
        dE -= step;
        if (std::abs(step) < kKeplerTolerance) break;
    }
    const double s = std::sin(dE), c = std::cos(dE);
    const double r = a_ + (r0 - a_) * c + sigma0 * sqrtA * s;
    const double f = 1 - a_ / r0 * (1 - c);
    const double g = meanAnomaly / meanMotion + std::sqrt(a_ * a_ * a_ / mu_) * (s - dE);
    const double fDot = -std::sqrt(mu_ * a_) / (r * r0) * s;
    const double gDot = 1 - a_ / r * (1 - c);
    return {f * r0v + g * v0v, fDot * r0v + gDot * v0v};
}

std::vector<double> flipTimes(const DVec3& moments, const DVec3& omegaBody, int axis, double duration, double dt) {
    // Euler's equations, torque-free: I·ω̇ = (I·ω) × ω, i.e. ω̇ = ((I·ω) × ω)/I componentwise.
    const auto rate = [&](const DVec3& w) { return glm::cross(moments * w, w) / moments; };
    std::vector<double> times;
    DVec3 w = omegaBody;
    const long steps = std::lround(duration / dt);
    for (long i = 0; i < steps; ++i) {
        const DVec3 k1 = rate(w);
        const DVec3 k2 = rate(w + 0.5 * dt * k1);
        const DVec3 k3 = rate(w + 0.5 * dt * k2);
        const DVec3 k4 = rate(w + dt * k3);
        const DVec3 next = w + dt / 6 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
        // The body-frame momentum I·ω has the sign of ω on each axis (I > 0).
        if ((next[axis] < 0) != (w[axis] < 0)) times.push_back(double(i) * dt + dt * w[axis] / (w[axis] - next[axis]));
        w = next;
    }
    return times;
}

}  // namespace stepwise::bench
