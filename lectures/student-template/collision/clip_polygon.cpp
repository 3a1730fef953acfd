/// @file clip_polygon.cpp
/// @brief YOUR Sutherland-Hodgman pass (lecture 6): a student template (lectures/student-template/README.md).
///
/// Copied to student/collision/clip_polygon.cpp, it replaces
/// src/collision/clip_polygon.cpp in the student preset's build. It defines
/// the function src/collision/clip_polygon.hpp declares (read its comment):
///
///     int clipPolygon(const ClipVertex* in, int count, const Vec3& normal, Real offset,
///                     std::uint8_t planeLabel, Real tolerance, ClipVertex* out);
///
/// Keep the part of the convex polygon in[0 .. count-1] with n.p <= offset
/// (lecture 6, "3. Box against box: reference face, incident face, clipping").
/// Walk the edges a -> b, starting with the closing edge (a = in[count-1],
/// b = in[0]); with d = n.p - offset, a vertex is inside when d <= tolerance:
///
///     a inside,  b inside    write b
///     a inside,  b outside   write the crossing a + (b - a) d_a/(d_a - d_b),
///                            inEdge = a.outEdge, outEdge = planeLabel
///     a outside, b inside    write the crossing, inEdge = planeLabel, outEdge = a.outEdge;
///                            then b
///     a outside, b outside   nothing
///
/// Never write more than kMaxClipVertices vertices; return how many you wrote.
/// Until you write it, the box-box manifold stops with
/// "student stage not written yet: stepwise::clipPolygon".
/// Test it: ctest --preset student -L contacts
#include "collision/clip_polygon.hpp"
#include "core/student_todo.hpp"

namespace stepwise {

int clipPolygon(const ClipVertex* in, int count, const Vec3& normal, Real offset, std::uint8_t planeLabel,
                Real tolerance, ClipVertex* out) {
    // ==== YOUR CODE BEGINS: lecture 6, "3. Box against box: reference face, incident face, clipping" ====
    // TODO: one Sutherland-Hodgman pass, as in the table above; the crossings carry the edge labels.
    return studentTodo<int>("stepwise::clipPolygon (collision/clip_polygon.cpp): "
                            "write one Sutherland-Hodgman pass over the edges a -> b (lecture 6, section 3)",
                            in, count, normal, offset, planeLabel, tolerance, out);
    // ==== YOUR CODE ENDS ====
}

}  // namespace stepwise
