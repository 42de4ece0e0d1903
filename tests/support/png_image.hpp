#pragma once
// Reading a PNG's pixels in tests (libpng's simplified API): the figures'
// content checks (heatmap frame, trail pixels, report screenshots).
#include <png.h>

#include <array>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace cic::testing {

struct RgbImage {
    int width = 0, height = 0;
    std::vector<unsigned char> rgb;   // rows from the top, 3 bytes a pixel
    std::array<int, 3> at(int x, int y) const {
        const std::size_t i = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x));
        return {rgb[i], rgb[i + 1], rgb[i + 2]};
    }
};

inline RgbImage read_png(const std::filesystem::path& file) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&image, file.c_str()))
        throw std::runtime_error("cannot read " + file.string() + ": " + image.message);
    image.format = PNG_FORMAT_RGB;
    RgbImage out;
    out.width = static_cast<int>(image.width);
    out.height = static_cast<int>(image.height);
    out.rgb.resize(PNG_IMAGE_SIZE(image));
    if (!png_image_finish_read(&image, nullptr, out.rgb.data(), 0, nullptr))
        throw std::runtime_error("cannot decode " + file.string() + ": " + image.message);
    return out;
}

} // namespace cic::testing
