#include "core/viewport/flight.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>

#include "core/image/png_writer.hpp"
#include "core/viewport/converge.hpp"
#include "core/viewport/image_error.hpp"

namespace fraktal::viewport {

namespace {

// Renders one frame and waits for the GPU, so the wall time is the frame's.
FrameStats timedFrame(Viewport& v, const Preset& p, const Camera& camera, int w, int h) {
    const auto start = std::chrono::steady_clock::now();
    FrameStats s = v.render(p.formula, camera, p.render, p.shading, w, h);
    glFinish();
    s.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return s;
}

}  // namespace

FlightResult fly(const Preset& preset, const FlightSettings& fs) {
    FlightResult result;
    Viewport viewport(fs.options);
    ViewportOptions referenceOptions = fs.options;
    referenceOptions.reproject = false;
    ViewportOptions centreOptions = referenceOptions;
    centreOptions.maxSamples = 1;  // under motion only sample 0 runs
    auto converged = [&](const ViewportOptions& options, const Camera& camera) {
        Viewport reference(options);
        return renderUntilSettled(reference, preset.formula, camera, preset.render, preset.shading, fs.width, fs.height,
                                  fs.maxRestFrames)
            .image;
    };
    Camera camera = preset.camera;
    if (fs.fromRest)
        renderUntilSettled(viewport, preset.formula, camera, preset.render, preset.shading, fs.width, fs.height,
                           fs.maxRestFrames);
    const int firstFrame = fs.fromRest ? 1 : 0;  // from rest, every counted frame moves
    const int movingWidth = fs.motionWidth > 0 ? fs.motionWidth : fs.width;
    const int movingHeight = fs.motionHeight > 0 ? fs.motionHeight : fs.height;
    double psnrSum = 0.0, psnrCentreSum = 0.0;
    for (int f = firstFrame; f < firstFrame + fs.frames; ++f) {
        camera = cameraOnPath(preset.camera, fs.path, f, fs.degreesPerFrame);
        FlightFrame frame;
        frame.stats = timedFrame(viewport, preset, camera, movingWidth, movingHeight);
        frame.psnrDb = frame.psnrCentreDb = NAN;
        if (fs.measureError) {
            const std::vector<float> image = viewport.readImage();
            const std::vector<float> reference = converged(referenceOptions, camera);
            const std::vector<float> centre = converged(centreOptions, camera);
            frame.psnrDb = std::min(displayPsnr(image, reference), 99.0);
            frame.psnrCentreDb = std::min(displayPsnr(image, centre), 99.0);
            if (!fs.dumpDirectory.empty()) {
                char name[32];
                std::snprintf(name, sizeof name, "frame_%03d", f);
                const auto png = [&](const char* suffix, const std::vector<float>& pixels) {
                    writePngAtomic(fs.dumpDirectory / (std::string(name) + suffix), fs.width, fs.height,
                                   displayRgb8(pixels));
                };
                png(".png", image);
                png("_ref.png", reference);
                png("_ref_centre.png", centre);
            }
            psnrSum += frame.psnrDb;
            psnrCentreSum += frame.psnrCentreDb;
        }
        result.meanDeEvalsPerPixel += frame.stats.deEvalsPerPixel / fs.frames;
        result.meanShadeDeEvalsPerPixel += frame.stats.shadeDeEvalsPerPixel / fs.frames;
        result.meanMilliseconds += frame.stats.milliseconds / fs.frames;
        result.frames.push_back(frame);
    }
    result.meanPsnrDb = fs.measureError ? psnrSum / fs.frames : NAN;
    result.meanPsnrCentreDb = fs.measureError ? psnrCentreSum / fs.frames : NAN;

    // The camera stops: record every image until settled, then compare them with the settled one.
    std::vector<std::vector<float>> rest;
    for (int f = 0; fs.restAfterPath && f < fs.maxRestFrames && !viewport.settled(); ++f) {
        result.restMillisecondsToSettle += timedFrame(viewport, preset, camera, fs.width, fs.height).milliseconds;
        if (fs.measureError) rest.push_back(viewport.readImage());
        result.restFramesToSettle = f + 1;
    }
    if (viewport.settled()) {
        result.settledDeEvalsPerPixel = timedFrame(viewport, preset, camera, fs.width, fs.height).deEvalsPerPixel;
        const std::vector<float> settledImage = viewport.readImage();
        for (size_t i = 0; i < rest.size(); ++i)
            if (displayPsnr(rest[i], settledImage) >= fs.restThresholdDb) {
                result.restFramesToThreshold = int(i) + 1;
                break;
            }
    }
    return result;
}

}  // namespace fraktal::viewport
