/// @file png_writer.hpp
/// @brief A minimal PNG encoder for screenshots: 8-bit RGB, uncompressed.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace stepwise::viewer {

/// @brief Encodes an RGB image as a PNG file's bytes.
///
/// The smallest PNG that every reader accepts, written by hand in about 80
/// lines so the viewer needs no image library. A PNG file is an 8-byte
/// signature and a list of chunks, each `length, type, data, CRC-32`:
///
/// - `IHDR`: width, height, bit depth 8, colour type 2 (RGB);
/// - `IDAT`: the image as a zlib stream. Each row is a filter byte (0, "none")
///   followed by its pixels. The zlib stream is a 2-byte header, the data
///   in *stored* deflate blocks (at most 65535 bytes each, no compression),
///   and the Adler-32 checksum of the data;
/// - `IEND`: empty, closes the file.
///
/// Stored blocks make the file as large as the raw pixels (3 bytes each);
/// what it buys is an encoder (and a decoder in the test) short enough to
/// read in one sitting. Specification: PNG (ISO/IEC 15948), RFC 1950 (zlib),
/// RFC 1951 (deflate).
/// @param width      pixels per row, > 0
/// @param height     rows, > 0
/// @param rgbTopDown width·height·3 bytes, the top row first
std::vector<std::uint8_t> encodePng(int width, int height, const std::vector<std::uint8_t>& rgbTopDown);

/// @brief Writes encodePng()'s bytes to @p path. @throws std::runtime_error when the file cannot be written.
void writePng(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgbTopDown);

/// @brief CRC-32 (ISO-HDLC, polynomial 0xEDB88320 reflected) of @p size bytes, as PNG chunks use.
std::uint32_t crc32(const std::uint8_t* data, std::size_t size);

/// @brief Adler-32 of @p size bytes, as the zlib stream's trailer uses (RFC 1950 §8.2).
std::uint32_t adler32(const std::uint8_t* data, std::size_t size);

}  // namespace stepwise::viewer
