/// @file renderer.cpp
/// @brief The 3D drawing: fixed-function OpenGL 1.x with one directional light.
#include "viewer/renderer.hpp"

#include <GL/freeglut.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

namespace stepwise::viewer {

namespace {

/// Length of a drawn velocity vector per m/s: the distance covered in this many seconds.
constexpr Real kVelocitySeconds = Real(0.25);
/// Length of a drawn angular-velocity vector per rad/s, m.
constexpr Real kSpinMetresPerRadian = Real(0.1);
/// Length of a drawn contact normal, m.
constexpr Real kNormalLength = Real(0.3);
/// Grid spacing on planes, m.
constexpr Real kGridSpacing = Real(1);
/// Half length of a drawn hinge or motor axis, m.
constexpr Real kJointAxisHalfLength = Real(0.3);

void color(const Color& c, float scale = 1.0f) { glColor3f(c.r * scale, c.g * scale, c.b * scale); }

void vertex(const Vec3& p) { glVertex3d(double(p.x), double(p.y), double(p.z)); }

/// Moves the model-view matrix to a body's pose.
void pushPose(const Vec3& position, const Quat& orientation) {
    glPushMatrix();
    glTranslated(double(position.x), double(position.y), double(position.z));
    const Real angle = glm::angle(orientation);
    if (std::abs(angle) > Real(1e-9)) {
        const Vec3 axis = glm::axis(orientation);
        glRotated(double(angle) * 180.0 / double(kPi), double(axis.x), double(axis.y), double(axis.z));
    }
}

/// Slices around, and stacks along, a solid sphere or round side: smooth at any zoom the viewer allows.
constexpr int kSolidSlices = 32;
constexpr int kSolidStacks = 20;
/// Slices and stacks of a sphere's outline: a few meridians and parallels, enough to see it turn.
constexpr int kWireSlices = 8;
constexpr int kWireStacks = 6;

/// What the drawing needs of a body's (or a compound part's) shape, in its own frame.
struct ShapeLook {
    Shape shape = Shape::Sphere;               ///< Which of the fields below are used.
    Real radius = 0;                           ///< Sphere, capsule, cylinder, m.
    Real height = 0;                           ///< Capsule segment, cylinder length, along y, m.
    Vec3 scale{1, 1, 1};                       ///< Box edge lengths, m.
    const ConvexHull* hull = nullptr;          ///< Shape::Hull.
    const CompoundShape* compound = nullptr;   ///< Shape::Compound.
    const TriangleMesh* mesh = nullptr;        ///< Shape::Mesh.
};

ShapeLook lookOf(const DynamicObject& b) {
    return {b.shape, b.radius, b.height, b.scale, b.hull.get(), b.compound.get(), nullptr};
}

ShapeLook lookOf(const KinematicsObject& b) {
    return {b.shape, b.radius, b.height, b.scale, b.hull.get(), b.compound.get(), b.mesh.get()};
}

ShapeLook lookOf(const CompoundPart& part) {
    return {part.shape, part.radius, part.height, part.scale, part.hull.get(), nullptr, nullptr};
}

void normal(const Vec3& n) { glNormal3d(double(n.x), double(n.y), double(n.z)); }

/// A cylinder of @p radius and full @p length along y, centred on the origin. GLUT's
/// cylinders stand on z from 0 to their height: a turn of −90° about x takes z to y.
void cylinderAlongY(Real radius, Real length, bool solid, int slices) {
    glPushMatrix();
    glRotated(-90.0, 1.0, 0.0, 0.0);
    glTranslated(0.0, 0.0, -0.5 * double(length));
    if (solid) {
        glutSolidCylinder(double(radius), double(length), slices, 1);
    } else {
        glutWireCylinder(double(radius), double(length), slices, 1);
    }
    glPopMatrix();
}

/// A sphere of @p radius at height @p y on the y axis (a capsule's end).
void sphereAt(Real y, Real radius, bool solid) {
    glPushMatrix();
    glTranslated(0.0, double(y), 0.0);
    if (solid) {
        glutSolidSphere(double(radius), kSolidSlices, kSolidStacks);
    } else {
        glutWireSphere(double(radius), kWireSlices, kWireStacks);
    }
    glPopMatrix();
}

/// A hull's faces, flat shaded: one normal per face, its loop counter-clockwise seen from outside.
void hullFaces(const ConvexHull& hull) {
    for (const HullFace& face : hull.faces) {
        glBegin(GL_POLYGON);
        normal(face.normal);
        for (std::uint32_t k = face.firstIndex; k < face.firstIndex + face.indexCount && k < hull.faceIndices.size(); ++k) {
            const std::uint32_t v = hull.faceIndices[k];
            if (v < hull.vertices.size()) vertex(hull.vertices[v]);
        }
        glEnd();
    }
}

/// A hull's edges (each once, ConvexHull::edges).
void hullEdges(const ConvexHull& hull) {
    glBegin(GL_LINES);
    for (const std::array<std::uint32_t, 2>& e : hull.edges) {
        if (e[0] >= hull.vertices.size() || e[1] >= hull.vertices.size()) continue;
        vertex(hull.vertices[e[0]]);
        vertex(hull.vertices[e[1]]);
    }
    glEnd();
}

/// A mesh's triangles, flat shaded (each its own normal), or their outlines.
void meshTriangles(const TriangleMesh& mesh, bool solid) {
    const std::size_t n = mesh.vertices.size();
    for (const std::array<std::uint32_t, 3>& t : mesh.triangles) {
        if (t[0] >= n || t[1] >= n || t[2] >= n) continue;
        const Vec3& a = mesh.vertices[t[0]];
        const Vec3& b = mesh.vertices[t[1]];
        const Vec3& c = mesh.vertices[t[2]];
        glBegin(solid ? GL_TRIANGLES : GL_LINE_LOOP);
        const Vec3 across = glm::cross(b - a, c - a);
        const Real length = glm::length(across);
        if (solid && length > 0) normal(across / length);
        vertex(a);
        vertex(b);
        vertex(c);
        glEnd();
    }
}

void solidShape(const ShapeLook& look) {
    const Real halfHeight = Real(0.5) * look.height;
    switch (look.shape) {
        case Shape::Sphere: glutSolidSphere(double(look.radius), kSolidSlices, kSolidStacks); break;
        case Shape::Box:
            glPushMatrix();
            glScaled(double(look.scale.x), double(look.scale.y), double(look.scale.z));
            glutSolidCube(1.0);
            glPopMatrix();
            break;
        case Shape::Capsule:  // a cylinder and two hemispheres (whole spheres: the halves inside are hidden)
            cylinderAlongY(look.radius, look.height, true, kSolidSlices);
            sphereAt(-halfHeight, look.radius, true);
            sphereAt(halfHeight, look.radius, true);
            break;
        case Shape::Cylinder: cylinderAlongY(look.radius, look.height, true, kSolidSlices); break;
        case Shape::Hull:
            if (look.hull) hullFaces(*look.hull);
            break;
        case Shape::Compound:
            if (!look.compound) break;
            for (const CompoundPart& part : look.compound->parts) {
                pushPose(part.position, part.orientation);
                solidShape(lookOf(part));
                glPopMatrix();
            }
            break;
        case Shape::Mesh:
            if (look.mesh) meshTriangles(*look.mesh, true);
            break;
    }
}

/// The shape's outline, grown by the factor @p grow about its centre: a box's or hull's edges,
/// a sphere's meridians and parallels, a capsule's or cylinder's rings, a mesh's triangles.
void wireShape(const ShapeLook& look, float grow = 1.002f) {
    glPushMatrix();
    glScaled(double(grow), double(grow), double(grow));
    const Real halfHeight = Real(0.5) * look.height;
    switch (look.shape) {
        case Shape::Sphere: glutWireSphere(double(look.radius), kWireSlices, kWireStacks); break;
        case Shape::Box:
            glScaled(double(look.scale.x), double(look.scale.y), double(look.scale.z));
            glutWireCube(1.0);
            break;
        case Shape::Capsule:
            cylinderAlongY(look.radius, look.height, false, kWireSlices);
            sphereAt(-halfHeight, look.radius, false);
            sphereAt(halfHeight, look.radius, false);
            break;
        case Shape::Cylinder: cylinderAlongY(look.radius, look.height, false, kWireSlices); break;
        case Shape::Hull:
            if (look.hull) hullEdges(*look.hull);
            break;
        case Shape::Compound:
            if (!look.compound) break;
            for (const CompoundPart& part : look.compound->parts) {
                pushPose(part.position, part.orientation);
                wireShape(lookOf(part), 1.0f);  // grown once already, with the whole body
                glPopMatrix();
            }
            break;
        case Shape::Mesh:
            if (look.mesh) meshTriangles(*look.mesh, false);
            break;
    }
    glPopMatrix();
}

/// Diagonal stripes (a 32×32 polygon stipple, one bit per pixel) that mark kinematic bodies.
const GLubyte* stripes() {
    static GLubyte pattern[128];
    static bool filled = false;
    if (!filled) {
        for (int y = 0; y < 32; ++y) {
            for (int x = 0; x < 32; ++x) {
                if (((x + y) / 4) % 2 == 0) pattern[y * 4 + x / 8] |= static_cast<GLubyte>(0x80u >> (x % 8));
            }
        }
        filled = true;
    }
    return pattern;
}

/// I: one colour per awake island (from a small palette, by the island's
/// lowest body index; soft body k is index dynamics().size() + k, islands.hpp),
/// kSleepingColor for a sleeping body or soft body.
Color islandColor(const World& world, bool asleep, std::uint32_t body) {
    static constexpr Color kPalette[] = {{0.9f, 0.45f, 0.2f}, {0.3f, 0.75f, 0.35f}, {0.85f, 0.3f, 0.6f},
                                         {0.95f, 0.8f, 0.2f}, {0.35f, 0.8f, 0.8f},  {0.6f, 0.4f, 0.9f}};
    if (asleep) return kSleepingColor;
    const std::uint32_t island = islandOf(world.islands(), body);
    return kPalette[island % (sizeof kPalette / sizeof kPalette[0])];
}

void drawBody(const ShapeLook& look, const Vec3& position, const Quat& orientation, const Color& c, bool kinematic) {
    pushPose(position, orientation);
    glEnable(GL_LIGHTING);
    color(c);
    solidShape(look);
    if (kinematic) {
        // Darker stripes drawn over the same surface.
        glDepthFunc(GL_LEQUAL);
        glEnable(GL_POLYGON_STIPPLE);
        glPolygonStipple(stripes());
        color(c, 0.55f);
        solidShape(look);
        glDisable(GL_POLYGON_STIPPLE);
        glDepthFunc(GL_LESS);
    }
    glDisable(GL_LIGHTING);
    color(c, 0.45f);
    glLineWidth(1.0f);
    wireShape(look);
    glPopMatrix();
}

/// A soft body's surface as its nodes are now: each triangle lit by its own normal, then its
/// edges (the springs) drawn darker over it, as a rigid body's wire frame is. In @p own colour:
/// the body's, or mixed with its space's when the spaces are overlaid.
void drawSoftBody(const SoftBody& body, const Color& own) {
    const auto corners = [&](const SoftFace& f) {
        return std::array<Vec3, 3>{body.nodePositions[f.a], body.nodePositions[f.b], body.nodePositions[f.c]};
    };
    glEnable(GL_LIGHTING);
    color(own);
    glBegin(GL_TRIANGLES);
    for (const SoftFace& f : body.faces) {
        const std::array<Vec3, 3> p = corners(f);
        const Vec3 across = glm::cross(p[1] - p[0], p[2] - p[0]);
        const Real length = glm::length(across);
        if (length > 0) normal(across / length);
        for (const Vec3& q : p) vertex(q);
    }
    glEnd();
    glDisable(GL_LIGHTING);
    color(own, 0.45f);
    glLineWidth(1.0f);
    glDepthFunc(GL_LEQUAL);
    for (const SoftFace& f : body.faces) {
        glBegin(GL_LINE_LOOP);
        for (const Vec3& q : corners(f)) vertex(q);
        glEnd();
    }
    glDepthFunc(GL_LESS);
}

/// Two unit vectors that, with @p n, make a right-handed orthonormal basis.
void basisFor(const Vec3& n, Vec3& u, Vec3& v) {
    const Vec3 helper = std::abs(n.y) < Real(0.9) ? Vec3(0, 1, 0) : Vec3(1, 0, 0);
    u = glm::normalize(glm::cross(helper, n));
    v = glm::cross(n, u);
}

/// A plane as a square around the point of the plane nearest the camera's
/// target, big enough to reach the horizon of the view, with a 1 m grid.
void drawPlane(const CollisionPlane& plane, const OrbitCamera& camera) {
    Vec3 u, v;
    basisFor(plane.normal, u, v);
    const Real half = std::max(Real(10), 2 * camera.distance);
    // The square's centre, snapped to the grid so the lines stay put as the camera moves.
    const Vec3 d = camera.target - plane.position;
    const Real cu = std::round(glm::dot(d, u) / kGridSpacing) * kGridSpacing;
    const Real cv = std::round(glm::dot(d, v) / kGridSpacing) * kGridSpacing;
    const Vec3 centre = plane.position + cu * u + cv * v;

    glEnable(GL_LIGHTING);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 1.0f);  // push the quad back so the grid lines on it win the depth test
    color(plane.color, 0.9f);
    glNormal3d(double(plane.normal.x), double(plane.normal.y), double(plane.normal.z));
    glBegin(GL_QUADS);
    vertex(centre - half * u - half * v);
    vertex(centre + half * u - half * v);
    vertex(centre + half * u + half * v);
    vertex(centre - half * u + half * v);
    glEnd();
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_LIGHTING);

    color(plane.color, 0.6f);
    glBegin(GL_LINES);
    const int lines = static_cast<int>(half / kGridSpacing);
    for (int i = -lines; i <= lines; ++i) {
        const Real s = Real(i) * kGridSpacing;
        vertex(centre + s * u - half * v);
        vertex(centre + s * u + half * v);
        vertex(centre - half * u + s * v);
        vertex(centre + half * u + s * v);
    }
    glEnd();
}

void drawAabb(const Aabb& box) {
    const Vec3& a = box.min;
    const Vec3& b = box.max;
    const Vec3 corners[8] = {{a.x, a.y, a.z}, {b.x, a.y, a.z}, {b.x, b.y, a.z}, {a.x, b.y, a.z},
                             {a.x, a.y, b.z}, {b.x, a.y, b.z}, {b.x, b.y, b.z}, {a.x, b.y, b.z}};
    static constexpr int kEdges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                          {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    glBegin(GL_LINES);
    for (const auto& e : kEdges) {
        vertex(corners[e[0]]);
        vertex(corners[e[1]]);
    }
    glEnd();
}

template <class Body>
Aabb boundsOf(const Body& b) {
    return shapeAabb(b);  // every shape's exact box (src/collision/aabb.hpp)
}

Vec3 centreOf(const SceneView& view, const BodyRef& ref) {
    return ref.kind == BodyKind::Dynamic ? view.dynamics[ref.index].position : view.kinematics[ref.index].position;
}

/// B: every bounding box; the bodies of a candidate pair in yellow, joined by a line.
void drawBroadphase(const SceneView& view) {
    std::vector<bool> paired(view.dynamics.size() + view.kinematics.size(), false);
    for (const CandidatePair& p : view.pairs) {
        paired[p.a] = true;
        if (p.b.kind == BodyKind::Dynamic) paired[p.b.index] = true;
        if (p.b.kind == BodyKind::Kinematic) paired[view.dynamics.size() + p.b.index] = true;
    }
    glLineWidth(1.0f);
    std::size_t i = 0;
    auto draw = [&](const Aabb& box) {
        if (paired[i++]) glColor3f(1.0f, 0.9f, 0.2f);
        else glColor3f(0.6f, 0.6f, 0.6f);
        drawAabb(box);
    };
    for (const DynamicObject& b : view.dynamics) draw(boundsOf(b));
    for (const KinematicsObject& b : view.kinematics) draw(boundsOf(b));
    glColor3f(1.0f, 0.9f, 0.2f);
    glBegin(GL_LINES);
    for (const CandidatePair& p : view.pairs) {
        if (p.b.kind == BodyKind::Plane) continue;
        vertex(view.dynamics[p.a].position);
        vertex(centreOf(view, p.b));
    }
    glEnd();
}

/// C: contact points (orange) and normals from A towards B (yellow); with
/// @p impulses, the normal's length grows with the contact's share of the largest impulse.
void drawContacts(const SceneView& view, bool impulses) {
    Real largest = 0;
    if (impulses) {
        for (const ImpulseReport& r : view.impulses) largest = std::max(largest, r.normalImpulse);
    }
    glLineWidth(2.0f);
    glColor3f(1.0f, 0.9f, 0.2f);
    glBegin(GL_LINES);
    for (std::size_t i = 0; i < view.contacts.size(); ++i) {
        const Contact& c = view.contacts[i];
        Real length = kNormalLength;
        if (impulses && largest > 0 && i < view.impulses.size()) {
            length = 2 * kNormalLength * view.impulses[i].normalImpulse / largest;
        }
        vertex(c.point);
        vertex(c.point + length * c.normal);
    }
    glEnd();
    glPointSize(7.0f);
    glColor3f(1.0f, 0.45f, 0.1f);
    glBegin(GL_POINTS);
    for (const Contact& c : view.contacts) vertex(c.point);
    glEnd();
    glLineWidth(1.0f);
}

/// V: velocity vectors (cyan, the distance covered in 0.25 s) and angular velocities (magenta, 0.1 m per rad/s).
void drawVelocities(const SceneView& view) {
    glLineWidth(2.0f);
    glBegin(GL_LINES);
    auto draw = [](const Vec3& x, const Vec3& v, const Vec3& w) {
        glColor3f(0.2f, 0.9f, 0.95f);
        vertex(x);
        vertex(x + kVelocitySeconds * v);
        glColor3f(0.95f, 0.3f, 0.9f);
        vertex(x);
        vertex(x + kSpinMetresPerRadian * w);
    };
    for (const DynamicObject& b : view.dynamics) draw(b.position, b.velocity, b.angularVelocity);
    for (const KinematicsObject& b : view.kinematics) draw(b.position, b.velocity, b.angularVelocity);
    glEnd();
    glLineWidth(1.0f);
}

/// Joints, always shown: the rod from each body's centre to its anchor and
/// between the anchors (light tan), the anchors as points, hinge and motor
/// axes (green). A broken joint is not drawn.
void drawJoints(const World& world, std::span<const DynamicObject> bodies) {
    glLineWidth(2.0f);
    glBegin(GL_LINES);
    for (const Joint& joint : world.joints()) {
        if (joint.broken) continue;
        const JointAnchors anchors = jointAnchors(joint, bodies);
        const DynamicObject& a = bodies[joint.bodyA];
        if (joint.kind != JointKind::AngularMotor) {  // a motor holds no point: only its axis is drawn
            glColor3f(0.95f, 0.85f, 0.6f);
            vertex(a.position);
            vertex(anchors.onA);
            vertex(anchors.onA);
            vertex(anchors.onB);
            if (joint.bodyB != kWorldAnchor) {
                vertex(anchors.onB);
                vertex(bodies[joint.bodyB].position);
            }
        }
        if (joint.kind == JointKind::Hinge || joint.kind == JointKind::AngularMotor) {
            const Quat orientationB =
                joint.bodyB == kWorldAnchor ? Quat(1, 0, 0, 0) : bodies[joint.bodyB].orientation;
            const Vec3 axis = orientationB * joint.localAxisB;
            const Vec3 centre = joint.kind == JointKind::Hinge ? anchors.onA : a.position;
            glColor3f(0.4f, 0.95f, 0.4f);
            vertex(centre - kJointAxisHalfLength * axis);
            vertex(centre + kJointAxisHalfLength * axis);
        }
    }
    glEnd();
    glPointSize(6.0f);
    glColor3f(0.95f, 0.85f, 0.6f);
    glBegin(GL_POINTS);
    for (const Joint& joint : world.joints()) {
        if (joint.broken || joint.kind == JointKind::AngularMotor) continue;
        const JointAnchors anchors = jointAnchors(joint, bodies);
        vertex(anchors.onA);
        vertex(anchors.onB);
    }
    glEnd();
    glLineWidth(1.0f);
}

void setUpLight() {
    // A directional light from above and in front (w = 0: a direction, in world
    // coordinates because the view matrix is already loaded).
    const GLfloat direction[4] = {0.35f, 1.0f, 0.55f, 0.0f};
    const GLfloat ambient[4] = {0.38f, 0.38f, 0.38f, 1.0f};
    const GLfloat diffuse[4] = {0.72f, 0.72f, 0.72f, 1.0f};
    const GLfloat black[4] = {0, 0, 0, 1};
    glLightfv(GL_LIGHT0, GL_POSITION, direction);
    glLightfv(GL_LIGHT0, GL_AMBIENT, ambient);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, diffuse);
    glLightfv(GL_LIGHT0, GL_SPECULAR, black);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, black);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glEnable(GL_LIGHT0);
    glEnable(GL_COLOR_MATERIAL);
    glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
    glEnable(GL_NORMALIZE);  // boxes are drawn as scaled unit cubes: rescale their normals
}

/// How one World is drawn: where, in what colours, and whether the mouse is on it.
struct WorldLook {
    Vec3 offset{0, 0, 0};        ///< Where its origin is drawn (SpaceLayout::offset), m.
    std::optional<Color> tint;   ///< Overlaid spaces: every body mixed with its space's colour.
    /// Side by side: its planes are drawn across this range of x only (its own coordinates), m.
    std::pair<Real, Real> band{-std::numeric_limits<Real>::infinity(), std::numeric_limits<Real>::infinity()};
    bool hovered = false;        ///< DrawOptions::hovered is one of its bodies.
    bool grabbed = false;        ///< The held body is one of its bodies.
    bool walkthrough = false;    ///< It is the World of the stage walk-through (no spaces).
};

/// Share of an overlaid body's colour that is its space's: enough to tell the spaces apart, with
/// a trace of the body's own colour left.
constexpr float kOverlaidTint = 0.65f;

Color tinted(const Color& own, const std::optional<Color>& tint) {
    if (!tint) return own;
    const float keep = 1.0f - kOverlaidTint;
    return {keep * own.r + kOverlaidTint * tint->r, keep * own.g + kOverlaidTint * tint->g,
            keep * own.b + kOverlaidTint * tint->b};
}

/// Overlaid, the spaces' planes lie on one another (one floor each): a plane that an earlier
/// space already has, at the same point with the same normal, is drawn once.
bool drawnBefore(const Simulation& simulation, std::size_t space, const CollisionPlane& plane) {
    for (std::size_t j = 0; j < space; ++j) {
        for (const CollisionPlane& other : simulation.worldAt(j).planes()) {
            if (other.position == plane.position && other.normal == plane.normal) return true;
        }
    }
    return false;
}

/// Everything of World @p space, in the current model-view (already moved by look.offset).
void drawWorld(const Simulation& simulation, std::size_t space, const OrbitCamera& camera, const DrawOptions& options,
               const WorldLook& look) {
    const World& world = simulation.worldAt(space);
    const SceneView view = simulation.viewOf(space);  // the live World, or the walk-through's snapshot

    // The planes' squares are centred under the camera's target, in this World's own coordinates.
    OrbitCamera local = camera;
    local.target -= look.offset;
    const bool clip = std::isfinite(look.band.first) && std::isfinite(look.band.second);
    if (clip) {  // keep x ≥ low and x ≤ high: a·x + d ≥ 0 for (a, 0, 0, d)
        const GLdouble low[4] = {1.0, 0.0, 0.0, -double(look.band.first)};
        const GLdouble high[4] = {-1.0, 0.0, 0.0, double(look.band.second)};
        glClipPlane(GL_CLIP_PLANE0, low);
        glClipPlane(GL_CLIP_PLANE1, high);
        glEnable(GL_CLIP_PLANE0);
        glEnable(GL_CLIP_PLANE1);
    }
    for (const CollisionPlane& plane : world.planes()) {
        if (look.tint && drawnBefore(simulation, space, plane)) continue;
        drawPlane(plane, local);
    }
    if (clip) {
        glDisable(GL_CLIP_PLANE0);
        glDisable(GL_CLIP_PLANE1);
    }
    for (std::uint32_t i = 0; i < view.dynamics.size(); ++i) {
        const DynamicObject& b = view.dynamics[i];
        const Color own = options.islands ? islandColor(world, b.asleep, i) : b.color;
        drawBody(lookOf(b), b.position, b.orientation, tinted(own, look.tint), false);
    }
    for (const KinematicsObject& b : view.kinematics) {
        drawBody(lookOf(b), b.position, b.orientation, tinted(b.color, look.tint), true);
    }
    for (std::uint32_t k = 0; k < world.softBodies().size(); ++k) {  // the live World's (the walk-through keeps no copy)
        const SoftBody& b = world.softBodies()[k];
        const auto unit = static_cast<std::uint32_t>(world.dynamics().size() + k);
        drawSoftBody(b, options.islands ? islandColor(world, b.asleep, unit) : tinted(b.color, look.tint));
    }

    glDisable(GL_LIGHTING);
    drawJoints(world, view.dynamics);
    if (look.hovered && options.hovered && options.hovered->kind != BodyKind::Plane) {
        glColor3f(1.0f, 0.95f, 0.2f);
        glLineWidth(3.0f);
        if (options.hovered->kind == BodyKind::Dynamic) {
            const DynamicObject& b = view.dynamics[options.hovered->index];
            pushPose(b.position, b.orientation);
            wireShape(lookOf(b), 1.03f);
        } else {
            const KinematicsObject& b = view.kinematics[options.hovered->index];
            pushPose(b.position, b.orientation);
            wireShape(lookOf(b), 1.03f);
        }
        glPopMatrix();
        glLineWidth(1.0f);
    }

    // The stage walk-through: ghosts where the bodies were at the start of the step, and the shown stage's overlay.
    const std::optional<std::size_t> shownIndex = look.walkthrough ? simulation.shownStage() : std::nullopt;
    const Stage stage = shownIndex ? simulation.walkthrough().snapshot(*shownIndex).event.stage : Stage::Count;  // Count: none
    if (shownIndex) {
        glColor3f(0.95f, 0.95f, 0.95f);
        for (std::size_t i = 0; i < view.dynamics.size(); ++i) {
            const DynamicObject& b = view.dynamics[i];
            const BodySnapshot& start = simulation.walkthrough().bodyAtStart(i);
            pushPose(start.position, start.orientation);
            wireShape(lookOf(b), 1.0f);
            glPopMatrix();
        }
    }
    const auto shown = [&](Stage s) { return stage == s; };

    // Overlays are drawn on top of the bodies so that contacts inside them show.
    glDisable(GL_DEPTH_TEST);
    if (options.boundingBoxes || shown(Stage::Broadphase)) drawBroadphase(view);
    if (options.contacts || shown(Stage::Narrowphase) || shown(Stage::ResolveImpulses) ||
        shown(Stage::CorrectPositions) || shown(Stage::PrepareConstraints) || shown(Stage::Restitution)) {
        drawContacts(view, shown(Stage::ResolveImpulses) || shown(Stage::Restitution));
    }
    if (options.velocities || shown(Stage::Integrate) || shown(Stage::ResolveImpulses) ||
        shown(Stage::SolveConstraints) || shown(Stage::RelaxConstraints) || shown(Stage::Restitution)) {
        drawVelocities(view);
    }
    if (const std::optional<Grab>& grab = simulation.grabbed(); grab && look.grabbed) {
        const Vec3 point = simulation.grabPoint();
        glColor3f(1.0f, 0.25f, 0.2f);
        glLineWidth(3.0f);
        glBegin(GL_LINES);
        vertex(point);
        vertex(point + Real(0.6) * grab->direction);
        glEnd();
        glPointSize(8.0f);
        glBegin(GL_POINTS);
        vertex(point);
        glEnd();
        glLineWidth(1.0f);
    }
    glEnable(GL_DEPTH_TEST);
}

}  // namespace

void drawScene(const Simulation& simulation, const OrbitCamera& camera, int width, int height,
               const DrawOptions& options) {
    glViewport(0, 0, width, height);
    glClearColor(kBackground[0], kBackground[1], kBackground[2], 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glShadeModel(GL_SMOOTH);

    glMatrixMode(GL_PROJECTION);
    const Mat4 projection = camera.projectionMatrix(Real(width) / Real(height));
    const glm::dmat4 p(projection);
    glLoadMatrixd(&p[0][0]);
    glMatrixMode(GL_MODELVIEW);
    const glm::dmat4 viewMatrix(camera.viewMatrix());
    glLoadMatrixd(&viewMatrix[0][0]);
    setUpLight();

    if (!simulation.hasSpaces()) {
        WorldLook look;
        look.hovered = true;
        look.grabbed = true;
        look.walkthrough = true;
        drawWorld(simulation, 0, camera, options, look);
        return;
    }
    const SpaceLayout& layout = simulation.layout();
    const bool overlaid = layout.arrangement() == SpaceArrangement::Overlaid;
    for (std::size_t k = 0; k < simulation.worldCount(); ++k) {
        WorldLook look;
        look.offset = layout.offset(k);
        if (overlaid) look.tint = spaceColor(k);
        look.band = layout.band(k);
        look.hovered = options.hoveredSpace == k;
        look.grabbed = simulation.grabbedSpace() == k;
        glPushMatrix();
        glTranslated(double(look.offset.x), double(look.offset.y), double(look.offset.z));
        drawWorld(simulation, k, camera, options, look);
        glPopMatrix();
    }
}

}  // namespace stepwise::viewer
