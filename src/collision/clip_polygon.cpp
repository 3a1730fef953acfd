/// @file clip_polygon.cpp
/// @brief One Sutherland–Hodgman pass: the polygon on the near side of a plane.
#include "collision/clip_polygon.hpp"

namespace stepwise {

int clipPolygon(const ClipVertex* in, int count, const Vec3& normal, Real offset, std::uint8_t planeLabel,
                Real tolerance, ClipVertex* out) {
    int written = 0;
    auto emit = [&](const ClipVertex& v) {
        if (written < kMaxClipVertices) out[written++] = v;
    };
    if (count <= 0) return 0;

    // Start with the edge that closes the polygon (last vertex → first).
    ClipVertex a = in[count - 1];
    Real da = glm::dot(normal, a.position) - offset;
    for (int i = 0; i < count; ++i) {
        const ClipVertex& b = in[i];
        const Real db = glm::dot(normal, b.position) - offset;
        const bool aInside = da <= tolerance;
        const bool bInside = db <= tolerance;
        // The edge a → b carries the label a.outEdge (== b.inEdge).
        if (aInside != bInside) {
            ClipVertex crossing;
            // da − db is never 0 here: one is ≤ tolerance, the other > tolerance.
            crossing.position = a.position + (b.position - a.position) * (da / (da - db));
            if (aInside) {  // leaving the kept side: arrive along a→b, leave along the plane
                crossing.inEdge = a.outEdge;
                crossing.outEdge = planeLabel;
            } else {        // entering the kept side: arrive along the plane, leave along a→b
                crossing.inEdge = planeLabel;
                crossing.outEdge = a.outEdge;
            }
            emit(crossing);
        }
        if (bInside) emit(b);
        a = b;
        da = db;
    }
    return written;
}

}  // namespace stepwise
