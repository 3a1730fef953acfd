/// @file bullet_world.cpp
/// @brief Builds and steps the Bullet world of a Stepwise scene (bullet_world.hpp says how it maps).
#include "bullet_world.hpp"

#include <btBulletDynamicsCommon.h>

#include <map>
#include <stdexcept>
#include <utility>

#include "dynamics/inertia.hpp"

namespace stepwise::bench {

namespace {

btVector3 bt(const Vec3& v) { return {btScalar(v.x), btScalar(v.y), btScalar(v.z)}; }
Vec3 toVec3(const btVector3& v) { return {Real(v.x()), Real(v.y()), Real(v.z())}; }

}  // namespace

BulletWorld::BulletWorld(const Scene& scene) : timeStep_(double(scene.settings.timeStep)) {
    if (!scene.kinematics.empty() || !scene.springs.empty() || !scene.joints.empty() || !scene.attractors.empty()) {
        throw std::invalid_argument(scene.sourcePath +
                                    ": the Bullet side translates dynamic bodies and planes only (no kinematic "
                                    "bodies, springs, joints or attractors)");
    }
    configuration_ = std::make_unique<btDefaultCollisionConfiguration>();
    dispatcher_ = std::make_unique<btCollisionDispatcher>(configuration_.get());
    broadphase_ = std::make_unique<btDbvtBroadphase>();
    solver_ = std::make_unique<btSequentialImpulseConstraintSolver>();
    world_ = std::make_unique<btDiscreteDynamicsWorld>(dispatcher_.get(), broadphase_.get(), solver_.get(),
                                                       configuration_.get());
    world_->setGravity(bt(scene.settings.gravity));

    // One shape per distinct size, shared by the bodies of that size (what Bullet's manual advises).
    std::map<std::pair<int, std::tuple<Real, Real, Real>>, btCollisionShape*> shapeOf;
    const auto shapeFor = [&](const DynamicObject& body) {
        const bool sphere = body.shape == Shape::Sphere;
        const auto key = sphere ? std::make_pair(0, std::make_tuple(body.radius, Real(0), Real(0)))
                                : std::make_pair(1, std::make_tuple(body.scale.x, body.scale.y, body.scale.z));
        auto found = shapeOf.find(key);
        if (found != shapeOf.end()) return found->second;
        if (sphere) {
            shapes_.push_back(std::make_unique<btSphereShape>(btScalar(body.radius)));
        } else {
            shapes_.push_back(std::make_unique<btBoxShape>(bt(body.halfExtents())));
        }
        shapeOf.emplace(key, shapes_.back().get());
        return shapes_.back().get();
    };

    for (DynamicObject body : scene.dynamics) {
        if (body.constantAcceleration != Vec3(0, 0, 0)) {
            throw std::invalid_argument(body.name + ": per-body accelerations are not translated to Bullet");
        }
        body.setMass(body.mass);
        initialiseMassProperties(body);  // Stepwise's principal moments: Bullet's btSphereShape has no hollow ball
        inertiaBody_.push_back(body.inertiaBody);
        const btTransform pose(btQuaternion(btScalar(body.orientation.x), btScalar(body.orientation.y),
                                            btScalar(body.orientation.z), btScalar(body.orientation.w)),
                               bt(body.position));
        motionStates_.push_back(std::make_unique<btDefaultMotionState>(pose));
        btRigidBody::btRigidBodyConstructionInfo info(btScalar(body.mass), motionStates_.back().get(), shapeFor(body),
                                                      bt(body.inertiaBody));
        info.m_restitution = btScalar(body.elasticity);
        info.m_friction = btScalar(body.friction);
        dynamics_.push_back(std::make_unique<btRigidBody>(info));
        btRigidBody& rigid = *dynamics_.back();
        rigid.setLinearVelocity(bt(body.velocity));
        rigid.setAngularVelocity(bt(body.angularVelocity));
        if (!scene.settings.sleeping) rigid.setActivationState(DISABLE_DEACTIVATION);
        world_->addRigidBody(&rigid);
    }
    for (const CollisionPlane& plane : scene.planes) {
        const Vec3 n = glm::normalize(plane.normal);
        shapes_.push_back(std::make_unique<btStaticPlaneShape>(bt(n), btScalar(glm::dot(n, plane.position))));
        motionStates_.push_back(std::make_unique<btDefaultMotionState>());
        btRigidBody::btRigidBodyConstructionInfo info(0, motionStates_.back().get(), shapes_.back().get());
        info.m_restitution = btScalar(plane.elasticity);
        info.m_friction = btScalar(plane.friction);
        statics_.push_back(std::make_unique<btRigidBody>(info));
        world_->addRigidBody(statics_.back().get());
    }
}

BulletWorld::~BulletWorld() {
    // Bodies leave the world before it (and their shapes) are destroyed.
    for (auto& body : dynamics_) world_->removeRigidBody(body.get());
    for (auto& body : statics_) world_->removeRigidBody(body.get());
}

void BulletWorld::step() {
    // maxSubSteps = 1, fixedTimeStep = h: exactly one step of h, no interpolation.
    world_->stepSimulation(btScalar(timeStep_), 1, btScalar(timeStep_));
}

void BulletWorld::states(std::vector<BodyState>& out) const {
    out.resize(dynamics_.size());
    for (std::size_t n = 0; n < dynamics_.size(); ++n) {
        const btRigidBody& body = *dynamics_[n];
        const btTransform& pose = body.getWorldTransform();
        const btQuaternion q = pose.getRotation();
        BodyState& s = out[n];
        s.position = toVec3(pose.getOrigin());
        s.orientation = Quat(Real(q.w()), Real(q.x()), Real(q.y()), Real(q.z()));
        s.velocity = toVec3(body.getLinearVelocity());
        s.angularVelocity = toVec3(body.getAngularVelocity());
        // L = R·I·Rᵀ·ω: Bullet keeps ω, Stepwise keeps L; the meters compare L.
        const Vec3 omegaBody = glm::conjugate(s.orientation) * s.angularVelocity;
        s.angularMomentum = s.orientation * (inertiaBody_[n] * omegaBody);
    }
}

std::size_t BulletWorld::sleepingCount() const {
    std::size_t sleeping = 0;
    for (const auto& body : dynamics_) sleeping += body->getActivationState() == ISLAND_SLEEPING ? 1 : 0;
    return sleeping;
}

int BulletWorld::manifoldCount() const { return dispatcher_->getNumManifolds(); }

void BulletWorld::setSolverIterations(int iterations) { world_->getSolverInfo().m_numIterations = iterations; }

}  // namespace stepwise::bench
