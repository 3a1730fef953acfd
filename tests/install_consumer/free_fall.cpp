// A ball dropped from rest for 1 s, simulated by the installed engine and checked against physics.
//
// Under constant gravity g the exact fall is y(t) = y0 − g·t²/2. Symplectic Euler updates the
// velocity first, v ← v − g·h, then the position with the new velocity, y ← y + h·v, so after
// N steps of h
//     v_N = −g·N·h = −g·t                      (exact: the velocity of a constant acceleration)
//     y_N = y0 − g·h²·(1 + 2 + … + N) = y0 − g·t²/2 − g·h·t/2,
// the ball leads the exact fall by g·h·t/2 (8.2 cm at h = 1/60 s, t = 1 s). The program prints
// what it measured and exits 0 when the engine is within that error, 1 when not.
#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>

#include "config/scene_loader.hpp"
#include "world/world.hpp"

int main() {
    using stepwise::Real;
    constexpr double g = 9.81, h = 1.0 / 60, y0 = 10, t = 1;
    constexpr int steps = 60;  // t / h
    // Solver=Impulse: the integrator takes whole steps of h (the sequential impulse would take
    // substeps of h/16, and its error would be a sixteenth of the one above).
    const char* sceneText =
        "World, Gravity=(0, -9.81, 0), TimeStep=1/60, Integrator=SymplecticEuler, Solver=Impulse\n"
        "DynamicObject, Name=ball, Position=(0, 10, 0), Radius=0.1\n";
    try {
        stepwise::World world(stepwise::parseScene(sceneText, "free_fall"));
        for (int i = 0; i < steps; ++i) world.step();
        const stepwise::DynamicObject* ball = world.findDynamic("ball");
        if (ball == nullptr) {
            std::printf("free_fall: FAIL: the World has no body named ball\n");
            return 1;
        }
        // Round-off: each of the steps may lose a few units in the last place of y0.
        const double roundOff = 10.0 * steps * y0 * double(std::numeric_limits<Real>::epsilon());
        const double y = double(ball->position.y), v = double(ball->velocity.y);
        const double error = std::abs(y - (y0 - g * t * t / 2));
        const double bound = g * h * t / 2;
        const bool timeOk = std::abs(double(world.time()) - t) <= roundOff;
        const bool positionOk = error <= bound + roundOff;
        const bool velocityOk = std::abs(v - (-g * t)) <= roundOff;
        // The headers were compiled here, the library where the engine was built: they must agree on
        // the definitions that change what the headers mean. The scene loader's default (the
        // library's) and a WorldSettings made here (this program's) must pick the same road.
        const bool definitionsOk = world.settings().fastPath == stepwise::WorldSettings{}.fastPath;
        std::printf("free_fall: t = %.6f s (expected %g s): %s\n", double(world.time()), t, timeOk ? "ok" : "FAIL");
        std::printf("free_fall: y = %.9f m, exact y0 - g t^2/2 = %.9f m, error %.6f m <= g h t/2 = %.6f m: %s\n", y,
                    y0 - g * t * t / 2, error, bound, positionOk ? "ok" : "FAIL");
        std::printf("free_fall: v = %.9f m/s, exact -g t = %.9f m/s: %s\n", v, -g * t, velocityOk ? "ok" : "FAIL");
        std::printf("free_fall: sizeof(Real) = %zu, fast path by default: library %s, headers %s: %s\n", sizeof(Real),
                    world.settings().fastPath ? "on" : "off", stepwise::WorldSettings{}.fastPath ? "on" : "off",
                    definitionsOk ? "ok" : "FAIL");
        const bool pass = timeOk && positionOk && velocityOk && definitionsOk;
        std::printf("free_fall: %s\n", pass ? "PASS" : "FAIL");
        return pass ? 0 : 1;
    } catch (const std::exception& error) {
        std::printf("free_fall: FAIL: %s\n", error.what());
        return 1;
    }
}
