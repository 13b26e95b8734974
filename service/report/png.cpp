#include "png.h"

#include <zlib.h>

#include <cstdint>
#include <vector>

namespace gvm::report {
namespace {

void put_u32(std::string& out, uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out += static_cast<char>((v >> shift) & 0xff);
}

// A chunk: length, type, data, and the CRC of type and data.
void put_chunk(std::string& out, const char (&type)[5], const std::string& data) {
  put_u32(out, static_cast<uint32_t>(data.size()));
  const size_t type_at = out.size();
  out.append(type, 4);
  out += data;
  const auto* crc_from = reinterpret_cast<const Bytef*>(out.data() + type_at);
  put_u32(out, static_cast<uint32_t>(crc32(0L, crc_from, static_cast<uInt>(out.size() - type_at))));
}

// The 'up' filter (each byte minus the one above) on every row: rendered pictures are mostly
// flat areas, which it turns into runs of zeros that deflate packs well.
std::vector<uint8_t> filtered_rows(const Image& image) {
  const size_t stride = static_cast<size_t>(image.width) * 4;
  std::vector<uint8_t> raw;
  raw.reserve((stride + 1) * static_cast<size_t>(image.height));
  for (int y = 0; y < image.height; ++y) {
    raw.push_back(2);
    const uint8_t* row = image.rgba.data() + stride * static_cast<size_t>(y);
    for (size_t i = 0; i < stride; ++i) {
      const uint8_t above = y > 0 ? row[i - stride] : 0;
      raw.push_back(static_cast<uint8_t>(row[i] - above));
    }
  }
  return raw;
}

bool well_formed(const Image& image) {
  return image.width > 0 && image.height > 0 &&
         image.rgba.size() == static_cast<size_t>(image.width) * static_cast<size_t>(image.height) * 4;
}

}  // namespace

std::string zlib_deflate(std::string_view bytes) {
  uLongf size = compressBound(static_cast<uLong>(bytes.size()));
  std::string out(size, '\0');
  // compress2 fails only for lack of memory or a too small buffer, neither possible here.
  compress2(reinterpret_cast<Bytef*>(out.data()), &size, reinterpret_cast<const Bytef*>(bytes.data()),
            static_cast<uLong>(bytes.size()), Z_DEFAULT_COMPRESSION);
  out.resize(size);
  return out;
}

std::string encode_png(const Image& image) {
  if (!well_formed(image)) return encode_png(Image{1, 1, std::vector<uint8_t>(4, 0)});
  std::string header;
  put_u32(header, static_cast<uint32_t>(image.width));
  put_u32(header, static_cast<uint32_t>(image.height));
  header += std::string{8, 6, 0, 0, 0};  // bit depth 8, RGBA, deflate, adaptive filters, no interlace
  std::string out = "\x89PNG\r\n\x1a\n";
  put_chunk(out, "IHDR", header);
  const std::vector<uint8_t> rows = filtered_rows(image);
  put_chunk(out, "IDAT", zlib_deflate({reinterpret_cast<const char*>(rows.data()), rows.size()}));
  put_chunk(out, "IEND", "");
  return out;
}

}  // namespace gvm::report
