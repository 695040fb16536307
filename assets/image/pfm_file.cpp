#include "assets/image/pfm_file.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include "assets/atomic_file.h"
#include "assets/input_error.h"

namespace pt {
namespace {

bool hostIsLittleEndian() {
    const uint32_t one = 1;
    uint8_t first = 0;
    std::memcpy(&first, &one, 1);
    return first == 1;
}

float byteSwapped(float v) {
    uint32_t bits;
    std::memcpy(&bits, &v, 4);
    bits = (bits >> 24) | ((bits >> 8) & 0xff00u) | ((bits << 8) & 0xff0000u) | (bits << 24);
    std::memcpy(&v, &bits, 4);
    return v;
}

}  // namespace

bool isPfmPath(const std::string& path) {
    if (path.size() < 4) return false;
    std::string extension = path.substr(path.size() - 4);
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    return extension == ".pfm";
}

void writePfm(const std::string& path, uint32_t width, uint32_t height, const std::vector<float>& rgba) {
    if (rgba.size() != size_t(width) * height * 4) {
        throw InputError(path + ": " + std::to_string(rgba.size()) + " floats for a " +
                         std::to_string(width) + "x" + std::to_string(height) + " RGBA image");
    }
    writeFileAtomically(path, [&](const std::string& temp) {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        // A negative scale says little-endian; rows go from the bottom up.
        out << "PF\n" << width << " " << height << "\n-1.0\n";
        std::vector<float> row(size_t(width) * 3);
        for (uint32_t y = height; y-- > 0;) {
            for (uint32_t x = 0; x < width; ++x) {
                for (int c = 0; c < 3; ++c) {
                    const float v = rgba[(size_t(y) * width + x) * 4 + c];
                    row[size_t(x) * 3 + c] = hostIsLittleEndian() ? v : byteSwapped(v);
                }
            }
            out.write(reinterpret_cast<const char*>(row.data()), std::streamsize(row.size() * sizeof(float)));
        }
        out.close();
        if (!out) throw InputError(path + ": cannot write the PFM image");
    });
}

std::vector<float> readPfm(const std::string& path, uint32_t& width, uint32_t& height) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path + ": cannot open the file");
    std::string magic;
    long long w = 0, h = 0;
    double scale = 0.0;
    in >> magic >> w >> h >> scale;
    if (!in || (magic != "PF" && magic != "Pf"))
        throw InputError(path + ": not a PFM file (no PF/Pf header)");
    if (w <= 0 || h <= 0 || w > 65536 || h > 65536) {
        throw InputError(path + ": PFM size " + std::to_string(w) + "x" + std::to_string(h) +
                         " is out of range");
    }
    if (scale == 0.0 || !std::isfinite(scale))
        throw InputError(path + ": PFM scale must be a non-zero number");
    in.get();  // the single whitespace character that ends the header
    const size_t channels = magic == "PF" ? 3 : 1;
    const size_t bytes = size_t(w) * size_t(h) * channels * sizeof(float);
    const auto truncated = [&](std::streamoff got) {
        return InputError(path + ": PFM pixel data is truncated (" + std::to_string(got) + " of " +
                          std::to_string(bytes) + " bytes)");
    };
    // The pixels must be in the file before memory is taken for them: a header of a few bytes
    // may claim 65536 x 65536 (48 GiB; found by fuzzing, issue 17).
    const std::streamoff pixelsStart = in.tellg();
    in.seekg(0, std::ios::end);
    const std::streamoff available = std::max<std::streamoff>(in.tellg() - pixelsStart, 0);
    in.seekg(pixelsStart);
    if (!in || uint64_t(available) < bytes) throw truncated(available);
    std::vector<float> data(bytes / sizeof(float));
    in.read(reinterpret_cast<char*>(data.data()), std::streamsize(bytes));
    if (in.gcount() != std::streamsize(bytes)) throw truncated(in.gcount());
    const bool swap = (scale < 0.0) != hostIsLittleEndian();
    width = uint32_t(w);
    height = uint32_t(h);
    std::vector<float> rgba(size_t(width) * height * 4, 1.0f);
    for (uint32_t y = 0; y < height; ++y) {
        const size_t fileRow = size_t(height - 1 - y);  // PFM rows run from the bottom
        for (uint32_t x = 0; x < width; ++x) {
            for (size_t c = 0; c < 3; ++c) {
                float v = data[(fileRow * width + x) * channels + (channels == 3 ? c : 0)];
                rgba[(size_t(y) * width + x) * 4 + c] = swap ? byteSwapped(v) : v;
            }
        }
    }
    return rgba;
}

}  // namespace pt
