#include "core/scene_object.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace fraktal {

const ObjectDesc* findObject(std::string_view id) {
    for (const ObjectDesc& o : allObjects())
        if (o.id == id) return &o;
    return nullptr;
}

SceneObject SceneObject::make(const ObjectDesc& kind) {
    SceneObject o;
    o.block = &kind;
    for (const ParamDecl& p : kind.params) o.values.push_back(p.defaultValue);
    return o;
}

vec3 repeatCell(const vec3& x, const vec3& period) {
    vec3 cell = x;
    for (int a = 0; a < 3; ++a)
        if (period[a] > 0.0) cell[a] = x[a] - period[a] * std::floor(x[a] / period[a] + 0.5);
    return cell;
}

glm::dmat3 Placement::localFromWorld() const {
    if (!turned()) return glm::dmat3(1.0);
    const glm::dmat3 turn(glm::rotate(glm::dmat4(1.0), glm::radians(angle), normalize(axis)));
    return glm::transpose(turn);
}

double SceneObject::distanceAt(const vec3& pos) const {
    const double d = block->distance(repeatCell(localFromWorld() * (pos - center), repeat), args());
    return hollow ? std::abs(d) : d;
}

// Mirrors fraktalObjects() in the generated GLSL (core/glsl_gen.cpp): keep the two in step.
double combineObjects(const std::vector<SceneObject>& objects, const vec3& pos, double distance, bool& inside,
                      bool escapeTime, int& surface) {
    for (size_t k = 0; k < objects.size(); ++k) {
        const SceneObject& o = objects[k];
        if (!o.enabled) continue;
        const double od = o.distanceAt(pos);
        // The object's distance as the operation takes it; it becomes the result's where it wins.
        double taken = od;
        bool wins = false;
        switch (o.operation) {
            case ObjectOperation::Join:
                wins = od < distance;
                if (od <= 0.0) inside = true;
                break;
            case ObjectOperation::Intersect:
                wins = od > distance;
                if (od > 0.0) inside = false;
                break;
            case ObjectOperation::Carve:
                taken = -od;
                wins = taken > distance;
                if (od <= 0.0) inside = false;
                break;
        }
        if (wins) {
            distance = taken;
            // An intersecting object is a limit box: its faces are the fractal's inside, cut
            // open, and keep the surface before it (as Mandelbulber2 colours a limit box's cut).
            if (o.operation != ObjectOperation::Intersect) surface = int(k);
        }
    }
    if (!escapeTime) inside = distance <= 0.0;
    return distance;
}

}  // namespace fraktal
