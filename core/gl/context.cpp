#include "core/gl/context.hpp"

// EGL comes from <EGL/egl.h>, GL from epoxy: epoxy's own eglGetPlatformDisplay aborts on
// EGL 1.4 displays (shared/PLATFORM.md), so the EXT entry point is loaded by hand.
// epoxy first: it defines the Khronos types that <EGL/egl.h> would otherwise redeclare.
#include <epoxy/gl.h>
// (after epoxy)
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <dlfcn.h>
#include <link.h>

#include <cstring>
#include <stdexcept>

namespace fraktal::gl {

namespace {

constexpr const char* kInstallHint =
    "a headless OpenGL 4.5 context needs EGL and Mesa: apt-get install libegl1 libgl1-mesa-dri "
    "(scripts/install-deps.sh installs everything)";

std::string eglErrorText(EGLint e) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "EGL error 0x%04x", unsigned(e));
    return buf;
}

EGLDisplay openDisplay(std::string& why) {
    auto getPlatformDisplay =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (getPlatformDisplay) {
        EGLDisplay d = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (d != EGL_NO_DISPLAY && eglInitialize(d, nullptr, nullptr)) return d;
        why += "surfaceless platform: " + eglErrorText(eglGetError()) + "; ";
        // An EGL device (a GPU driver's, or Mesa's software device).
        auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
        if (queryDevices) {
            EGLDeviceEXT devices[8];
            EGLint count = 0;
            if (queryDevices(8, devices, &count)) {
                for (EGLint i = 0; i < count; ++i) {
                    d = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
                    if (d != EGL_NO_DISPLAY && eglInitialize(d, nullptr, nullptr)) return d;
                }
            }
            why += "EGL devices: none usable; ";
        }
    } else {
        why += "eglGetPlatformDisplayEXT is missing; ";
    }
    EGLDisplay d = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    if (d != EGL_NO_DISPLAY && eglInitialize(d, nullptr, nullptr)) return d;
    why += "default display: " + eglErrorText(eglGetError());
    return EGL_NO_DISPLAY;
}

// Mesa loads its driver (swrast_dri.so, the llvmpipe) at eglInitialize and unloads it at
// eglTerminate. Kept loaded instead (RTLD_NODELETE on the already loaded library), so that the
// allocations the driver keeps until exit are named by the leak checker (the sanitizer run) and by
// profilers rather than being "<unknown module>", which no suppression can match. A process that
// makes a context again would load the driver again anyway.
void keepGlDriverLoaded() {
    dl_iterate_phdr(
        [](dl_phdr_info* info, size_t, void*) {
            const char* name = info->dlpi_name;
            const size_t n = name ? std::strlen(name) : 0;
            if (n > 7 && std::strcmp(name + n - 7, "_dri.so") == 0)
                dlopen(name, RTLD_LAZY | RTLD_NOLOAD | RTLD_NODELETE);
            return 0;
        },
        nullptr);
}

}  // namespace

std::unique_ptr<HeadlessContext> HeadlessContext::create(Profile profile) {
    std::string why;
    EGLDisplay display = openDisplay(why);
    if (display == EGL_NO_DISPLAY)
        throw std::runtime_error("cannot open an EGL display (" + why + "): " + kInstallHint);
    keepGlDriverLoaded();
    if (!eglBindAPI(EGL_OPENGL_API)) {
        eglTerminate(display);
        throw std::runtime_error("EGL cannot bind the desktop OpenGL API: " + std::string(kInstallHint));
    }
    const EGLint core[] = {
        EGL_CONTEXT_MAJOR_VERSION,           4,       EGL_CONTEXT_MINOR_VERSION, 5, EGL_CONTEXT_OPENGL_PROFILE_MASK,
        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    // No version asked: the driver gives its highest compatibility version.
    const EGLint compatibility[] = {EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT,
                                    EGL_NONE};
    EGLContext context =
        eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, profile == Profile::Core ? core : compatibility);
    if (context == EGL_NO_CONTEXT) {
        const EGLint e = eglGetError();
        eglTerminate(display);
        throw std::runtime_error(std::string("cannot create an OpenGL ") +
                                 (profile == Profile::Core ? "4.5 core" : "compatibility") + " context (" +
                                 eglErrorText(e) + "): " + kInstallHint);
    }
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
        const EGLint e = eglGetError();
        eglDestroyContext(display, context);
        eglTerminate(display);
        throw std::runtime_error("cannot make the OpenGL context current (" + eglErrorText(e) + ")");
    }
    std::unique_ptr<HeadlessContext> c(new HeadlessContext);
    c->display_ = display;
    c->context_ = context;
    return c;
}

HeadlessContext::~HeadlessContext() {
    auto display = static_cast<EGLDisplay>(display_);
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display, static_cast<EGLContext>(context_));
    eglTerminate(display);
}

std::unique_ptr<HeadlessContext::Shared> HeadlessContext::createShared() const {
    const EGLint attributes[] = {
        EGL_CONTEXT_MAJOR_VERSION,           4,       EGL_CONTEXT_MINOR_VERSION, 5, EGL_CONTEXT_OPENGL_PROFILE_MASK,
        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    EGLContext context = eglCreateContext(static_cast<EGLDisplay>(display_), EGL_NO_CONFIG_KHR,
                                          static_cast<EGLContext>(context_), attributes);
    if (context == EGL_NO_CONTEXT)
        throw std::runtime_error("cannot create a shared OpenGL context (" + eglErrorText(eglGetError()) + ")");
    std::unique_ptr<Shared> shared(new Shared);
    shared->display_ = display_;
    shared->context_ = context;
    return shared;
}

HeadlessContext::Shared::~Shared() {
    eglDestroyContext(static_cast<EGLDisplay>(display_), static_cast<EGLContext>(context_));
}

void HeadlessContext::Shared::bind() {
    eglBindAPI(EGL_OPENGL_API);  // the bound API is per thread (EGL 1.5, 3.7)
    if (!eglMakeCurrent(static_cast<EGLDisplay>(display_), EGL_NO_SURFACE, EGL_NO_SURFACE,
                        static_cast<EGLContext>(context_)))
        throw std::runtime_error("cannot make the shared OpenGL context current (" + eglErrorText(eglGetError()) + ")");
}

void HeadlessContext::Shared::unbind() {
    eglMakeCurrent(static_cast<EGLDisplay>(display_), EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
}

std::string HeadlessContext::renderer() const {
    const auto* r = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return r ? r : "unknown";
}

}  // namespace fraktal::gl
