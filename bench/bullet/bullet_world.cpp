/// @file bullet_world.cpp
/// @brief Builds and steps the Bullet world of a Stepwise scene (bullet_world.hpp says how it maps).
#include "bullet_world.hpp"

#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

#include <glm/gtc/constants.hpp>

#include "objects/inertia.hpp"

namespace stepwise::bench {

namespace {

btVector3 bt(const Vec3& v) { return {btScalar(v.x), btScalar(v.y), btScalar(v.z)}; }
btQuaternion bt(const Quat& q) { return {btScalar(q.x), btScalar(q.y), btScalar(q.z), btScalar(q.w)}; }
Vec3 toVec3(const btVector3& v) { return {Real(v.x()), Real(v.y()), Real(v.z())}; }

}  // namespace

BulletWorld::BulletWorld(const Scene& scene)
    : timeStep_(double(scene.settings.timeStep)), springs_(scene.springs), attractors_(scene.attractors) {
    for (const KinematicsObject& k : scene.kinematics) {
        if (k.velocity != Vec3(0, 0, 0) || k.angularVelocity != Vec3(0, 0, 0)) {
            throw std::invalid_argument(scene.sourcePath + ": " + k.name +
                                        ": the Bullet side translates only kinematic bodies at rest (static boxes); "
                                        "this one has a velocity");
        }
        if (k.shape != Shape::Box) {
            throw std::invalid_argument(scene.sourcePath + ": " + k.name + ": a kinematic " + toString(k.shape) +
                                        " is not translated to Bullet (static boxes are)");
        }
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
        if (body.shape != Shape::Sphere && body.shape != Shape::Box) {
            throw std::invalid_argument(body.name + ": a " + toString(body.shape) +
                                        " is not translated to Bullet (the side-by-side has spheres and boxes)");
        }
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
    for (const JointDef& joint : scene.joints) addJoint(scene, joint);
    if (!springs_.empty() || !attractors_.empty()) world_->setInternalTickCallback(&BulletWorld::applyForces, this, true);
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
    // Static boxes: mass 0 is Bullet's static body; one shape per box (a level has few).
    for (const KinematicsObject& k : scene.kinematics) {
        shapes_.push_back(std::make_unique<btBoxShape>(bt(k.halfExtents())));
        motionStates_.push_back(std::make_unique<btDefaultMotionState>(btTransform(bt(k.orientation), bt(k.position))));
        btRigidBody::btRigidBodyConstructionInfo info(0, motionStates_.back().get(), shapes_.back().get());
        info.m_restitution = btScalar(k.elasticity);
        info.m_friction = btScalar(k.friction);
        statics_.push_back(std::make_unique<btRigidBody>(info));
        world_->addRigidBody(statics_.back().get());
    }
}

void BulletWorld::addJoint(const Scene& scene, const JointDef& joint) {
    const auto bodyNamed = [&](const std::string& name) -> btRigidBody* {
        if (name.empty()) return nullptr;  // the world
        const auto found = std::find_if(scene.dynamics.begin(), scene.dynamics.end(),
                                        [&](const DynamicObject& b) { return b.name == name; });
        if (found == scene.dynamics.end()) {
            throw std::invalid_argument(scene.sourcePath + ": " + joint.name + ": no DynamicObject named '" + name + "'");
        }
        return dynamics_[std::size_t(found - scene.dynamics.begin())].get();
    };
    if (joint.maxForce != kUnbreakable) {
        throw std::invalid_argument(scene.sourcePath + ": " + joint.name + ": MaxForce is not translated to Bullet");
    }
    btRigidBody* a = bodyNamed(joint.bodyA);
    btRigidBody* b = bodyNamed(joint.bodyB);
    const auto body = std::find_if(scene.dynamics.begin(), scene.dynamics.end(),
                                   [&](const DynamicObject& d) { return d.name == joint.bodyA; });
    const bool pendulumRod = joint.kind == JointKind::Distance && !b && glm::length(joint.anchorA - body->position) == 0;
    // A world point in a body's own frame (Bullet's constraints take their points there).
    const auto inBody = [](const btRigidBody& rigid, const Vec3& point) { return rigid.getWorldTransform().inverse() * bt(point); };
    if (pendulumRod) {
        // The pin: the fixed point, in the body's own frame, stays where it is in the world.
        joints_.push_back(std::make_unique<btPoint2PointConstraint>(*a, inBody(*a, joint.anchorB)));
    } else if (joint.kind == JointKind::Ball) {
        if (b) {
            joints_.push_back(std::make_unique<btPoint2PointConstraint>(*a, *b, inBody(*a, joint.anchorA), inBody(*b, joint.anchorA)));
        } else {
            joints_.push_back(std::make_unique<btPoint2PointConstraint>(*a, inBody(*a, joint.anchorA)));
        }
    } else if (joint.kind == JointKind::Hinge && !joint.motor) {
        joints_.push_back(hinge(joint, *a, b));
    } else {
        throw std::invalid_argument(scene.sourcePath + ": " + joint.name + ": the Bullet side translates BallJoints, "
                                    "HingeJoints without motor or MaxForce, and a DistanceJoint from a body's centre "
                                    "to a fixed point; this is a " + toString(joint.kind));
    }
    // Stepwise's joined bodies do not collide unless CollideConnected=true; Bullet's flag says the same.
    world_->addConstraint(joints_.back().get(), !joint.collideConnected);
}

std::unique_ptr<btTypedConstraint> BulletWorld::hinge(const JointDef& joint, btRigidBody& a, btRigidBody* b) {
    // One world frame F at the anchor whose z is the axis; each body gets F in its own
    // frame, so Bullet's hinge angle is 0 at the start, as Stepwise's is.
    const Vec3 z = glm::normalize(joint.axis);
    const Vec3 helper = std::abs(z.x) < Real(0.9) ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    const Vec3 x = glm::normalize(glm::cross(helper, z));
    const Vec3 y = glm::cross(z, x);
    const btTransform frame(btMatrix3x3(btScalar(x.x), btScalar(y.x), btScalar(z.x), btScalar(x.y), btScalar(y.y),
                                        btScalar(z.y), btScalar(x.z), btScalar(y.z), btScalar(z.z)),
                            bt(joint.anchorA));
    std::unique_ptr<btHingeConstraint> hinge;
    // Stepwise's angle is A's about the axis as seen from B. Bullet's two-body hinge
    // with useReferenceFrameA = true measures its body B as seen from its body A, so
    // Stepwise's B is Bullet's A; its one-body hinge (the world as the other end),
    // with useReferenceFrameA = false, measures the body's own turn. Both were checked
    // against btHingeConstraint::getHingeAngle() for a body turned +0.3 rad: +0.3.
    if (b) {
        hinge = std::make_unique<btHingeConstraint>(*b, a, b->getWorldTransform().inverse() * frame,
                                                    a.getWorldTransform().inverse() * frame, true);
    } else {
        hinge = std::make_unique<btHingeConstraint>(a, a.getWorldTransform().inverse() * frame, false);
    }
    if (joint.lowerAngle || joint.upperAngle) {
        // No limit on one side: Bullet's limits span at most ±π, so the open side is ±π.
        hinge->setLimit(btScalar(joint.lowerAngle.value_or(-glm::pi<Real>())),
                        btScalar(joint.upperAngle.value_or(glm::pi<Real>())));
    }
    return hinge;
}

BulletWorld::~BulletWorld() {
    // Joints and bodies leave the world before it (and their shapes) are destroyed.
    for (auto& joint : joints_) world_->removeConstraint(joint.get());
    for (auto& body : dynamics_) world_->removeRigidBody(body.get());
    for (auto& body : statics_) world_->removeRigidBody(body.get());
}

void BulletWorld::applyForces(btDynamicsWorld* world, btScalar) {
    const BulletWorld& self = *static_cast<const BulletWorld*>(world->getWorldUserInfo());
    for (const Spring& spring : self.springs_) {
        // Spring's force law (src/forces/spring.hpp), on Bullet's bodies: anchors in the body frames.
        btRigidBody& a = *self.dynamics_[spring.bodyA];
        btRigidBody* b = spring.bodyB == kFixedInWorld ? nullptr : self.dynamics_[spring.bodyB].get();
        const btVector3 anchorA = a.getWorldTransform() * bt(spring.anchorA);
        const btVector3 anchorB = b ? b->getWorldTransform() * bt(spring.anchorB) : bt(spring.anchorB);
        const btVector3 armA = anchorA - a.getCenterOfMassPosition();
        const btVector3 armB = b ? anchorB - b->getCenterOfMassPosition() : btVector3(0, 0, 0);
        const btVector3 between = anchorB - anchorA;
        const btScalar length = between.length();
        if (length < btScalar(kMinSpringLength)) continue;
        const btVector3 n = between / length;
        const btVector3 rate = (b ? b->getVelocityInLocalPoint(armB) : btVector3(0, 0, 0)) - a.getVelocityInLocalPoint(armA);
        const btVector3 force =
            (btScalar(spring.stiffness) * (length - btScalar(spring.restLength)) + btScalar(spring.damping) * rate.dot(n)) * n;
        a.applyForce(force, armA);
        if (b) b->applyForce(-force, armB);
    }
    for (const Attractor& attractor : self.attractors_) {
        for (const auto& body : self.dynamics_) {
            const Vec3 acceleration = attractorAcceleration(attractor, toVec3(body->getCenterOfMassPosition()));
            body->applyCentralForce(bt(acceleration) / body->getInvMass());
        }
    }
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

int BulletWorld::solverIterations() const { return world_->getSolverInfo().m_numIterations; }

}  // namespace stepwise::bench
