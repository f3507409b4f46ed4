#!/usr/bin/env python3
"""Writes bench/stills/<preset>.fract: mandelbulber2 2.20 settings for the same scene as our preset.

Same formula and parameters, iteration count, bailout, camera (position, target, vertical field of
view), detail level and DE factor; shadows and ambient occlusion on; glow, reflections, fog off.
Size and anti-aliasing are set on mandelbulber2's command line by run.sh (-r, -O).

Axes: our presets are y-up, mandelbulber2 is z-up. Each scene is carried over by a proper rotation
(no mirror, so the image is not flipped) that maps our y onto mandelbulber2's z and under which the
fractal maps onto mandelbulber2's formula:
  - Menger, Mandelbox, Sierpinski: (x, y, z) -> (z, x, y), a cyclic permutation; the cube and the
    tetrahedron with vertex (1, 1, 1) are symmetric under it.
  - Mandelbulb: (x, y, z) -> (-x, z, y). Our bulb is the seed's (theta = acos(y / r) from the y axis,
    phi = atan2(x, z)); mandelbulber2's "Mandelbulb - Multi" (formula 65) in cosine mode with
    acos, atan2 and axis order zxy computes the same map in these coordinates (phi changes sign,
    which the -x absorbs). Its plain "Mandelbulb" (formula 2) uses asin, a different shape.

Camera: mandelbulber2 drives the view by camera_rotation (yaw, pitch, roll in degrees): forward =
(-sin(yaw) cos(pitch), cos(yaw) cos(pitch), sin(pitch)), checked against its defaults (camera
(3, -6, 2) looking at the origin: rotation 26.565, -16.60154). Its perspective field of view `fov`
is the tangent extent of the image height: fov = 2 tan(fovY / 2).
Detail: mandelbulber2 stops a ray at distance * pixel / detail_level (pixel = the footprint of one
pixel at unit distance); ours stops at distance * pixel * detail, so detail_level = 1 / detail.
"""
import json
import math
import pathlib

HERE = pathlib.Path(__file__).resolve().parent
PRESETS = HERE.parent.parent / "presets"


def number(v):
    return ("%.10g" % v).replace(".", ",")  # mandelbulber2 writes decimal commas


def vec(v):
    v = [c + 0.0 for c in v]  # no -0
    return " ".join(number(c) for c in v)


def cyclic(p):
    return (p[2], p[0], p[1])


def bulb_axes(p):
    return (-p[0], p[2], p[1])


SCENES = {
    "menger": (cyclic, {"formula_1": 7}, {}),
    "mandelbox": (cyclic, {"formula_1": 8}, {
        "mandelbox_scale": 2, "mandelbox_folding_limit": 1, "mandelbox_folding_value": 2,
        "mandelbox_folding_min_radius": 0.5, "mandelbox_folding_fixed_radius": 1}),
    "sierpinski_tetrahedron": (cyclic, {"formula_1": 110}, {}),
    "mandelbulb": (bulb_axes, {"formula_1": 65}, {
        "transf_pwr_8": 8, "mandelbulbMulti_order_of_xyz": 4, "mandelbulbMulti_acos_or_asin": 0,
        "mandelbulbMulti_atan_or_atan2": 1, "transf_function_enabledx_false": "true"}),
    # (+ c is added by mandelbulber2's main loop for this formula; its own "add c" would add it twice)
}


def main():
    for name, (axes, main_params, fractal_params) in SCENES.items():
        preset = json.loads((PRESETS / f"{name}.json").read_text())
        formula, camera = preset["formula"], preset["camera"]
        render = preset.get("render", {})
        position, target = axes(camera["position"]), axes(camera["target"])
        forward = [t - p for t, p in zip(target, position)]
        distance = math.sqrt(sum(c * c for c in forward))
        f = [c / distance for c in forward]
        yaw = math.degrees(math.atan2(-f[0], f[1]))
        pitch = math.degrees(math.asin(f[2]))
        sy, cy = math.sin(math.radians(yaw)), math.cos(math.radians(yaw))
        sp, cp = math.sin(math.radians(pitch)), math.cos(math.radians(pitch))
        top = (sy * sp, -cy * sp, cp)
        params = dict(main_params)
        params.update({
            "N": formula.get("iterations", 12),
            "bailout": formula.get("bailout", 4),
            "use_default_bailout": "false",
            "DE_factor": formula.get("deFactor", 1.0),
            "camera": vec(position),
            "target": vec(target),
            "camera_rotation": vec((yaw, pitch, 0.0)),
            "camera_top": vec(top),
            "camera_distance_to_target": number(distance),
            "fov": number(2 * math.tan(math.radians(camera.get("fovY", 40)) / 2)),
            "detail_level": number(1.0 / render.get("detail", 0.5)),
            "shadows_enabled": "true",
            "ambient_occlusion_enabled": "true",
            "ambient_occlusion_mode": 0,  # "fast": steps along the normal, as ours (the seed's)
            "glow_enabled": "false",
            "raytraced_reflections": "false",
            "antialiasing_enabled": "false",
        })
        lines = ["# Mandelbulber settings file", "# version 2.20", "# only modified parameters",
                 "[main_parameters]"]  # mandelbulber2 refuses any further comment line
        lines += [f"{k} {number(v) if isinstance(v, float) else v};" for k, v in sorted(params.items())]
        if fractal_params:
            lines.append("[fractal_1]")
            lines += [f"{k} {number(v) if isinstance(v, float) else v};" for k, v in sorted(fractal_params.items())]
        (HERE / f"{name}.fract").write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
