/// @file convex_hull.cpp
/// @brief qhull's facets → merged polygon faces with ordered loops, edges, volume.
#include "objects/convex_hull.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <tuple>
#include <utility>
#include <vector>

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

#include "objects/mass_properties.hpp"

namespace stepwise {

namespace {

/// A hull spans a solid only from 4 points that are not coplanar.
constexpr std::size_t kMinHullPoints = 4;
/// qhull's command: plain "qhull" builds the 3-d hull and, by default, merges facets that
/// round-off leaves coplanar ('C-0'), so a flat face comes back as one facet with all its
/// corners. 'Qt' (triangulated output) is what must *not* be asked for.
char kQhullCommand[] = "qhull";
/// Dimension of the points.
constexpr int kDimension = 3;

/// Owns one qhull run: its state and the memory stream its messages go to.
class QhullRun {
public:
    QhullRun() {
        // qhull prints its messages to a FILE*; an in-memory one keeps them off the
        // terminal and lets an error quote them.
        messages_ = open_memstream(&text_, &size_);
        qh_zero(&qh_, messages_);
    }
    ~QhullRun() {
        int curlong = 0;
        int totlong = 0;
        qh_freeqhull(&qh_, !qh_ALL);
        qh_memfreeshort(&qh_, &curlong, &totlong);
        if (messages_ != nullptr) std::fclose(messages_);
        std::free(text_);
    }
    QhullRun(const QhullRun&) = delete;
    QhullRun& operator=(const QhullRun&) = delete;

    qhT* state() { return &qh_; }
    FILE* messages() { return messages_; }

    /// The first line qhull wrote (its error's summary), or "".
    std::string firstMessage() {
        if (messages_ == nullptr) return "";
        std::fflush(messages_);
        const std::string all(text_ != nullptr ? text_ : "", size_);
        return all.substr(0, all.find('\n'));
    }

private:
    qhT qh_{};
    FILE* messages_ = nullptr;
    char* text_ = nullptr;
    std::size_t size_ = 0;
};

void checkPoints(std::span<const Vec3> points) {
    if (points.size() < kMinHullPoints) {
        throw HullError(HullProblem::TooFewPoints, "a hull needs at least 4 points that are not coplanar, got " +
                                                       std::to_string(points.size()));
    }
    if (points.size() > kMaxHullPoints) {
        throw HullError(HullProblem::TooManyPoints, "a hull takes at most " + std::to_string(kMaxHullPoints) +
                                                        " points, got " + std::to_string(points.size()));
    }
    for (std::size_t i = 0; i < points.size(); ++i) {
        const Vec3& p = points[i];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
            throw HullError(HullProblem::NotFinite, "point " + std::to_string(i + 1) +
                                                        " has a coordinate that is NaN or infinite");
        }
    }
}

/// Sorts @p loop (vertex indices of one flat face) counter-clockwise about @p normal,
/// seen from outside: by the angle of each corner around the face's centre, measured
/// from u towards w = n × u (the right-hand rule about n). A convex polygon's corners
/// appear around its centre in angle order.
void orderLoop(std::vector<std::uint32_t>& loop, const std::vector<Vec3>& vertices, const Vec3& normal) {
    Vec3 centre(0);
    for (const std::uint32_t i : loop) centre += vertices[i];
    centre /= Real(loop.size());
    const Vec3 u = glm::normalize(vertices[loop.front()] - centre);
    const Vec3 w = glm::cross(normal, u);
    std::vector<std::pair<Real, std::uint32_t>> byAngle;
    byAngle.reserve(loop.size());
    for (const std::uint32_t i : loop) {
        const Vec3 d = vertices[i] - centre;
        byAngle.emplace_back(std::atan2(glm::dot(d, w), glm::dot(d, u)), i);
    }
    std::sort(byAngle.begin(), byAngle.end());
    for (std::size_t k = 0; k < loop.size(); ++k) loop[k] = byAngle[k].second;
}

}  // namespace

ConvexHull buildConvexHull(std::span<const Vec3> points) {
    checkPoints(points);
    // All points in one place: qhull cannot even measure the cloud's width, and says so
    // as an internal error; the answer is simpler said here.
    if (std::all_of(points.begin(), points.end(), [&](const Vec3& p) { return p == points.front(); })) {
        throw HullError(HullProblem::Flat, "all the points coincide: their hull has no volume (a hull needs at "
                                           "least 4 points that are not coplanar)");
    }
    std::vector<coordT> coordinates;
    coordinates.reserve(points.size() * kDimension);
    for (const Vec3& p : points) {
        coordinates.push_back(coordT(p.x));
        coordinates.push_back(coordT(p.y));
        coordinates.push_back(coordT(p.z));
    }

    QhullRun run;
    qhT* qh = run.state();
    if (run.messages() == nullptr) throw HullError(HullProblem::Failed, "qhull could not be started (out of memory)");
    const int status = qh_new_qhull(qh, kDimension, static_cast<int>(points.size()), coordinates.data(), False,
                                    kQhullCommand, nullptr, run.messages());
    // qh_ERRsingular: "initial simplex is flat"; qh_ERRinput, for input of the right size and
    // shape: "input is less than 3-dimensional" (e.g. every x the same).
    if (status == qh_ERRsingular || status == qh_ERRinput) {
        throw HullError(HullProblem::Flat, "the points are coplanar, collinear or coincident: their hull has no "
                                           "volume (a hull needs at least 4 points that are not coplanar)");
    }
    if (status != qh_ERRnone) {
        throw HullError(HullProblem::Failed, "qhull could not build the hull: " + run.firstMessage());
    }

    ConvexHull hull;
    // qhull's vertices are input points; number them again, densely, in the order met.
    std::vector<std::int64_t> compact(points.size(), -1);
    facetT* facet = nullptr;
    vertexT* vertex = nullptr;
    vertexT** vertexp = nullptr;
    std::vector<std::uint32_t> loop;
    FORALLfacets {
        loop.clear();
        FOREACHvertex_(facet->vertices) {
            const int id = qh_pointid(qh, vertex->point);
            if (id < 0 || std::size_t(id) >= points.size()) continue;
            if (compact[std::size_t(id)] < 0) {
                compact[std::size_t(id)] = std::int64_t(hull.vertices.size());
                hull.vertices.push_back(points[std::size_t(id)]);
            }
            loop.push_back(std::uint32_t(compact[std::size_t(id)]));
        }
        if (loop.size() < 3) continue;
        HullFace face;
        face.normal = glm::normalize(Vec3(Real(facet->normal[0]), Real(facet->normal[1]), Real(facet->normal[2])));
        orderLoop(loop, hull.vertices, face.normal);
        face.firstIndex = std::uint32_t(hull.faceIndices.size());
        face.indexCount = std::uint32_t(loop.size());
        hull.faceIndices.insert(hull.faceIndices.end(), loop.begin(), loop.end());
        hull.faces.push_back(face);
    }
    if (hull.faces.size() < kMinHullPoints) {
        throw HullError(HullProblem::Flat, "the points' hull has fewer than 4 faces, so no volume");
    }

    // The corners in a fixed order, by z, then y, then x: the numbering (the contacts' feature
    // ids) then depends on the points alone, not on the order qhull met them in. A box's corners
    // come out numbered as box_features.hpp numbers them (bit i set: + along axis i), so a hull
    // cube's contacts with a plane are a box's, in the same order.
    std::vector<std::uint32_t> byPosition(hull.vertices.size());
    for (std::uint32_t i = 0; i < byPosition.size(); ++i) byPosition[i] = i;
    std::sort(byPosition.begin(), byPosition.end(), [&](std::uint32_t x, std::uint32_t y) {
        const Vec3& p = hull.vertices[x];
        const Vec3& q = hull.vertices[y];
        return std::tie(p.z, p.y, p.x) < std::tie(q.z, q.y, q.x);
    });
    std::vector<std::uint32_t> renumbered(byPosition.size());
    std::vector<Vec3> sorted(byPosition.size());
    for (std::uint32_t i = 0; i < byPosition.size(); ++i) {
        renumbered[byPosition[i]] = i;
        sorted[i] = hull.vertices[byPosition[i]];
    }
    hull.vertices = std::move(sorted);
    for (std::uint32_t& index : hull.faceIndices) index = renumbered[index];

    // Plane offsets: the largest dot(n, v) over all corners, so dot(n, v) ≤ offset holds for
    // every vertex exactly, even where merging tilted a face by round-off.
    for (HullFace& face : hull.faces) {
        face.offset = glm::dot(face.normal, hull.vertices.front());
        for (const Vec3& v : hull.vertices) face.offset = std::max(face.offset, glm::dot(face.normal, v));
    }
    // Edges: every side of every loop, as (smaller index, larger), each once. Two faces
    // share each edge, running along it in opposite directions.
    for (const HullFace& face : hull.faces) {
        for (std::uint32_t k = 0; k < face.indexCount; ++k) {
            const std::uint32_t a = hull.faceIndices[face.firstIndex + k];
            const std::uint32_t b = hull.faceIndices[face.firstIndex + (k + 1) % face.indexCount];
            hull.edges.push_back({std::min(a, b), std::max(a, b)});
        }
    }
    std::sort(hull.edges.begin(), hull.edges.end());
    hull.edges.erase(std::unique(hull.edges.begin(), hull.edges.end()), hull.edges.end());

    hull.volume = polyhedronMassProperties(hull).volume;
    if (!(hull.volume > 0)) {
        throw HullError(HullProblem::Flat, "the points' hull has no volume (they are coplanar, collinear or coincident)");
    }
    for (const Vec3& v : hull.vertices) hull.boundingRadius = std::max(hull.boundingRadius, glm::length(v));
    return hull;
}

}  // namespace stepwise
