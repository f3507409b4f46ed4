// Compares the depth (Z) of a render with a reference render of the same view: the pixels where
// the reference meets the object and the render does not (its rays stepped past the surface, or
// gave up), where it lands behind the reference's hit (a step through the surface to something
// further), and where it meets something the reference does not.
// Usage: depth_compare REFERENCE.exr RENDER.exr
// Prints: reference_hits missed deeper_10pct extra_hits
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>

#include <cmath>
#include <cstdio>
#include <vector>

namespace {

std::vector<float> depthOf(const char* path, int& width, int& height) {
    Imf::InputFile file(path);
    const Imath::Box2i window = file.header().dataWindow();
    width = window.max.x - window.min.x + 1;
    height = window.max.y - window.min.y + 1;
    std::vector<float> z(size_t(width) * size_t(height));
    Imf::FrameBuffer frame;
    char* origin = reinterpret_cast<char*>(z.data() - window.min.x - ptrdiff_t(window.min.y) * width);
    frame.insert("Z", Imf::Slice(Imf::FLOAT, origin, sizeof(float), sizeof(float) * size_t(width)));
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
    return z;
}

// A miss has depth 1e30 (core/image/image_strip.hpp: "depth of the nearest hit").
bool isHit(float z) { return std::isfinite(z) && z < 1e9f; }

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: %s REFERENCE.exr RENDER.exr\n", argv[0]);
        return 2;
    }
    int w = 0, h = 0, w2 = 0, h2 = 0;
    const std::vector<float> reference = depthOf(argv[1], w, h), render = depthOf(argv[2], w2, h2);
    if (w != w2 || h != h2) {
        std::fprintf(stderr, "%s is %dx%d, %s %dx%d\n", argv[1], w, h, argv[2], w2, h2);
        return 2;
    }
    long hits = 0, missed = 0, deeper = 0, extra = 0;
    for (size_t i = 0; i < reference.size(); ++i) {
        const bool r = isHit(reference[i]), t = isHit(render[i]);
        hits += r;
        if (r && !t) ++missed;
        if (r && t && render[i] > 1.1f * reference[i]) ++deeper;
        if (!r && t) ++extra;
    }
    std::printf("%ld %ld %ld %ld\n", hits, missed, deeper, extra);
    return 0;
}
