/// @file bullet_world.hpp
/// @brief The same scene in Bullet 3: a btDiscreteDynamicsWorld built from a Stepwise Scene.
///
/// Only the benchmark uses Bullet (`stepwise-bench bullet`, built with
/// -DSTEPWISE_WITH_BULLET=ON); the engine never does. The translation keeps
/// Bullet's own defaults wherever the scene says nothing, so the comparison is
/// with Bullet as people use it (docs/benchmarks.md, "Side by side with Bullet"):
///
/// | scene                     | Bullet                                                                 |
/// |---------------------------|------------------------------------------------------------------------|
/// | DynamicObject, Sphere     | btSphereShape(radius), one shape shared by every sphere of that radius |
/// | DynamicObject, Box        | btBoxShape(scale/2) (default collision margin 0.04 m, inside the box)  |
/// | CollisionPlane            | btStaticPlaneShape(n, n·p) on a static body                            |
/// | Mass, inertia             | setMassProps(m, I) with Stepwise's principal moments (hollow spheres too) |
/// | Elasticity, Friction      | setRestitution, setFriction: Bullet combines both by product, as Stepwise |
/// | World TimeStep, Gravity   | stepSimulation(h, 1, h): exactly one fixed step per call; setGravity    |
/// | World Sleep=false         | DISABLE_DEACTIVATION on every body; Sleep=true keeps Bullet's default sleeping |
/// | Spring                    | its force, F = (k·(l − L₀) + c·(v_B − v_A)·n)·n, applied at the anchors before each step |
/// | Attractor                 | its pull, m·a with a = −μ·r/\|r\|³ (attractorAcceleration()), at the centre before each step |
/// | DistanceJoint from a body's centre to a fixed point | btPoint2PointConstraint at the fixed point: the body turns with the rod |
/// | KinematicsObject, Box, no velocity | a static body (mass 0) of btBoxShape(scale/2): a level's floor and walls |
/// | BallJoint                 | btPoint2PointConstraint at the anchor (to the world when there is no BodyB) |
/// | HingeJoint (no motor)     | btHingeConstraint about the axis at the anchor; LowerAngle, UpperAngle as setLimit (Bullet's default softness) |
/// | CollideConnected=false    | addConstraint(…, disableCollisionsBetweenLinkedBodies = true)          |
///
/// Bullet has no force generators: its manual's way to add a force is a
/// callback before each internal step (setInternalTickCallback(…, true)) that
/// calls applyForce, which is what springs and attractors get here. Bullet
/// then integrates every force as Stepwise's SymplecticEuler does: v += h·F/m,
/// then x += h·v. Bullet has no distance joint either; a pin at the pivot is
/// the pendulum its users build, and it makes the bob turn with the rod (a
/// compound pendulum: preparePendulumTurningBob() in bench/reference_problems.hpp
/// judges it against its own exact period).
///
/// Everything else is Bullet's default: btDbvtBroadphase, btSequentialImpulseConstraintSolver
/// with 10 iterations, split impulse on, ERP 0.2, no continuous collision detection,
/// implicit gyroscopic term on. Moving kinematic bodies, other joints (ropes,
/// motors, breakable joints) and per-body accelerations are not translated
/// (the constructor throws, naming the record).
#pragma once

#include <LinearMath/btScalar.h>

#include <memory>
#include <vector>

#include "../scenario_metrics.hpp"
#include "world/scene.hpp"

class btCollisionShape;
class btDefaultCollisionConfiguration;
class btCollisionDispatcher;
class btBroadphaseInterface;
class btSequentialImpulseConstraintSolver;
class btDiscreteDynamicsWorld;
class btRigidBody;
class btDefaultMotionState;
class btDynamicsWorld;
class btTypedConstraint;

namespace stepwise::bench {

/// @brief A Bullet world holding the bodies and planes of a Stepwise scene.
class BulletWorld {
public:
    /// @brief Builds the Bullet world from @p scene (as loaded from its file).
    /// @throws std::invalid_argument when the scene holds something not translated (see the file comment).
    explicit BulletWorld(const Scene& scene);
    ~BulletWorld();
    BulletWorld(const BulletWorld&) = delete;
    BulletWorld& operator=(const BulletWorld&) = delete;

    /// @brief One fixed step of the scene's time step.
    void step();
    /// @brief Copies the dynamic bodies' states into @p out, in the scene's order.
    void states(std::vector<BodyState>& out) const;
    /// @brief Number of dynamic bodies.
    std::size_t bodyCount() const { return dynamics_.size(); }
    /// @brief Bodies Bullet has put to sleep (ISLAND_SLEEPING) now.
    std::size_t sleepingCount() const;
    /// @brief Contact manifolds Bullet keeps now (each up to 4 points).
    int manifoldCount() const;
    /// @brief Sets the sequential-impulse solver's iterations per step (Bullet's default: 10).
    void setSolverIterations(int iterations);
    /// @brief The sequential-impulse solver's iterations per step.
    int solverIterations() const;

private:
    /// Translates one joint record (the table above), or throws naming it.
    void addJoint(const Scene& scene, const JointDef& joint);
    /// A btHingeConstraint for @p joint between @p a and @p b (nullptr: the world), limits included.
    static std::unique_ptr<btTypedConstraint> hinge(const JointDef& joint, btRigidBody& a, btRigidBody* b);
    /// Bullet's pre-step callback: adds the springs' and attractors' forces for the step about to run.
    static void applyForces(btDynamicsWorld* world, btScalar timeStep);

    double timeStep_;
    std::unique_ptr<btDefaultCollisionConfiguration> configuration_;
    std::unique_ptr<btCollisionDispatcher> dispatcher_;
    std::unique_ptr<btBroadphaseInterface> broadphase_;
    std::unique_ptr<btSequentialImpulseConstraintSolver> solver_;
    std::unique_ptr<btDiscreteDynamicsWorld> world_;
    std::vector<std::unique_ptr<btCollisionShape>> shapes_;
    std::vector<std::unique_ptr<btDefaultMotionState>> motionStates_;
    std::vector<std::unique_ptr<btRigidBody>> dynamics_;  ///< In the scene's order.
    std::vector<std::unique_ptr<btRigidBody>> statics_;   ///< The planes and static boxes.
    std::vector<Vec3> inertiaBody_;                       ///< Principal moments, for L = I_world·ω.
    std::vector<Spring> springs_;                         ///< The scene's, as it gives them.
    std::vector<Attractor> attractors_;                   ///< The scene's, as it gives them.
    std::vector<std::unique_ptr<btTypedConstraint>> joints_;
};

}  // namespace stepwise::bench
