// A process saving a preset is killed with SIGKILL at moments spread over the save, many times:
// the file on disk is always the complete old or the complete new version, never a mix, a
// truncation or a missing file; the backup is always a complete preset too. The kills are timed
// from the save's measured duration, so that both dangerous moments are met: kills while the new
// version is being written (the old one must stay) and kills after it replaced the old one.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <deque>
#include <fstream>
#include <numeric>
#include <optional>
#include <random>
#include <sstream>
#include <thread>

#include "test_support.hpp"

using namespace fraktal;

namespace {

using Clock = std::chrono::steady_clock;  // CLOCK_MONOTONIC: one clock for the parent and its children

std::string readAll(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// A child process that saves `preset` over `file`. It writes the time to `started` just before
// its first savePresetFile and to `finished` just after that returned, then saves the same
// version again and again until it is killed (so that every kill interrupts a save).
struct Saver {
    pid_t pid = -1;
    int started = -1, finished = -1;  // the read ends
    Clock::time_point saveStarted;
};

Saver startSaver(const std::filesystem::path& file, const Preset& preset) {
    int started[2], finished[2];
    if (pipe(started) != 0) return {};
    if (pipe(finished) != 0) {
        close(started[0]);
        close(started[1]);
        return {};
    }
    const pid_t child = fork();
    if (child == 0) {
        close(started[0]);
        close(finished[0]);
        const Clock::time_point t0 = Clock::now();
        if (write(started[1], &t0, sizeof t0) != sizeof t0) _exit(4);
        for (int i = 0;; ++i) {
            try {
                savePresetFile(file, preset);
            } catch (...) {
                _exit(3);
            }
            const Clock::time_point t1 = Clock::now();
            if (i == 0 && write(finished[1], &t1, sizeof t1) != sizeof t1) _exit(4);
        }
    }
    close(started[1]);
    close(finished[1]);
    Saver s{child, started[0], finished[0], {}};
    if (child > 0 && read(s.started, &s.saveStarted, sizeof s.saveStarted) != sizeof s.saveStarted)
        s.pid = -1;  // the child died before saving
    return s;
}

// Kills the child and reaps it; when its first save returned, if it did. False in `signalled`
// when the child did not die of the kill (it stopped by itself: a save threw).
std::optional<Clock::time_point> killSaver(Saver& s, bool& signalled) {
    kill(s.pid, SIGKILL);
    int status = 0;
    waitpid(s.pid, &status, 0);
    signalled = WIFSIGNALED(status);
    Clock::time_point returned;
    // The child is gone: the pipe reads at its end when it wrote nothing.
    const bool didReturn = read(s.finished, &returned, sizeof returned) == sizeof returned;
    close(s.started);
    close(s.finished);
    return didReturn ? std::optional(returned) : std::nullopt;
}

double micros(Clock::duration d) { return std::chrono::duration<double, std::micro>(d).count(); }

}  // namespace

TEST(PresetSave, KilledMidSaveLeavesTheOldOrTheNewFile) {
    const test::Sandbox sandbox("fraktal_kill_");
    const std::filesystem::path file = sandbox.path("scene.json");

    // Two versions that differ in size and content, with long descriptions so that a save takes
    // long enough to be interrupted in the middle.
    Preset a = loadPreset(test::sourceDir() / "presets/mandelbox.json");
    Preset b = a;
    a.description = std::string(60000, 'a');
    b.description = std::string(30000, 'b');
    b.formula.nodes[0].values[0].x = 1.5;
    const std::string textA = serializePreset(a), textB = serializePreset(b);
    savePresetFile(file, a);
    savePresetFile(file, a);  // so that a backup exists from the start

    // The save's duration: the median of the last seven that returned, seven measured first. On
    // the 2-core machine a save takes about 1 ms alone, and 10 to 25 ms while another process
    // writes and flushes a file; the estimate follows such changes during the rounds below.
    std::deque<double> recent;
    auto estimate = [&] {
        std::vector<double> sorted(recent.begin(), recent.end());
        std::sort(sorted.begin(), sorted.end());
        return sorted[sorted.size() / 2];
    };
    auto measured = [&](double duration) {
        recent.push_back(duration);
        if (recent.size() > 7) recent.pop_front();
    };
    for (int i = 0; i < 7; ++i) {
        Saver s = startSaver(file, readAll(file) == textA ? b : a);
        ASSERT_GT(s.pid, 0);
        Clock::time_point returned;
        ASSERT_EQ(read(s.finished, &returned, sizeof returned), ssize_t(sizeof returned)) << "the save did not finish";
        measured(micros(returned - s.saveStarted));
        bool signalled = false;
        killSaver(s, signalled);
    }

    // Kills at delays spread evenly over twice the estimated duration, in random order, at least
    // 60 and until both moments were met (at most 300). The new version replaces the old one near
    // the end of the save (the new file is written and flushed, renamed over the old one, and the
    // folder flushed), so about a third of the kills come before that, and most of those while the
    // new file is written (its temporary file is left behind); the rest come after. A kill
    // meant for after the save's end that finds it still running says the estimate is short: it
    // grows by half.
    constexpr int kRounds = 60, kMaxRounds = 300;
    constexpr double kSpread = 2.0;
    std::vector<int> order(kRounds);
    std::iota(order.begin(), order.end(), 0);
    std::mt19937 rng(99);
    int keptOld = 0, keptOldMidWrite = 0, landedBeforeReturn = 0, landedAfterReturn = 0, rounds = 0;
    for (; rounds < kMaxRounds; ++rounds) {
        const int stratum = rounds % kRounds;
        if (stratum == 0) std::shuffle(order.begin(), order.end(), rng);
        if (rounds >= kRounds && keptOldMidWrite > 0 && landedBeforeReturn + landedAfterReturn > 0) break;
        const std::string before = readAll(file);
        Saver s = startSaver(file, before == textA ? b : a);
        ASSERT_GT(s.pid, 0) << "round " << rounds << ": the saving process did not start";
        const double share = (order[size_t(stratum)] + 0.5) / kRounds, delay = kSpread * estimate() * share;
        std::this_thread::sleep_until(s.saveStarted + std::chrono::duration<double, std::micro>(delay));
        bool signalled = false;
        const std::optional<Clock::time_point> returned = killSaver(s, signalled);
        ASSERT_TRUE(signalled) << "round " << rounds << ": the saving process stopped by itself (a save threw)";
        if (returned)
            measured(micros(*returned - s.saveStarted));
        else if (kSpread * share > 1.0)
            measured(1.5 * estimate());

        const std::string now = readAll(file);
        ASSERT_TRUE(now == textA || now == textB)
            << "round " << rounds << ": the file is neither version (" << now.size() << " bytes)";
        const std::string backup = readAll(file.string() + ".bak");
        ASSERT_TRUE(backup == textA || backup == textB) << "round " << rounds << ": the backup is broken";
        EXPECT_NO_THROW(loadPreset(file));
        // A killed save leaves its temporary file (hidden, .scene.tmp-<pid>-*); never the preset.
        const std::string temporary = ".scene.tmp-" + std::to_string(s.pid) + "-";
        bool leftTemporary = false;
        for (const auto& e : std::filesystem::directory_iterator(sandbox.dir))
            if (e.path().filename().string().rfind(temporary, 0) == 0) {
                leftTemporary = true;
                std::filesystem::remove(e.path());
            }
        if (now == before) {
            EXPECT_FALSE(returned) << "round " << rounds << ": the save returned, the old version is on disk";
            ++keptOld;
            keptOldMidWrite += leftTemporary;
        } else {
            (returned ? landedAfterReturn : landedBeforeReturn)++;
        }
    }
    std::printf(
        "%d kills, the save estimated at %.0f us at the end: %d kept the old version (%d of them while the new file "
        "was written), %d came after the new one replaced it (%d of them before the first save returned)\n",
        rounds, estimate(), keptOld, keptOldMidWrite, landedBeforeReturn + landedAfterReturn, landedBeforeReturn);
    EXPECT_GT(keptOldMidWrite, 0) << "no kill came while the new version was written";
    EXPECT_GT(landedBeforeReturn + landedAfterReturn, 0) << "no kill came after the new version replaced the old one";
}

TEST(PresetSave, KeepsTheBackupOfThePreviousVersion) {
    const auto dir = std::filesystem::temp_directory_path() / ("fraktal_bak_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const auto file = dir / "scene.json";
    Preset p = loadPreset(test::sourceDir() / "presets/menger.json");
    savePresetFile(file, p);
    EXPECT_FALSE(std::filesystem::exists(file.string() + ".bak"));
    const std::string first = readAll(file);
    p.formula.iterations = 5;
    savePresetFile(file, p);
    EXPECT_EQ(readAll(file.string() + ".bak"), first);
    EXPECT_EQ(loadPreset(file).formula.iterations, 5);
    std::filesystem::remove_all(dir);
}
