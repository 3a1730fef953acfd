/// @file png_writer.cpp
/// @brief The PNG encoder: signature, IHDR, IDAT in stored deflate blocks, IEND.
#include "viewer/png_writer.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <stdexcept>

namespace stepwise::viewer {

namespace {

/// Largest payload of one stored deflate block (its LEN field is 16 bits).
constexpr std::size_t kMaxStoredBlock = 65535;

void putBigEndian32(std::vector<std::uint8_t>& out, std::uint32_t value) {
    for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<std::uint8_t>(value >> shift));
}

/// Appends one chunk: length, type, data, CRC-32 of type and data.
void putChunk(std::vector<std::uint8_t>& out, const char (&type)[5], const std::vector<std::uint8_t>& data) {
    putBigEndian32(out, static_cast<std::uint32_t>(data.size()));
    const std::size_t typeStart = out.size();
    out.insert(out.end(), type, type + 4);
    out.insert(out.end(), data.begin(), data.end());
    putBigEndian32(out, crc32(out.data() + typeStart, out.size() - typeStart));
}

}  // namespace

std::uint32_t crc32(const std::uint8_t* data, std::size_t size) {
    static const std::array<std::uint32_t, 256> table = [] {
        std::array<std::uint32_t, 256> t{};
        for (std::uint32_t n = 0; n < 256; ++n) {
            std::uint32_t c = n;
            for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
            t[n] = c;
        }
        return t;
    }();
    std::uint32_t c = 0xFFFFFFFFu;
    for (std::size_t i = 0; i < size; ++i) c = table[(c ^ data[i]) & 0xFFu] ^ (c >> 8);
    return c ^ 0xFFFFFFFFu;
}

std::uint32_t adler32(const std::uint8_t* data, std::size_t size) {
    std::uint32_t a = 1, b = 0;
    for (std::size_t i = 0; i < size; ++i) {
        a = (a + data[i]) % 65521u;
        b = (b + a) % 65521u;
    }
    return (b << 16) | a;
}

std::vector<std::uint8_t> encodePng(int width, int height, const std::vector<std::uint8_t>& rgbTopDown) {
    const std::size_t rowBytes = static_cast<std::size_t>(width) * 3;
    if (width <= 0 || height <= 0 || rgbTopDown.size() != rowBytes * static_cast<std::size_t>(height)) {
        throw std::invalid_argument("encodePng: the pixel buffer does not match width x height x 3");
    }
    // The filtered image: each row is prefixed with filter type 0 (none).
    std::vector<std::uint8_t> raw;
    raw.reserve((rowBytes + 1) * static_cast<std::size_t>(height));
    for (int y = 0; y < height; ++y) {
        raw.push_back(0);
        const auto row = rgbTopDown.begin() + static_cast<std::ptrdiff_t>(rowBytes * static_cast<std::size_t>(y));
        raw.insert(raw.end(), row, row + static_cast<std::ptrdiff_t>(rowBytes));
    }
    // The zlib stream: header (deflate, 32 KiB window, no dictionary; 0x7801 is divisible by 31),
    // stored blocks "BFINAL/BTYPE=00, LEN, ~LEN, bytes", then Adler-32.
    std::vector<std::uint8_t> zlib = {0x78, 0x01};
    for (std::size_t at = 0;; at += kMaxStoredBlock) {
        const std::size_t length = std::min(kMaxStoredBlock, raw.size() - at);
        const bool last = at + length >= raw.size();
        zlib.push_back(last ? 1 : 0);
        const auto len = static_cast<std::uint16_t>(length);
        const auto nlen = static_cast<std::uint16_t>(~len);
        for (std::uint16_t v : {len, nlen}) {  // little-endian, unlike the rest of PNG
            zlib.push_back(static_cast<std::uint8_t>(v & 0xFFu));
            zlib.push_back(static_cast<std::uint8_t>(v >> 8));
        }
        zlib.insert(zlib.end(), raw.begin() + static_cast<std::ptrdiff_t>(at),
                    raw.begin() + static_cast<std::ptrdiff_t>(at + length));
        if (last) break;
    }
    putBigEndian32(zlib, adler32(raw.data(), raw.size()));

    std::vector<std::uint8_t> header;
    putBigEndian32(header, static_cast<std::uint32_t>(width));
    putBigEndian32(header, static_cast<std::uint32_t>(height));
    header.insert(header.end(), {8, 2, 0, 0, 0});  // bit depth 8, RGB, deflate, filter set 0, no interlace

    std::vector<std::uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    putChunk(png, "IHDR", header);
    putChunk(png, "IDAT", zlib);
    putChunk(png, "IEND", {});
    return png;
}

void writePng(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgbTopDown) {
    const std::vector<std::uint8_t> bytes = encodePng(width, height, rgbTopDown);
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (!file) throw std::runtime_error("cannot write '" + path + "'");
    const bool ok = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
    if (std::fclose(file) != 0 || !ok) throw std::runtime_error("cannot write '" + path + "'");
}

}  // namespace stepwise::viewer
