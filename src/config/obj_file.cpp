/// @file obj_file.cpp
/// @brief OBJ through tinyobjloader: check the file, read it into memory, hand it over, convert.
#include "config/obj_file.hpp"

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

#include <tiny_obj_loader.h>

namespace stepwise {

namespace {

/// tinyobjloader's messages end with a newline and may hold several lines: the first says why.
std::string firstLine(const std::string& text) {
    std::string line = text.substr(0, text.find('\n'));
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    return line;
}

}  // namespace

ObjModel readObjFile(const std::string& path) {
    std::error_code status;
    const std::filesystem::file_status type = std::filesystem::status(path, status);
    if (!std::filesystem::exists(type)) throw ObjError("no such file");
    if (std::filesystem::is_directory(type)) throw ObjError("it is a directory");
    if (!std::filesystem::is_regular_file(type)) {
        // A FIFO no one writes blocks the read forever, /dev/zero never ends: a model is a file on disk.
        const char* kind = std::filesystem::is_fifo(type)             ? "a FIFO"
                           : std::filesystem::is_character_file(type) ? "a character device"
                           : std::filesystem::is_block_file(type)     ? "a block device"
                           : std::filesystem::is_socket(type)         ? "a socket"
                                                                      : "not a regular file";
        throw ObjError(std::string("it is ") + kind + ", not a regular file");
    }
    const std::uintmax_t bytes = std::filesystem::file_size(path, status);
    if (status) throw ObjError(status.message());
    if (bytes > kMaxObjFileBytes) {
        throw ObjError("it is " + std::to_string(bytes) + " bytes, more than the " + std::to_string(kMaxObjFileBytes) +
                       " a model may have");
    }

    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ObjError(errno != 0 ? std::generic_category().message(errno) : "it could not be opened");
    std::ostringstream contents;
    contents << in.rdbuf();
    if (in.bad()) throw ObjError("read error");
    std::istringstream text(contents.str());

    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warnings;
    std::string errors;
    // No material reader: `mtllib` lines are skipped, so no other file is opened. Triangulated.
    const bool ok = tinyobj::LoadObj(&attrib, &shapes, &materials, &warnings, &errors, &text, nullptr, true);
    if (!ok) throw ObjError("tinyobjloader: " + (errors.empty() ? std::string("not an OBJ file") : firstLine(errors)));

    ObjModel model;
    constexpr std::size_t kCoordinates = 3;
    if (attrib.vertices.size() < kCoordinates) throw ObjError("it has no vertices (no 'v x y z' line)");
    model.vertices.reserve(attrib.vertices.size() / kCoordinates);
    for (std::size_t i = 0; i + 2 < attrib.vertices.size(); i += kCoordinates) {
        model.vertices.emplace_back(Real(attrib.vertices[i]), Real(attrib.vertices[i + 1]), Real(attrib.vertices[i + 2]));
    }
    for (const tinyobj::shape_t& shape : shapes) {
        std::size_t next = 0;
        for (const unsigned char corners : shape.mesh.num_face_vertices) {
            if (corners == 3 && next + 3 <= shape.mesh.indices.size()) {
                std::array<std::uint32_t, 3> triangle{};
                bool valid = true;
                for (std::size_t k = 0; k < 3; ++k) {
                    const int index = shape.mesh.indices[next + k].vertex_index;
                    valid = valid && index >= 0 && std::size_t(index) < model.vertices.size();
                    triangle[k] = std::uint32_t(index);
                }
                if (!valid) throw ObjError("a face uses a vertex that does not exist");
                model.triangles.push_back(triangle);
            }
            next += corners;
        }
    }
    return model;
}

}  // namespace stepwise
