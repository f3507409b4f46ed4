// Camera: the one frame every ray is built from (CPU rays, the shaders' uniforms, the editor's
// controls), and the pixel footprint the hit threshold and reprojection margin scale with.
#include "core/camera.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace fraktal {
namespace {

void expectNear(const vec3& a, const vec3& b, double tolerance = 1e-12) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(Camera, BasisIsRightHandedOrthonormalAndLooksAtTheTarget) {
    Camera camera;
    camera.position = vec3(1.5, -2.0, 3.25);
    camera.target = vec3(-0.5, 0.25, 0.1);
    camera.up = vec3(0.2, 1.0, -0.3);  // not orthogonal to the look: the basis straightens it
    const CameraBasis b = camera.basis();
    expectNear(b.forward, normalize(camera.target - camera.position));
    EXPECT_NEAR(length(b.right), 1.0, 1e-12);
    EXPECT_NEAR(length(b.up), 1.0, 1e-12);
    EXPECT_NEAR(dot(b.right, b.up), 0.0, 1e-12);
    EXPECT_NEAR(dot(b.right, b.forward), 0.0, 1e-12);
    EXPECT_NEAR(dot(b.up, b.forward), 0.0, 1e-12);
    expectNear(glm::cross(b.right, b.up), -b.forward);  // x right, y up, looking down -z
    EXPECT_GT(dot(b.up, camera.up), 0.0);
    // The same frame as worldFromCamera's (glm::lookAt).
    const glm::dmat4 m = camera.worldFromCamera();
    expectNear(vec3(m[0]), b.right);
    expectNear(vec3(m[1]), b.up);
    expectNear(vec3(m[2]), -b.forward);
}

TEST(Camera, RaysThroughTheImageEdgesSpanTheFieldOfView) {
    Camera camera;
    camera.position = vec3(0.3, 0.4, 5.0);
    camera.target = vec3(0.0, 0.1, 0.0);
    camera.fovY = 50.0;
    const double aspect = 16.0 / 9.0;
    const CameraBasis b = camera.basis();
    expectNear(camera.rayDirection(0.0, 0.0, aspect), b.forward);
    const double halfFov = std::acos(dot(camera.rayDirection(0.0, 1.0, aspect), b.forward));
    EXPECT_NEAR(halfFov, glm::radians(25.0), 1e-12);
    EXPECT_GT(dot(camera.rayDirection(0.0, 1.0, aspect), b.up), 0.0);
    EXPECT_GT(dot(camera.rayDirection(1.0, 0.0, aspect), b.right), 0.0);
    EXPECT_NEAR(std::tan(std::acos(dot(camera.rayDirection(1.0, 0.0, aspect), b.forward))),
                camera.tanHalfFovY() * aspect, 1e-12);
    // A pixel of a 360-row image spans 1/360 of the image plane's height at unit distance.
    EXPECT_NEAR(camera.pixelAngle(360), 2.0 * std::tan(glm::radians(25.0)) / 360.0, 1e-15);
}

// The fish eye is equidistant: the angle from the view axis is fovY/2 times the distance from
// the centre in image heights' halves, in every direction (a 180-degree dome at the top edge).
// The equirectangular image spans 2 fovY across and fovY up whatever its aspect: at 180 degrees
// its left and right edges look backward and its top edge straight up. Their pixels are fovY /
// height (2 fovY / width across an equirectangular image narrower than 2:1).
TEST(Camera, WideProjectionsSpanTheirAngles) {
    Camera camera;
    camera.position = vec3(0.3, 0.4, 5.0);
    camera.target = vec3(0.0, 0.1, 0.0);
    camera.fovY = 180.0;
    const CameraBasis b = camera.basis();
    const double aspect = 16.0 / 9.0;
    camera.projection = Projection::FishEye;
    expectNear(camera.rayDirection(0.0, 0.0, aspect), b.forward);
    expectNear(camera.rayDirection(0.0, 1.0, aspect), b.up);
    expectNear(camera.rayDirection(0.5 / aspect, 0.0, aspect), normalize(b.forward + b.right));
    const vec3 corner = camera.rayDirection(0.6 / aspect, -0.8, aspect);
    EXPECT_NEAR(std::acos(dot(corner, b.forward)), glm::radians(90.0), 1e-12);  // |(0.6, -0.8)| = 1
    EXPECT_NEAR(dot(corner, b.right) / dot(corner, -b.up), 0.6 / 0.8, 1e-12);
    EXPECT_NEAR(camera.pixelAngle(360, 640), glm::radians(180.0) / 360.0, 1e-15);

    camera.projection = Projection::Equirectangular;
    expectNear(camera.rayDirection(0.0, 0.0, aspect), b.forward);
    expectNear(camera.rayDirection(1.0, 0.0, aspect), -b.forward);
    expectNear(camera.rayDirection(0.5, 0.0, aspect), b.right);
    expectNear(camera.rayDirection(0.5, 0.0, 2.0), b.right);  // the same whatever the aspect
    expectNear(camera.rayDirection(0.3, 1.0, aspect), b.up);
    EXPECT_NEAR(camera.pixelAngle(360, 720), glm::radians(180.0) / 360.0, 1e-15);
    EXPECT_NEAR(camera.pixelAngle(360, 640), glm::radians(360.0) / 640.0, 1e-15);
}

}  // namespace
}  // namespace fraktal
