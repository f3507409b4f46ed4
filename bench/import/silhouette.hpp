// Hit masks of a scene's silhouette and their agreement: a pixel is a hit where the object covers
// at least half of it (fraktal's EXR A channel; a PNG's alpha, 8- or 16-bit). Shared by
// bench/import/silhouette_iou.cpp (Mandelbulber2's masks), bench/frag (a frag's own raytracer's,
// bench_frag_host) and the test that runs the frag host (tests/frag_host_test.cpp).
#pragma once

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <stb/stb_image.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace fraktal::silhouette {

struct Mask {
    int width = 0, height = 0;
    std::vector<unsigned char> hit;
};

inline Mask readExrMask(const std::string& path) {
    Imf::InputFile file(path.c_str());
    const Imath::Box2i dw = file.header().dataWindow();
    Mask m{dw.max.x - dw.min.x + 1, dw.max.y - dw.min.y + 1, {}};
    if (!file.header().channels().findChannel("A")) throw std::runtime_error(path + ": no A channel");
    std::vector<float> alpha(size_t(m.width) * size_t(m.height));
    Imf::FrameBuffer fb;
    char* base = reinterpret_cast<char*>(alpha.data()) -
                 (ptrdiff_t(dw.min.x) + ptrdiff_t(dw.min.y) * m.width) * ptrdiff_t(sizeof(float));
    fb.insert("A", Imf::Slice(Imf::FLOAT, base, sizeof(float), sizeof(float) * size_t(m.width)));
    file.setFrameBuffer(fb);
    file.readPixels(dw.min.y, dw.max.y);
    for (float a : alpha) m.hit.push_back(a >= 0.5f);
    return m;
}

inline Mask readPngMask(const std::string& path) {
    int w = 0, h = 0, n = 0;
    stbi_us* pixels = stbi_load_16(path.c_str(), &w, &h, &n, 4);
    if (!pixels) throw std::runtime_error(path + ": " + stbi_failure_reason());
    Mask m{w, h, {}};
    for (size_t i = 0; i < size_t(w) * size_t(h); ++i) m.hit.push_back(pixels[4 * i + 3] >= 32768);
    stbi_image_free(pixels);
    return m;
}

inline Mask readMask(const std::string& path) { return path.ends_with(".exr") ? readExrMask(path) : readPngMask(path); }

struct Agreement {
    double iou = 1.0;  // intersection over union; two empty masks agree (neither sees the object)
    long aPixels = 0, bPixels = 0;
};

inline Agreement compare(const Mask& a, const Mask& b) {
    if (a.width != b.width || a.height != b.height) throw std::runtime_error("the two images differ in size");
    long both = 0, either = 0;
    Agreement r;
    for (size_t i = 0; i < a.hit.size(); ++i) {
        both += a.hit[i] && b.hit[i], either += a.hit[i] || b.hit[i];
        r.aPixels += a.hit[i], r.bPixels += b.hit[i];
    }
    if (either) r.iou = double(both) / double(either);
    return r;
}

}  // namespace fraktal::silhouette
