/// @file obj_file.hpp
/// @brief Reads the points and triangles of a Wavefront OBJ file (for `File=model.obj`).
///
/// OBJ is the plain-text model format every modelling tool writes: `v x y z`
/// lines for points, `f a b c …` lines for faces (indices from 1). The engine
/// reads it with tinyobjloader (Debian: libtinyobjloader-dev), a library made
/// for the format, rather than by hand: the format has corners (negative
/// indices, `v/vt/vn` triples, polygons of any size, line continuations) a
/// hand-written reader gets wrong. Faces come back triangulated; normals,
/// texture coordinates, groups and materials are not used. A material file
/// (`mtllib`) is never opened: the model's geometry is all a body needs.
#pragma once

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace stepwise {

/// @brief Largest OBJ file read, bytes: a scene's model, not a film set (and never /dev/zero).
inline constexpr std::uintmax_t kMaxObjFileBytes = 64u * 1024u * 1024u;

/// @brief What an OBJ file holds for collision: its points and its faces as triangles.
struct ObjModel {
    std::vector<Vec3> vertices;                            ///< Every `v` line, in file order, m.
    std::vector<std::array<std::uint32_t, 3>> triangles;  ///< Every face, triangulated; indices into vertices.
};

/// @brief Thrown by readObjFile(): the reason, in words, without the path (the caller names it).
class ObjError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// @brief Reads @p path (a regular file of at most kMaxObjFileBytes) as OBJ.
///
/// A FIFO, a device or a folder is refused before anything is read, as the
/// scene loader refuses them for scenes: one would block or never end.
/// @throws ObjError when the file is missing, not a regular file, too large,
///         unreadable, not OBJ as tinyobjloader reads it, or has no vertices.
///         A file with vertices but no faces is returned as it is: a hull needs
///         only points, and a mesh's loader says that it needs faces.
ObjModel readObjFile(const std::string& path);

}  // namespace stepwise
