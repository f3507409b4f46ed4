// Silhouettes of one scene from fraktal and from Mandelbulber2, compared: the intersection over
// union of the two hit masks (a pixel is a hit where the object covers at least half of it:
// fraktal's EXR A channel, Mandelbulber2's 16-bit PNG alpha). Built and run by bench/import/run.sh.
// Usage:
//   silhouette_iou FRAKTAL.exr MB2.png            prints: iou fraktal_px mb2_px
//   silhouette_iou --sheet OUT.png A.exr B.png ...  a contact sheet: one row per pair, fraktal's
//                                                 mask, Mandelbulber2's, and both (yellow: both,
//                                                 red: fraktal only, green: Mandelbulber2 only)
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <stb_image.h>
#include <stb_image_write.h>

#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

struct Mask {
    int width = 0, height = 0;
    std::vector<unsigned char> hit;
};

Mask readExrMask(const std::string& path) {
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

Mask readPngMask(const std::string& path) {
    int w = 0, h = 0, n = 0;
    stbi_us* pixels = stbi_load_16(path.c_str(), &w, &h, &n, 4);
    if (!pixels) throw std::runtime_error(path + ": " + stbi_failure_reason());
    Mask m{w, h, {}};
    for (size_t i = 0; i < size_t(w) * size_t(h); ++i) m.hit.push_back(pixels[4 * i + 3] >= 32768);
    stbi_image_free(pixels);
    return m;
}

Mask readMask(const std::string& path) { return path.ends_with(".exr") ? readExrMask(path) : readPngMask(path); }

}  // namespace

int main(int argc, char** argv) try {
    if (argc >= 5 && std::string(argv[1]) == "--sheet" && (argc - 3) % 2 == 0) {
        std::vector<Mask> a, b;
        for (int i = 3; i < argc; i += 2) a.push_back(readMask(argv[i])), b.push_back(readMask(argv[i + 1]));
        const int w = a[0].width, h = a[0].height, gap = 4;
        const int sheetW = 3 * w + 2 * gap, sheetH = int(a.size()) * (h + gap);
        std::vector<unsigned char> rgb(size_t(sheetW) * size_t(sheetH) * 3, 40);
        for (size_t row = 0; row < a.size(); ++row)
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x) {
                    if (a[row].width != w || b[row].width != w || a[row].height != h || b[row].height != h) continue;
                    const bool fa = a[row].hit[size_t(y * w + x)], fb = b[row].hit[size_t(y * w + x)];
                    auto put = [&](int column, unsigned char r, unsigned char g, unsigned char bl) {
                        unsigned char* p = &rgb[(size_t(row) * size_t(h + gap) + size_t(y)) * size_t(sheetW) * 3 +
                                                size_t(column * (w + gap) + x) * 3];
                        p[0] = r, p[1] = g, p[2] = bl;
                    };
                    put(0, fa ? 230 : 0, fa ? 230 : 0, fa ? 230 : 0);
                    put(1, fb ? 230 : 0, fb ? 230 : 0, fb ? 230 : 0);
                    put(2, fa ? 230 : 0, fb ? 230 : 0, 0);
                }
        if (!stbi_write_png(argv[2], sheetW, sheetH, 3, rgb.data(), sheetW * 3))
            throw std::runtime_error(std::string("cannot write ") + argv[2]);
        return 0;
    }
    if (argc != 3) {
        std::fprintf(stderr, "usage: %s FRAKTAL.exr MB2.png | --sheet OUT.png A.exr B.png ...\n", argv[0]);
        return 2;
    }
    const Mask a = readMask(argv[1]), b = readMask(argv[2]);
    if (a.width != b.width || a.height != b.height) throw std::runtime_error("the two images differ in size");
    long both = 0, either = 0, na = 0, nb = 0;
    for (size_t i = 0; i < a.hit.size(); ++i) {
        both += a.hit[i] && b.hit[i], either += a.hit[i] || b.hit[i];
        na += a.hit[i], nb += b.hit[i];
    }
    // Two empty masks agree (both programs see no object).
    std::printf("%.4f %ld %ld\n", either ? double(both) / double(either) : 1.0, na, nb);
    return 0;
} catch (const std::exception& e) {
    std::fprintf(stderr, "silhouette_iou: %s\n", e.what());
    return 1;
}
