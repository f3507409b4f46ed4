// A headless OpenGL 4.5 core context through EGL (Mesa's surfaceless platform, or an EGL
// device), for the command line and the tests. The editor gets its context from GLFW instead;
// the renderer code is the same for both.
#pragma once

#include <memory>
#include <string>

namespace fraktal::gl {

class HeadlessContext {
   public:
    // Core: GL 4.5 core, what fraktal renders with. Compatibility: the driver's highest
    // compatibility-profile version, for running foreign GLSL written against the fixed-function
    // built-ins (gl_Vertex, gl_FragColor, texture2D), as Fragmentarium frags are (bench/frag).
    enum class Profile { Core, Compatibility };
    // Creates and makes current a GL 4.5 core context (or a compatibility one). Throws
    // std::runtime_error saying why it failed and what to install.
    static std::unique_ptr<HeadlessContext> create(Profile profile = Profile::Core);
    ~HeadlessContext();
    HeadlessContext(const HeadlessContext&) = delete;
    HeadlessContext& operator=(const HeadlessContext&) = delete;

    std::string renderer() const;  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"

    // A second context that shares this one's objects (programs, buffers, textures), for GL work
    // on another thread, e.g. compiling programs in the background. Not current anywhere until
    // its bind(). Destroy it before this context.
    class Shared {
       public:
        ~Shared();
        Shared(const Shared&) = delete;
        Shared& operator=(const Shared&) = delete;
        void bind();    // makes it current on the calling thread (throws if EGL refuses)
        void unbind();  // releases it from the calling thread

       private:
        friend class HeadlessContext;
        Shared() = default;
        void* display_ = nullptr;
        void* context_ = nullptr;
    };
    std::unique_ptr<Shared> createShared() const;

   private:
    HeadlessContext() = default;
    void* display_ = nullptr;
    void* context_ = nullptr;
};

}  // namespace fraktal::gl
