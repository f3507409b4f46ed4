// fraktal's own stand-ins for FragM's standard includes, so that a frag opens without FragM
// installed. MathUtils.frag and Complex.frag: the functions DE code calls, with FragM's names and
// meaning (written for fraktal from what they compute, not copied). The raytracers and 3D.frag:
// only what a DE reads of them (PI, orbitTrap), since fraktal renders the frag itself.
#pragma once

#include <map>
#include <string>

namespace fraktal::frag {

// Include name as a frag writes it ("MathUtils.frag") -> fraktal's text for it.
const std::map<std::string, std::string, std::less<>>& builtinIncludes();

// Whether the include is one of the raytracers (or the camera/buffer includes) that fraktal
// replaces with its own renderer.
bool isRaytracerInclude(std::string_view name);

}  // namespace fraktal::frag
