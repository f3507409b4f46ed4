// Silhouettes of one scene from fraktal and from a peer (Mandelbulber2, or a frag's own raytracer),
// compared: the intersection over union of the two hit masks (silhouette.hpp). Built and run by
// bench/import/run.sh and bench/frag/run.sh.
// Usage:
//   silhouette_iou FRAKTAL.exr MB2.png            prints: iou fraktal_px mb2_px
//   silhouette_iou --sheet OUT.png A.exr B.png ...  a contact sheet: one row per pair, fraktal's
//                                                 mask, Mandelbulber2's, and both (yellow: both,
//                                                 red: fraktal only, green: Mandelbulber2 only)
#include <stb_image_write.h>

#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "silhouette.hpp"

using namespace fraktal::silhouette;

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
    const Agreement r = compare(readMask(argv[1]), readMask(argv[2]));
    std::printf("%.4f %ld %ld\n", r.iou, r.aPixels, r.bPixels);
    return 0;
} catch (const std::exception& e) {
    std::fprintf(stderr, "silhouette_iou: %s\n", e.what());
    return 1;
}
