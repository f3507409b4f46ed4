// Sampling error of a render's coverage (alpha) against a converged render of the same scene, so
// renderers that shade differently (fraktal, mandelbulber2) can be compared at equal quality: both
// write the share of each pixel the object covers, and the silhouette is where too few samples
// show as jaggies. Built and run by bench/stills/equal_quality.sh.
// Errors: RMSE of coverage over all pixels and over the edge pixels (those the truth covers
// partly: the set is the same for every image scored against one truth).
// Usage: coverage_error TRUTH IMAGE [PGM]   (each an EXR with an A channel, or a 16-bit PNG: its
// alpha, or an opaque one's first channel, a white-on-black mask). Prints: rmse edge_rmse edge_px.
// PGM: also writes the truth and the image side by side there.
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <stb_image.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

struct Coverage {
    int width = 0, height = 0;
    std::vector<float> alpha;
};

Coverage readExrAlpha(const std::string& path) {
    Imf::InputFile file(path.c_str());
    const Imath::Box2i dw = file.header().dataWindow();
    Coverage c;
    c.width = dw.max.x - dw.min.x + 1;
    c.height = dw.max.y - dw.min.y + 1;
    if (!file.header().channels().findChannel("A")) throw std::runtime_error(path + ": no A channel");
    c.alpha.assign(size_t(c.width) * size_t(c.height), 0.0f);
    Imf::FrameBuffer fb;
    char* base = reinterpret_cast<char*>(c.alpha.data()) -
                 (ptrdiff_t(dw.min.x) + ptrdiff_t(dw.min.y) * c.width) * ptrdiff_t(sizeof(float));
    fb.insert("A", Imf::Slice(Imf::FLOAT, base, sizeof(float), sizeof(float) * size_t(c.width)));
    file.setFrameBuffer(fb);
    file.readPixels(dw.min.y, dw.max.y);
    return c;
}

Coverage readPngCoverage(const std::string& path) {
    int w = 0, h = 0, n = 0;
    stbi_us* pixels = stbi_load_16(path.c_str(), &w, &h, &n, 4);
    if (!pixels) throw std::runtime_error(path + ": " + stbi_failure_reason());
    Coverage c{w, h, std::vector<float>(size_t(w) * size_t(h))};
    const int channel = n == 2 || n == 4 ? 3 : 0;  // alpha, or an opaque mask's grey
    for (size_t i = 0; i < c.alpha.size(); ++i) c.alpha[i] = float(pixels[4 * i + channel]) / 65535.0f;
    stbi_image_free(pixels);
    return c;
}

Coverage readCoverage(const std::string& path) {
    return path.ends_with(".exr") ? readExrAlpha(path) : readPngCoverage(path);
}

}  // namespace

int main(int argc, char** argv) try {
    if (argc != 3 && argc != 4) {
        std::fprintf(stderr, "usage: %s TRUTH IMAGE [PGM]\n", argv[0]);
        return 2;
    }
    const Coverage truth = readCoverage(argv[1]);
    const Coverage image = readCoverage(argv[2]);
    if (truth.width != image.width || truth.height != image.height)
        throw std::runtime_error("the truth and the image differ in size");

    double squares = 0.0, edgeSquares = 0.0;
    long edges = 0;
    const auto partly = [](double c) { return c > 1e-3 && c < 1.0 - 1e-3; };
    for (size_t i = 0; i < image.alpha.size(); ++i) {
        const double error = double(image.alpha[i]) - double(truth.alpha[i]);
        squares += error * error;
        if (partly(truth.alpha[i])) ++edges, edgeSquares += error * error;
    }
    if (argc == 4) {
        std::FILE* out = std::fopen(argv[3], "wb");
        if (!out) throw std::runtime_error(std::string(argv[3]) + ": cannot write");
        std::fprintf(out, "P5 %d %d 255\n", image.width * 2, image.height);
        for (int y = 0; y < image.height; ++y)
            for (const Coverage* c : {&truth, &image})
                for (int x = 0; x < image.width; ++x)
                    std::fputc(int(std::lround(255.0 * std::clamp(c->alpha[size_t(y) * size_t(image.width) + size_t(x)],
                                                                  0.0f, 1.0f))),
                               out);
        std::fclose(out);
    }
    std::printf("%.5f %.5f %ld\n", std::sqrt(squares / double(image.alpha.size())),
                std::sqrt(edgeSquares / double(std::max(edges, 1L))), edges);
    return 0;
} catch (const std::exception& e) {
    std::fprintf(stderr, "coverage_error: %s\n", e.what());
    return 1;
}
