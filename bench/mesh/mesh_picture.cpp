// A picture of a mesh file as a slicer or a viewer would show it, drawn on the CPU: the file read
// back with Assimp (core/mesh/mesh_file.hpp, as another program reads it), rasterised with a depth
// buffer, each triangle lit by a key light and a headlight (Lambert) and coloured by its vertices'
// colours (grey without), 3x3 supersampled. For the README's gallery and for looking at a print
// before printing it; not a renderer.
// Usage: bench_mesh_picture MESH.{ply,obj,stl,glb} OUT.png [SIZE] [AZIMUTH_DEG ELEVATION_DEG]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <vector>

#include "core/image/png_writer.hpp"
#include "core/mesh/mesh_file.hpp"

using fraktal::vec3;

namespace {

struct View {
    vec3 right, up, forward;  // camera axes (forward into the picture)
    vec3 centre;
    double scale;  // pixels per mesh unit
    int size;
};

double srgbEncode(double linear) {
    const double c = std::clamp(linear, 0.0, 1.0);
    return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3 && argc != 4 && argc != 6) {
        std::fprintf(stderr, "usage: %s MESH OUT.png [SIZE] [AZIMUTH_DEG ELEVATION_DEG]\n", argv[0]);
        return 2;
    }
    const int size = argc >= 4 ? std::atoi(argv[3]) : 640;
    const double azimuth = (argc == 6 ? std::atof(argv[4]) : 35.0) * M_PI / 180.0;
    const double elevation = (argc == 6 ? std::atof(argv[5]) : 25.0) * M_PI / 180.0;
    const fraktal::mesh::TriangleMesh mesh = fraktal::mesh::readMesh(argv[1]);
    if (mesh.triangles.empty()) {
        std::fprintf(stderr, "%s: no triangles\n", argv[1]);
        return 1;
    }
    const auto box = mesh.bounds();
    View v;
    v.forward =
        -vec3(std::cos(elevation) * std::sin(azimuth), std::sin(elevation), std::cos(elevation) * std::cos(azimuth));
    v.right = glm::normalize(glm::cross(v.forward, vec3(0.0, 1.0, 0.0)));
    v.up = glm::cross(v.right, v.forward);
    v.centre = 0.5 * (box[0] + box[1]);
    v.size = size * 3;  // supersampled
    const vec3 extent = box[1] - box[0];
    // A box seen from a corner spans up to about 1.45 times its largest side.
    v.scale = 0.9 * v.size / (1.45 * std::max(extent.x, std::max(extent.y, extent.z)));
    const vec3 key = glm::normalize(-v.forward + v.up * 0.8 - v.right * 0.6);

    const int n = v.size;
    std::vector<double> depth(size_t(n) * n, std::numeric_limits<double>::infinity());
    std::vector<vec3> colour(size_t(n) * n, vec3(0.93, 0.94, 0.96));  // a light studio grey
    const bool coloured = mesh.colors.size() == mesh.points.size();
    for (const auto& t : mesh.triangles) {
        vec3 p[3], screen[3];
        for (int k = 0; k < 3; ++k) {
            p[k] = mesh.point(t[k]);
            const vec3 q = p[k] - v.centre;
            screen[k] = vec3(0.5 * n + glm::dot(q, v.right) * v.scale, 0.5 * n - glm::dot(q, v.up) * v.scale,
                             glm::dot(q, v.forward));
        }
        const vec3 normal = glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0]));
        if (!std::isfinite(normal.x)) continue;
        // Two-sided: a cut-away or an inner wall shows lit too.
        const double facing = glm::dot(normal, v.forward) < 0.0 ? 1.0 : -1.0;
        const double light = 0.25 + 0.55 * std::max(0.0, facing * glm::dot(normal, key)) +
                             0.2 * std::max(0.0, -facing * glm::dot(normal, v.forward));
        vec3 albedo(0.62);
        if (coloured) {
            albedo = vec3(0.0);
            for (uint32_t i : t) albedo += vec3(mesh.colors[i][0], mesh.colors[i][1], mesh.colors[i][2]) / 3.0;
        }
        const vec3 shade = albedo * light;
        const double area = (screen[1].x - screen[0].x) * (screen[2].y - screen[0].y) -
                            (screen[2].x - screen[0].x) * (screen[1].y - screen[0].y);
        if (std::abs(area) < 1e-12) continue;
        const int x0 = std::max(0, int(std::floor(std::min({screen[0].x, screen[1].x, screen[2].x}))));
        const int x1 = std::min(n - 1, int(std::ceil(std::max({screen[0].x, screen[1].x, screen[2].x}))));
        const int y0 = std::max(0, int(std::floor(std::min({screen[0].y, screen[1].y, screen[2].y}))));
        const int y1 = std::min(n - 1, int(std::ceil(std::max({screen[0].y, screen[1].y, screen[2].y}))));
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const double px = x + 0.5, py = y + 0.5;
                double w[3];
                for (int k = 0; k < 3; ++k) {
                    const vec3 &a = screen[(k + 1) % 3], &b = screen[(k + 2) % 3];
                    w[k] = ((b.x - a.x) * (py - a.y) - (px - a.x) * (b.y - a.y)) / area;
                }
                if (w[0] < 0.0 || w[1] < 0.0 || w[2] < 0.0) continue;
                const double z = w[0] * screen[0].z + w[1] * screen[1].z + w[2] * screen[2].z;
                const size_t at = size_t(y) * n + x;
                if (z >= depth[at]) continue;
                depth[at] = z;
                colour[at] = shade;
            }
    }
    std::vector<uint8_t> rgb(size_t(size) * size * 3);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            vec3 sum(0.0);
            for (int dy = 0; dy < 3; ++dy)
                for (int dx = 0; dx < 3; ++dx) sum += colour[size_t(3 * y + dy) * n + 3 * x + dx];
            for (int c = 0; c < 3; ++c)
                rgb[(size_t(y) * size + x) * 3 + c] = uint8_t(std::lround(255.0 * srgbEncode(sum[c] / 9.0)));
        }
    fraktal::writePngAtomic(argv[2], size, size, rgb);
    std::printf("%s: %zu triangles drawn into %s (%dx%d)\n", argv[1], mesh.triangles.size(), argv[2], size, size);
    return 0;
}
