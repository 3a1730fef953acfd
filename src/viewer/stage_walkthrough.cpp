/// @file stage_walkthrough.cpp
/// @brief Capturing each stage of one step (poses, pairs, contacts, impulses) and saying what it produced.
#include "viewer/stage_walkthrough.hpp"

#include <algorithm>
#include <cstdarg>
#include <cstdio>

#include "world/object_name.hpp"

namespace stepwise::viewer {

namespace {

/// Millimetres per metre: moves and depths of a step are millimetres.
constexpr double kMillimetres = 1e3;
/// Longest description, characters (a line of the overlay wraps anyway).
constexpr std::size_t kDescriptionChars = 240;

/// A fixed buffer the description is written into with printf formats (no allocation).
class Line {
public:
    [[gnu::format(printf, 2, 3)]] void add(const char* format, ...) {
        if (used_ + 1 >= sizeof text_) return;
        va_list args;
        va_start(args, format);
        const int n = std::vsnprintf(text_ + used_, sizeof text_ - used_, format, args);
        va_end(args);
        if (n > 0) used_ = std::min(sizeof text_ - 1, used_ + static_cast<std::size_t>(n));
    }
    void addVector(const Vec3& v) { add("(%.3g, %.3g, %.3g)", double(v.x), double(v.y), double(v.z)); }
    const char* text() const { return text_; }

private:
    char text_[kDescriptionChars] = {};
    std::size_t used_ = 0;
};


const char* plural(std::size_t n) { return n == 1 ? "" : "s"; }

/// The body (index into dynamics then kinematics) whose @p change between
/// two pose blocks is largest, and that largest change.
struct Largest {
    std::size_t index = 0;
    Real amount = 0;
    bool found = false;
};

template <class Change>
Largest largest(std::span<const BodySnapshot> before, std::span<const BodySnapshot> after, std::size_t from,
                std::size_t to, Change change) {
    Largest best;
    for (std::size_t i = from; i < to; ++i) {
        const Real amount = change(before[i], after[i]);
        if (amount > best.amount) best = {i, amount, true};
    }
    return best;
}

Real moved(const BodySnapshot& a, const BodySnapshot& b) { return glm::length(b.position - a.position); }
Real velocityChange(const BodySnapshot& a, const BodySnapshot& b) { return glm::length(b.velocity - a.velocity); }

template <class T>
void copyRange(std::vector<T>& all, const std::vector<T>& now, std::size_t& begin, std::size_t& count) {
    begin = all.size();
    count = now.size();
    all.insert(all.end(), now.begin(), now.end());
}

}  // namespace

SceneView liveView(const World& world) {
    return {world.dynamics(), world.kinematics(), world.candidatePairs(), world.contacts(), world.impulses()};
}

void StageWalkthrough::beforeStage(const StageEvent& event, const World& world) {
    if (!recording_) {
        // The step's first stage: start a new recording in the arrays of the last one.
        recording_ = true;
        count_ = 0;
        shown_ = 0;
        pairs_.clear();
        contacts_.clear();
        impulses_.clear();
        poses_.clear();
        bodies_ = world.dynamics().size() + world.kinematics().size();
        dynamics_ = world.dynamics();  // element-wise copy: the names keep their storage from step to step
        kinematics_ = world.kinematics();
        capturePoses(world);  // block 0: the start of the step
    }
    secondsBefore_ = world.stageRecords()[static_cast<std::size_t>(event.stage)].lastSeconds;
}

void StageWalkthrough::afterStage(const StageEvent& event, const World& world) {
    if (!recording_) return;  // set in the middle of a step: wait for the next one
    if (count_ == snapshots_.size()) snapshots_.emplace_back();
    StageSnapshot& s = snapshots_[count_];
    const StageSnapshot* previous = count_ > 0 ? &snapshots_[count_ - 1] : nullptr;
    s.event = event;
    s.seconds = world.stageRecords()[static_cast<std::size_t>(event.stage)].lastSeconds - secondsBefore_;

    // Pairs, contacts and impulses change only in the stage that writes
    // them; the snapshots after it share its copy. Before this step's stage
    // ran, there are none to show (the World still holds the last step's).
    s.pairsBegin = previous ? previous->pairsBegin : 0;
    s.pairsCount = previous ? previous->pairsCount : 0;
    s.contactsBegin = previous ? previous->contactsBegin : 0;
    s.contactsCount = previous ? previous->contactsCount : 0;
    s.impulsesBegin = previous ? previous->impulsesBegin : 0;
    s.impulsesCount = previous ? previous->impulsesCount : 0;
    if (event.stage == Stage::Broadphase) copyRange(pairs_, world.candidatePairs(), s.pairsBegin, s.pairsCount);
    if (event.stage == Stage::Narrowphase) copyRange(contacts_, world.contacts(), s.contactsBegin, s.contactsCount);
    if (event.stage == Stage::ResolveImpulses || event.stage == Stage::Restitution) {
        copyRange(impulses_, world.impulses(), s.impulsesBegin, s.impulsesCount);
    }

    capturePoses(world);
    ++count_;
    describe(s, world);
}

void StageWalkthrough::afterStep(const World&) { recording_ = false; }

void StageWalkthrough::capturePoses(const World& world) {
    for (const DynamicObject& b : world.dynamics()) {
        poses_.push_back({b.position, b.orientation, b.velocity, b.angularVelocity, b.asleep});
    }
    for (const KinematicsObject& b : world.kinematics()) {
        poses_.push_back({b.position, b.orientation, b.velocity, b.angularVelocity, false});
    }
}

void StageWalkthrough::describe(StageSnapshot& s, const World& world) const {
    const std::size_t k = count_ - 1;  // this snapshot's index; its poses are block k + 1
    const std::span<const BodySnapshot> all(poses_);
    const std::span<const BodySnapshot> before = all.subspan(k * bodies_, bodies_);
    const std::span<const BodySnapshot> after = all.subspan((k + 1) * bodies_, bodies_);
    const std::size_t nd = dynamics_.size();
    auto name = [&](std::size_t i) -> const std::string& {
        return i < nd ? dynamics_[i].name : kinematics_[i - nd].name;
    };

    Line line;
    if (s.event.substep >= 0) line.add("substep %d/%d: ", s.event.substep + 1, s.event.substeps);
    line.add("%s: ", stageName(s.event.stage));
    // The body whose velocity the stage changed most, and its velocity now.
    auto velocityLine = [&](const char* what) {
        const Largest dv = largest(before, after, 0, nd, velocityChange);
        if (!dv.found) {
            line.add("no velocity changed");
            return;
        }
        line.add("%s %s dv %.3g m/s, v now ", what, name(dv.index).c_str(), double(dv.amount));
        line.addVector(after[dv.index].velocity);
        line.add(" m/s");
    };

    switch (s.event.stage) {
        case Stage::ApplyForces: {
            const auto awake = std::find_if(world.dynamics().begin(), world.dynamics().end(),
                                            [](const DynamicObject& b) { return !b.asleep; });
            line.add("%zu bod%s", nd, nd == 1 ? "y" : "ies");
            if (awake != world.dynamics().end()) {
                line.add("; %s a = ", awake->name.c_str());
                line.addVector(awake->acceleration);
                line.add(" m/s^2");
            }
            break;
        }
        case Stage::Integrate: {
            const double h = double(s.event.timeStep) / s.event.substeps;
            line.add("%s, h = %.4g s: ", toString(world.settings().integrator), h);
            const Largest move = largest(before, after, 0, nd, moved);
            if (!move.found) {
                line.add("nothing moved");
                break;
            }
            const BodySnapshot& b = after[move.index];
            line.add("%s moved %.3g mm to ", name(move.index).c_str(), kMillimetres * double(move.amount));
            line.addVector(b.position);
            line.add(" m, v_y %.3g m/s", double(b.velocity.y));
            break;
        }
        case Stage::MoveKinematics: {
            const Largest move = largest(before, after, nd, bodies_, moved);
            line.add("%zu kinematic bod%s", bodies_ - nd, bodies_ - nd == 1 ? "y" : "ies");
            if (move.found) {
                line.add("; %s moved %.3g mm", name(move.index).c_str(), kMillimetres * double(move.amount));
            }
            break;
        }
        case Stage::Broadphase: {
            const std::vector<CandidatePair>& pairs = world.candidatePairs();
            line.add("%zu candidate pair%s (bounding boxes overlap)", pairs.size(), plural(pairs.size()));
            if (!pairs.empty()) {
                line.add(", e.g. %s - %s", world.dynamics()[pairs[0].a].name.c_str(),
                         objectName(world, pairs[0].b).c_str());
            }
            break;
        }
        case Stage::Narrowphase: {
            const std::vector<Contact>& contacts = world.contacts();
            line.add("%zu contact%s", contacts.size(), plural(contacts.size()));
            const auto deepest = std::max_element(contacts.begin(), contacts.end(),
                                                  [](const Contact& a, const Contact& b) { return a.depth < b.depth; });
            if (deepest != contacts.end()) {
                const double depth = kMillimetres * double(deepest->depth);
                if (depth >= 0) line.add(", deepest %.3g mm", depth);
                else line.add(", closest gap %.3g mm (speculative)", -depth);
                line.add(" (%s - %s)", world.dynamics()[deepest->a].name.c_str(), objectName(world, deepest->b).c_str());
            }
            break;
        }
        case Stage::ResolveImpulses: {
            Real normal = 0, friction = 0;
            for (const ImpulseReport& r : world.impulses()) {
                normal += r.normalImpulse;
                friction += r.frictionImpulse;
            }
            line.add("%zu impulse%s, normal %.3g N*s, friction %.3g N*s; ", world.impulses().size(),
                     plural(world.impulses().size()), double(normal), double(friction));
            velocityLine("largest");
            break;
        }
        case Stage::CorrectPositions: {
            const Largest move = largest(before, after, 0, nd, moved);
            if (!move.found) {
                line.add("no overlap to remove");
                break;
            }
            line.add("%s pushed %.3g mm to ", name(move.index).c_str(), kMillimetres * double(move.amount));
            line.addVector(after[move.index].position);
            line.add(" m");
            break;
        }
        case Stage::PrepareConstraints:
            line.add("%zu contact constraint%s, %zu joint%s, warm start %s", world.solverContacts().size(),
                     plural(world.solverContacts().size()), world.joints().size(), plural(world.joints().size()),
                     world.settings().warmStarting ? "on" : "off");
            break;
        case Stage::SolveConstraints:
        case Stage::RelaxConstraints: {
            Real normal = 0;
            for (const SolverContact& c : world.solverContacts()) normal += c.normalImpulse;
            line.add("sum of normal impulses %.3g N*s; ", double(normal));
            velocityLine("largest");
            break;
        }
        case Stage::Restitution:
            velocityLine("bounce: largest");
            break;
        case Stage::Sleep: {
            const auto asleep = static_cast<std::size_t>(std::count_if(
                world.dynamics().begin(), world.dynamics().end(), [](const DynamicObject& b) { return b.asleep; }));
            line.add("%zu asleep, %zu awake", asleep, nd - asleep);
            break;
        }
        case Stage::Continuous:
            line.add("%zu fast bodies stopped at their time of impact", world.bodiesStoppedAtImpact());
            break;
        case Stage::SoftBodies:
            line.add("%zu soft bodies", world.softBodies().size());
            break;
        case Stage::Count: break;
    }
    s.description.assign(line.text());  // keeps the string's storage from the last step
}

void StageWalkthrough::show(std::size_t k) {
    shown_ = std::min(k, count_ > 0 ? count_ - 1 : 0);
    if (count_ == 0) return;
    const std::size_t nd = dynamics_.size();
    for (std::size_t i = 0; i < bodies_; ++i) {
        const BodySnapshot& b = body(shown_, i);
        GameObject& object = i < nd ? static_cast<GameObject&>(dynamics_[i]) : kinematics_[i - nd];
        object.position = b.position;
        object.orientation = b.orientation;
        if (i < nd) {
            dynamics_[i].velocity = b.velocity;
            dynamics_[i].angularVelocity = b.angularVelocity;
            dynamics_[i].asleep = b.asleep;
        } else {
            kinematics_[i - nd].velocity = b.velocity;
            kinematics_[i - nd].angularVelocity = b.angularVelocity;
        }
    }
}

SceneView StageWalkthrough::view() const {
    if (count_ == 0) return {dynamics_, kinematics_, {}, {}, {}};
    const StageSnapshot& s = snapshots_[shown_];
    return {dynamics_, kinematics_, std::span<const CandidatePair>(pairs_).subspan(s.pairsBegin, s.pairsCount),
            std::span<const Contact>(contacts_).subspan(s.contactsBegin, s.contactsCount),
            std::span<const ImpulseReport>(impulses_).subspan(s.impulsesBegin, s.impulsesCount)};
}

bool StageWalkthrough::isSummaryStop(std::size_t k) const {
    const StageEvent& e = snapshots_[k].event;
    return e.substep < 0 || e.substep == 0 || e.substep == e.substeps - 1;
}

std::size_t StageWalkthrough::memoryBytes() const {
    std::size_t bytes = snapshots_.capacity() * sizeof(StageSnapshot) + poses_.capacity() * sizeof(BodySnapshot) +
                        pairs_.capacity() * sizeof(CandidatePair) + contacts_.capacity() * sizeof(Contact) +
                        impulses_.capacity() * sizeof(ImpulseReport) +
                        dynamics_.capacity() * sizeof(DynamicObject) + kinematics_.capacity() * sizeof(KinematicsObject);
    for (const StageSnapshot& s : snapshots_) bytes += s.description.capacity();
    return bytes;
}

void StageWalkthrough::clear() {
    count_ = 0;
    shown_ = 0;
    bodies_ = 0;
    recording_ = false;
    poses_.clear();
    pairs_.clear();
    contacts_.clear();
    impulses_.clear();
    dynamics_.clear();
    kinematics_.clear();
}

}  // namespace stepwise::viewer
