// Times ExrStripWriter alone (no rendering): reads an EXR that `fraktal render` wrote, strip by
// strip, into ImageStrips shaped like the renderer's, and writes them again, timing only the
// writer. Built and run by bench/stills/exr_write.sh.
// Usage: exr_write IN.exr OUT.exr THREADS
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>

#include "core/image/exr_writer.hpp"
#include "core/render/tiles.hpp"

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: %s IN.exr OUT.exr THREADS\n", argv[0]);
        return 2;
    }
    using namespace fraktal;
    Imf::InputFile in(argv[1]);
    const Imath::Box2i dw = in.header().dataWindow();
    const int width = dw.max.x - dw.min.x + 1, height = dw.max.y - dw.min.y + 1;
    ExrMetadata meta;
    meta.presetJson = readExrPreset(argv[1]);
    double writeSeconds = 0.0, writeCpuSeconds = 0.0;  // wall clock; CPU time of every thread
    {
        const auto t0 = std::chrono::steady_clock::now();
        std::clock_t c0 = std::clock();
        ExrStripWriter out(argv[2], width, height, false, meta, std::atoi(argv[3]));
        writeSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        writeCpuSeconds += double(std::clock() - c0) / CLOCKS_PER_SEC;
        ImageStrip strip;
        for (const TileRect& s : stripsOf(width, height, stillStripRows(width, 256))) {
            strip.resize(width, s.y, s.height);
            Imf::FrameBuffer fb;
            for (const ExrChannelSource& c : exrStripChannels())
                fb.insert(c.name, Imf::Slice::Make(Imf::FLOAT, strip.buffers()[size_t(c.buffer)]->data() + c.component,
                                                   Imath::V2i(dw.min.x, dw.min.y + s.y), width, s.height,
                                                   4 * sizeof(float), 4 * sizeof(float) * size_t(width)));
            in.setFrameBuffer(fb);
            in.readPixels(dw.min.y + s.y, dw.min.y + s.y + s.height - 1);
            const auto t1 = std::chrono::steady_clock::now();
            c0 = std::clock();
            out.write(strip);
            writeSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
            writeCpuSeconds += double(std::clock() - c0) / CLOCKS_PER_SEC;
        }
        const auto t2 = std::chrono::steady_clock::now();
        c0 = std::clock();
        out.close();
        writeSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t2).count();
        writeCpuSeconds += double(std::clock() - c0) / CLOCKS_PER_SEC;
    }
    std::printf("%dx%d, %s compression threads (0: one per core): write %.2f s wall (%.1f Mpixel/s), %.2f s CPU\n",
                width, height, argv[3], writeSeconds, double(width) * height / writeSeconds / 1e6, writeCpuSeconds);
    return 0;
}
