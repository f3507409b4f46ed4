#include "core/viewport/pass_timer.hpp"

namespace fraktal::viewport {

PassTimer::PassTimer() { glCreateQueries(GL_TIMESTAMP, kMaxMarks + 1, queries_); }

PassTimer::~PassTimer() { glDeleteQueries(kMaxMarks + 1, queries_); }

void PassTimer::begin() {
    marks_ = 0;
    glQueryCounter(queries_[0], GL_TIMESTAMP);
}

void PassTimer::mark(const char* pass) {
    if (marks_ >= kMaxMarks) return;
    names_[marks_] = pass;
    ++marks_;
    glQueryCounter(queries_[marks_], GL_TIMESTAMP);
}

std::vector<PassTime> PassTimer::read() {
    std::vector<PassTime> out;
    GLuint64 previous = 0;
    glGetQueryObjectui64v(queries_[0], GL_QUERY_RESULT, &previous);
    for (int i = 0; i < marks_; ++i) {
        GLuint64 now = 0;
        glGetQueryObjectui64v(queries_[i + 1], GL_QUERY_RESULT, &now);
        out.push_back(PassTime{names_[i], double(now - previous) * 1e-6});
        previous = now;
    }
    return out;
}

}  // namespace fraktal::viewport
